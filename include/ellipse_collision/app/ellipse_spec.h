#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/ellipsoid.h"
#include "ellipse_collision/core/frame_projection.h"
#include "ellipse_collision/core/first_contact.h"

namespace ellipse_collision::app {

/// The third dimension of a link that tilts with its frame (an arm's links) or of an obstacle
/// that is a 3D body (a cluster of a point cloud): with the spec's x, y, radius_x, radius_y and
/// angle (the yaw) it makes the ellipsoid {c + R D u : |u| <= 1}, c = (x, y, z),
/// R = Rz(angle) Ry(pitch) Rx(roll), D = diag(radius_x, radius_y, radius_z), all in frame_id.
/// Such an ellipse is checked by its shadow on the fixed frame's plane (core::shadowOnPlane()),
/// which covers it however its frame tilts.
struct EllipsoidPart {
  double z{0.0};         ///< centre in frame_id [m]
  double roll{0.0};      ///< about the ellipsoid's x axis [rad]
  double pitch{0.0};     ///< about its y axis, after roll [rad]
  double radius_z{0.0};  ///< semi-axis along its own z axis [m], > 0
};

/// A named ellipse attached to a tf frame, as configured or requested (the fields of msg Ellipse).
struct EllipseSpec {
  std::string name;      ///< unique across links and obstacles
  std::string frame_id;  ///< tf frame whose xy-plane holds the ellipse
  double x{0.0};         ///< centre in frame_id [m]
  double y{0.0};         ///< centre in frame_id [m]
  double angle{0.0};     ///< counter-clockwise from frame_id's x axis to the ellipse's x axis [rad]
  double radius_x{0.0};  ///< [m], > 0
  double radius_y{0.0};  ///< [m], > 0
  double padding{0.0};   ///< added to both radii [m], >= 0
  /// Own velocity in frame_id's axes (the frame's motion from tf comes on top): used by the
  /// time-to-contact prediction and timed path checks. Finite, within core::kMaxSpeed [m/s] and
  /// core::kMaxAngularVelocity [rad/s].
  double vx{0.0};                ///< [m/s]
  double vy{0.0};                ///< [m/s]
  double angular_velocity{0.0};  ///< about the centre, counter-clockwise about frame_id's z [rad/s]
  /// Set for an ellipsoid (links and obstacles alike: configuration, URDF fits, messages, the
  /// obstacle store); otherwise the ellipse lies in frame_id's xy-plane.
  std::optional<EllipsoidPart> ellipsoid;
};

/// Checks every field of `spec` except whether its frame exists (that needs tf): name and frame
/// non-empty, frame without a leading '/', the core's value rules for the centre, angle and radii
/// (core::coordinateViolation() and friends; for an ellipsoid also z, roll, pitch, radius_z, and
/// radius_z = 0 only with z, roll and pitch 0 too: messages give a planar ellipse radius_z = 0,
/// so an ellipsoid part with radius_z = 0 and a tilt is a forgotten radius_z, refused naming the
/// first of z, roll, pitch that is not 0), padding finite, >= 0 and <= kMaxRadius; vx, vy
/// finite within [-core::kMaxSpeed, core::kMaxSpeed], angular_velocity finite within
/// [-core::kMaxAngularVelocity, core::kMaxAngularVelocity].
/// `frame_key` is how the caller spells the frame field ("frame_id" in messages, "frame" in YAML).
std::optional<FieldError> findInvalidField(const EllipseSpec& spec,
                                           const std::string& frame_key = "frame_id");

/// findInvalidField(), then the radii the core is given: radius_x, radius_y (and radius_z) grown by
/// spec.padding + global_padding (as paddedEllipse() does) must lie within [kMinRadius,
/// kMaxRadius]. A violation names the radius key, with its own value as `actual`. Every
/// configured entry and every request or topic ellipse passes this before it is used.
std::optional<FieldError> findInvalidPaddedField(const EllipseSpec& spec, double global_padding,
                                                 const std::string& frame_key = "frame_id");

/// The ellipse in its own frame with both radii grown by spec.padding + global_padding [m].
core::Ellipse paddedEllipse(const EllipseSpec& spec, double global_padding);

/// A planar, unpadded, standing spec named `name` in `frame` holding `ellipse` as it is (the
/// inverse of paddedEllipse() with no padding).
EllipseSpec planarSpec(const core::Ellipse& ellipse, const std::string& name,
                       const std::string& frame);

/// The ellipsoid in its own frame with all three radii grown as paddedEllipse() grows its two
/// (radius + spec.padding + global_padding [m], summed in that order); requires spec.ellipsoid.
core::Ellipsoid paddedEllipsoid(const EllipseSpec& spec, double global_padding);

/// The padded spec placed in the fixed frame's plane through `fixed_from_frame`: a planar spec
/// projected (core::projectToPlane(), refused edge-on), an ellipsoid by its shadow
/// (core::shadowOnPlane(), never edge-on). The one placement rule of every check, path check,
/// prediction and the velocity gate.
core::ProjectionResult placeInPlane(const EllipseSpec& spec, double global_padding,
                                    const Eigen::Isometry3d& fixed_from_frame);

/// The spec's own velocity in a target frame's plane: (vx, vy, 0) turned by the frame's
/// orientation and projected; the angular velocity about the frame's z axis counts by the z
/// component of that axis in the target frame (exact for frames parallel to the plane).
core::Motion ownMotion(const EllipseSpec& spec, const Eigen::Isometry3d& target_from_frame);

}  // namespace ellipse_collision::app

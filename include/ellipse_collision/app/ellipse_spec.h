#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"

namespace ellipse_collision::app {

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
};

/// Checks every field of `spec` except whether its frame exists (that needs tf): name and frame
/// non-empty, frame without a leading '/', the core's value rules for the centre, angle and radii
/// (core::coordinateViolation() and friends), padding finite, >= 0 and <= kMaxRadius; vx, vy
/// finite within [-core::kMaxSpeed, core::kMaxSpeed], angular_velocity finite within
/// [-core::kMaxAngularVelocity, core::kMaxAngularVelocity].
/// `frame_key` is how the caller spells the frame field ("frame_id" in messages, "frame" in YAML).
std::optional<FieldError> findInvalidField(const EllipseSpec& spec,
                                           const std::string& frame_key = "frame_id");

/// findInvalidField(), then the radii the core is given: radius_x and radius_y grown by
/// spec.padding + global_padding (as paddedEllipse() does) must lie within [kMinRadius,
/// kMaxRadius]. A violation names the radius key, with its own value as `actual`. Every
/// configured entry and every request or topic ellipse passes this before it is used.
std::optional<FieldError> findInvalidPaddedField(const EllipseSpec& spec, double global_padding,
                                                 const std::string& frame_key = "frame_id");

/// The ellipse in its own frame with both radii grown by spec.padding + global_padding [m].
core::Ellipse paddedEllipse(const EllipseSpec& spec, double global_padding);

/// The spec's own velocity in a target frame's plane: (vx, vy, 0) turned by the frame's
/// orientation and projected; the angular velocity about the frame's z axis counts by the z
/// component of that axis in the target frame (exact for frames parallel to the plane).
core::Motion ownMotion(const EllipseSpec& spec, const Eigen::Isometry3d& target_from_frame);

}  // namespace ellipse_collision::app

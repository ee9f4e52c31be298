#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/frame_projection.h"

namespace ellipse_collision::core {

/// A closed 3D ellipsoid in some frame: {center + R(orientation) diag(radii) u : |u| <= 1}.
/// A link that tilts at run time is one of these: its shadow on the fixed frame's plane
/// (shadowOnPlane()) covers the link at every joint angle, which a planar ellipse seen edge-on
/// cannot.
struct Ellipsoid {
  Eigen::Vector3d center{0.0, 0.0, 0.0};                             ///< [m]
  Eigen::Quaterniond orientation{Eigen::Quaterniond::Identity()};    ///< frame from ellipsoid axes
  Eigen::Vector3d radii{1.0, 1.0, 1.0};  ///< semi-axes along the ellipsoid's own x, y, z [m], > 0
};

/// Why `ellipsoid` cannot be used, naming the field and its value ("radii.z = 0 must be > 0"), or
/// an empty string: centre coordinates and radii keep the rules of Ellipse's fields (see
/// ellipse.h), the orientation is finite and of unit norm within 1e-6.
std::string invalidReason(const Ellipsoid& ellipsoid);

/// The shape matrix R diag(radii^2) R^T: the ellipsoid is {x : (x - c)^T A^-1 (x - c) <= 1} [m^2].
Eigen::Matrix3d shapeMatrix(const Ellipsoid& ellipsoid);

/// The orthogonal shadow on the fixed frame's xy-plane of `in_frame`, an ellipsoid in a frame
/// whose pose in the fixed frame is `fixed_from_frame`.
/// Certified to contain the exact shadow of the given data (method and cost:
/// doc/core_methods.md).
///
/// Errors (`name` only names the ellipsoid in them): an invalid `in_frame` (see invalidReason()),
/// a non-finite transform, a shadow that invalidReason(Ellipse) refuses (a centre moved beyond
/// kMaxCoordinate, a radius beyond kMaxRadius), or one too thin to certify: an axis ratio above
/// about 7e16, where the certification's own error bound reaches half the shadow's width (only a
/// needle at least 7e7 m long gets there).
ProjectionResult shadowOnPlane(const Ellipsoid& in_frame, const Eigen::Isometry3d& fixed_from_frame,
                               const std::string& name);

}  // namespace ellipse_collision::core

#pragma once

#include <Eigen/Geometry>
#include <string>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// A projection is refused as edge-on when the projected ellipse's smaller semi-axis is below this
/// fraction of the smaller radius it had in its own frame (for a circle: the frame's z axis is
/// within about 1e-6 rad of the fixed plane). Below it the ellipse is numerically a line segment:
/// its minor radius carries a relative rounding error of roughly 1e-16 / kMinProjectedThinning
/// and the collision tests become ill-conditioned.
constexpr double kMinProjectedThinning = 1e-6;

/// Either the projected ellipse (when `error` is empty) or why there is none.
struct ProjectionResult {
  Ellipse ellipse;    ///< in the fixed frame's xy-plane; meaningful only when ok()
  std::string error;  ///< names the ellipse and the reason; empty on success
  bool ok() const { return error.empty(); }
};

/// Orthogonal projection onto the fixed frame's xy-plane of `in_frame`, an ellipse lying in the
/// xy-plane of a frame whose pose in the fixed frame is `fixed_from_frame`.
///
/// The image of {c + R(angle) diag(radius_x, radius_y) u : |u| <= 1} is exactly the ellipse
/// {c' + A u} with c' = (fixed_from_frame * (c, 0)).xy and A = P R(angle) diag(radius_x, radius_y),
/// P the top-left 2x2 block of the rotation. The returned radii are A's singular values
/// (radius_x >= radius_y), its angle the direction of the first left singular vector, in
/// (-pi/2, pi/2] [rad]. `name` is only used to make error messages name the ellipse.
///
/// Errors: an invalid `in_frame` (see invalidReason()), a non-finite transform, an edge-on frame
/// (see kMinProjectedThinning), or a projection that invalidReason() refuses (a radius thinned
/// below kMinRadius, a centre moved beyond kMaxCoordinate).
ProjectionResult projectToPlane(const Ellipse& in_frame, const Eigen::Isometry3d& fixed_from_frame,
                                const std::string& name);

}  // namespace ellipse_collision::core

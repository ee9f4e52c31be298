#pragma once

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {
namespace detail {

/// The circle tests compare squared lengths computed in double; this relative margin keeps their
/// decisions clear of rounding so that near-tangent pairs go on to the exact stages.
inline constexpr double kCircleMargin = 1e-12;

/// Whether circles of these centres [m] whose radii add up to `radius_sum` [m] are certainly apart.
inline bool circlesApart(const Eigen::Vector2d& center_a, const Eigen::Vector2d& center_b,
                         double radius_sum) {
  return (center_b - center_a).squaredNorm() > radius_sum * radius_sum * (1.0 + kCircleMargin);
}

/// overlap() for a pair whose bounding circles meet.
bool overlapOfNearPair(const Ellipse& a, const Ellipse& b);

}  // namespace detail

/// True iff the closed ellipses share a point (containment is a collision). Cheap exact bounding
/// and inscribed circle tests first, then the polygonal early-out, and the eigenvalue test whenever
/// those cannot prove the answer. Both ellipses must be valid (see invalidReason()).
/// The bounding-circle rejection, which decides most pairs of a scene, is inline.
inline bool overlap(const Ellipse& a, const Ellipse& b) {
  return !detail::circlesApart(a.center, b.center, boundingRadius(a) + boundingRadius(b)) &&
         detail::overlapOfNearPair(a, b);
}

}  // namespace ellipse_collision::core

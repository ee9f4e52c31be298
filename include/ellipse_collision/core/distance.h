#pragma once

#include <Eigen/Core>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// How far apart two ellipses are, and where.
struct Clearance {
  /// False iff overlap() says the closed ellipses share a point; then distance is 0 and the points
  /// are meaningless (left at the origin).
  bool separated{false};
  /// Euclidean minimum distance between the two ellipses [m]; 0 when they overlap, and possibly 0
  /// when separated but touching to within rounding.
  double distance{0.0};
  /// The point of the first ellipse's rim closest to the second ellipse [m].
  Eigen::Vector2d point_a{0.0, 0.0};
  /// The point of the second ellipse's rim closest to the first ellipse [m].
  Eigen::Vector2d point_b{0.0, 0.0};
};

/// Exact minimum distance between `a` and `b` and its witness points (point_b - point_a is normal
/// to both rims). The overlap decision is overlap()'s, so the two functions always agree.
/// Absolute error about epsilon times the radii (method and accuracy: doc/core_methods.md). Both
/// ellipses must be valid (see invalidReason()).
Clearance distance(const Ellipse& a, const Ellipse& b);

}  // namespace ellipse_collision::core

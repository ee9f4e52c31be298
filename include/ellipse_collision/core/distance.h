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
///
/// Method: the concave support-function dual (Boyd & Vandenberghe, 8.2.3)
///   distance = max over unit u of  u . (c_b - c_a) - h_a(u) - h_b(u),
/// with h the support function of the centred ellipse, maximised over the angle of u by a bracketed
/// Halley/Newton iteration (no local minimum to stop in, see distance.cpp); the witness points are
/// the support points of the maximising u. Only c_b - c_a enters, so centres may be far from the
/// origin. Accuracy: the absolute error is about epsilon times the radii, from rounding cos and sin
/// of the angles (the small gap between large support values is evaluated in double-double), so
/// the relative error stays below 1e-9 down to distances of 1e-6 of the larger radius, for axis
/// ratios up to 1e3 and sizes 1e-4..1e4 m. Both ellipses must be valid (see invalidReason()).
Clearance distance(const Ellipse& a, const Ellipse& b);

}  // namespace ellipse_collision::core

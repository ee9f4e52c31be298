#pragma once

#include <Eigen/Core>

#include "ellipse_collision/ellipse.h"

namespace ellipse_collision::detail {

/// Ellipse `other` seen in the frame where ellipse `unit` is the unit circle at the origin:
/// other = {center + axes * u : |u| <= 1}. Both collision tests work in this frame, where the
/// centres have been subtracted before anything else so far-away scenes keep their precision.
struct RelativeShape {
  Eigen::Vector2d center;
  Eigen::Matrix2d axes;          ///< columns: images of the other ellipse's semi-axes
  Eigen::Matrix2d inverse_axes;  ///< axes^-1, built from its factors rather than by inversion
  double determinant;            ///< det(axes) = area(other) / area(unit) > 0
};

RelativeShape relativeShape(const Ellipse& unit, const Ellipse& other);

/// The pair in the frame of the ellipse with the larger area: then det(axes) <= 1 and the
/// maximiser of Q(s) lies where s is represented most finely. Ties are broken by a total order
/// on the fields, so that (a, b) and (b, a) compute the very same numbers: every test built on
/// this is exactly symmetric.
RelativeShape canonicalRelativeShape(const Ellipse& a, const Ellipse& b);

}  // namespace ellipse_collision::detail

#pragma once

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "sin_cos.h"

namespace ellipse_collision::core::detail {

/// The per-ellipse factors of the frame change. PreparedEllipse computes them once; the plain API
/// computes them per pair with this same function, so both APIs see the very same numbers.
struct FrameFactors {
  double cos_angle;
  double sin_angle;
  double inverse_radius_x;  ///< [1/m]
  double inverse_radius_y;  ///< [1/m]
};

inline FrameFactors frameFactors(const Ellipse& e, const SinCos& trig) {
  return {trig.cos, trig.sin, 1.0 / e.radius_x, 1.0 / e.radius_y};
}

inline FrameFactors frameFactors(const Ellipse& e) { return frameFactors(e, sinCos(e.angle)); }

inline const Ellipse& ellipseOf(const Ellipse& e) { return e; }
inline const Ellipse& ellipseOf(const PreparedEllipse& e) { return e.ellipse(); }

/// sin and cos of both angles within kCoarseSinCosError, for the centre-line test: the coarse
/// series for plain ellipses, the stored values (closer still) for prepared ones.
inline SinCosPair coarseSinCosPairOf(const Ellipse& a, const Ellipse& b) {
  return sinCosPairCoarse(a.angle, b.angle);
}
inline SinCosPair coarseSinCosPairOf(const PreparedEllipse& a, const PreparedEllipse& b) {
  return {{a.sinAngle(), a.cosAngle()}, {b.sinAngle(), b.cosAngle()}};
}

inline FrameFactors frameFactors(const PreparedEllipse& e) {
  return {e.cosAngle(), e.sinAngle(), e.inverseRadiusX(), e.inverseRadiusY()};
}

/// Ellipse `other` seen in the frame where ellipse `unit` is the unit circle at the origin:
/// other = {center + u_x p + u_y q : |u| <= 1}, p and q the images of its semi-axes. Both
/// collision tests work in this frame, where the centres have been subtracted before anything
/// else so far-away scenes keep their precision. Plain doubles, and built inline: the hot path
/// keeps it in registers (GCC writes small Eigen objects with scalar stores and reads them back
/// with vector loads, which stalls store forwarding).
struct RelativeShape {
  double center_x, center_y;
  double p_x, p_y;
  double q_x, q_y;
  double determinant;  ///< det(p, q) = area(other) / area(unit) > 0
};

/// The relative rotation comes from the angle-difference identities on the factors' cos and sin:
/// no trigonometry per pair, and equal angles still give an exactly zero relative sine. Only the
/// unit's inverse radii are used.
inline RelativeShape relativeShape(const Ellipse& unit, const FrameFactors& unit_factors,
                                   const Ellipse& other, double other_cos, double other_sin) {
  const double cos_unit = unit_factors.cos_angle;
  const double sin_unit = unit_factors.sin_angle;
  const double inv_rx = unit_factors.inverse_radius_x;
  const double inv_ry = unit_factors.inverse_radius_y;
  const double offset_x = other.center.x() - unit.center.x();
  const double offset_y = other.center.y() - unit.center.y();

  RelativeShape shape;
  shape.center_x = (cos_unit * offset_x + sin_unit * offset_y) * inv_rx;
  shape.center_y = (cos_unit * offset_y - sin_unit * offset_x) * inv_ry;
  // cos and sin of (other.angle - unit.angle).
  const double c = other_cos * cos_unit + other_sin * sin_unit;
  const double s = other_sin * cos_unit - other_cos * sin_unit;
  // [p q] = diag(1/rx, 1/ry) * R(relative_angle) * diag(other.rx, other.ry)
  shape.p_x = c * other.radius_x * inv_rx;
  shape.p_y = s * other.radius_x * inv_ry;
  shape.q_x = -s * other.radius_y * inv_rx;
  shape.q_y = c * other.radius_y * inv_ry;
  shape.determinant = (other.radius_x * inv_rx) * (other.radius_y * inv_ry);
  return shape;
}

/// The total order that breaks ties of area in precedesAsUnit().
bool precedesAsUnitOnEqualArea(const Ellipse& a, const Ellipse& b);

/// Whether `a` is the unit of the canonical frame of the pair (a, b): the ellipse with the larger
/// area, so that det(p, q) <= 1 and the maximiser of Q(s) lies where s is represented most
/// finely. Ties are broken by a total order on the fields, so that (a, b) and (b, a) compute the
/// very same numbers: every test built on this is exactly symmetric.
inline bool precedesAsUnit(const Ellipse& a, const Ellipse& b) {
  // The areas decide all but ties, and as a value rather than a branch.
  const double area_a = a.radius_x * a.radius_y, area_b = b.radius_x * b.radius_y;
  if (area_a != area_b) return area_a > area_b;
  return precedesAsUnitOnEqualArea(a, b);
}

/// The pair in its canonical frame (see precedesAsUnit()).
inline RelativeShape canonicalRelativeShape(const Ellipse& a, const Ellipse& b) {
  const bool a_is_unit = precedesAsUnit(a, b);
  const Ellipse& unit = a_is_unit ? a : b;
  const Ellipse& other = a_is_unit ? b : a;
  // Both angles in one sinCosPair(): the same bits as PreparedEllipse's one at a time.
  const SinCosPair trig = sinCosPair(unit.angle, other.angle);
  return relativeShape(unit, frameFactors(unit, trig.first), other, trig.second.cos,
                       trig.second.sin);
}

inline RelativeShape canonicalRelativeShape(const PreparedEllipse& a, const PreparedEllipse& b) {
  const bool a_is_unit = precedesAsUnit(a.ellipse(), b.ellipse());
  const PreparedEllipse& unit = a_is_unit ? a : b;
  const PreparedEllipse& other = a_is_unit ? b : a;
  return relativeShape(unit.ellipse(), frameFactors(unit), other.ellipse(), other.cosAngle(),
                       other.sinAngle());
}

/// The other ellipse's own axes in that frame (the eigenvectors of M = [p q] [p q]^T, whose
/// eigenvalues are its squared semi-axes), and the centre offset along them, in which Q(s)
/// separates into two terms.
struct PrincipalShape {
  double lambda[2];     ///< squared semi-axes of the other ellipse, lambda[0] >= lambda[1] > 0
  double semi_axis[2];  ///< sqrt(lambda)
  double offset[2];     ///< |centre offset| along those axes, >= 0
};

PrincipalShape principalShape(const RelativeShape& shape);

}  // namespace ellipse_collision::core::detail

#pragma once

#include <quadmath.h>

#include <string>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {
namespace test {

/// Contact scale t* computed in quad precision, independently of the eigenvalue test: t* is the
/// gauge of d = c_b - c_a with respect to the Minkowski sum of the two centred ellipses,
///   t* = max over unit u of (u . d) / (h_a(u) + h_b(u)),  h(u) = sqrt(u^T S u),
/// maximised over u = (cos phi, sin phi) by dense sampling and a quad-precision bisection on the
/// sign of the derivative.
struct OracleContactScale {
  __float128 quad{0};  ///< t* in quad precision (dimensionless)
  double value{0.0};   ///< t* rounded to double
  __float128 phi{0};   ///< direction of the maximising unit vector u [rad]; 0 when d == 0
};

/// t* of the pair given by the double-valued fields; 0 when the centres coincide.
OracleContactScale oracleContactScale(const Ellipse& a, const Ellipse& b);

/// True iff the oracle's t* <= 1 (the closed ellipses share a point).
bool oracleOverlap(const Ellipse& a, const Ellipse& b);

/// Copy of `b` whose centre is moved along d = c_b - c_a so that t* becomes `target` (t* is
/// homogeneous of degree 1 in d). The new centre is rounded to double, so callers must re-measure
/// t* of the returned pair with oracleContactScale() instead of trusting `target`.
/// Requires c_a != c_b and target > 0.
Ellipse placeAtContactScale(const Ellipse& a, const Ellipse& b, double target);

/// Quad value as text with 36 significant digits, for failure messages.
std::string toString(__float128 value);

/// Both ellipses as "a = {cx, cy, rx, ry, angle}, b = {...}" with %.17g, for failure messages.
std::string describePair(const Ellipse& a, const Ellipse& b);

}  // namespace test
}  // namespace ellipse_collision::core

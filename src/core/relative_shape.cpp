#include "relative_shape.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace ellipse_collision::core::detail {
namespace {

// The eigenvector's squared length is formed directly between these, and after an exact rescaling
// by a power of two outside them (which changes no bit where nothing underflows or overflows).
// Inside, the eigenvector's components times an offset of 1e-290 stay normal numbers: an
// eigenvector of length 1e-58 times an offset of 1e-280 underflowed to "coincident centres"
// (fuzzer finding).
constexpr double kSmallestSafeNormSq = 0x1p-100;
constexpr double kLargestSafeNormSq = 0x1p100;

}  // namespace

PrincipalShape principalShape(const RelativeShape& shape) {
  const double m00 = shape.p_x * shape.p_x + shape.q_x * shape.q_x;
  const double m01 = shape.p_x * shape.p_y + shape.q_x * shape.q_y;
  const double m11 = shape.p_y * shape.p_y + shape.q_y * shape.q_y;
  const double half_difference = 0.5 * (m00 - m11);
  const double root = std::sqrt(half_difference * half_difference + m01 * m01);

  PrincipalShape principal;
  principal.lambda[0] = 0.5 * (m00 + m11) + root;
  principal.semi_axis[0] = std::sqrt(principal.lambda[0]);
  // The small ones from det(p, q) = product of the semi-axes avoid the cancellation in
  // mean - root.
  principal.semi_axis[1] = shape.determinant / principal.semi_axis[0];
  principal.lambda[1] = principal.semi_axis[1] * principal.semi_axis[1];

  // Eigenvector of lambda[0], from whichever of the two equivalent forms has no cancellation.
  double ex = half_difference >= 0.0 ? half_difference + root : m01;
  double ey = half_difference >= 0.0 ? m01 : root - half_difference;
  double norm_sq = ex * ex + ey * ey;
  if (!(norm_sq >= kSmallestSafeNormSq && norm_sq <= kLargestSafeNormSq)) {
    // Tiny (M = I up to an off-diagonal 1e-158: a subnormal square kept 1e-9 of the offsets,
    // fuzzer finding) or huge: scaled by a power of two before squaring.
    const double larger = std::max(std::abs(ex), std::abs(ey));
    if (larger > 0.0 && std::isfinite(larger)) {
      const int exponent = std::ilogb(larger);
      ex = std::ldexp(ex, -exponent);
      ey = std::ldexp(ey, -exponent);
      norm_sq = ex * ex + ey * ey;
    } else {  // M is a multiple of the identity: any basis diagonalises it
      ex = 1.0;
      ey = 0.0;
      norm_sq = 1.0;
    }
  }
  const double inverse_norm = 1.0 / std::sqrt(norm_sq);
  principal.offset[0] = std::abs(ex * shape.center_x + ey * shape.center_y) * inverse_norm;
  principal.offset[1] = std::abs(ex * shape.center_y - ey * shape.center_x) * inverse_norm;
  return principal;
}

bool precedesAsUnitOnEqualArea(const Ellipse& a, const Ellipse& b) {
  return std::make_tuple(a.radius_x, a.radius_y, a.angle, a.center.x(), a.center.y()) >=
         std::make_tuple(b.radius_x, b.radius_y, b.angle, b.center.x(), b.center.y());
}

}  // namespace ellipse_collision::core::detail

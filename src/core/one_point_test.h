#pragma once

#include <Eigen/Core>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/polygonal_early_out.h"
#include "sin_cos.h"

namespace ellipse_collision::core::detail {

/// Used only up to this axis ratio R / r of either ellipse: errors in the shape matrices are
/// amplified by up to the square of the ratio (see kOnePointMargin).
inline constexpr double kOnePointMaxRatio = 30.0;

/// Relative margin of both certificates. With cos and sin off by e = kCoarseSinCosError, each
/// shape matrix moves by at most 4e R^2; K(s) >= (1-s) r_a^2 + s r_b^2 in every direction, so F(s)
/// and the two norms move relatively by a small multiple of 4e ratio^2 <= 4e-11 * 900 < 4e-8;
/// rounding adds ratio^2 times a few 1e-16.
inline constexpr double kOnePointMargin = 1e-6;

/// The Perram-Wertheim function at one point s of (0, 1), with both of its certificates
/// (Perram and Wertheim 1985; the eigenvalue test's Q(s) in another frame). With M the shape
/// matrices (x in an ellipse iff (x - c)^T M^-1 (x - c) <= 1), d = c_b - c_a and
/// K = (1 - s) M_a + s M_b:
/// - F(s) = s (1 - s) d^T K^-1 d is at most max F = t*^2, so F(s) > 1 proves the pair apart;
/// - the point x = c_a + (1 - s) M_a K^-1 d = c_b - s M_b K^-1 d lies in a iff
///   (1 - s)^2 y^T M_a y <= 1 and in b iff s^2 y^T M_b y <= 1 (y = K^-1 d): both prove overlap.
/// At the maximising s both certificates are tight, so a good guess decides most pairs that the
/// centre-line test leaves. `s` is that guess; the answer is valid for any s in (0, 1).
inline PolygonalResult onePointTest(const Ellipse& a, const SinCos& trig_a, const Ellipse& b,
                                    const SinCos& trig_b, double s) {
  using Lanes = Eigen::Array2d;  // lane 0 is a, lane 1 is b
  const Lanes radius_x(a.radius_x, b.radius_x), radius_y(a.radius_y, b.radius_y);
  const Lanes major = radius_x.max(radius_y), minor = radius_x.min(radius_y);
  if (!((major <= kOnePointMaxRatio * minor).all() && s > 0.0 && s < 1.0)) {
    return PolygonalResult::Unknown;
  }
  const Lanes cos_angle(trig_a.cos, trig_b.cos), sin_angle(trig_a.sin, trig_b.sin);
  const Lanes xx = radius_x.square(), yy = radius_y.square();
  // M = R diag(rx^2, ry^2) R^T
  const Lanes m00 = xx * cos_angle.square() + yy * sin_angle.square();
  const Lanes m01 = (xx - yy) * cos_angle * sin_angle;
  const Lanes m11 = xx * sin_angle.square() + yy * cos_angle.square();
  const double sc = 1.0 - s;
  const double k00 = sc * m00[0] + s * m00[1];
  const double k01 = sc * m01[0] + s * m01[1];
  const double k11 = sc * m11[0] + s * m11[1];
  const double dx = b.center.x() - a.center.x();
  const double dy = b.center.y() - a.center.y();
  const double inverse_det = 1.0 / (k00 * k11 - k01 * k01);
  const double y0 = (k11 * dx - k01 * dy) * inverse_det;
  const double y1 = (k00 * dy - k01 * dx) * inverse_det;
  const Lanes norm = m00 * (y0 * y0) + 2.0 * m01 * (y0 * y1) + m11 * (y1 * y1);  // y^T M y
  const double value = s * sc * (sc * norm[0] + s * norm[1]);
  if (value > 1.0 + kOnePointMargin) return PolygonalResult::Separate;
  if (sc * sc * norm[0] <= 1.0 - kOnePointMargin && s * s * norm[1] <= 1.0 - kOnePointMargin) {
    return PolygonalResult::Overlap;
  }
  return PolygonalResult::Unknown;
}

}  // namespace ellipse_collision::core::detail

#pragma once

#include <Eigen/Core>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/polygonal_early_out.h"
#include "sin_cos.h"

namespace ellipse_collision::core::detail {

/// The centre-line test reads the angles through sinCosPairCoarse(): an error e =
/// kCoarseSinCosError in cos and sin moves d.u and d.v by at most 2 e |d|, hence each |d| h(d^)
/// by at most 2 sqrt(2) e R |d| <= 3e-11 R (R_a + R_b), since the bounding circles meet. Rounding
/// adds some 1e-15 of the same. Separation is claimed only beyond this margin on (R_a + R_b)^2.
inline constexpr double kCentreLineApartMargin = 1e-10;

/// The overlap certificate is used only up to this axis ratio R / r: the radial extent's
/// denominator t >= r |d| moves by the same 3e-11 R |d|, relatively 3e-11 R / r <= 3e-8 for
/// each ellipse; overlap is claimed only beyond this relative margin.
inline constexpr double kCentreLineMaxRatio = 1e3;
inline constexpr double kCentreLineCoverMargin = 1e-7;

/// The squares below neither overflow nor, where it matters, underflow: radii and coordinates
/// obey the ellipse rules (1e-9..1e9 m, |centre| <= 1e9 m), and a square below 1e-308 is either
/// negligible against the other term or both are and the centres nearly coincide (Overlap, right).
/// The two facts about a pair that can be read along the line through its centres, d = b - a,
/// with the ellipses' own cos and sin and no frame change:
/// - separating axis d: the ellipses are apart if |d| exceeds the sum of their supports along d,
///   h(d^) = sqrt((rx d.u)^2 + (ry d.v)^2) / |d| (u, v the ellipse's axes);
/// - radial extents: each ellipse, convex and containing its centre, contains the segment from
///   its centre to its rim towards the other, of length rho(d^) = rx ry |d| /
///   sqrt((ry d.u)^2 + (rx d.v)^2); if the two lengths add up to |d| the segments cover the
///   centre line and the ellipses share a point (this includes containment and subsumes the
///   inscribed circles).
/// Most pairs whose bounding circles meet are decided here (82 % of the benchmark's near mix), for
/// a fraction of the polygonal test's work; the rest is Unknown and goes to the exact stages.
/// Exactly symmetric in (a, b): swapping negates d and swaps the lanes, which changes no bit of
/// the sums and products compared.
struct CentreLineResult {
  PolygonalResult result;
  /// h_a / (h_a + h_b) from the supports along d: the maximiser of the Perram-Wertheim function for
  /// two circles of those radii, a starting guess for onePointTest(); 1/2 for coincident centres.
  double circle_guess;
};

inline CentreLineResult centreLineTest(const Ellipse& a, const SinCos& trig_a, const Ellipse& b,
                                       const SinCos& trig_b) {
  // Lane 0 is a, lane 1 is b: every per-ellipse quantity is computed for both at once (Eigen maps
  // Array2d onto SSE2, and its square root sets no errno).
  using Lanes = Eigen::Array2d;
  const double dx = b.center.x() - a.center.x();
  const double dy = b.center.y() - a.center.y();
  const Lanes cos_angle(trig_a.cos, trig_b.cos), sin_angle(trig_a.sin, trig_b.sin);
  const Lanes radius_x(a.radius_x, b.radius_x), radius_y(a.radius_y, b.radius_y);
  const Lanes along_u = dx * cos_angle + dy * sin_angle;  // d.u
  const Lanes along_v = dy * cos_angle - dx * sin_angle;  // d.v
  const double squared_distance = dx * dx + dy * dy;

  // |d| h(d^) per ellipse: apart iff |d|^2 exceeds their sum (margin: kCentreLineApartMargin).
  const Lanes support = ((radius_x * along_u).square() + (radius_y * along_v).square()).sqrt();
  const Lanes major = radius_x.max(radius_y), minor = radius_x.min(radius_y);
  const double scale = major[0] + major[1];
  const bool apart =
      squared_distance > support[0] + support[1] + kCentreLineApartMargin * scale * scale;

  // rho_a + rho_b >= |d| with rho = rx ry |d| / t, t = sqrt((ry d.u)^2 + (rx d.v)^2), multiplied
  // out: area_a t_b + area_b t_a >= t_a t_b (margin: kCentreLineCoverMargin, ratio cap).
  const Lanes t = ((radius_y * along_u).square() + (radius_x * along_v).square()).sqrt();
  const Lanes area = radius_x * radius_y;
  const bool ratios_ok = (major <= kCentreLineMaxRatio * minor).all();
  const bool covered =
      ratios_ok & (area[0] * t[1] + area[1] * t[0] >= t[0] * t[1] * (1.0 + kCentreLineCoverMargin));

  const double support_sum = support[0] + support[1];
  const double circle_guess = support_sum > 0.0 ? support[0] / support_sum : 0.5;
  if (apart) return {PolygonalResult::Separate, circle_guess};
  if (covered) return {PolygonalResult::Overlap, circle_guess};
  return {PolygonalResult::Unknown, circle_guess};
}

}  // namespace ellipse_collision::core::detail

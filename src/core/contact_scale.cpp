#include "ellipse_collision/core/contact_scale.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact_scale_quartic.h"
#include "contact_scale_detail.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "relative_shape.h"

namespace ellipse_collision::core {
namespace detail {
namespace {

// A point of (0, 1) kept as the pair (s, 1 - s): near s = 1 the complement carries the digits
// that s itself cannot, and both appear in Q(s).
struct Param {
  double s;
  double sc;
};

Param fromS(double s) { return {s, 1.0 - s}; }
Param fromComplement(double sc) { return {1.0 - sc, sc}; }
Param shifted(const Param& p, double delta) {
  return p.s + delta <= 0.5 ? fromS(p.s + delta) : fromComplement(p.sc - delta);
}
// Distance from `from` to `to` along s, computed from whichever representation is finer.
double gap(const Param& from, const Param& to) {
  return std::max(from.s, to.s) <= 0.5 ? to.s - from.s : from.sc - to.sc;
}

struct Sample {
  Param at;
  double value;  ///< Q
  double slope;  ///< dQ/ds
};

/// Bounds on max Q from one point s: Q(s) = value, Q'(s) = slope, step = -Q'(s) / Q''(s).
struct LocalBounds {
  double lower;
  double upper;  ///< infinity when the point is too far from the maximiser to bound it
};

/// With m <= |Q''| <= M on I = [s, s + 2 step] and |slope| <= 2 m |step|, Q' vanishes in I and
///   Q(s) + slope^2 / (2 M) <= max Q <= Q(s) + slope^2 / (2 m).
/// Both sides are ~ the true gap slope^2 / (2 |Q''(s)|), and they differ by a factor ~ the
/// relative change of Q'' over I, which shrinks with the step: the bounds close cubically, while
/// the tangent crossing leans on the far end of the bracket and needs a slope of ~1e-15. They
/// certify 1e-16 (the old 1e-15 with the tangents) about one step earlier.
LocalBounds localBounds(const QFunction& q, const double inverse_g[2], double value, double slope,
                        double step) {
  // -Q'' = sum_i c_i with c_i = 2 w_i lambda_i / g_i^3 and g_i linear in s, so over I each c_i is
  // c_i(s) / (1 + e_i)^3 at the far end and monotone, e_i = (1 - lambda_i) 2 step / g_i(s). For
  // 0 <= e <= 1/6: 1 - 3 e <= (1 + e)^-3 and (1 - e)^-3 <= 1 + 6 e, so m >= c (1 - 3 e_grow) and
  // M <= c (1 + 6 e_shrink), c = -Q''(s), which gives the bounds without a division. The cap
  // 0.1 keeps m >= 0.7 c, so |slope| <= 2 m |step| holds with room to spare for rounding.
  double grow = 0.0, shrink = 0.0;
  for (int i = 0; i < 2; ++i) {
    const double e = (1.0 - q.lambda[i]) * 2.0 * step * inverse_g[i];
    grow = std::max(grow, e);
    shrink = std::max(shrink, -e);
  }
  constexpr double kMaxRelativeChange = 0.1;
  if (!(grow <= kMaxRelativeChange && shrink <= kMaxRelativeChange)) {
    return {value, std::numeric_limits<double>::infinity()};
  }
  // slope^2 / (2 c); the factors 1 -+ 1e-8 cover the rounding of these few operations.
  const double model_gain = 0.5 * std::abs(slope * step);
  return {value + model_gain * (1.0 - 6.0 * shrink) * (1.0 - 1e-8),
          value + model_gain * (1.0 + 6.0 * grow) * (1.0 + 1e-8)};
}

}  // namespace

QFunction QFunction::fromPrincipal(const PrincipalShape& shape) {
  // Q(s) = d^T (I/(1-s) + M/s)^-1 d with M = [p q] [p q]^T; in M's eigenbasis it separates
  // into w_i s (1-s) / (lambda_i (1-s) + s).
  QFunction q;
  q.offset_scale = std::max(shape.offset[0], shape.offset[1]);
  const double inverse_scale = q.offset_scale > 0.0 ? 1.0 / q.offset_scale : 0.0;
  for (int i = 0; i < 2; ++i) {
    q.lambda[i] = shape.lambda[i];
    q.root_lambda[i] = shape.semi_axis[i];
    const double normalised = shape.offset[i] * inverse_scale;
    q.weight[i] = normalised * normalised;
  }
  return q;
}

QMaximum maximizeQ(const QFunction& q, double decision_threshold) {
  QMaximum result;
  const double total_weight = q.weight[0] + q.weight[1];
  if (!(total_weight > 0.0)) {  // coincident centres: Q == 0
    return result;
  }

  // Q(0) = Q(1) = 0, Q'(0) > 0 > Q'(1) and Q is strictly concave: the maximiser is bracketed.
  Sample lo{{0.0, 1.0}, 0.0, q.weight[0] / q.lambda[0] + q.weight[1] / q.lambda[1]};
  Sample hi{{1.0, 0.0}, 0.0, -total_weight};

  // For two circles the maximiser satisfies s / (1 - s) = sqrt(lambda); blend that by weight:
  // s / (1 - s) = blend / total_weight, with s from a single division.
  const double blend = q.weight[0] * q.root_lambda[0] + q.weight[1] * q.root_lambda[1];
  const double inverse_sum = 1.0 / (blend + total_weight);
  Param at = blend <= total_weight ? fromS(blend * inverse_sum)
                                   : fromComplement(total_weight * inverse_sum);

  constexpr int kMaxIterations = 100;
  constexpr double kRelativeTolerance = 1e-16;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    ++result.iterations;
    // g_i = lambda_i (1 - s) + s > 0; Q = s (1 - s) sum_i w_i / g_i.
    const double g[2] = {q.lambda[0] * at.sc + at.s, q.lambda[1] * at.sc + at.s};
    const double inverse_g[2] = {1.0 / g[0], 1.0 / g[1]};
    const double sq_s = at.s * at.s, sq_sc = at.sc * at.sc;
    double value = 0.0, slope = 0.0;  // Q, Q'
    for (int i = 0; i < 2; ++i) {
      const double wg = q.weight[i] * inverse_g[i];
      // In this order Q rounds less, on average and at worst, than with s (1 - s) factored out.
      value += wg * at.s * at.sc;
      slope += wg * (q.lambda[i] * sq_sc - sq_s) * inverse_g[i];
    }
    (slope > 0.0 ? lo : hi) = Sample{at, value, slope};

    // Q' = N1 / D^2, Q'' = -N2 / D^3 and Q''' = N3 / D^4 over D = g0 g1. Halley's step on Q',
    // -2 Q' Q'' / (2 Q''^2 - Q' Q'''), converges cubically (2.5 instead of 3.3 iterations on the
    // colliding pairs of a robot scene), and in these numerators the next point waits for one
    // division; the reciprocals above feed only the bounds.
    const double g0 = g[0], g1 = g[1], product = g0 * g1;
    const double slope_numerator = q.weight[0] * (q.lambda[0] * sq_sc - sq_s) * g1 * g1 +
                                   q.weight[1] * (q.lambda[1] * sq_sc - sq_s) * g0 * g0;
    const double curvature_numerator = 2.0 * (q.weight[0] * q.lambda[0] * g1 * g1 * g1 +
                                              q.weight[1] * q.lambda[1] * g0 * g0 * g0);
    const double third_numerator =
        6.0 * (q.weight[0] * q.lambda[0] * (1.0 - q.lambda[0]) * (g1 * g1) * (g1 * g1) +
               q.weight[1] * q.lambda[1] * (1.0 - q.lambda[1]) * (g0 * g0) * (g0 * g0));
    const double newton_step = slope_numerator * product / curvature_numerator;
    const double halley_denominator =
        2.0 * curvature_numerator * curvature_numerator - slope_numerator * third_numerator;
    // Where Halley's denominator is not safely positive (far from the maximiser), plain Newton.
    const double step =
        halley_denominator > 0.0
            ? 2.0 * slope_numerator * curvature_numerator * product / halley_denominator
            : newton_step;

    const LocalBounds local = localBounds(q, inverse_g, value, slope, newton_step);
    result.lower = std::max(result.lower, local.lower);
    if (result.lower > decision_threshold) {
      result.upper = std::max(result.upper, result.lower);
      return result;
    }
    result.upper = std::max(result.lower, local.upper);
    if (!(local.upper < std::numeric_limits<double>::infinity())) {
      // Far from the maximiser: Q is concave, so it lies below both tangents, and their crossing
      // bounds max Q from above.
      const double width = gap(lo.at, hi.at);
      const double offset = (hi.value - lo.value - hi.slope * width) / (lo.slope - hi.slope);
      result.upper =
          std::max(result.lower, lo.value + lo.slope * std::clamp(offset, 0.0, width));
    }
    if (result.upper <= decision_threshold ||
        result.upper - result.lower <= kRelativeTolerance * result.lower || slope == 0.0) {
      return result;
    }

    // Safeguarded: accept the step only if it lands strictly inside the bracket and shrinks it
    // fast enough, otherwise bisect.
    const double to_lo = gap(at, lo.at);  // <= 0
    const double to_hi = gap(at, hi.at);  // >= 0
    if (std::isfinite(step) && step > to_lo && step < to_hi && step != 0.0 &&
        std::abs(step) < 0.75 * (to_hi - to_lo)) {
      at = shifted(at, step);
    } else {
      at = shifted(lo.at, 0.5 * gap(lo.at, hi.at));
    }
    if (gap(lo.at, at) <= 0.0 || gap(at, hi.at) <= 0.0) {
      return result;  // the bracket cannot be split further in double precision
    }
  }
  return result;
}

}  // namespace detail

bool eigenvalueOverlap(const Ellipse& a, const Ellipse& b) {
  return detail::eigenvalueOverlapPrincipal(
      detail::principalShape(detail::canonicalRelativeShape(a, b)));
}

double contactScale(const Ellipse& a, const Ellipse& b) {
  return detail::solveContactScale(detail::canonicalRelativeShape(a, b));
}

double contactScale(const PreparedEllipse& a, const PreparedEllipse& b) {
  return detail::solveContactScale(detail::canonicalRelativeShape(a, b));
}

namespace detail {

double contactScalePrincipal(const PrincipalShape& shape) {
  const QFunction q = QFunction::fromPrincipal(shape);
  return q.offset_scale * std::sqrt(maximizeQ(q, kNoDecision).lower);
}

bool eigenvalueOverlapPrincipal(const PrincipalShape& shape) {
  // max Q = t*^2, so the ellipses overlap iff max Q <= 1, i.e. iff the normalised maximum is at
  // most 1 / offset_scale^2 (infinite for nearly coincident centres: overlap).
  const QFunction q = QFunction::fromPrincipal(shape);
  if (!(q.offset_scale > 0.0)) return true;  // coincident centres
  const double inverse_scale = 1.0 / q.offset_scale;
  const double threshold = inverse_scale * inverse_scale;
  const auto maximum = maximizeQ(q, threshold);
  return !(maximum.lower > threshold);
}

}  // namespace detail
}  // namespace ellipse_collision::core

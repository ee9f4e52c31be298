#include "ellipse_collision/core/eigenvalue_test.h"

#include <algorithm>
#include <cmath>

#include "eigenvalue_test_detail.h"
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
  const auto evaluate = [&q](const Param& p) {
    Sample sample{p, 0.0, 0.0};
    double curvature = 0.0;
    for (int i = 0; i < 2; ++i) {
      const double inverse_g = 1.0 / (q.lambda[i] * p.sc + p.s);
      const double wg = q.weight[i] * inverse_g;
      sample.value += wg * p.s * p.sc;
      sample.slope += wg * (q.lambda[i] * p.sc * p.sc - p.s * p.s) * inverse_g;
      curvature += wg * q.lambda[i] * inverse_g * inverse_g;
    }
    return std::pair<Sample, double>(sample, -2.0 * curvature);
  };

  QMaximum result;
  const double total_weight = q.weight[0] + q.weight[1];
  if (!(total_weight > 0.0)) {  // coincident centres: Q == 0
    return result;
  }

  // Q(0) = Q(1) = 0, Q'(0) > 0 > Q'(1) and Q is strictly concave: the maximiser is bracketed.
  Sample lo{{0.0, 1.0}, 0.0, q.weight[0] / q.lambda[0] + q.weight[1] / q.lambda[1]};
  Sample hi{{1.0, 0.0}, 0.0, -total_weight};

  // For two circles the maximiser satisfies s / (1 - s) = sqrt(lambda); blend that by weight.
  const double ratio =
      (q.weight[0] * q.root_lambda[0] + q.weight[1] * q.root_lambda[1]) / total_weight;
  Param at = ratio <= 1.0 ? fromS(ratio / (1.0 + ratio)) : fromComplement(1.0 / (1.0 + ratio));

  constexpr int kMaxIterations = 100;
  constexpr double kRelativeTolerance = 1e-15;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    ++result.iterations;
    const auto [sample, second] = evaluate(at);
    result.lower = std::max(result.lower, sample.value);
    if (result.lower > decision_threshold) {
      result.upper = std::max(result.upper, result.lower);
      return result;
    }
    (sample.slope > 0.0 ? lo : hi) = sample;

    // Concavity: Q lies below both tangents, so their crossing bounds max Q from above.
    const double width = gap(lo.at, hi.at);
    const double offset = (hi.value - lo.value - hi.slope * width) / (lo.slope - hi.slope);
    result.upper = std::max(result.lower, lo.value + lo.slope * std::clamp(offset, 0.0, width));
    if (result.upper <= decision_threshold ||
        result.upper - result.lower <= kRelativeTolerance * result.lower || sample.slope == 0.0) {
      return result;
    }

    // Safeguarded Newton: accept the step only if it lands strictly inside the bracket and
    // shrinks it fast enough, otherwise bisect.
    const double step = second < 0.0 ? -sample.slope / second : 0.0;
    const double to_lo = gap(at, lo.at);  // <= 0
    const double to_hi = gap(at, hi.at);  // >= 0
    if (std::isfinite(step) && step > to_lo && step < to_hi && step != 0.0 &&
        std::abs(step) < 0.75 * (to_hi - to_lo)) {
      at = shifted(at, step);
    } else {
      at = shifted(lo.at, 0.5 * width);
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
  return detail::contactScalePrincipal(
      detail::principalShape(detail::canonicalRelativeShape(a, b)));
}

double contactScale(const PreparedEllipse& a, const PreparedEllipse& b) {
  return detail::contactScalePrincipal(
      detail::principalShape(detail::canonicalRelativeShape(a, b)));
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

#include "contact_scale_quartic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact_scale_detail.h"

namespace ellipse_collision::core::detail {
namespace {

/// The quartic answers for shapes whose M has eigenvalues within this ratio (axis ratio 1e9 in
/// the frame where the unit ellipse is the unit circle).
constexpr double kMaxEigenvalueRatio = 1e18;

/// Relative error of max Q allowed by the stopping rule's model: far below the few ulps of the
/// value itself, so the stopping rule never decides the digits returned.
constexpr double kQuarticModelError = 1e-17;
/// ... and the model (Q quadratic about its maximum) is trusted once the Newton step is below
/// this fraction of x.
constexpr double kModelStepFraction = 1e-6;

double certifiedScale(const ScaleProblem& problem) {
  return contactScalePrincipal(principalShape(problem.shape));
}

}  // namespace

ScaleProblem scaleProblem(const RelativeShape& shape) {
  ScaleProblem problem;
  problem.shape = shape;
  // std::max drops a NaN: a NaN offset (invalid input) must stay one, an answer of no meaning,
  // and not read as coincident centres, t* = 0.
  problem.offset_scale = std::isnan(shape.center_x) || std::isnan(shape.center_y)
                             ? std::numeric_limits<double>::quiet_NaN()
                             : std::max(std::abs(shape.center_x), std::abs(shape.center_y));
  // Q is homogeneous of degree 2 in the offset: normalising keeps tiny offsets from underflowing.
  const double inverse_scale = problem.offset_scale > 0.0 ? 1.0 / problem.offset_scale : 0.0;
  const double dx = shape.center_x * inverse_scale, dy = shape.center_y * inverse_scale;
  const double m00 = shape.p_x * shape.p_x + shape.q_x * shape.q_x;
  const double m01 = shape.p_x * shape.p_y + shape.q_x * shape.q_y;
  const double m11 = shape.p_y * shape.p_y + shape.q_y * shape.q_y;
  // adj([p q]) d, whose squared length is d^T adj(M) d: a sum of squares, never negative.
  const double cross_q = shape.q_y * dx - shape.q_x * dy;
  const double cross_p = shape.p_x * dy - shape.p_y * dx;
  problem.alpha = dx * dx + dy * dy;
  problem.beta = cross_q * cross_q + cross_p * cross_p;
  problem.tau = m00 + m11;
  problem.delta = shape.determinant * shape.determinant;  // det M without the cancellation

  const double alpha = problem.alpha, beta = problem.beta, tau = problem.tau,
               delta = problem.delta;
  const double k4 = -alpha, k3 = -2.0 * beta, k2 = alpha * (tau + delta) - beta * (1.0 + tau),
               k1 = 2.0 * alpha * delta, k0 = beta * delta;
  const double at_one = k4 + k3 + k2 + k1 + k0;  // P(1): the root lies beyond 1 iff P(1) > 0
  problem.reversed = at_one > 0.0;
  const double forward[5] = {k4, k3, k2, k1, k0};
  for (int i = 0; i < 5; ++i) problem.coefficient[i] = forward[problem.reversed ? 4 - i : i];
  // Beyond an axis ratio of 1e9 in the unit frame (tau^2 / delta ~ lambda_max / lambda_min) the
  // relative frame itself has lost digits (a needle along the offset: both methods 3e-9 off
  // the quad oracle, on opposite sides): there the certified maximisation answers, so that
  // contactScale() errs as overlap()'s decision does, not against it (fuzzer finding).
  problem.fallback = !(std::isfinite(problem.offset_scale) && std::isfinite(k2) &&
                       std::isfinite(at_one) && k0 > 0.0 && std::isfinite(k0) &&
                       tau * tau <= kMaxEigenvalueRatio * delta);

  // Start: t^2 ~ d^T M d / |d|^2, the squared radius of the other ellipse along the offset (exact
  // for two circles, where t* = that radius).
  const double along = m00 * dx * dx + 2.0 * m01 * dx * dy + m11 * dy * dy;
  // alpha >= 1 (normalised offset); `along` may underflow for a needle along the offset.
  const double start =
      along > 0.0 ? std::sqrt(problem.reversed ? alpha / along : along / alpha) : 0.0;
  problem.x = start > 0.0 && start <= 1.0 ? start : (start > 1.0 ? 1.0 : 0.5);
  problem.lo = 0.0;
  problem.hi = 1.0;
  problem.done = false;
  return problem;
}

// Not inlined: the tests and benchmarks that step a problem themselves run the very same
// instructions as solveContactScales(), so no contraction choice of the compiler can make their
// bits differ.
__attribute__((noinline)) bool stepContactScale(ScaleProblem& problem, double* scale) {
  const double x = problem.x;
  const double* k = problem.coefficient;
  const double value = (((k[0] * x + k[1]) * x + k[2]) * x + k[3]) * x + k[4];
  const double slope = ((4.0 * k[0] * x + 3.0 * k[1]) * x + 2.0 * k[2]) * x + k[3];
  const double curvature = (12.0 * k[0] * x + 6.0 * k[1]) * x + 2.0 * k[2];
  // Q = numerator / denominator at x (t = x, or t = 1 / x with both multiplied by x^3).
  double numerator, denominator;
  if (!problem.reversed) {
    numerator = x * (problem.alpha * x + problem.beta);
    denominator = (1.0 + x) * ((x + problem.tau) * x + problem.delta);
  } else {
    numerator = x * (problem.alpha + problem.beta * x);
    denominator = (x + 1.0) * ((problem.delta * x + problem.tau) * x + 1.0);
  }
  // Near the root Q falls from its maximum by about Q'' h^2 / 2 over the Newton step h, which in
  // either variable is value^2 / (2 |slope| numerator denominator) relative to Q.
  const double abs_slope = std::abs(slope);
  if (denominator > 0.0 && std::abs(value) <= kModelStepFraction * x * abs_slope &&
      value * value <= 2.0 * kQuarticModelError * abs_slope * numerator * denominator) {
    *scale = problem.offset_scale * std::sqrt(numerator / denominator);
    problem.done = true;
    return true;
  }
  // P > 0 left of the root; the reversed polynomial is < 0 there.
  const bool left_of_root = problem.reversed ? value < 0.0 : value > 0.0;
  (left_of_root ? problem.lo : problem.hi) = x;
  // Halley's step where its denominator is safely positive, Newton's otherwise; a step that
  // leaves the bracket bisects it, one too small to move x leaves it.
  const double halley_denominator = 2.0 * slope * slope - value * curvature;
  const bool has_step = halley_denominator > 0.0 || slope != 0.0;
  const double step = halley_denominator > 0.0 ? -2.0 * value * slope / halley_denominator
                      : has_step              ? -value / slope
                                              : 0.0;
  const double next = x + step;
  if (has_step && next > problem.lo && next < problem.hi) {
    problem.x = next;
  } else if (!has_step || std::abs(step) > 1e-15 * x) {
    problem.x = 0.5 * (problem.lo + problem.hi);
  }
  return false;
}

void solveContactScales(ScaleProblem* problems, std::size_t count, double* scales) {
  std::size_t open = 0;
  for (std::size_t i = 0; i < count; ++i) {
    ScaleProblem& problem = problems[i];
    if (problem.offset_scale == 0.0) {
      scales[i] = 0.0;  // coincident centres
      problem.done = true;
    } else if (problem.fallback) {
      scales[i] = certifiedScale(problem);
      problem.done = true;
    } else {
      ++open;
    }
  }
  for (int step = 0; step < kMaxQuarticSteps && open > 0; ++step) {
    for (std::size_t i = 0; i < count; ++i) {
      if (!problems[i].done && stepContactScale(problems[i], &scales[i])) --open;
    }
  }
  for (std::size_t i = 0; i < count && open > 0; ++i) {
    if (!problems[i].done) {
      scales[i] = certifiedScale(problems[i]);
      --open;
    }
  }
}

double solveContactScale(const RelativeShape& shape) {
  ScaleProblem problem = scaleProblem(shape);
  double scale = 0.0;
  solveContactScales(&problem, 1, &scale);
  return scale;
}

int quarticStepsOf(const RelativeShape& shape) {
  ScaleProblem problem = scaleProblem(shape);
  if (problem.offset_scale == 0.0) return 0;
  if (problem.fallback) return kMaxQuarticSteps + 1;
  double scale = 0.0;
  for (int step = 1; step <= kMaxQuarticSteps; ++step) {
    if (stepContactScale(problem, &scale)) return step;
  }
  return kMaxQuarticSteps + 1;
}

}  // namespace ellipse_collision::core::detail

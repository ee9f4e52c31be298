#pragma once

#include <cstddef>

#include "relative_shape.h"

namespace ellipse_collision::core::detail {

/// The contact scale t* = sqrt(max_s Q(s)) of one pair, as the root of a quartic. With t = s / (1 - s),
/// M = [p q] [p q]^T and the centre offset d (normalised, see offset_scale),
///   Q = t (alpha t + beta) / ((1 + t) (t^2 + tau t + delta)),
///   alpha = |d|^2, beta = d^T adj(M) d = |adj([p q]) d|^2, tau = trace M, delta = det M,
/// (expand d^T (I / (1 - s) + M / s)^-1 d with the 2x2 adjugate: no eigenvectors, no square root),
/// and Q'(t) = P(t) / denominator^2 with
///   P(t) = -alpha t^4 - 2 beta t^3 + (alpha (tau + delta) - beta (1 + tau)) t^2
///          + 2 alpha delta t + beta delta.
/// P's coefficients change sign once (Descartes): its one positive root is the maximiser. For a
/// root beyond t = 1 the iteration runs on x = 1 / t (the reversed polynomial), so that x always
/// lies in (0, 1], where the Halley steps on a quartic converge from a start a factor of a few off
/// and both ends of s keep their digits. Every sum in Q is of positive terms: the value at the root
/// rounds to a few ulps.
struct ScaleProblem {
  RelativeShape shape;  ///< kept for the certified fallback (contactScalePrincipal())
  double offset_scale;  ///< the larger offset component; Q scales with its square
  double alpha, beta, tau, delta;
  double coefficient[5];  ///< of P in x, highest power first
  double x, lo, hi;       ///< current point and bracket of the root in x, 0 <= lo < x < hi <= 1
  bool reversed;          ///< x = 1 / t
  bool done;              ///< the contact scale has been written
  /// The quartic does not answer (its coefficients overflow or underflow, or the other ellipse
  /// has an axis ratio beyond 1e9 in the unit frame): the certified maximisation of Q does.
  bool fallback;
};

/// A robot scene's colliding pairs take 2-4 steps; pairs of axis ratio 1e5 may need more, and
/// the few that are not done by then take the certified maximisation.
inline constexpr int kMaxQuarticSteps = 12;

ScaleProblem scaleProblem(const RelativeShape& shape);

/// One Halley step on the problem, safeguarded by the bracket. Returns true, with the contact
/// scale in *scale and `done` set, when the current point is the root to within
/// kQuarticModelError of max Q; a done problem must not be stepped again.
bool stepContactScale(ScaleProblem& problem, double* scale);

/// The contact scale of each problem into scales[i]. The problems are stepped side by side, so
/// their divisions overlap in the pipeline instead of waiting on each other; a problem not done
/// within kMaxQuarticSteps takes the certified maximisation of Q instead. Each problem goes
/// through the same steps whatever the others do: one alone gets the same bits.
void solveContactScales(ScaleProblem* problems, std::size_t count, double* scales);

/// solveContactScales() of one pair.
double solveContactScale(const RelativeShape& shape);

/// How many steps solveContactScales() takes on this pair: kMaxQuarticSteps + 1 where the
/// certified maximisation answers (fallback, or not done within kMaxQuarticSteps), 0 for
/// coincident centres. For tests and benchmarks.
int quarticStepsOf(const RelativeShape& shape);

}  // namespace ellipse_collision::core::detail

#pragma once

#include <limits>

#include "relative_shape.h"

namespace ellipse_collision::core::detail {

/// Q(s) = sum_i weight[i] * s (1 - s) / (lambda[i] (1 - s) + s): the eigenvalue test's function in
/// the eigenbasis of the other ellipse's shape matrix, in the frame where the unit ellipse is the
/// unit circle. max over s in (0, 1) of Q is t*^2.
struct QFunction {
  /// Squared components of the centre offset along the eigenvectors, divided by offset_scale^2:
  /// Q is homogeneous of degree 2 in the offset, and normalising keeps tiny offsets from
  /// underflowing to "coincident centres". The true Q is offset_scale^2 times this one.
  double weight[2];
  double offset_scale;    ///< the larger offset component (0 for coincident centres)
  double lambda[2];       ///< eigenvalues of [p q] [p q]^T (see RelativeShape), > 0
  double root_lambda[2];  ///< sqrt(lambda), for the starting point

  static QFunction fromPrincipal(const PrincipalShape& shape);
};

/// Bounds on max Q: lower <= max Q <= upper (up to rounding).
struct QMaximum {
  double lower{0.0};
  double upper{0.0};
  int iterations{0};
};

/// Pass as decision_threshold to converge fully, without the decision exits.
inline constexpr double kNoDecision = std::numeric_limits<double>::quiet_NaN();

/// Bracketed, safeguarded Halley iteration on Q'. Stops as soon as lower > decision_threshold or
/// upper <= decision_threshold (certified decisions), or when the bounds agree to 1e-16
/// (relative).
QMaximum maximizeQ(const QFunction& q, double decision_threshold);

bool eigenvalueOverlapPrincipal(const PrincipalShape& shape);

/// t* = sqrt(max Q), fully converged.
double contactScalePrincipal(const PrincipalShape& shape);

}  // namespace ellipse_collision::core::detail

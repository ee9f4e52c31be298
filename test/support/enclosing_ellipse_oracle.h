#pragma once

#include <quadmath.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {
namespace test {

/// Which arithmetic the oracle's Newton iterations run in.
enum class OraclePrecision {
  Quad,        ///< __float128 throughout: about 1e-24 relative in area, slow (use for <= ~100 points)
  LongDouble,  ///< long double iterations: about 1e-12 relative in area, for large sets
};

/// The minimum-area enclosing ellipse found independently of the implementation: a primal
/// log-barrier method on the convex form {x : |B x + b| <= 1}, B symmetric positive definite,
/// minimising -log det B subject to |B p_i + b|^2 <= 1, with damped Newton steps on the five
/// parameters and the barrier weight mu driven down to `target_gap` / n. Every iterate is strictly
/// feasible, so `area` is the area of an ellipse containing every point (an upper bound on the
/// minimum) and the barrier's duality bound gives minimum >= area * exp(-gap).
struct OracleEllipse {
  __float128 area{0};  ///< [m^2]
  __float128 gap{0};   ///< bound on log(area / minimum area)
  bool converged{false};
  __float128 center_x{0}, center_y{0};  ///< [m]
  /// The ellipse {p : |B p + b| <= 1} in the caller's coordinates: B = [[b_xx, b_xy], [b_xy,
  /// b_yy]] [1/m], b = (b_x, b_y).
  __float128 b_xx{0}, b_xy{0}, b_yy{0}, b_x{0}, b_y{0};
};

/// Requires a point set that spans area (not all collinear).
OracleEllipse oracleMinimumAreaEllipse(const std::vector<Eigen::Vector2d>& points,
                                       OraclePrecision precision = OraclePrecision::Quad);

/// |B p + b|^2 of the oracle's ellipse, in quad: <= 1 inside.
__float128 oracleQuadraticForm(const OracleEllipse& e, const Eigen::Vector2d& p);

/// The same minimum for large, dense sets (thousands of points on circles, where the barrier's
/// Newton steps become short): the oracle on a growing subset, adding the points outside its
/// ellipse, until none is outside; then the subset's minimum ellipse contains every point and is
/// therefore the set's. converged is false if that did not happen within the round limit.
OracleEllipse oracleMinimumAreaEllipseByCuttingPlanes(const std::vector<Eigen::Vector2d>& points);

/// ((p - c) in the ellipse's axes / radii)^2 summed, in quad precision from the double fields:
/// the point is inside the closed ellipse iff this is <= 1 (to ~1e-33).
__float128 quadQuadraticForm(const Ellipse& e, const Eigen::Vector2d& p);

/// pi * radius_x * radius_y in quad precision [m^2].
__float128 quadArea(const Ellipse& e);

/// The ellipse as "{cx, cy, rx, ry, angle}" with %.17g, for failure messages.
std::string describeEllipse(const Ellipse& e);

}  // namespace test
}  // namespace ellipse_collision::core

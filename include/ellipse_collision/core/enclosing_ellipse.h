#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// How an enclosing-ellipse computation ended.
enum class EnclosingStatus {
  Ok,          ///< `ellipse` is valid (see invalidReason()) and contains every point
  Degenerate,  ///< the points span no area: see EnclosingEllipse's segment fields
  Error,       ///< no ellipse: see `error`
};

/// Result of minimumAreaEllipse() / enclosingEllipseWithMinRadius().
struct EnclosingEllipse {
  EnclosingStatus status{EnclosingStatus::Error};

  /// Ok: contains every input point, certified: each point's normalised quadratic form, evaluated
  /// from the double fields with rounding accounted for, is <= 1. radius_x >= radius_y [m],
  /// angle in (-pi/2, pi/2] [rad]. Unspecified otherwise.
  Ellipse ellipse;

  /// Degenerate: the thin description. Every point lies within `half_width` [m] of the segment
  /// [segment_start, segment_end] [m] (equal ends for one distinct point), to rounding (about
  /// 1e-15 of the points' extent). Grow it with enclosingEllipseWithMinRadius().
  Eigen::Vector2d segment_start{0.0, 0.0};
  Eigen::Vector2d segment_end{0.0, 0.0};
  double half_width{0.0};

  /// Ok from minimumAreaEllipse(): an upper bound on area(ellipse) / (minimum area) - 1 from the
  /// optimiser's duality gap, before the few-ulp certification growth (dimensionless).
  double area_excess_bound{0.0};

  /// Error: why, naming the offending point and value ("points[3].x = nan is not finite").
  std::string error;

  bool ok() const { return status == EnclosingStatus::Ok; }
};

/// Point sets whose width (smallest extent over all directions) is at most this fraction of their
/// extent count as collinear: below it the thin direction is set by the rounding of the input
/// (about 1e-16 of the coordinates) more than by the data, and the optimiser's precision would
/// fall below the promised 1e-6 in area.
constexpr double kDegenerateRelativeWidth = 1e-9;

/// The optimiser stops when its duality gap bounds the area excess by 1.5 times this.
constexpr double kEnclosingGapTolerance = 1e-10;

/// The minimum-area ellipse containing every point [m].
/// Khachiyan's dual problem on a core set of hull points, certified against every point in long
/// double (method and cost: doc/core_methods.md).
///
/// Status:
/// - Error: no points; a coordinate not finite or outside [-kMaxCoordinate, kMaxCoordinate]; or
///   the enclosing ellipse's radius would exceed kMaxRadius.
/// - Degenerate: one distinct point, or all points collinear, or a width at most
///   kDegenerateRelativeWidth of the extent or below 2 kMinRadius (the minor radius could fall
///   below kMinRadius): the segment fields describe the points.
/// - Ok otherwise. The area is within about 1e-9 (relative) of the minimum, plus the rounding of
///   the centre to a double: 2 ulp(|centre|) / radius_y relative.
EnclosingEllipse minimumAreaEllipse(const std::vector<Eigen::Vector2d>& points);

/// An ellipse containing every point [m] with both radii >= `min_radius` [m], for clusters that
/// may be one point, two points or a line (sensor returns). The minimum-area ellipse when both of
/// its radii already reach `min_radius`; a too-small radius is raised to `min_radius` (same axes),
/// or, when smaller, the band ellipse below along its major axis (a noisy wall: the raised
/// minimum-area ellipse would be sqrt(2) times longer than the wall); for Degenerate sets, the ellipse along the segment with radius_y = max(min_radius,
/// sqrt(2) half_width) and the smallest radius_x >= min_radius that contains the points. Always
/// certified like minimumAreaEllipse(). Status Ok or Error (the errors of minimumAreaEllipse(), or
/// `min_radius` not finite or outside [kMinRadius, kMaxRadius]); never Degenerate.
EnclosingEllipse enclosingEllipseWithMinRadius(const std::vector<Eigen::Vector2d>& points,
                                               double min_radius);

/// The ellipse of the band of `points` [m] along the unit `direction`: centred on the band (the
/// extreme projections along and across), radius_y = max(min_radius, sqrt(2) half-width) across
/// it and the smallest radius_x >= min_radius that contains the band's box. O(n), no optimiser:
/// for thin sets (a wall's returns) about as small as enclosingEllipseWithMinRadius(), which uses
/// it. Certified like minimumAreaEllipse(); Status Ok or Error (points or min_radius invalid, an
/// out-of-range ellipse).
EnclosingEllipse bandEllipse(const std::vector<Eigen::Vector2d>& points,
                             const Eigen::Vector2d& direction, double min_radius);

/// Upper bound on the optimiser's steps per minimumAreaEllipse() call; reaching it still returns
/// a certified enclosing ellipse, with a larger area_excess_bound.
constexpr int kMaxOptimiserIterations = 20000;

}  // namespace ellipse_collision::core

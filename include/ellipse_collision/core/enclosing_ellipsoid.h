#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipsoid.h"

namespace ellipse_collision::core {

/// How minimumVolumeEllipsoid() ended.
struct EnclosingEllipsoid {
  bool ok{false};
  /// ok: contains every input point, certified: each point's normalised quadratic form, evaluated
  /// in long double from the double fields with rounding accounted for, is <= 1.
  Ellipsoid ellipsoid;
  /// ok: an upper bound on volume(ellipsoid) / (minimum volume) - 1 from the optimiser's duality
  /// gap, before the few-ulp certification growth (dimensionless).
  double volume_excess_bound{0.0};
  /// Not ok: why, naming the offending point and value ("points[3].z = nan is not finite").
  std::string error;
};

/// Point sets whose smallest principal extent is at most this fraction of their largest span no
/// volume: their minimum-volume ellipsoid would be flat to rounding.
constexpr double kDegenerateRelativeThickness = 1e-9;

/// The optimiser stops when its duality gap bounds the volume excess by 2 times this.
constexpr double kEnclosingEllipsoidGapTolerance = 1e-9;

/// The minimum-volume ellipsoid containing every point [m] (Löwner–John ellipsoid).
/// The 2D fit's method in one more dimension, certified against every point in long double
/// (method and cost: doc/core_methods.md).
///
/// Errors: no points; a coordinate not finite or outside [-kMaxCoordinate, kMaxCoordinate]; a set
/// spanning no volume (fewer than 4 affinely independent points, or thinner than
/// kDegenerateRelativeThickness of its extent or 2 kMinRadius); a radius beyond kMaxRadius.
EnclosingEllipsoid minimumVolumeEllipsoid(const std::vector<Eigen::Vector3d>& points);

/// Grows all radii of `ellipsoid` by the smallest common factor (plus a few ulps) that puts every
/// point inside, evaluated in long double from the double fields as minimumVolumeEllipsoid()
/// certifies (a no-op when they already are): for an ellipsoid whose fields were rewritten (its
/// orientation turned into roll, pitch and yaw) to stay certified. False if that did not succeed
/// (a radius no longer finite).
bool growToContain(Ellipsoid& ellipsoid, const std::vector<Eigen::Vector3d>& points);

/// Upper bound on the optimiser's Khachiyan steps per call; reaching it still returns a certified
/// enclosing ellipsoid, with a larger volume_excess_bound.
constexpr int kMaxEllipsoidOptimiserSteps = 200000;

}  // namespace ellipse_collision::core

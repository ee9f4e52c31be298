#include "ellipse_collision/overlap.h"

#include "eigenvalue_test_detail.h"
#include "polygonal_test_detail.h"
#include "relative_shape.h"

namespace ellipse_collision {
namespace {

// The circle tests compare squared lengths computed in double; this keeps their decisions clear
// of rounding so that near-tangent pairs go on to the exact stages.
constexpr double kCircleMargin = 1e-12;

}  // namespace

bool overlap(const Ellipse& a, const Ellipse& b) {
  const double distance_sq = (b.center - a.center).squaredNorm();
  const double bounding = boundingRadius(a) + boundingRadius(b);
  if (distance_sq > bounding * bounding * (1.0 + kCircleMargin)) return false;
  const double inscribed = inscribedRadius(a) + inscribedRadius(b);
  if (distance_sq < inscribed * inscribed * (1.0 - kCircleMargin)) return true;

  const auto shape = detail::canonicalRelativeShape(a, b);
  switch (detail::polygonalTestRelative(shape, kDefaultPolygonalIterations)) {
    case PolygonalResult::Overlap:
      return true;
    case PolygonalResult::Separate:
      return false;
    case PolygonalResult::Unknown:
      break;
  }
  return detail::eigenvalueOverlapRelative(shape);
}

}  // namespace ellipse_collision

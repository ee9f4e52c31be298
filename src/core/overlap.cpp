#include "ellipse_collision/core/overlap.h"

#include <Eigen/Core>

#include "centre_line_test.h"
#include "contact_scale_detail.h"
#include "one_point_test.h"
#include "ellipse_collision/core/polygonal_early_out.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "overlap_detail.h"
#include "polygonal_early_out_detail.h"
#include "relative_shape.h"

namespace ellipse_collision::core {
namespace {

/// Past the bounding circles: the inscribed circles meeting prove overlap, free of
/// trigonometry; the centre-line test decides most other pairs cheaply, and the Perram-Wertheim
/// function at one point most of the rest (both with the coarse sines and cosines and margins
/// that cover them); then the polygonal early-out,
/// and the eigenvalue test when it cannot decide, in the canonical frame of the pair.
template <typename AnyEllipse>
bool exactStages(const AnyEllipse& a, const AnyEllipse& b, double inscribed_sum,
                 int max_iterations) {
  const Ellipse& ellipse_a = detail::ellipseOf(a);
  const Ellipse& ellipse_b = detail::ellipseOf(b);
  if ((ellipse_b.center - ellipse_a.center).squaredNorm() <
      inscribed_sum * inscribed_sum * (1.0 - detail::kCircleMargin)) {
    return true;
  }
  const detail::SinCosPair trig = detail::coarseSinCosPairOf(a, b);
  const detail::CentreLineResult centre_line =
      detail::centreLineTest(ellipse_a, trig.first, ellipse_b, trig.second);
  if (centre_line.result != PolygonalResult::Unknown) {
    return centre_line.result == PolygonalResult::Overlap;
  }
  const PolygonalResult one_point = detail::onePointTest(ellipse_a, trig.first, ellipse_b,
                                                         trig.second, centre_line.circle_guess);
  if (one_point != PolygonalResult::Unknown) return one_point == PolygonalResult::Overlap;
  const detail::RelativeShape relative = detail::canonicalRelativeShape(a, b);
  switch (detail::polygonalTestRelative(relative, max_iterations)) {
    case PolygonalResult::Overlap:
      return true;
    case PolygonalResult::Separate:
      return false;
    case PolygonalResult::Unknown:
      break;
  }
  return detail::eigenvalueOverlapPrincipal(detail::principalShape(relative));
}

}  // namespace

namespace detail {

bool overlapOfNearPair(const Ellipse& a, const Ellipse& b) {
  return exactStages(a, b, inscribedRadius(a) + inscribedRadius(b), kOverlapPolygonalIterations);
}

bool overlapOfNearPair(const PreparedEllipse& a, const PreparedEllipse& b) {
  return exactStages(a, b, a.inscribedRadius() + b.inscribedRadius(), kOverlapPolygonalIterations);
}

bool overlapWithPolygonalCap(const Ellipse& a, const Ellipse& b, int max_iterations) {
  return !circlesApart(a.center, b.center, boundingRadius(a) + boundingRadius(b)) &&
         exactStages(a, b, inscribedRadius(a) + inscribedRadius(b), max_iterations);
}

}  // namespace detail
}  // namespace ellipse_collision::core

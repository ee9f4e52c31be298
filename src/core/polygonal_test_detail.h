#pragma once

#include "ellipse_collision/polygonal_test.h"
#include "relative_shape.h"

namespace ellipse_collision::detail {

/// The polygonal test against the unit circle at the origin for `shape` (see relativeShape()).
PolygonalResult polygonalTestRelative(const RelativeShape& shape, int max_iterations);

}  // namespace ellipse_collision::detail

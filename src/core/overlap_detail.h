#pragma once

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core::detail {

/// overlap() with another iteration cap for its polygonal stage; for the benchmark that picked
/// kOverlapPolygonalIterations. The answer is the same for every cap, only the time differs.
bool overlapWithPolygonalCap(const Ellipse& a, const Ellipse& b, int max_iterations);

}  // namespace ellipse_collision::core::detail

#pragma once

// The points of a link's collision shapes, one shape after another: the loop shared by the planar
// outline (shape_outline.cpp) and the 3D hull (shape_hull.cpp). Internal to the core (src/core).

#include <string>
#include <vector>

#include "ellipse_collision/core/shape_outline.h"

namespace ellipse_collision::core::detail {

/// `points_of(shape)` for every shape, concatenated; on the first refused shape nothing but its
/// error, as "shapes[i]: <error>". `Result` has `points`, `error` and ok().
template <class Result, class PointsOf>
Result linkPoints(const std::vector<CollisionShape>& shapes, PointsOf points_of) {
  Result result;
  if (shapes.empty()) {
    result.error = "shapes is empty";
    return result;
  }
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    Result one = points_of(shapes[i]);
    if (!one.ok()) {
      result.points.clear();
      result.error = "shapes[" + std::to_string(i) + "]: " + one.error;
      return result;
    }
    result.points.insert(result.points.end(), one.points.begin(), one.points.end());
  }
  return result;
}

}  // namespace ellipse_collision::core::detail

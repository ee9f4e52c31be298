#include "ellipse_collision/core/indexed_obstacles.h"

#include <algorithm>
#include <utility>

#include "scene_entry.h"

namespace ellipse_collision::core {
namespace {

/// The obstacles' boxes, each obstacle also added to `batch` (prepared once, with its culling
/// columns: a sincos, two divisions and two square roots, 150-180 instructions, that a check
/// would otherwise spend each time a pair needed the exact stages or a contact scale,
/// doc/benchmarks.md, batch pair tests); or no box and an empty batch when one is refused (then
/// `error` says which and why). The batch's own validation is the one the obstacles get.
std::vector<BoundingBox> obstacleBoxes(const std::vector<NamedEllipse>& obstacles,
                                       EllipseBatch* batch, std::string* error) {
  std::vector<BoundingBox> boxes;
  boxes.reserve(obstacles.size());
  batch->reserve(obstacles.size());
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const NamedEllipse& entry = obstacles[i];
    if (entry.role != EllipseRole::Obstacle) {
      *error = detail::entryLabel("obstacles", i, entry) + ": role must be Obstacle";
    } else if (!batch->add(entry.ellipse).empty()) {
      *error = detail::invalidEntryReason("obstacles", i, entry);
    }
    if (!error->empty()) {
      batch->clear();
      return {};
    }
    boxes.push_back(boundingCircleBox(entry.ellipse));
  }
  return boxes;
}

}  // namespace

IndexedObstacles::IndexedObstacles() : grid_(std::vector<BoundingBox>{}) {}

IndexedObstacles::IndexedObstacles(std::vector<NamedEllipse> obstacles)
    : obstacles_(std::move(obstacles)), grid_(obstacleBoxes(obstacles_, &batch_, &error_)) {
  if (!error_.empty()) obstacles_.clear();
}

void IndexedObstacles::within(const Eigen::Vector2d& point, double reach,
                              std::vector<std::size_t>* indices) const {
  // The box about the disc, widened like the obstacles' own boxes (far beyond the rounding of the
  // exact test below), so that every obstacle the test keeps has a box that overlaps it.
  const double half = std::max(reach, 0.0);
  grid_.overlapping(detail::boxAround(point, half, half), indices);
  const auto far = [&](std::size_t k) {
    return !mayComeWithin(obstacles_[k].ellipse, 0.0, point, reach);
  };
  indices->erase(std::remove_if(indices->begin(), indices->end(), far), indices->end());
}

}  // namespace ellipse_collision::core

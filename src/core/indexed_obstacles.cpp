#include "ellipse_collision/core/indexed_obstacles.h"

#include <utility>

#include "scene_entry.h"

namespace ellipse_collision::core {
namespace {

/// The obstacles' boxes, or none when one is refused (then `error` says which and why).
std::vector<BoundingBox> obstacleBoxes(const std::vector<NamedEllipse>& obstacles,
                                       std::string* error) {
  std::vector<BoundingBox> boxes;
  boxes.reserve(obstacles.size());
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const NamedEllipse& entry = obstacles[i];
    if (entry.role != EllipseRole::Obstacle) {
      *error = detail::entryLabel("obstacles", i, entry) + ": role must be Obstacle";
      return {};
    }
    if (!isValid(entry.ellipse)) {
      *error = detail::invalidEntryReason("obstacles", i, entry);
      return {};
    }
    boxes.push_back(boundingCircleBox(entry.ellipse));
  }
  return boxes;
}

}  // namespace

IndexedObstacles::IndexedObstacles() : grid_(std::vector<BoundingBox>{}) {}

IndexedObstacles::IndexedObstacles(std::vector<NamedEllipse> obstacles)
    : obstacles_(std::move(obstacles)), grid_(obstacleBoxes(obstacles_, &error_)) {
  if (!error_.empty()) obstacles_.clear();
}

}  // namespace ellipse_collision::core

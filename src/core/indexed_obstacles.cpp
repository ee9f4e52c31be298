#include "ellipse_collision/core/indexed_obstacles.h"

#include <utility>

namespace ellipse_collision::core {
namespace {

/// The obstacles' boxes, or none when one is refused (then `error` says which and why).
std::vector<BoundingBox> obstacleBoxes(const std::vector<NamedEllipse>& obstacles,
                                       std::string* error) {
  std::vector<BoundingBox> boxes;
  boxes.reserve(obstacles.size());
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const NamedEllipse& entry = obstacles[i];
    const auto where = [&] {
      return "obstacles[" + std::to_string(i) + "] ('" + entry.name + "')";
    };
    if (entry.role != EllipseRole::Obstacle) {
      *error = where() + ": role must be Obstacle";
      return {};
    }
    if (!isValid(entry.ellipse)) {
      *error = where() + ": " + invalidReason(entry.ellipse);
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

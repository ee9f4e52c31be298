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
  if (!error_.empty()) {
    obstacles_.clear();
    return;
  }
  // Prepared here, once while the obstacles stand, rather than per pair and check: a sincos,
  // two divisions and two square roots (150-180 instructions) each time a pair needed the exact
  // stages or a contact scale (doc/benchmarks.md, batch pair tests).
  const std::size_t count = obstacles_.size();
  prepared_.reserve(count);
  center_x_.reserve(count);
  center_y_.reserve(count);
  bounding_.reserve(count);
  inscribed_.reserve(count);
  for (const NamedEllipse& obstacle : obstacles_) {
    const PreparedEllipse& prepared = prepared_.emplace_back(obstacle.ellipse);
    center_x_.push_back(prepared.ellipse().center.x());
    center_y_.push_back(prepared.ellipse().center.y());
    bounding_.push_back(prepared.boundingRadius());
    inscribed_.push_back(prepared.inscribedRadius());
  }
}

}  // namespace ellipse_collision::core

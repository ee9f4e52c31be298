#include "ellipse_collision/app/standing_obstacles.h"

#include <utility>
#include <vector>

namespace ellipse_collision::app {

std::shared_ptr<const core::IndexedObstacles> StandingObstacles::update(
    bool unchanged, const core::Scene& scene, std::size_t first_obstacle) {
  if (!unchanged) {
    standing_checks_ = 0;
    index_.reset();
    return nullptr;
  }
  ++standing_checks_;
  if (!index_ && standing_checks_ >= kChecksBeforeIndexing) {
    std::vector<core::NamedEllipse> obstacles;
    obstacles.reserve(scene.size() - first_obstacle);
    for (std::size_t k = first_obstacle; k < scene.size(); ++k) obstacles.push_back(scene.entry(k));
    auto index = std::make_shared<const core::IndexedObstacles>(std::move(obstacles));
    // The registry validated them, so a refusal would be a bug: stream, and try again later.
    if (index->error().empty()) {
      index_ = std::move(index);
    } else {
      standing_checks_ = 0;
    }
  }
  return index_;
}

}  // namespace ellipse_collision::app

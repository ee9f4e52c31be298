#include "ellipse_collision/app/standing_obstacles.h"

namespace ellipse_collision::app {

const core::IndexedObstacles* StandingObstacles::update(
    bool unchanged, std::vector<core::NamedEllipse>::const_iterator begin,
    std::vector<core::NamedEllipse>::const_iterator end) {
  if (!unchanged) {
    standing_checks_ = 0;
    index_.reset();
    return nullptr;
  }
  ++standing_checks_;
  if (!index_ && standing_checks_ >= kChecksBeforeIndexing) {
    index_.emplace(std::vector<core::NamedEllipse>(begin, end));
    // The registry validated them, so a refusal would be a bug: stream, and try again later.
    if (!index_->error().empty()) {
      index_.reset();
      standing_checks_ = 0;
    }
  }
  return index_ ? &*index_ : nullptr;
}

}  // namespace ellipse_collision::app

#include "ellipse_collision/app/obstacle_persistence.h"

#include <utility>

namespace ellipse_collision::app {

ObstaclePersistence::ObstaclePersistence(const std::string& path, std::string session,
                                         std::uint64_t service_revision, std::string refusal)
    : session_(std::move(session)),
      service_revision_(service_revision),
      refusal_(path.empty() ? std::string() : std::move(refusal)) {
  if (!path.empty() && refusal_.empty()) writer_ = std::make_unique<ObstacleStoreWriter>(path);
}

StoredObstacles ObstaclePersistence::stamped(StoredObstacles stored) const {
  stored.session = session_;
  stored.service_revision = service_revision_;
  return stored;
}

std::string ObstaclePersistence::afterServiceCall(const EllipseRegistry& registry,
                                                  bool removed_topic_obstacle) {
  ++service_revision_;
  if (!writer_) return refusal_;
  if (removed_topic_obstacle) {
    behind_ = false;
    return writer_->writeNow(stamped(registry.runtimeObstacles()));
  }
  // The service obstacles alone: a call does not rewrite a perception stream's topic obstacles
  // (100,000 of them took 88 ms per call, on the node's spinner).
  return writer_->writeServiceNow(stamped(registry.serviceObstacles()));
}

void ObstaclePersistence::writeIfBehind(const EllipseRegistry& registry) {
  if (!writer_ || !behind_) return;
  behind_ = false;
  // One snapshot per period however many messages came: the copy is taken here, the text and the
  // disk are the writer thread's.
  writer_->writeLater(stamped(registry.runtimeObstacles()));
}

std::string ObstaclePersistence::lastError() const {
  return writer_ ? writer_->lastError() : refusal_;
}

void ObstaclePersistence::flush() {
  if (writer_) writer_->flush();
}

}  // namespace ellipse_collision::app

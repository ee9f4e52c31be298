#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/obstacle_store.h"
#include "ellipse_collision/app/obstacle_store_writer.h"

namespace ellipse_collision::app {

/// The rule of the obstacle store (the node's `obstacle_store`): which file a change of the
/// runtime obstacles makes durable, and when. A service call that changed only service obstacles
/// writes them alone to the service record (serviceRecordPath()), before it answers; one that
/// removed a topic obstacle writes the whole store, since the record holds no topic obstacles; a
/// topic message or an expiry only marks the store behind, and the periodic write sends it to the
/// writer's thread. Every file carries the launch's session and the count of its service calls
/// (service_revision), by which loadObstacleStore() orders a store and a record.
class ObstaclePersistence {
 public:
  /// `path` "" = the store is off: only the service calls are counted. `service_revision` is the
  /// count found at start-up in this launch's files (loadObstacleStore()), restored or not, so that
  /// a later record never loses to a stale one of the same launch.
  /// `refusal` not empty: a file at the store's paths is not the store's (LoadedStore::not_ours),
  /// so nothing is ever written and every write reports `refusal` as its error.
  ObstaclePersistence(const std::string& path, std::string session, std::uint64_t service_revision,
                      std::string refusal = {});

  /// After a service call changed `registry`. `removed_topic_obstacle`: it removed a topic
  /// obstacle (registry.anyTopicObstacle(names), asked before the call). Waits until the file is on
  /// disk: "" or why the write failed.
  std::string afterServiceCall(const EllipseRegistry& registry, bool removed_topic_obstacle);
  /// After a topic message, or the obstacle timeout, changed the topic obstacles.
  void topicChanged() { behind_ = true; }
  /// The periodic write: a snapshot of `registry` for the writer's thread when the store is
  /// behind, without waiting for the disk.
  void writeIfBehind(const EllipseRegistry& registry);

  bool enabled() const { return writer_ != nullptr; }
  bool behind() const { return behind_; }
  /// The newest finished write's error, "" after a success or with the store off; the refusal
  /// when writes are refused.
  std::string lastError() const;
  std::uint64_t serviceRevision() const { return service_revision_; }
  /// Waits until every queued write is on disk (for tests; the destructor does it too).
  void flush();

 private:
  StoredObstacles stamped(StoredObstacles stored) const;

  std::string session_;
  std::uint64_t service_revision_;
  std::string refusal_;
  bool behind_{false};
  std::unique_ptr<ObstacleStoreWriter> writer_;  ///< null when the store is off
};

}  // namespace ellipse_collision::app

#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "ellipse_collision/app/obstacle_store.h"

namespace ellipse_collision::app {

/// Writes the obstacle store (serializeObstacles(), writeFileAtomically()) on a thread of its own,
/// so that the caller never waits for the disk unless it asks to: a perception stream of 10,000
/// obstacles at 10 Hz made the node write and fsync 1.3 MB ten times a second on its one spinner
/// thread. Only the newest snapshot is written: snapshots queued while a write is under way
/// replace each other, and a burst costs one write. All writes go through this one thread, in the
/// order they were queued, so an older snapshot never lands after a newer one.
class ObstacleStoreWriter {
 public:
  /// Writes to `path`, creating the directories above it (makeParentDirectories()) when needed.
  explicit ObstacleStoreWriter(std::string path);
  /// Writes what is still queued, then stops the thread: a clean shutdown loses nothing.
  ~ObstacleStoreWriter();
  ObstacleStoreWriter(const ObstacleStoreWriter&) = delete;
  ObstacleStoreWriter& operator=(const ObstacleStoreWriter&) = delete;

  /// Queues `obstacles` in place of any snapshot still queued, and returns at once.
  void writeLater(StoredObstacles obstacles);
  /// Queues `obstacles` like writeLater() and waits until they (or a newer snapshot) are on disk:
  /// "" or why the write failed (the failing step with errno's text).
  std::string writeNow(StoredObstacles obstacles);
  /// Writes `record` (service obstacles alone) to serviceRecordPath() of the store and waits
  /// until it (or a newer record) is on disk: "" or why the write failed. Queued records replace
  /// each other as snapshots do, and a record goes before a queued snapshot (its caller waits).
  std::string writeServiceNow(StoredObstacles record);
  /// Waits until nothing is queued or being written.
  void flush();

  /// The outcome of the newest finished write: "" after a success (and before any write).
  std::string lastError() const;
  /// Writes finished so far (successful or not).
  std::size_t writes() const;

 private:
  void run();

  const std::string path_;
  mutable std::mutex mutex_;
  std::condition_variable queued_or_stopping_;
  std::condition_variable written_;
  /// One file's newest queued content and how far its writes got.
  struct Slot {
    std::optional<StoredObstacles> queued;
    std::uint64_t queued_version{0};   ///< version of the newest content ever queued
    std::uint64_t written_version{0};  ///< version of the newest content written
    std::string last_error;            ///< outcome of the newest finished write
  };
  /// Queues `content` in `slot`; returns its version.
  std::uint64_t queue(Slot& slot, StoredObstacles content);
  /// Writes what `slot` holds to `path` (the lock is released meanwhile).
  void writeSlot(Slot& slot, const std::string& path, std::unique_lock<std::mutex>& lock);

  const std::string record_path_;
  Slot store_;    ///< the whole store, at path_
  Slot service_;  ///< the service record, at record_path_
  std::string last_error_;
  std::size_t writes_{0};
  bool stopping_{false};
  std::thread thread_;  ///< last: started once every member above exists
};

}  // namespace ellipse_collision::app

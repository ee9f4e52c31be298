#include "ellipse_collision/app/obstacle_store_writer.h"

#include <utility>

namespace ellipse_collision::app {

ObstacleStoreWriter::ObstacleStoreWriter(std::string path)
    : path_(std::move(path)), record_path_(serviceRecordPath(path_)), thread_([this] { run(); }) {}

ObstacleStoreWriter::~ObstacleStoreWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  queued_or_stopping_.notify_one();
  thread_.join();
}

std::uint64_t ObstacleStoreWriter::queue(Slot& slot, StoredObstacles content) {
  slot.queued = std::move(content);
  ++slot.queued_version;
  queued_or_stopping_.notify_one();
  return slot.queued_version;
}

void ObstacleStoreWriter::writeLater(StoredObstacles obstacles) {
  std::lock_guard<std::mutex> lock(mutex_);
  queue(store_, std::move(obstacles));
}

std::string ObstacleStoreWriter::writeNow(StoredObstacles obstacles) {
  std::unique_lock<std::mutex> lock(mutex_);
  const std::uint64_t version = queue(store_, std::move(obstacles));
  written_.wait(lock, [&] { return store_.written_version >= version; });
  return store_.last_error;
}

std::string ObstacleStoreWriter::writeServiceNow(StoredObstacles record) {
  std::unique_lock<std::mutex> lock(mutex_);
  const std::uint64_t version = queue(service_, std::move(record));
  written_.wait(lock, [&] { return service_.written_version >= version; });
  return service_.last_error;
}

void ObstacleStoreWriter::flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  written_.wait(lock, [&] {
    return store_.written_version >= store_.queued_version &&
           service_.written_version >= service_.queued_version;
  });
}

std::string ObstacleStoreWriter::lastError() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_error_;
}

std::size_t ObstacleStoreWriter::writes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return writes_;
}

void ObstacleStoreWriter::writeSlot(Slot& slot, const std::string& path,
                                    std::unique_lock<std::mutex>& lock) {
  const StoredObstacles content = std::move(*slot.queued);
  slot.queued.reset();
  const std::uint64_t version = slot.queued_version;
  lock.unlock();
  // Serialised here too: for 10,000 obstacles that is milliseconds the caller does not wait for.
  std::string error = makeParentDirectories(path);
  if (error.empty()) error = writeFileAtomically(path, serializeObstacles(content));
  lock.lock();
  slot.last_error = error;
  last_error_ = std::move(error);
  slot.written_version = version;
  ++writes_;
  written_.notify_all();
}

void ObstacleStoreWriter::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    queued_or_stopping_.wait(
        lock, [&] { return service_.queued.has_value() || store_.queued.has_value() || stopping_; });
    // A service record first: its caller is waiting. Either order is safe, since a record
    // applies only over a store of an older service_revision (applyNewerServiceRecord()).
    if (service_.queued) {
      writeSlot(service_, record_path_, lock);
    } else if (store_.queued) {
      writeSlot(store_, path_, lock);
    } else {
      return;  // stopping, and everything queued is written
    }
  }
}

}  // namespace ellipse_collision::app

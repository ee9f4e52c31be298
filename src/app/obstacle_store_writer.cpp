#include "ellipse_collision/app/obstacle_store_writer.h"

#include <utility>

namespace ellipse_collision::app {

ObstacleStoreWriter::ObstacleStoreWriter(std::string path)
    : path_(std::move(path)), thread_([this] { run(); }) {}

ObstacleStoreWriter::~ObstacleStoreWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  queued_or_stopping_.notify_one();
  thread_.join();
}

void ObstacleStoreWriter::writeLater(StoredObstacles obstacles) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queued_ = std::move(obstacles);
    ++queued_version_;
  }
  queued_or_stopping_.notify_one();
}

std::string ObstacleStoreWriter::writeNow(StoredObstacles obstacles) {
  std::unique_lock<std::mutex> lock(mutex_);
  queued_ = std::move(obstacles);
  const std::uint64_t version = ++queued_version_;
  queued_or_stopping_.notify_one();
  written_.wait(lock, [&] { return written_version_ >= version; });
  return last_error_;
}

void ObstacleStoreWriter::flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  written_.wait(lock, [&] { return written_version_ >= queued_version_; });
}

std::string ObstacleStoreWriter::lastError() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_error_;
}

std::size_t ObstacleStoreWriter::writes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return writes_;
}

void ObstacleStoreWriter::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    queued_or_stopping_.wait(lock, [&] { return queued_.has_value() || stopping_; });
    if (!queued_) return;  // stopping, and everything queued is written
    const StoredObstacles obstacles = std::move(*queued_);
    queued_.reset();
    const std::uint64_t version = queued_version_;
    lock.unlock();
    // Serialised here too: for 10,000 obstacles that is milliseconds the caller does not wait for.
    std::string error = makeParentDirectories(path_);
    if (error.empty()) error = writeFileAtomically(path_, serializeObstacles(obstacles));
    lock.lock();
    last_error_ = std::move(error);
    written_version_ = version;
    ++writes_;
    written_.notify_all();
  }
}

}  // namespace ellipse_collision::app

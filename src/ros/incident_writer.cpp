#include "ellipse_collision/ros/incident_writer.h"

#include <ros/console.h>
#include <ros/time.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include "ellipse_collision/ros/incident_bag.h"

namespace ellipse_collision {

namespace fs = std::filesystem;

IncidentWriter::IncidentWriter(std::string directory, std::size_t max_files, double max_megabytes)
    : directory_(std::move(directory)),
      max_files_(max_files),
      max_megabytes_(max_megabytes),
      thread_([this] { run(); }) {}

IncidentWriter::~IncidentWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

std::string IncidentWriter::write(app::Incident incident, std::string settings_yaml,
                                  std::string fixed_frame) {
  // Named by wall time: an incident's name says when it happened, whatever the ROS clock is.
  std::string name = app::incidentFileName(ros::WallTime::now().toSec(), incident.trigger);
  std::lock_guard<std::mutex> lock(mutex_);
  if (name <= last_name_) name = last_name_.substr(0, last_name_.size() - 4) + "_1.bag";
  last_name_ = name;
  const std::string path = directory_ + "/" + name;
  queue_.push_back({path, std::move(incident), std::move(settings_yaml), std::move(fixed_frame)});
  wake_.notify_one();
  return path;
}

IncidentWriter::Status IncidentWriter::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

void IncidentWriter::flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return queue_.empty() && !busy_; });
}

void IncidentWriter::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, and everything written
    const Job job = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    lock.unlock();
    writeOne(job);
    lock.lock();
    busy_ = false;
    if (queue_.empty()) idle_.notify_all();
  }
}

void IncidentWriter::writeOne(const Job& job) {
  std::string error;
  try {
    std::error_code ec;
    fs::create_directories(directory_, ec);
    if (ec) throw std::runtime_error("cannot create " + directory_ + ": " + ec.message());
    writeIncidentBag(job.path, job.incident, job.settings_yaml, job.fixed_frame);
    keepWithinBudget();
  } catch (const std::exception& e) {
    error = e.what();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (error.empty()) {
    ++status_.written;
    status_.last_file = job.path;
    status_.last_error.clear();
    ROS_INFO_STREAM("ellipse_collision: incident (" << job.incident.trigger << ") written to "
                                                    << job.path);
  } else {
    ++status_.failed;
    status_.last_error = "cannot write incident " + job.path + ": " + error;
    ROS_WARN_STREAM_THROTTLE(10.0, "ellipse_collision: " << status_.last_error);
  }
}

void IncidentWriter::keepWithinBudget() {
  std::vector<app::IncidentFile> files;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory_, ec)) {
    const std::string name = entry.path().filename().string();
    // Our bags only: whatever else a user keeps there is not ours to remove.
    if (name.rfind("incident_", 0) != 0 || entry.path().extension() != ".bag") continue;
    std::error_code size_ec;
    const std::uintmax_t bytes = entry.file_size(size_ec);
    files.push_back({name, size_ec ? 0 : static_cast<std::uint64_t>(bytes)});
  }
  for (const std::string& name : app::incidentFilesToRemove(files, max_files_, max_megabytes_)) {
    std::error_code remove_ec;
    fs::remove(directory_ + "/" + name, remove_ec);
    if (remove_ec) {
      ROS_WARN_STREAM_THROTTLE(10.0, "ellipse_collision: cannot remove old incident "
                                         << name << ": " << remove_ec.message());
    }
  }
}

}  // namespace ellipse_collision

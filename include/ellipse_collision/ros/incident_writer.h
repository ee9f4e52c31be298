#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <thread>

#include "ellipse_collision/app/incident_recorder.h"

namespace ellipse_collision {

/// Writes incident bags on a thread of its own, so that a decision never waits for the disk:
/// each bag goes to `directory` (created when missing) under app::incidentFileName(), then the
/// oldest bags there are removed to stay within max_files and max_megabytes
/// (app::incidentFilesToRemove()). A failure (a full or read-only disk) is kept for
/// /diagnostics and logged, throttled; it never throws.
class IncidentWriter {
 public:
  IncidentWriter(std::string directory, std::size_t max_files, double max_megabytes);
  /// Writes what is queued, then stops the thread.
  ~IncidentWriter();
  IncidentWriter(const IncidentWriter&) = delete;
  IncidentWriter& operator=(const IncidentWriter&) = delete;

  /// Queues `incident` with its `settings` YAML (incidentSettingsYaml()); returns the path it
  /// will be written to.
  std::string write(app::Incident incident, std::string settings_yaml, std::string fixed_frame);

  /// What /diagnostics shows.
  struct Status {
    std::uint64_t written{0};  ///< bags written
    std::uint64_t failed{0};   ///< bags that could not be written
    std::string last_file;     ///< the last bag written
    std::string last_error;    ///< why the latest write failed; "" after a success
  };
  Status status() const;
  const std::string& directory() const { return directory_; }
  /// Waits until every queued bag is written or failed (tests).
  void flush();

 private:
  struct Job {
    std::string path;
    app::Incident incident;
    std::string settings_yaml;
    std::string fixed_frame;
  };
  void run();
  void writeOne(const Job& job);
  void keepWithinBudget();

  const std::string directory_;
  const std::size_t max_files_;
  const double max_megabytes_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable idle_;
  std::deque<Job> queue_;
  bool busy_{false};
  bool stopping_{false};
  Status status_;
  std::string last_name_;  ///< the last file name handed out (two incidents within 1 ms)
  std::thread thread_;
};

}  // namespace ellipse_collision

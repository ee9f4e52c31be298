#pragma once

#include <string>

namespace ellipse_collision {

/// When to log a condition that may last or come back many times a second (a contact on the
/// planned path, a held arm): when it starts or its subject changes, at most once per
/// `min_interval_s`, so that the terminal tells what happened without repeating it.
class LogOnChange {
 public:
  explicit LogOnChange(double min_interval_s) : min_interval_s_(min_interval_s) {}

  /// Whether to log `subject` at `now_s` [s]; "" = the condition is over (never logged). A
  /// subject is logged when it differs from the last one logged, or is the same one back after
  /// the condition was over, and min_interval_s has passed since the last log line.
  bool shouldLog(const std::string& subject, double now_s);

 private:
  double min_interval_s_;
  std::string logged_;  ///< the last subject logged
  double logged_at_s_{0.0};
  bool ever_logged_{false};
  bool over_since_log_{false};  ///< an empty subject came since the last log line
};

}  // namespace ellipse_collision

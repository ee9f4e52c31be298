#include "demo_log_on_change.h"

namespace ellipse_collision {

bool LogOnChange::shouldLog(const std::string& subject, double now_s) {
  if (subject.empty()) {
    over_since_log_ = true;
    return false;
  }
  if (ever_logged_) {
    if (subject == logged_ && !over_since_log_) return false;
    if (now_s - logged_at_s_ < min_interval_s_) return false;
  }
  logged_ = subject;
  logged_at_s_ = now_s;
  ever_logged_ = true;
  over_since_log_ = false;
  return true;
}

}  // namespace ellipse_collision

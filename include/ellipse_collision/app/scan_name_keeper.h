#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/app/scan_obstacles.h"

namespace ellipse_collision::app {

/// Keeps the names of one sensor's obstacle ellipses from message to message, so that markers
/// and the obstacle store do not churn while the scene stays. Named by its first key alone
/// (scanObstacles()), an ellipse is renamed whenever range noise moves its first split point by
/// one beam. Instead, an ellipse takes the name of the last message's ellipse whose keys it
/// shares most, when they share more than half the keys of the shorter of the two; pairs are
/// matched greedily, most shared keys first, each name at most once. An ellipse that matches none
/// of them is matched the same way against the ellipses that went away within the last
/// kRememberedMessages messages (noise splits a stretch in one scan and not in the next: the
/// piece comes back under its name). Else it keeps its first-key name (with "_2", "_3", ...
/// appended should another ellipse already hold it). Only `name` changes, never the geometry.
class ScanNameKeeper {
 public:
  /// How long a name that went away can come back [messages].
  static constexpr std::size_t kRememberedMessages = 40;

  /// Renames `obstacles.ellipses` as above and remembers them for the next message. A message on
  /// another ring of keys (a scan of another beam count) or in another frame starts afresh.
  void rename(SensorObstacles& obstacles);

  /// Names that were in the last message and are not in this one (for tests and statistics).
  std::size_t namesDropped() const { return dropped_; }

 private:
  struct Named {
    std::string name;
    KeySpan span;
    std::size_t message{0};  ///< the last message that had it
  };
  std::vector<Named> last_;
  std::vector<Named> gone_;  ///< went away within kRememberedMessages, oldest first
  std::size_t message_{0};
  std::size_t key_ring_{0};
  std::string frame_id_;
  std::size_t dropped_{0};
};

/// How many keys the spans `a` and `b` share on a ring of `ring` keys.
std::size_t sharedKeys(const KeySpan& a, const KeySpan& b, std::size_t ring);

}  // namespace ellipse_collision::app

#pragma once

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace ellipse_collision::app {

/// The per-source freshness rule: a source with a timeout > 0 that has not delivered an accepted
/// message for longer than its timeout (or none yet) is silent, and a silent source makes every
/// answer incomplete. Ages count from when a message was accepted (the ROS clock at receipt),
/// not from its header stamp: what is measured is the source's silence, whatever its clock.
class SourceFreshness {
 public:
  struct Source {
    std::string name;
    double timeout_s{0.0};  ///< [s]; 0 = never silent
  };
  /// What /diagnostics shows of one source.
  struct Stats {
    std::string name;
    double rate_hz{0.0};       ///< accepted messages per second over the last few (0: fewer than 2)
    double age_s{-1.0};        ///< since the last accepted message [s]; -1 = none yet
    std::size_t obstacles{0};  ///< in its last accepted message
    std::size_t messages{0};   ///< accepted so far
  };

  explicit SourceFreshness(std::vector<Source> sources);

  /// Source `index` delivered an accepted message of `obstacles` obstacles at `now_s` [s].
  void received(std::size_t index, double now_s, std::size_t obstacles);
  /// Every silent source at `now_s`, as "source 'rear_scan' silent for 0.8 s" or "source
  /// 'rear_scan' silent: no message yet" (in the order of the list).
  std::vector<std::string> silent(double now_s) const;
  std::vector<Stats> stats(double now_s) const;
  std::size_t size() const { return states_.size(); }

  /// Receipt times kept for the rate.
  static constexpr std::size_t kRateWindow = 10;

 private:
  struct State {
    Source source;
    std::deque<double> received_s;  ///< the last kRateWindow receipt times, oldest first
    std::size_t obstacles{0};
    std::size_t messages{0};
  };
  std::vector<State> states_;
};

}  // namespace ellipse_collision::app

#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/collision_check.h"

namespace ellipse_collision::app {

/// A frame unavailable or stale for longer than this [s] is an error, not a warning: one missed
/// transform is a hiccup, a second of them is a sensor or driver that is gone.
inline constexpr double kMaxMissingS = 1.0;

/// What the node knows about its checks at one moment, for its health report.
struct CheckHealthInputs {
  const CheckOutcome* outcome{nullptr};  ///< the last successful full check; null before one
  std::string check_failure;             ///< why the latest full check failed ("" if it did not)
  /// Each frame missing (unavailable or stale) at the last check, and for how long [s].
  std::vector<std::pair<std::string, double>> missing_for_s;
  std::string obstacles_error;  ///< why the last ~obstacles message was refused ("" = accepted)
  /// Listed sources whose last message was refused: "source 'front': why".
  std::vector<std::string> source_errors;
  std::string store_error;      ///< the obstacle store's last write failure ("" = none)
};

/// The health a safety consumer acts on (/diagnostics).
struct CheckHealth {
  enum class Level { Ok, Warn, Error };
  /// Error: the latest check failed, a frame has been missing longer than kMaxMissingS, or an
  /// obstacle source is silent past its timeout.
  /// Warn: anything else in `problems`. Ok: no problem, or only "no check yet".
  Level level{Level::Ok};
  /// The problems joined with "; ", or the scene's state: "in collision", "contact predicted in
  /// <t> s (<a> / <b>)", "closer than the warning distance", "clear".
  std::string message;
  std::vector<std::string> missing_for;  ///< "frame: seconds" (to 0.1 s), one per missing frame
};

CheckHealth assessCheckHealth(const CheckHealthInputs& inputs);

}  // namespace ellipse_collision::app

#include "ellipse_collision/app/check_health.h"

#include <algorithm>
#include <cmath>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

CheckHealth assessCheckHealth(const CheckHealthInputs& inputs) {
  CheckHealth health;
  std::vector<std::string> problems;
  const CheckOutcome* outcome = inputs.outcome;
  if (!outcome) problems.push_back("no check yet");
  if (outcome && !outcome->unavailable_frames.empty()) {
    problems.push_back("frames unavailable: " + joinText(outcome->unavailable_frames, ", "));
  }
  if (outcome && !outcome->stale_frames.empty()) {
    problems.push_back("frames stale: " + joinText(outcome->stale_frames, ", "));
  }
  if (outcome && !outcome->skipped.empty()) {
    problems.push_back("skipped: " + joinText(outcome->skipped, "; "));
  }
  bool missing_too_long = false;
  for (const auto& [frame, seconds] : inputs.missing_for_s) {
    const double shown = std::max(0.0, seconds);
    missing_too_long = missing_too_long || shown > kMaxMissingS;
    health.missing_for.push_back(frame + ": " + core::formatNumber(std::round(shown * 10.0) / 10.0));
  }
  if (missing_too_long) {
    problems.push_back("a frame has been unavailable or stale for more than " +
                       core::formatNumber(kMaxMissingS) + " s");
  }
  if (!inputs.obstacles_error.empty()) {
    problems.push_back("last ~obstacles message refused: " + inputs.obstacles_error);
  }
  for (const std::string& refused : inputs.source_errors) {
    problems.push_back("last message refused: " + refused);
  }
  const bool silent = outcome && !outcome->silent_sources.empty();
  if (silent) problems.push_back(joinText(outcome->silent_sources, "; "));
  if (!inputs.check_failure.empty()) problems.push_back("last check failed: " + inputs.check_failure);
  if (!inputs.store_error.empty()) problems.push_back("obstacle store: " + inputs.store_error);

  const bool only_waiting = !outcome && problems.size() == 1;
  health.level = !inputs.check_failure.empty() || missing_too_long || silent
                     ? CheckHealth::Level::Error
                 : problems.empty() || only_waiting ? CheckHealth::Level::Ok
                                                    : CheckHealth::Level::Warn;
  if (!problems.empty()) {
    health.message = joinText(problems, "; ");
  } else if (!outcome->collisions.empty()) {
    health.message = "in collision";
  } else if (!outcome->predicted.empty()) {
    const core::PredictedContact& soonest = outcome->predicted.front();
    health.message = "contact predicted in " + core::formatNumber(soonest.time) + " s (" +
                     soonest.name_a + " / " + soonest.name_b + ")";
  } else if (!outcome->warnings.empty()) {
    health.message = "closer than the warning distance";
  } else {
    health.message = "clear";
  }
  return health;
}

}  // namespace ellipse_collision::app

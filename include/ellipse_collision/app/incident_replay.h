#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/app/gate_config.h"
#include "ellipse_collision/app/incident_recorder.h"
#include "ellipse_collision/app/velocity_gate.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::app {

/// What an incident's decisions were judged with besides their own record: the gate's settings
/// and the allowed pairs (an incident bag's `settings`).
struct ReplaySettings {
  GateConfig gate;
  core::AllowedPairs allowed;
};

/// A field in which a decision judged again differs from the recorded one: its name as
/// ~gate_state spells it ("scale", "output.linear.x", "link") and both values as they read back.
struct DecisionDifference {
  std::string field;
  std::string recorded;
  std::string replayed;
};

/// The first field of the decision in which `replayed` differs from `recorded`, numbers compared
/// bit for bit, in the order action, scale, output, contact_predicted, time_to_contact (when
/// predicted), link, obstacle, contact_point (when predicted), braking_distance, free_distance,
/// unavoidable, impact_speed; nothing when every one is the same. The reason is not compared.
std::optional<DecisionDifference> firstDifference(const GateDecision& recorded,
                                                  const GateDecision& replayed);

/// The decision judged again from `recorded` alone: its input, its placed links and obstacles
/// (in the fixed frame) with their motions, the robot's pose and its GateMemory, through the
/// gate's rules (judgeOnScene()) with `settings`. Precondition: recorded.memory is set (the rules
/// judged it) and every motion's index is one of its obstacles.
GateDecision replayDecision(const RecordedDecision& recorded, const ReplaySettings& settings);

/// A recorded decision the replay did not reproduce: its place in the incident (from 0), its
/// stamp [s] and the first field that differs.
struct ReplayMismatch {
  std::size_t index{0};
  double stamp_s{0.0};
  DecisionDifference difference;
};

/// The replay of an incident: how many decisions it holds, how many the gate's rules judged (and
/// were judged again; the others were decided before the rules: a screened command, TIMEOUT, a
/// failed check, INCOMPLETE) and those not reproduced.
struct ReplayReport {
  std::size_t decisions{0};
  std::size_t replayed{0};
  std::vector<ReplayMismatch> mismatches;
  /// Every decision judged by the rules was reproduced, and there was at least one: an incident
  /// without one proves nothing.
  bool reproduced() const { return replayed > 0 && mismatches.empty(); }
};

/// Each decision of `decisions` that the rules judged, judged again (replayDecision()) and
/// compared (firstDifference()).
ReplayReport replayIncident(const std::vector<RecordedDecision>& decisions,
                            const ReplaySettings& settings);

/// "decision 12 at 103.25 s: scale recorded 0.5, replayed 0.49"
std::string describeMismatch(const ReplayMismatch& mismatch);
/// "replay: 143 of 143 decisions reproduced (4 decided before the gate's rules, not replayed)",
/// or "replay: no decision judged by the gate's rules in 3 decisions: nothing to reproduce".
std::string replaySummary(const ReplayReport& report);

}  // namespace ellipse_collision::app

#pragma once

#include <string>
#include <vector>

#include "ellipse_collision/RecordedDecision.h"
#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/gate_config.h"
#include "ellipse_collision/app/incident_recorder.h"
#include "ellipse_collision/app/incident_replay.h"

namespace ellipse_collision {

/// The message of one recorded decision (msg/RecordedDecision.msg) in `fixed_frame`; its
/// obstacles are filled in only `with_obstacles` (the first decision of a set in a bag).
RecordedDecision toMsg(const app::RecordedDecision& recorded, const std::string& fixed_frame,
                       bool with_obstacles);

/// The format of the incident bags written here (`format` in `settings`): 2 added what a replay
/// needs (RecordedDecision's judged_by_rules and the fields after it), 3 the moving obstacles'
/// ages (moving_since). Bags of another format cannot be replayed.
constexpr int kIncidentBagFormat = 3;

/// The `settings` topic of an incident bag: YAML of the format, the trigger and of what the gate
/// judged with (fixed_frame, padding, self_collision, allowed_pairs and every gate/ key), as
/// doc/incidents.md lists it.
std::string incidentSettingsYaml(const app::Incident& incident, const app::GateConfig& gate,
                                 const app::CheckSettings& check);

/// Writes `incident` to the bag `path`: `settings` once (the YAML above), then one `decisions`
/// message per decision at its stamp. Throws std::runtime_error (rosbag's errors included) when
/// the bag cannot be written; a partly written file is removed.
void writeIncidentBag(const std::string& path, const app::Incident& incident,
                      const std::string& settings_yaml, const std::string& fixed_frame);

/// The settings a replay needs (every gate/ key and allowed_pairs) from the `settings` YAML of
/// an incident bag of format kIncidentBagFormat; the error names the key and value (a missing
/// `format`: a bag too old to replay; a gate setting out of range), or "".
std::string parseIncidentSettingsYaml(const std::string& yaml, app::ReplaySettings* settings);

/// An incident bag read back for a replay.
struct ReplayInput {
  app::ReplaySettings settings;
  std::vector<app::RecordedDecision> decisions;  ///< oldest first, obstacles shared per set
};

/// Reads the incident bag `path` (its `settings` and `decisions`); the error, naming the bag and
/// the field, when it cannot be opened, is of another or older format (a replay needs format
/// kIncidentBagFormat), or a decision's fields do not fit together, or "".
std::string readIncidentBag(const std::string& path, ReplayInput* input);

}  // namespace ellipse_collision

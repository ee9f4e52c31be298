#pragma once

#include <string>

#include "ellipse_collision/RecordedDecision.h"
#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/gate_config.h"
#include "ellipse_collision/app/incident_recorder.h"

namespace ellipse_collision {

/// The message of one recorded decision (msg/RecordedDecision.msg) in `fixed_frame`; its
/// obstacles are filled in only `with_obstacles` (the first decision of a set in a bag).
RecordedDecision toMsg(const app::RecordedDecision& recorded, const std::string& fixed_frame,
                       bool with_obstacles);

/// The `settings` topic of an incident bag: YAML of the trigger and of what the gate judged with
/// (fixed_frame, padding, self_collision, allowed_pairs and every gate/ key), as
/// doc/incidents.md lists it.
std::string incidentSettingsYaml(const app::Incident& incident, const app::GateConfig& gate,
                                 const app::CheckSettings& check);

/// Writes `incident` to the bag `path`: `settings` once (the YAML above), then one `decisions`
/// message per decision at its stamp. Throws std::runtime_error (rosbag's errors included) when
/// the bag cannot be written; a partly written file is removed.
void writeIncidentBag(const std::string& path, const app::Incident& incident,
                      const std::string& settings_yaml, const std::string& fixed_frame);

}  // namespace ellipse_collision

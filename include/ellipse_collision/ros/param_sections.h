#pragma once

#include <xmlrpcpp/XmlRpcValue.h>

#include <string>
#include <vector>

#include "ellipse_collision/app/fleet_footprint.h"
#include "ellipse_collision/app/gate_config.h"
#include "ellipse_collision/app/incident_recorder.h"
#include "ellipse_collision/app/obstacle_source.h"

// The node's dict- and list-valued parameters, one reader each (gate_params.cpp, fleet_params.cpp,
// incident_params.cpp, source_params.cpp): types and required keys are checked here, every value
// rule in the application layer. Each throws ConfigError naming the key.
namespace ellipse_collision::params {

/// `gate: {enabled, robot_frame, horizon, ...}`: ranges by app::findInvalidGateSetting().
app::GateConfig readGate(const XmlRpc::XmlRpcValue& value);

/// `fleet: {enabled, topic, frame, robot_name, rate}`; robot_name defaults to
/// `default_robot_name`. Ranges by app::findInvalidSetting(), which the caller applies.
app::FleetSettings readFleet(const XmlRpc::XmlRpcValue& value,
                             const std::string& default_robot_name);

/// `incident: {enabled, before, after, ...}`: ranges by app::findInvalidIncidentSetting().
app::IncidentSettings readIncident(const XmlRpc::XmlRpcValue& value);

/// `sources`: a list of {name, type, topic, timeout, <scan keys for types scan and cloud,
/// min_radius for range, required for robots>}; every value rule in app::findInvalidSources().
/// A robots source's topic defaults to `fleet_topic`, its timeout to app::kDefaultRobotsTimeoutS;
/// tracks live in `fixed_frame` unless the entry says otherwise.
std::vector<app::SourceSpec> readSources(const XmlRpc::XmlRpcValue& list,
                                         const std::string& fixed_frame,
                                         const std::string& fleet_topic);

}  // namespace ellipse_collision::params

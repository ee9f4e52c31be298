#include "ellipse_collision/ros/node_config.h"

#include <ros/names.h>

#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/core/unique_names.h"
#include "ellipse_collision/ros/param_sections.h"

namespace ellipse_collision {

using XmlRpc::XmlRpcValue;
using namespace params;  // NOLINT(google-build-using-namespace): the readers of one file family

app::MonitorSettings nodeMonitorDefaults() {
  app::MonitorSettings settings;
  settings.check.max_transform_age_s = 0.5;
  return settings;
}

namespace {

// Every key the node reads, in the order of config/ellipse_collision.yaml's documentation.
const std::vector<std::string> kKnownKeys = {"fixed_frame",
                                             "rate",
                                             "tf_timeout",
                                             "padding",
                                             "links",
                                             "links_from_urdf",
                                             "obstacles",
                                             "allowed_pairs",
                                             "self_collision",
                                             "warning_distance",
                                             "max_transform_age",
                                             "obstacle_timeout",
                                             "max_obstacles",
                                             "max_name_length",
                                             "obstacle_store",
                                             "obstacle_store_period",
                                             "robot_frame",
                                             "prediction_horizon",
                                             "marker_refresh_period",
                                             "gate",
                                             "sources",
                                             "fleet",
                                             "incident"};

bool has(const XmlRpcValue& root, const char* key) {
  return root.getType() == XmlRpcValue::TypeStruct && root.hasMember(key);
}

/// The scalar parameters, each in its range from the one table (or its own limit).
void readScalars(const XmlRpcValue& root, NodeConfig* config) {
  if (has(root, "fixed_frame")) {
    config->monitor.check.fixed_frame =
        readFrame(root["fixed_frame"], "parameter ~fixed_frame", "fixed_frame");
  }
  if (has(root, "robot_frame")) {
    config->monitor.robot_frame =
        readFrame(root["robot_frame"], "parameter ~robot_frame", "robot_frame");
  }
  if (has(root, "prediction_horizon")) {
    config->monitor.prediction_horizon_s = readSetting(root, "prediction_horizon");
  }
  if (has(root, "rate")) {
    config->monitor.rate_hz = readSetting(root, "rate");
  }
  if (has(root, "tf_timeout")) {
    config->tf_timeout_s = readSetting(root, "tf_timeout");
  }
  if (has(root, "padding")) {
    config->monitor.check.global_padding_m = readSetting(root, "padding");
  }
  if (has(root, "self_collision")) {
    config->monitor.check.rules.self_collision =
        readBool(root["self_collision"], "parameter ~self_collision", "self_collision");
  }
  if (has(root, "warning_distance")) {
    config->monitor.check.rules.warning_distance = readSetting(root, "warning_distance");
  }
  if (has(root, "max_transform_age")) {
    config->monitor.check.max_transform_age_s = readSetting(root, "max_transform_age");
  }
  if (has(root, "obstacle_timeout")) {
    config->monitor.obstacle_timeout_s = readSetting(root, "obstacle_timeout");
  }
  if (has(root, "max_obstacles")) {
    config->limits.max_obstacles = static_cast<std::size_t>(readWhole(
        root["max_obstacles"], "parameter ~max_obstacles", "max_obstacles", kMaxObstaclesLimit));
  }
  if (has(root, "max_name_length")) {
    config->limits.max_name_length =
        static_cast<std::size_t>(readWhole(root["max_name_length"], "parameter ~max_name_length",
                                           "max_name_length", kMaxNameLengthLimit));
  }
  if (has(root, "obstacle_store")) {
    config->obstacle_store =
        readString(root["obstacle_store"], "parameter ~obstacle_store", "obstacle_store");
  }
  if (has(root, "obstacle_store_period")) {
    config->monitor.obstacle_store_period_s = readSetting(root, "obstacle_store_period");
  }
  if (has(root, "marker_refresh_period")) {
    config->marker_refresh_period_s = readSetting(root, "marker_refresh_period");
  }
}

/// gate/, fleet/, incident/ and sources.
void readSections(const XmlRpcValue& root, const std::string& default_robot_name,
                  NodeConfig* config) {
  if (has(root, "gate")) config->monitor.gate = readGate(root["gate"]);
  config->fleet.robot_name = default_robot_name;
  if (has(root, "fleet")) config->fleet = readFleet(root["fleet"], default_robot_name);
  if (const auto invalid = app::findInvalidSetting(config->fleet)) {
    fail("parameter ~fleet", invalid->key, invalid->expected, invalid->actual);
  }
  if (has(root, "incident")) config->monitor.incident = readIncident(root["incident"]);
  if (has(root, "sources")) {
    config->monitor.sources =
        readSources(root["sources"], config->monitor.check.fixed_frame, config->fleet.topic);
  }
}

/// links, links_from_urdf and obstacles, each checked with the global padding.
void readEllipses(const XmlRpcValue& root, const UrdfLinkFitter& fit_urdf_links,
                  NodeConfig* config) {
  if (!has(root, "links") && !has(root, "links_from_urdf")) {
    throw ConfigError(
        "parameter ~links, key 'links': expected a list of ellipses (required unless "
        "links_from_urdf is given; may be []), got nothing (is the YAML loaded into the node's "
        "private namespace?)");
  }
  if (has(root, "links"))
    config->links =
        parseEllipseList(root["links"], "links", config->monitor.check.global_padding_m);
  if (has(root, "links_from_urdf")) {
    const app::LinkFitResult fitted = readLinksFromUrdf(root["links_from_urdf"], fit_urdf_links);
    for (const app::EllipseSpec& spec : fitted.links) {
      if (const auto invalid =
              app::findInvalidPaddedField(spec, config->monitor.check.global_padding_m, "frame")) {
        fail("parameter ~links_from_urdf (link '" + spec.name + "')", invalid->key,
             invalid->expected, invalid->actual);
      }
      config->links.push_back(spec);
    }
    config->urdf_links_skipped = fitted.skipped;
  }
  if (has(root, "obstacles")) {
    config->obstacles =
        parseEllipseList(root["obstacles"], "obstacles", config->monitor.check.global_padding_m);
  }
}

/// Links and obstacles share one name space; allowed_pairs name two of them.
void readNamesAndPairs(const XmlRpcValue& root, NodeConfig* config) {
  // Each entry's own name is non-empty already.
  std::vector<std::pair<std::string, const app::EllipseSpec*>> entries;  // (where, spec)
  for (std::size_t i = 0; i < config->links.size(); ++i) {
    entries.emplace_back(app::entryName("links", i), &config->links[i]);
  }
  for (std::size_t i = 0; i < config->obstacles.size(); ++i) {
    entries.emplace_back(app::entryName("obstacles", i), &config->obstacles[i]);
  }
  if (const auto problem = core::findNameProblem(
          entries.size(),
          [&](std::size_t i) -> std::string_view { return entries[i].second->name; })) {
    const auto& [where, spec] = entries[problem->index];
    fail(where + " (name '" + spec->name + "')", "name", "a name used by no other entry",
         "a duplicate of " + entries[problem->first_index].first);
  }
  std::map<std::string, std::string> defined;  // name -> entry that defines it
  for (const auto& [where, spec] : entries) defined.emplace(spec->name, where);
  if (has(root, "allowed_pairs")) {
    for (const auto& [a, b] : readAllowedPairs(root["allowed_pairs"], defined)) {
      config->monitor.check.rules.allowed.add(a, b);
    }
  }
}

}  // namespace

NodeConfig parseNodeConfig(const XmlRpcValue& private_namespace,
                           const UrdfLinkFitter& fit_urdf_links,
                           const std::string& default_robot_name) {
  XmlRpcValue root = private_namespace;
  if (root.getType() == XmlRpcValue::TypeInvalid) root = XmlRpcValue();
  if (root.getType() != XmlRpcValue::TypeInvalid && root.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError("private namespace: expected a dict of parameters, got " +
                      describeValue(root));
  }
  if (root.getType() == XmlRpcValue::TypeStruct) {
    refuseUnknownKeys(root, kKnownKeys, "parameter ~");
  }
  NodeConfig config;
  readScalars(root, &config);
  readSections(root, default_robot_name, &config);
  readEllipses(root, fit_urdf_links, &config);
  readNamesAndPairs(root, &config);
  return config;
}

std::string rosHome() {
  const char* ros_home = std::getenv("ROS_HOME");
  const char* home = std::getenv("HOME");
  return ros_home && *ros_home ? std::string(ros_home)
         : home && *home       ? std::string(home) + "/.ros"
                               : std::string("/tmp");
}

std::string defaultIncidentDirectory() { return rosHome() + "/ellipse_collision/incidents"; }

std::string defaultObstacleStore(const std::string& node_name) {
  const std::string directory = rosHome();
  std::string file = node_name;
  for (char& c : file) c = c == '/' ? '_' : c;
  if (!file.empty() && file.front() == '_') file.erase(0, 1);
  return directory + "/ellipse_collision/" + file + ".obstacles";
}

NodeConfig loadNodeConfig(const ros::NodeHandle& private_nh, const UrdfLinkFitter& fit_urdf_links) {
  // Absent namespace: no parameters at all, which parseNodeConfig reports as a missing ~links.
  const XmlRpcValue params = privateNamespace(private_nh);
  // The private namespace is the node's name; its parent the node's namespace.
  const std::string& node_name = private_nh.getNamespace();
  return parseNodeConfig(
      params, fit_urdf_links,
      app::defaultFleetRobotName(ros::names::parentNamespace(node_name), node_name));
}

}  // namespace ellipse_collision

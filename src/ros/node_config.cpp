#include "ellipse_collision/ros/node_config.h"

#include <ros/names.h>
#include <ros/param.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/unique_names.h"
#include "ellipse_collision/ros/conversions.h"

namespace ellipse_collision {
namespace {

using XmlRpc::XmlRpcValue;

// Links and obstacles alike; radius_z makes an ellipsoid (app::EllipsoidPart), z, roll, pitch
// optional with it.
const std::vector<std::string> kEllipseKeys = {"name",  "frame",    "x",        "y",
                                               "angle", "radius_x", "radius_y", "padding",
                                               "z",     "roll",     "pitch",    "radius_z"};

/// The first key of the dict `value` that is not one of `keys`, or nothing: every dict of the
/// configuration refuses unknown keys (a typo would otherwise be ignored silently).
std::optional<std::string> unknownKey(const XmlRpcValue& value,
                                      const std::vector<std::string>& keys) {
  XmlRpcValue copy = value;  // begin() and end() of XmlRpcValue are not const
  for (auto it = copy.begin(); it != copy.end(); ++it) {
    if (std::find(keys.begin(), keys.end(), it->first) == keys.end()) return it->first;
  }
  return std::nullopt;
}

std::string describeValue(const XmlRpcValue& value) {
  XmlRpcValue copy = value;  // the conversion operators of XmlRpcValue are not const
  switch (copy.getType()) {
    case XmlRpcValue::TypeBoolean:
      return std::string(static_cast<bool&>(copy) ? "true" : "false") + " (a bool)";
    case XmlRpcValue::TypeInt:
      return std::to_string(static_cast<int&>(copy)) + " (an int)";
    case XmlRpcValue::TypeDouble:
      return core::formatNumber(static_cast<double&>(copy)) + " (a double)";
    case XmlRpcValue::TypeString:
      return "'" + static_cast<std::string&>(copy) + "' (a string)";
    case XmlRpcValue::TypeArray:
      return "a list of " + std::to_string(copy.size());
    case XmlRpcValue::TypeStruct:
      return "a dict";
    case XmlRpcValue::TypeDateTime:
      return "a date";
    case XmlRpcValue::TypeBase64:
      return "binary data";
    case XmlRpcValue::TypeInvalid:
      break;
  }
  return "nothing";
}

[[noreturn]] void fail(const std::string& where, const std::string& key,
                       const std::string& expected, const std::string& actual) {
  throw ConfigError(describeConfigError(where, {key, expected, actual}));
}

/// A number, accepting ints where a double is expected (YAML `1` is an int).
double readNumber(const XmlRpcValue& value, const std::string& where, const std::string& key) {
  XmlRpcValue copy = value;
  if (copy.getType() == XmlRpcValue::TypeDouble) return static_cast<double&>(copy);
  if (copy.getType() == XmlRpcValue::TypeInt) return static_cast<int&>(copy);
  fail(where, key, "a number", describeValue(value));
}

std::string readString(const XmlRpcValue& value, const std::string& where, const std::string& key) {
  XmlRpcValue copy = value;
  if (copy.getType() != XmlRpcValue::TypeString) fail(where, key, "a string", describeValue(value));
  return static_cast<std::string&>(copy);
}

bool readBool(const XmlRpcValue& value, const std::string& where, const std::string& key) {
  XmlRpcValue copy = value;
  if (copy.getType() != XmlRpcValue::TypeBoolean) {
    fail(where, key, "true or false", describeValue(value));
  }
  return static_cast<bool&>(copy);
}

/// Renders a violation of the application layer's setting rules as a configuration error.
void failOn(const std::optional<app::FieldError>& error, const std::string& where) {
  if (error) fail(where, error->key, error->expected, error->actual);
}

/// A finite number >= 0 within [min, max] (or exactly 0 when zero_allowed, for "off"):
/// app::findOutsideSettingRange(). Refused, never clamped.
double readInRange(const XmlRpcValue& value, const std::string& where, const std::string& key,
                   double min, double max, bool zero_allowed = false) {
  const double number = readNumber(value, where, key);
  failOn(app::findOutsideSettingRange(key, number, min, max, zero_allowed), where);
  return number;
}

/// Top-level scalar parameter `key` ("rate") in its range from the one table,
/// app::settingRange(): the same rule reconfigure applies.
double readSetting(const XmlRpcValue& root, const std::string& key) {
  const std::string where = "parameter ~" + key;
  const double number = readNumber(root[key], where, key);
  failOn(app::findOutsideSettingRange(key, number), where);
  return number;
}

/// A whole number within [1, max] (YAML `100000` is an int; 1e5 as a double is accepted if whole).
double readWhole(const XmlRpcValue& value, const std::string& where, const std::string& key,
                 double max) {
  const double number = readInRange(value, where, key, 1.0, max);
  if (number != std::floor(number)) fail(where, key, "a whole number", core::formatNumber(number));
  return number;
}

std::string readFrame(const XmlRpcValue& value, const std::string& where, const std::string& key) {
  const std::string frame = readString(value, where, key);
  if (frame.empty()) fail(where, key, "a non-empty tf frame id", "''");
  if (frame.front() == '/') {
    fail(where, key, "a tf2 frame id without a leading '/'", "'" + frame + "'");
  }
  return frame;
}

app::EllipseSpec readEllipse(const XmlRpcValue& entry, const std::string& where,
                             double global_padding) {
  if (entry.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError(where + ": expected a dict with keys " + app::joinText(kEllipseKeys, ", ") +
                      ", got " + describeValue(entry));
  }
  // Name the entry by its name as soon as there is one, so the message points at the YAML.
  std::string label = where;
  if (entry.hasMember("name") && entry["name"].getType() == XmlRpcValue::TypeString) {
    label = where + " (name '" + readString(entry["name"], where, "name") + "')";
  }
  if (const auto key = unknownKey(entry, kEllipseKeys)) {
    throw ConfigError(label + ": unknown key '" + *key + "' (expected one of " +
                      app::joinText(kEllipseKeys, ", ") + ")");
  }
  const bool ellipsoid = entry.hasMember("z") || entry.hasMember("roll") ||
                         entry.hasMember("pitch") || entry.hasMember("radius_z");
  if (ellipsoid && !entry.hasMember("radius_z")) {
    throw ConfigError(label +
                      ": missing key 'radius_z' (z, roll and pitch describe an ellipsoid, "
                      "which needs radius_z)");
  }
  for (const char* key : {"name", "frame", "x", "y", "angle", "radius_x", "radius_y"}) {
    if (!entry.hasMember(key)) {
      throw ConfigError(label + ": missing key '" + key +
                        "' (required: name, frame, x, y, angle, radius_x, radius_y; padding is "
                        "optional, radius_z with optional z, roll, pitch makes an ellipsoid)");
    }
  }

  app::EllipseSpec spec;
  spec.name = readString(entry["name"], label, "name");
  spec.frame_id = readString(entry["frame"], label, "frame");
  spec.x = readNumber(entry["x"], label, "x");
  spec.y = readNumber(entry["y"], label, "y");
  spec.angle = readNumber(entry["angle"], label, "angle");
  spec.radius_x = readNumber(entry["radius_x"], label, "radius_x");
  spec.radius_y = readNumber(entry["radius_y"], label, "radius_y");
  if (entry.hasMember("padding")) spec.padding = readNumber(entry["padding"], label, "padding");
  if (ellipsoid) {
    app::EllipsoidPart part;
    part.radius_z = readNumber(entry["radius_z"], label, "radius_z");
    if (entry.hasMember("z")) part.z = readNumber(entry["z"], label, "z");
    if (entry.hasMember("roll")) part.roll = readNumber(entry["roll"], label, "roll");
    if (entry.hasMember("pitch")) part.pitch = readNumber(entry["pitch"], label, "pitch");
    spec.ellipsoid = part;
  }
  if (const auto invalid = app::findInvalidPaddedField(spec, global_padding, "frame")) {
    fail(label, invalid->key, invalid->expected, invalid->actual);
  }
  return spec;
}

std::vector<app::EllipseSpec> readEllipseList(const XmlRpcValue& list, const std::string& key,
                                              double global_padding) {
  if (list.getType() != XmlRpcValue::TypeArray) {
    fail("parameter ~" + key, key, "a list of ellipses", describeValue(list));
  }
  std::vector<app::EllipseSpec> specs;
  for (int i = 0; i < list.size(); ++i) {
    specs.push_back(readEllipse(list[i], app::entryName(key, i), global_padding));
  }
  return specs;
}

std::vector<std::pair<std::string, std::string>> readAllowedPairs(
    const XmlRpcValue& list, const std::map<std::string, std::string>& defined) {
  const std::string key = "allowed_pairs";
  if (list.getType() != XmlRpcValue::TypeArray) {
    fail("parameter ~" + key, key, "a list of [name_a, name_b]", describeValue(list));
  }
  std::vector<std::pair<std::string, std::string>> pairs;
  for (int i = 0; i < list.size(); ++i) {
    const std::string where = app::entryName(key, i);
    const XmlRpcValue& pair = list[i];
    if (pair.getType() != XmlRpcValue::TypeArray || pair.size() != 2) {
      throw ConfigError(where + ": expected a list of two names [name_a, name_b], got " +
                        describeValue(pair));
    }
    std::string names[2];
    for (int k = 0; k < 2; ++k) {
      const std::string element = app::entryName(where, k);
      XmlRpcValue copy = pair[k];
      if (copy.getType() != XmlRpcValue::TypeString) {
        throw ConfigError(element + ": expected a link or obstacle name, got " +
                          describeValue(copy));
      }
      names[k] = static_cast<std::string&>(copy);
      if (!defined.count(names[k])) {
        throw ConfigError(
            element + " = '" + names[k] +
            "': expected the name of a configured link or obstacle, got an unknown name");
      }
    }
    if (names[0] == names[1]) {
      throw ConfigError(where + ": expected two different names, got '" + names[0] + "' twice");
    }
    pairs.emplace_back(names[0], names[1]);
  }
  return pairs;
}

/// `links_from_urdf: {param, links, padding, shape}` -> the fitted link ellipses.
app::LinkFitResult readLinksFromUrdf(const XmlRpcValue& value,
                                     const UrdfLinkFitter& fit_urdf_links) {
  const std::string where = "parameter ~links_from_urdf";
  if (value.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError(where + ": expected a dict {param, links, padding, shape}, got " +
                      describeValue(value));
  }
  static const std::vector<std::string> kUrdfKeys = {"param", "links", "padding", "shape"};
  if (const auto key = unknownKey(value, kUrdfKeys)) {
    throw ConfigError(where + ": unknown key '" + *key + "' (expected one of " +
                      app::joinText(kUrdfKeys, ", ") + ")");
  }
  std::string param = "robot_description";
  if (value.hasMember("param")) {
    param = readString(value["param"], where, "param");
    if (param.empty()) fail(where, "param", "a parameter name", "''");
  }
  app::LinkFitOptions options;
  if (value.hasMember("links")) {
    const XmlRpcValue& links = value["links"];
    if (links.getType() != XmlRpcValue::TypeArray) {
      fail(where, "links", "a list of link names", describeValue(links));
    }
    for (int i = 0; i < links.size(); ++i) {
      options.links.push_back(readString(links[i], where, app::entryName("links", i)));
    }
  }
  if (value.hasMember("padding")) {
    // The links' own padding keeps the range of the global one.
    const app::SettingRange& padding = app::settingRange("padding");
    options.padding = readInRange(value["padding"], where, "padding", padding.min, padding.max);
  }
  if (value.hasMember("shape")) {
    const std::string name = readString(value["shape"], where, "shape");
    const std::optional<app::LinkShape> shape = app::linkShapeNamed(name);
    if (!shape) fail(where, "shape", app::kLinkShapeNames, "'" + name + "'");
    options.shape = *shape;
  }
  if (!fit_urdf_links) throw ConfigError(where + ": no URDF reader in this program");
  try {
    return fit_urdf_links(param, options);
  } catch (const std::runtime_error& error) {
    throw ConfigError(where + ": " + error.what());
  }
}

/// `gate: {enabled, robot_frame, horizon, ...}`: types here, ranges by
/// app::findInvalidGateSetting().
app::GateConfig readGate(const XmlRpcValue& value) {
  const std::string where = "parameter ~gate";
  if (value.getType() != XmlRpcValue::TypeStruct) {
    fail(where, "gate", "a dict of gate parameters", describeValue(value));
  }
  static const std::vector<std::string> kGateKeys = {"enabled",
                                                     "robot_frame",
                                                     "horizon",
                                                     "time_before_collision",
                                                     "stop_time",
                                                     "margin",
                                                     "resolution",
                                                     "cmd_vel_timeout",
                                                     "on_incomplete",
                                                     "max_linear_speed",
                                                     "max_angular_speed",
                                                     "reaction_time",
                                                     "max_linear_deceleration",
                                                     "max_angular_deceleration",
                                                     "odom_topic"};
  if (const auto key = unknownKey(value, kGateKeys)) {
    throw ConfigError("parameter ~gate/" + *key + ": unknown key (expected one of " +
                      app::joinText(kGateKeys, ", ") + ")");
  }
  app::GateConfig gate;
  if (value.hasMember("enabled")) gate.enabled = readBool(value["enabled"], where, "gate/enabled");
  if (value.hasMember("robot_frame")) {
    gate.robot_frame = readString(value["robot_frame"], where, "gate/robot_frame");
  }
  for (const auto& [key, field] : {std::pair<const char*, double*>{"horizon", &gate.timing.horizon},
                                   {"time_before_collision", &gate.timing.time_before_collision},
                                   {"stop_time", &gate.timing.stop_time},
                                   {"margin", &gate.timing.margin},
                                   {"resolution", &gate.timing.resolution},
                                   {"cmd_vel_timeout", &gate.cmd_vel_timeout_s},
                                   {"max_linear_speed", &gate.max_linear_speed},
                                   {"max_angular_speed", &gate.max_angular_speed},
                                   {"reaction_time", &gate.base.reaction_time},
                                   {"max_linear_deceleration", &gate.base.linear_deceleration},
                                   {"max_angular_deceleration", &gate.base.angular_deceleration}}) {
    if (value.hasMember(key)) *field = readNumber(value[key], where, std::string("gate/") + key);
  }
  if (value.hasMember("odom_topic")) {
    gate.odom_topic = readString(value["odom_topic"], where, "gate/odom_topic");
  }
  if (value.hasMember("on_incomplete")) {
    const std::string policy = readString(value["on_incomplete"], where, "gate/on_incomplete");
    failOn(app::parseOnIncomplete(policy, &gate.on_incomplete), where);
  }
  if (const auto invalid = app::findInvalidGateSetting(gate)) {
    fail(where, invalid->key, invalid->expected, invalid->actual);
  }
  return gate;
}

/// `fleet: {enabled, topic, frame, robot_name, rate}`: types here, ranges by
/// app::findInvalidSetting().
app::FleetSettings readFleet(const XmlRpcValue& value, const std::string& default_robot_name) {
  const std::string where = "parameter ~fleet";
  if (value.getType() != XmlRpcValue::TypeStruct) {
    fail(where, "fleet", "a dict {enabled, topic, frame, robot_name, rate}", describeValue(value));
  }
  static const std::vector<std::string> kFleetKeys = {"enabled", "topic", "frame", "robot_name",
                                                      "rate"};
  if (const auto key = unknownKey(value, kFleetKeys)) {
    throw ConfigError("parameter ~fleet/" + *key + ": unknown key (expected one of " +
                      app::joinText(kFleetKeys, ", ") + ")");
  }
  app::FleetSettings fleet;
  fleet.robot_name = default_robot_name;
  if (value.hasMember("enabled"))
    fleet.enabled = readBool(value["enabled"], where, "fleet/enabled");
  if (value.hasMember("topic")) fleet.topic = readString(value["topic"], where, "fleet/topic");
  if (value.hasMember("frame")) fleet.frame = readString(value["frame"], where, "fleet/frame");
  if (value.hasMember("robot_name")) {
    fleet.robot_name = readString(value["robot_name"], where, "fleet/robot_name");
  }
  if (value.hasMember("rate")) fleet.rate = readNumber(value["rate"], where, "fleet/rate");
  return fleet;
}

/// `incident: {enabled, before, after, ...}`: types here, ranges by
/// app::findInvalidIncidentSetting().
app::IncidentSettings readIncident(const XmlRpcValue& value) {
  const std::string where = "parameter ~incident";
  if (value.getType() != XmlRpcValue::TypeStruct) {
    fail(where, "incident", "a dict of incident parameters", describeValue(value));
  }
  static const std::vector<std::string> kIncidentKeys = {
      "enabled",      "before",    "after",         "actions",
      "min_interval", "max_files", "max_megabytes", "directory"};
  if (const auto key = unknownKey(value, kIncidentKeys)) {
    throw ConfigError("parameter ~incident/" + *key + ": unknown key (expected one of " +
                      app::joinText(kIncidentKeys, ", ") + ")");
  }
  app::IncidentSettings incident;
  if (value.hasMember("enabled")) {
    incident.enabled = readBool(value["enabled"], where, "incident/enabled");
  }
  for (const auto& [key, field] : {std::pair<const char*, double*>{"before", &incident.before_s},
                                   {"after", &incident.after_s},
                                   {"min_interval", &incident.min_interval_s},
                                   {"max_megabytes", &incident.max_megabytes}}) {
    if (value.hasMember(key))
      *field = readNumber(value[key], where, std::string("incident/") + key);
  }
  if (value.hasMember("max_files")) {
    incident.max_files = static_cast<std::size_t>(
        readWhole(value["max_files"], where, "incident/max_files", app::kMaxIncidentFiles));
  }
  if (value.hasMember("directory")) {
    incident.directory = readString(value["directory"], where, "incident/directory");
  }
  if (value.hasMember("actions")) {
    XmlRpcValue list = value["actions"];
    if (list.getType() != XmlRpcValue::TypeArray) {
      fail(where, "incident/actions", "a list of gate actions", describeValue(list));
    }
    std::vector<std::string> names;
    for (int i = 0; i < list.size(); ++i) {
      names.push_back(readString(list[i], where, "incident/actions[" + std::to_string(i) + "]"));
    }
    failOn(app::parseIncidentActions(names, &incident.actions), where);
  }
  failOn(app::findInvalidIncidentSetting(incident), where);
  return incident;
}

/// scan_obstacles' keys, in a node's private namespace or in a scan source's entry.
const std::vector<std::string> kScanKeys = {"cluster_distance",
                                            "min_cluster_points",
                                            "min_radius",
                                            "range_noise_sigma",
                                            "free_space_tolerance",
                                            "z_min",
                                            "z_max",
                                            "name_prefix"};

/// The scan keys `root` holds into `settings` (types only: the ranges are findInvalidSetting()'s).
/// `where(key)` names the place in messages, `prefix` + key the key.
void readScanSettings(const XmlRpcValue& root,
                      const std::function<std::string(const std::string&)>& where,
                      app::ScanObstacleSettings* settings, const std::string& prefix = "") {
  for (const auto& [key, field] :
       {std::pair<const char*, double*>{"cluster_distance", &settings->cluster_distance},
        {"min_radius", &settings->min_radius},
        {"range_noise_sigma", &settings->range_noise_sigma},
        {"free_space_tolerance", &settings->free_space_tolerance},
        {"z_min", &settings->z_min},
        {"z_max", &settings->z_max}}) {
    if (root.hasMember(key)) *field = readNumber(root[key], where(key), prefix + key);
  }
  if (root.hasMember("min_cluster_points")) {
    XmlRpcValue value = root["min_cluster_points"];
    if (value.getType() != XmlRpcValue::TypeInt) {
      fail(where("min_cluster_points"), prefix + "min_cluster_points", "an integer",
           describeValue(value));
    }
    settings->min_cluster_points = static_cast<int&>(value);
  }
  if (root.hasMember("name_prefix")) {
    settings->name_prefix =
        readString(root["name_prefix"], where("name_prefix"), prefix + "name_prefix");
  }
}

/// A `tracking` dict into `settings` (types only: the ranges are findInvalidSetting()'s); keys
/// read as `prefix` + "tracking/" + key, `where(that)` names the place.
void readTracking(const XmlRpcValue& root,
                  const std::function<std::string(const std::string&)>& where,
                  const std::string& prefix, app::TrackingSettings* settings) {
  const std::string base = prefix + "tracking";
  if (root.getType() != XmlRpcValue::TypeStruct)
    fail(where(base), base, "a dict", describeValue(root));
  static const std::vector<std::string> kKeys = {"enabled",       "fixed_frame",   "max_speed",
                                                 "max_size",      "confirm_count", "min_speed",
                                                 "position_sigma"};
  if (const auto unknown = unknownKey(root, kKeys)) {
    const std::string key = base + "/" + *unknown;
    fail(where(key), key, "one of " + app::joinText(kKeys, ", "), "an unknown key");
  }
  const auto key = [&](const char* k) { return base + "/" + k; };
  if (root.hasMember("enabled")) {
    settings->enabled = readBool(root["enabled"], where(key("enabled")), key("enabled"));
  }
  if (root.hasMember("fixed_frame")) {
    settings->fixed_frame =
        readString(root["fixed_frame"], where(key("fixed_frame")), key("fixed_frame"));
  }
  for (const auto& [name, field] :
       {std::pair<const char*, double*>{"max_speed", &settings->max_speed},
        {"max_size", &settings->max_size},
        {"min_speed", &settings->min_speed},
        {"position_sigma", &settings->position_sigma}}) {
    if (root.hasMember(name)) *field = readNumber(root[name], where(key(name)), key(name));
  }
  if (root.hasMember("confirm_count")) {
    XmlRpcValue value = root["confirm_count"];
    if (value.getType() != XmlRpcValue::TypeInt) {
      fail(where(key("confirm_count")), key("confirm_count"), "an integer", describeValue(value));
    }
    settings->confirm_count = static_cast<int&>(value);
  }
}

/// `sources`: a list of {name, type, topic, timeout, <scan keys for types scan and cloud,
/// min_radius for range, required for robots>}; types and required keys here, every value rule
/// in app::findInvalidSources(). A robots source's topic defaults to `fleet_topic`, its timeout
/// to app::kDefaultRobotsTimeoutS.
std::vector<app::SourceSpec> readSources(const XmlRpcValue& list, const std::string& fixed_frame,
                                         const std::string& fleet_topic) {
  const std::string where = "parameter ~sources";
  if (list.getType() != XmlRpcValue::TypeArray) {
    fail(where, "sources", "a list of {name, type, topic, timeout, ...}", describeValue(list));
  }
  static const std::vector<std::string> kSourceKeys = {"name", "type", "topic", "timeout"};
  std::vector<std::string> scan_source_keys = kSourceKeys;
  scan_source_keys.insert(scan_source_keys.end(), kScanKeys.begin(), kScanKeys.end());
  scan_source_keys.push_back("tracking");
  std::vector<std::string> range_source_keys = kSourceKeys;
  range_source_keys.push_back("min_radius");
  std::vector<std::string> robots_source_keys = kSourceKeys;
  robots_source_keys.push_back("required");
  std::vector<app::SourceSpec> sources;
  for (int i = 0; i < list.size(); ++i) {
    const std::string entry = app::entryName("sources", i);
    const XmlRpcValue& value = list[i];
    if (value.getType() != XmlRpcValue::TypeStruct) {
      fail(where, entry, "a dict {name, type, topic, timeout, ...}", describeValue(value));
    }
    for (const char* required : {"name", "type"}) {
      if (!value.hasMember(required)) {
        fail(where, entry + "." + required, "a value (required)", "nothing");
      }
    }
    app::SourceSpec source;
    source.name = readString(value["name"], where, entry + ".name");
    const std::string type = readString(value["type"], where, entry + ".type");
    failOn(app::parseSourceType(type, entry + ".type", &source.type), where);
    const bool robots = source.type == app::SourceType::Robots;
    if (value.hasMember("topic")) {
      source.topic = readString(value["topic"], where, entry + ".topic");
    } else if (robots) {
      source.topic = fleet_topic;
    } else {
      fail(where, entry + ".topic", "a value (required)", "nothing");
    }
    if (robots) source.timeout_s = app::kDefaultRobotsTimeoutS;
    if (value.hasMember("timeout")) {
      source.timeout_s = readNumber(value["timeout"], where, entry + ".timeout");
    }
    const std::vector<std::string>& keys = source.type == app::SourceType::Ellipses ? kSourceKeys
                                           : source.type == app::SourceType::Range
                                               ? range_source_keys
                                           : robots ? robots_source_keys
                                                    : scan_source_keys;
    if (const auto key = unknownKey(value, keys)) {
      fail(where, entry + "." + *key,
           "one of " + app::joinText(keys, ", ") + " (type " + type + ")", "an unknown key");
    }
    if (value.hasMember("required")) {
      source.required = readBool(value["required"], where, entry + ".required");
    }
    if (source.type != app::SourceType::Ellipses && !robots) {
      readScanSettings(
          value, [&](const std::string&) { return where; }, &source.scan, entry + ".");
    }
    // Tracks live in the node's fixed frame unless the source says otherwise.
    source.tracking.fixed_frame = fixed_frame;
    if (value.hasMember("tracking")) {
      readTracking(
          value["tracking"], [&](const std::string&) { return where; }, entry + ".",
          &source.tracking);
    }
    sources.push_back(std::move(source));
  }
  failOn(app::findInvalidSources(sources), where);
  return sources;
}

}  // namespace

std::string describeConfigError(const std::string& where, const app::FieldError& error) {
  return where + ", key '" + error.key + "': expected " + error.expected + ", got " + error.actual;
}

app::MonitorSettings nodeMonitorDefaults() {
  app::MonitorSettings settings;
  settings.check.max_transform_age_s = 0.5;
  return settings;
}

NodeConfig parseNodeConfig(const XmlRpcValue& params, const UrdfLinkFitter& fit_urdf_links,
                           const std::string& default_robot_name) {
  XmlRpcValue root = params;
  if (root.getType() == XmlRpcValue::TypeInvalid) root = XmlRpcValue();
  if (root.getType() != XmlRpcValue::TypeInvalid && root.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError("private namespace: expected a dict of parameters, got " +
                      describeValue(root));
  }

  // Every key the node reads, in the order of config/ellipse_collision.yaml's documentation.
  static const std::vector<std::string> kKnownKeys = {"fixed_frame",
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
  if (root.getType() == XmlRpcValue::TypeStruct) {
    if (const auto key = unknownKey(root, kKnownKeys)) {
      throw ConfigError("parameter ~" + *key + ": unknown key (expected one of " +
                        app::joinText(kKnownKeys, ", ") + ")");
    }
  }
  const auto has = [&root](const char* key) {
    return root.getType() == XmlRpcValue::TypeStruct && root.hasMember(key);
  };

  NodeConfig config;
  if (has("fixed_frame")) {
    config.monitor.check.fixed_frame =
        readFrame(root["fixed_frame"], "parameter ~fixed_frame", "fixed_frame");
  }
  if (has("robot_frame")) {
    config.monitor.robot_frame =
        readFrame(root["robot_frame"], "parameter ~robot_frame", "robot_frame");
  }
  if (has("prediction_horizon")) {
    config.monitor.prediction_horizon_s = readSetting(root, "prediction_horizon");
  }
  if (has("rate")) {
    config.monitor.rate_hz = readSetting(root, "rate");
  }
  if (has("tf_timeout")) {
    config.tf_timeout_s = readSetting(root, "tf_timeout");
  }
  if (has("padding")) {
    config.monitor.check.global_padding_m = readSetting(root, "padding");
  }
  if (has("self_collision")) {
    config.monitor.check.rules.self_collision =
        readBool(root["self_collision"], "parameter ~self_collision", "self_collision");
  }
  if (has("warning_distance")) {
    config.monitor.check.rules.warning_distance = readSetting(root, "warning_distance");
  }
  if (has("max_transform_age")) {
    config.monitor.check.max_transform_age_s = readSetting(root, "max_transform_age");
  }
  if (has("obstacle_timeout")) {
    config.monitor.obstacle_timeout_s = readSetting(root, "obstacle_timeout");
  }
  if (has("max_obstacles")) {
    config.limits.max_obstacles = static_cast<std::size_t>(readWhole(
        root["max_obstacles"], "parameter ~max_obstacles", "max_obstacles", kMaxObstaclesLimit));
  }
  if (has("max_name_length")) {
    config.limits.max_name_length =
        static_cast<std::size_t>(readWhole(root["max_name_length"], "parameter ~max_name_length",
                                           "max_name_length", kMaxNameLengthLimit));
  }
  if (has("obstacle_store")) {
    config.obstacle_store =
        readString(root["obstacle_store"], "parameter ~obstacle_store", "obstacle_store");
  }
  if (has("obstacle_store_period")) {
    config.monitor.obstacle_store_period_s = readSetting(root, "obstacle_store_period");
  }
  if (has("marker_refresh_period")) {
    config.marker_refresh_period_s = readSetting(root, "marker_refresh_period");
  }
  if (has("gate")) config.monitor.gate = readGate(root["gate"]);
  config.fleet.robot_name = default_robot_name;
  if (has("fleet")) config.fleet = readFleet(root["fleet"], default_robot_name);
  if (const auto invalid = app::findInvalidSetting(config.fleet)) {
    fail("parameter ~fleet", invalid->key, invalid->expected, invalid->actual);
  }
  if (has("incident")) config.monitor.incident = readIncident(root["incident"]);
  if (has("sources")) {
    config.monitor.sources =
        readSources(root["sources"], config.monitor.check.fixed_frame, config.fleet.topic);
  }
  if (!has("links") && !has("links_from_urdf")) {
    throw ConfigError(
        "parameter ~links, key 'links': expected a list of ellipses (required unless "
        "links_from_urdf is given; may be []), got nothing (is the YAML loaded into the node's "
        "private namespace?)");
  }
  if (has("links"))
    config.links = readEllipseList(root["links"], "links", config.monitor.check.global_padding_m);
  if (has("links_from_urdf")) {
    const app::LinkFitResult fitted = readLinksFromUrdf(root["links_from_urdf"], fit_urdf_links);
    for (const app::EllipseSpec& spec : fitted.links) {
      if (const auto invalid =
              app::findInvalidPaddedField(spec, config.monitor.check.global_padding_m, "frame")) {
        fail("parameter ~links_from_urdf (link '" + spec.name + "')", invalid->key,
             invalid->expected, invalid->actual);
      }
      config.links.push_back(spec);
    }
    config.urdf_links_skipped = fitted.skipped;
  }
  if (has("obstacles")) {
    config.obstacles =
        readEllipseList(root["obstacles"], "obstacles", config.monitor.check.global_padding_m);
  }

  // Links and obstacles share one name space; each entry's own name is non-empty already.
  std::vector<std::pair<std::string, const app::EllipseSpec*>> entries;  // (where, spec)
  for (std::size_t i = 0; i < config.links.size(); ++i) {
    entries.emplace_back(app::entryName("links", i), &config.links[i]);
  }
  for (std::size_t i = 0; i < config.obstacles.size(); ++i) {
    entries.emplace_back(app::entryName("obstacles", i), &config.obstacles[i]);
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
  if (has("allowed_pairs")) {
    for (const auto& [a, b] : readAllowedPairs(root["allowed_pairs"], defined)) {
      config.monitor.check.rules.allowed.add(a, b);
    }
  }
  return config;
}

std::vector<app::EllipseSpec> parseEllipseList(const XmlRpcValue& list, const std::string& key,
                                               double global_padding) {
  return readEllipseList(list, key, global_padding);
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
  XmlRpcValue params;
  // Absent namespace: no parameters at all, which parseNodeConfig reports as a missing ~links.
  if (!ros::param::get(private_nh.getNamespace(), params)) params = XmlRpcValue();
  // The private namespace is the node's name; its parent the node's namespace.
  const std::string& node_name = private_nh.getNamespace();
  return parseNodeConfig(
      params, fit_urdf_links,
      app::defaultFleetRobotName(ros::names::parentNamespace(node_name), node_name));
}

app::ScanObstacleSettings parseScanObstacleSettings(const XmlRpcValue& params) {
  XmlRpcValue root = params;
  if (root.getType() == XmlRpcValue::TypeInvalid) return {};
  if (root.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError("private namespace: expected a dict of parameters, got " +
                      describeValue(root));
  }
  std::vector<std::string> keys = kScanKeys;
  keys.push_back("tracking");
  if (const auto key = unknownKey(root, keys)) {
    throw ConfigError("parameter ~" + *key + ": unknown key (expected one of " +
                      app::joinText(keys, ", ") + ")");
  }
  app::ScanObstacleSettings settings;
  readScanSettings(
      root, [](const std::string& key) { return "parameter ~" + key; }, &settings);
  if (const auto invalid = app::findInvalidSetting(settings)) {
    fail("parameter ~" + invalid->key, invalid->key, invalid->expected, invalid->actual);
  }
  return settings;
}

app::ScanObstacleSettings loadScanObstacleSettings(const ros::NodeHandle& private_nh) {
  XmlRpcValue params;
  if (!ros::param::get(private_nh.getNamespace(), params)) params = XmlRpcValue();
  return parseScanObstacleSettings(params);
}

app::TrackingSettings parseTrackingSettings(const XmlRpcValue& params) {
  app::TrackingSettings settings;
  if (params.getType() != XmlRpcValue::TypeStruct || !params.hasMember("tracking")) {
    return settings;
  }
  readTracking(
      params["tracking"], [](const std::string& key) { return "parameter ~" + key; }, "",
      &settings);
  if (const auto invalid = app::findInvalidSetting(settings)) {
    fail("parameter ~" + invalid->key, invalid->key, invalid->expected, invalid->actual);
  }
  return settings;
}

app::TrackingSettings loadTrackingSettings(const ros::NodeHandle& private_nh) {
  XmlRpcValue params;
  if (!ros::param::get(private_nh.getNamespace(), params)) params = XmlRpcValue();
  return parseTrackingSettings(params);
}

}  // namespace ellipse_collision

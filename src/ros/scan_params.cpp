#include "ellipse_collision/ros/scan_params.h"

#include <utility>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/ros/param_reading.h"

namespace ellipse_collision {
namespace params {

using XmlRpc::XmlRpcValue;

const std::vector<std::string>& scanKeys() {
  static const std::vector<std::string> keys = {"cluster_distance",
                                                "min_cluster_points",
                                                "min_radius",
                                                "range_noise_sigma",
                                                "free_space_tolerance",
                                                "z_min",
                                                "z_max",
                                                "name_prefix"};
  return keys;
}

void readScanSettings(const XmlRpcValue& root,
                      const std::function<std::string(const std::string&)>& where,
                      app::ScanObstacleSettings* settings, const std::string& prefix) {
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

}  // namespace params

using XmlRpc::XmlRpcValue;

app::ScanObstacleSettings parseScanObstacleSettings(const XmlRpcValue& private_namespace) {
  XmlRpcValue root = private_namespace;
  if (root.getType() == XmlRpcValue::TypeInvalid) return {};
  if (root.getType() != XmlRpcValue::TypeStruct) {
    throw ConfigError("private namespace: expected a dict of parameters, got " +
                      params::describeValue(root));
  }
  std::vector<std::string> keys = params::scanKeys();
  keys.push_back("tracking");
  params::refuseUnknownKeys(root, keys, "parameter ~");
  app::ScanObstacleSettings settings;
  params::readScanSettings(
      root, [](const std::string& key) { return "parameter ~" + key; }, &settings);
  if (const auto invalid = app::findInvalidSetting(settings)) {
    params::fail("parameter ~" + invalid->key, invalid->key, invalid->expected, invalid->actual);
  }
  return settings;
}

app::TrackingSettings parseTrackingSettings(const XmlRpcValue& private_namespace) {
  app::TrackingSettings settings;
  if (private_namespace.getType() != XmlRpcValue::TypeStruct ||
      !private_namespace.hasMember("tracking")) {
    return settings;
  }
  params::readTracking(
      private_namespace["tracking"], [](const std::string& key) { return "parameter ~" + key; }, "",
      &settings);
  if (const auto invalid = app::findInvalidSetting(settings)) {
    params::fail("parameter ~" + invalid->key, invalid->key, invalid->expected, invalid->actual);
  }
  return settings;
}

}  // namespace ellipse_collision

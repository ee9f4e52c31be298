#include <utility>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/ros/param_reading.h"
#include "ellipse_collision/ros/param_sections.h"
#include "ellipse_collision/ros/scan_params.h"

namespace ellipse_collision {
namespace params {

using XmlRpc::XmlRpcValue;

std::vector<app::SourceSpec> readSources(const XmlRpcValue& list, const std::string& fixed_frame,
                                         const std::string& fleet_topic) {
  const std::string where = "parameter ~sources";
  if (list.getType() != XmlRpcValue::TypeArray) {
    fail(where, "sources", "a list of {name, type, topic, timeout, ...}", describeValue(list));
  }
  static const std::vector<std::string> kSourceKeys = {"name", "type", "topic", "timeout"};
  std::vector<std::string> scan_source_keys = kSourceKeys;
  scan_source_keys.insert(scan_source_keys.end(), scanKeys().begin(), scanKeys().end());
  scan_source_keys.push_back("tracking");
  std::vector<std::string> range_source_keys = kSourceKeys;
  range_source_keys.push_back("min_radius");
  std::vector<std::string> robots_source_keys = kSourceKeys;
  robots_source_keys.push_back("required");
  robots_source_keys.push_back("padding");
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
    if (value.hasMember("padding")) {
      source.padding_m = readNumber(value["padding"], where, entry + ".padding");
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
}  // namespace params
}  // namespace ellipse_collision

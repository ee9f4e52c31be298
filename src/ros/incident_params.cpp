#include <utility>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/ros/param_reading.h"
#include "ellipse_collision/ros/param_sections.h"

namespace ellipse_collision {
namespace params {

using XmlRpc::XmlRpcValue;

app::IncidentSettings readIncident(const XmlRpcValue& value) {
  const std::string where = "parameter ~incident";
  if (value.getType() != XmlRpcValue::TypeStruct) {
    fail(where, "incident", "a dict of incident parameters", describeValue(value));
  }
  static const std::vector<std::string> kIncidentKeys = {
      "enabled",      "before",    "after",         "actions",
      "min_interval", "max_files", "max_megabytes", "directory"};
  refuseUnknownKeys(value, kIncidentKeys, "parameter ~incident/");
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
}  // namespace params
}  // namespace ellipse_collision

#include <utility>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/ros/param_reading.h"
#include "ellipse_collision/ros/param_sections.h"

namespace ellipse_collision {
namespace params {

using XmlRpc::XmlRpcValue;

app::FleetSettings readFleet(const XmlRpcValue& value, const std::string& default_robot_name) {
  const std::string where = "parameter ~fleet";
  if (value.getType() != XmlRpcValue::TypeStruct) {
    fail(where, "fleet", "a dict {enabled, topic, frame, robot_name, rate}", describeValue(value));
  }
  static const std::vector<std::string> kFleetKeys = {"enabled", "topic", "frame", "robot_name",
                                                      "rate"};
  refuseUnknownKeys(value, kFleetKeys, "parameter ~fleet/");
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
}  // namespace params
}  // namespace ellipse_collision

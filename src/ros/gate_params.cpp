#include <utility>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/ros/param_reading.h"
#include "ellipse_collision/ros/param_sections.h"

namespace ellipse_collision {
namespace params {

using XmlRpc::XmlRpcValue;

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
  refuseUnknownKeys(value, kGateKeys, "parameter ~gate/");
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
}  // namespace params
}  // namespace ellipse_collision

#include "ellipse_collision/ros/incident_bag.h"

#include <rosbag/bag.h>
#include <std_msgs/String.h>

#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "ellipse_collision/ros/conversions.h"

namespace ellipse_collision {
namespace {

Ellipse ellipseMsg(const core::NamedEllipse& placed, const std::string& frame) {
  Ellipse msg;
  msg.name = placed.name;
  msg.frame_id = frame;
  msg.x = placed.ellipse.center.x();
  msg.y = placed.ellipse.center.y();
  msg.angle = placed.ellipse.angle;
  msg.radius_x = placed.ellipse.radius_x;  // padding included: what the gate judged
  msg.radius_y = placed.ellipse.radius_y;
  return msg;
}

EllipseArray arrayMsg(const std::vector<core::NamedEllipse>& placed,
                      const std_msgs::Header& header) {
  EllipseArray msg;
  msg.header = header;
  msg.ellipses.reserve(placed.size());
  for (const core::NamedEllipse& p : placed) msg.ellipses.push_back(ellipseMsg(p, header.frame_id));
  return msg;
}

/// Every digit a double needs to be read back bit for bit (replay).
std::string exact(double value) {
  std::ostringstream out;
  out << std::setprecision(17) << value;
  return out.str();
}

/// A YAML single-quoted string.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

/// rosbag refuses times before ros::TIME_MIN (a decision at ROS time 0 in a fresh simulation).
ros::Time bagTime(double stamp_s) { return std::max(ros::Time(stamp_s), ros::TIME_MIN); }

}  // namespace

RecordedDecision toMsg(const app::RecordedDecision& recorded, const std::string& fixed_frame,
                       bool with_obstacles) {
  RecordedDecision msg;
  msg.header.stamp = bagTime(recorded.stamp_s);
  msg.header.frame_id = fixed_frame;
  msg.decision = toMsg(recorded.decision);
  msg.decision.header = msg.header;
  msg.judged_scene = recorded.judged_scene;
  msg.complete = recorded.complete;
  msg.robot.x = recorded.robot.position.x();
  msg.robot.y = recorded.robot.position.y();
  msg.robot.theta = recorded.robot.yaw;
  msg.links = arrayMsg(recorded.links, msg.header);
  msg.obstacle_set = recorded.obstacles->id;
  msg.obstacles_changed = with_obstacles;
  if (with_obstacles) {
    msg.obstacles = arrayMsg(recorded.obstacles->obstacles, msg.header);
  } else {
    msg.obstacles.header = msg.header;
  }
  for (const app::ObstacleMotion& m : recorded.motions) {
    msg.moving_obstacles.push_back(static_cast<std::uint32_t>(m.index));
    msg.moving_vx.push_back(m.motion.velocity.x());
    msg.moving_vy.push_back(m.motion.velocity.y());
    msg.moving_angular_velocity.push_back(m.motion.angular_velocity);
  }
  for (const auto& [name, age] : recorded.source_ages) {
    msg.source_names.push_back(name);
    msg.source_ages.push_back(age);
  }
  for (const auto& [name, age] : recorded.frame_ages) {
    msg.frame_names.push_back(name);
    msg.frame_ages.push_back(age);
  }
  return msg;
}

std::string incidentSettingsYaml(const app::Incident& incident, const app::GateConfig& gate,
                                 const app::CheckSettings& check) {
  std::ostringstream yaml;
  yaml << "trigger: " << quoted(incident.trigger) << "\n"
       << "trigger_time: " << exact(incident.trigger_s) << "\n"
       << "fixed_frame: " << quoted(check.fixed_frame) << "\n"
       << "padding: " << exact(check.global_padding_m) << "\n"
       << "self_collision: " << (check.rules.self_collision ? "true" : "false") << "\n"
       << "allowed_pairs: [";
  bool first = true;
  for (const auto& [a, b] : check.rules.allowed.pairs()) {
    yaml << (first ? "" : ", ") << "[" << quoted(a) << ", " << quoted(b) << "]";
    first = false;
  }
  yaml << "]\n"
       << "gate:\n"
       << "  enabled: " << (gate.enabled ? "true" : "false") << "\n"
       << "  robot_frame: " << quoted(gate.robot_frame) << "\n"
       << "  horizon: " << exact(gate.timing.horizon) << "\n"
       << "  time_before_collision: " << exact(gate.timing.time_before_collision) << "\n"
       << "  stop_time: " << exact(gate.timing.stop_time) << "\n"
       << "  margin: " << exact(gate.timing.margin) << "\n"
       << "  resolution: " << exact(gate.timing.resolution) << "\n"
       << "  cmd_vel_timeout: " << exact(gate.cmd_vel_timeout_s) << "\n"
       << "  on_incomplete: " << app::toString(gate.on_incomplete) << "\n"
       << "  max_linear_speed: " << exact(gate.max_linear_speed) << "\n"
       << "  max_angular_speed: " << exact(gate.max_angular_speed) << "\n"
       << "  reaction_time: " << exact(gate.base.reaction_time) << "\n"
       << "  max_linear_deceleration: " << exact(gate.base.linear_deceleration) << "\n"
       << "  max_angular_deceleration: " << exact(gate.base.angular_deceleration) << "\n"
       << "  odom_topic: " << quoted(gate.odom_topic) << "\n";
  return yaml.str();
}

void writeIncidentBag(const std::string& path, const app::Incident& incident,
                      const std::string& settings_yaml, const std::string& fixed_frame) {
  try {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    std_msgs::String settings;
    settings.data = settings_yaml;
    const double first_s =
        incident.decisions.empty() ? incident.trigger_s : incident.decisions.front().stamp_s;
    bag.write("settings", bagTime(first_s), settings);
    std::uint64_t written_set = 0;  // none yet: the first decision carries its obstacles
    for (const app::RecordedDecision& recorded : incident.decisions) {
      const bool with_obstacles = recorded.obstacles->id != written_set;
      written_set = recorded.obstacles->id;
      const RecordedDecision msg = toMsg(recorded, fixed_frame, with_obstacles);
      bag.write("decisions", msg.header.stamp, msg);
    }
    bag.close();
  } catch (const std::exception& error) {
    std::remove(path.c_str());
    throw std::runtime_error(error.what());
  }
}

}  // namespace ellipse_collision

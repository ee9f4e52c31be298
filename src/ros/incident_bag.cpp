#include "ellipse_collision/ros/incident_bag.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <std_msgs/String.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "ellipse_collision/core/number_format.h"
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
    msg.moving_since.push_back(m.since_s);
  }
  for (const auto& [name, age] : recorded.source_ages) {
    msg.source_names.push_back(name);
    msg.source_ages.push_back(age);
  }
  for (const auto& [name, age] : recorded.frame_ages) {
    msg.frame_names.push_back(name);
    msg.frame_ages.push_back(age);
  }
  if (const auto& memory = recorded.memory) {
    msg.judged_by_rules = true;
    const core::Twist& v = memory->base.velocity;
    msg.base_velocity.linear.x = v.vx;
    msg.base_velocity.linear.y = v.vy;
    msg.base_velocity.angular.z = v.wz;
    msg.command_period = memory->base.command_period;
    msg.world_revision = memory->world_revision;
    if (const auto& hold = memory->hold) {
      msg.hold_active = true;
      msg.hold_input = toMsg(hold->input);
      msg.hold_scale = hold->scale;
      msg.hold_world_revision = hold->world_revision;
      msg.hold_free_distance = hold->free_distance_m;
    }
  }
  return msg;
}

std::string incidentSettingsYaml(const app::Incident& incident, const app::GateConfig& gate,
                                 const app::CheckSettings& check) {
  std::ostringstream yaml;
  yaml << "format: " << kIncidentBagFormat << "\n"
       << "trigger: " << quoted(incident.trigger) << "\n"
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

namespace {

/// The `key: value` lines of the settings YAML as incidentSettingsYaml() writes them, the keys of
/// the `gate:` block as "gate/horizon". Not a YAML parser: the format is this file's own.
std::map<std::string, std::string> settingsLines(const std::string& yaml) {
  std::map<std::string, std::string> values;
  std::istringstream lines(yaml);
  std::string line;
  std::string block;
  while (std::getline(lines, line)) {
    const std::size_t colon = line.find(':');
    if (line.empty() || colon == std::string::npos) continue;
    const bool indented = line.rfind("  ", 0) == 0;
    const std::size_t start = line.find_first_not_of(' ');
    const std::string key = line.substr(start, colon - start);
    std::string value = colon + 1 < line.size() ? line.substr(colon + 1) : "";
    value.erase(0, value.find_first_not_of(' '));
    if (!indented && value.empty()) {
      block = key + "/";
      continue;
    }
    values[(indented ? block : std::string()) + key] = value;
  }
  return values;
}

/// The single-quoted YAML strings in `text`, in order ('' is a quote).
std::vector<std::string> quotedStrings(const std::string& text) {
  std::vector<std::string> strings;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\'') continue;
    std::string value;
    for (++i; i < text.size(); ++i) {
      if (text[i] == '\'' && i + 1 < text.size() && text[i + 1] == '\'') {
        value += '\'';
        ++i;
      } else if (text[i] == '\'') {
        break;
      } else {
        value += text[i];
      }
    }
    strings.push_back(value);
  }
  return strings;
}

class SettingsReader {
 public:
  explicit SettingsReader(const std::string& yaml) : values_(settingsLines(yaml)) {}

  const std::string& error() const { return error_; }
  bool has(const std::string& key) const { return values_.count(key) != 0; }

  double number(const std::string& key) {
    const std::string* text = raw(key);
    if (!text) return 0.0;
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(text->c_str(), &end);
    if (text->empty() || *end != '\0' || errno == ERANGE) fail(key, *text, "a number");
    return value;
  }
  bool flag(const std::string& key) {
    const std::string* text = raw(key);
    if (!text) return false;
    if (*text != "true" && *text != "false") fail(key, *text, "true or false");
    return *text == "true";
  }
  std::string text(const std::string& key) {
    const std::string* value = raw(key);
    if (!value) return "";
    const std::vector<std::string> strings = quotedStrings(*value);
    if (strings.size() != 1) fail(key, *value, "a quoted string");
    return strings.empty() ? "" : strings[0];
  }
  const std::string* raw(const std::string& key) {
    const auto found = values_.find(key);
    if (found != values_.end()) return &found->second;
    if (error_.empty()) error_ = "settings: no '" + key + "'";
    return nullptr;
  }
  void fail(const std::string& key, const std::string& value, const std::string& expected) {
    if (error_.empty()) error_ = "settings: " + key + " = " + value + ": expected " + expected;
  }

 private:
  std::map<std::string, std::string> values_;
  std::string error_;
};

}  // namespace

std::string parseIncidentSettingsYaml(const std::string& yaml, app::ReplaySettings* settings) {
  SettingsReader in(yaml);
  if (!in.has("format")) {
    return "settings: no 'format': the bag was written before replay was possible (format 1); "
           "it holds no base velocity or hold state to judge its decisions again with";
  }
  const double format = in.number("format");
  if (in.error().empty() && format != kIncidentBagFormat) {
    return "settings: format = " + core::formatNumber(format) + ": this version replays format " +
           std::to_string(kIncidentBagFormat);
  }
  app::GateConfig& gate = settings->gate;
  gate.enabled = in.flag("gate/enabled");
  gate.robot_frame = in.text("gate/robot_frame");
  gate.timing.horizon = in.number("gate/horizon");
  gate.timing.time_before_collision = in.number("gate/time_before_collision");
  gate.timing.stop_time = in.number("gate/stop_time");
  gate.timing.margin = in.number("gate/margin");
  gate.timing.resolution = in.number("gate/resolution");
  gate.cmd_vel_timeout_s = in.number("gate/cmd_vel_timeout");
  gate.max_linear_speed = in.number("gate/max_linear_speed");
  gate.max_angular_speed = in.number("gate/max_angular_speed");
  gate.base.reaction_time = in.number("gate/reaction_time");
  gate.base.linear_deceleration = in.number("gate/max_linear_deceleration");
  gate.base.angular_deceleration = in.number("gate/max_angular_deceleration");
  gate.odom_topic = in.text("gate/odom_topic");
  if (const std::string* policy = in.raw("gate/on_incomplete")) {
    if (const auto invalid = app::parseOnIncomplete(*policy, &gate.on_incomplete)) {
      return app::describeFieldError("settings", *invalid);
    }
  }
  const std::string* pairs = in.raw("allowed_pairs");
  if (!in.error().empty()) return in.error();
  const std::vector<std::string> names = quotedStrings(*pairs);
  if (names.size() % 2 != 0) {
    return "settings: allowed_pairs = " + *pairs + ": expected a list of pairs of names";
  }
  for (std::size_t i = 0; i < names.size(); i += 2) settings->allowed.add(names[i], names[i + 1]);
  if (const auto invalid = app::findInvalidGateSetting(gate)) {
    return app::describeFieldError("settings", *invalid);
  }
  return "";
}

namespace {

core::NamedEllipse placedEllipse(const Ellipse& msg, core::EllipseRole role) {
  core::Ellipse e;
  e.center = Eigen::Vector2d(msg.x, msg.y);
  e.angle = msg.angle;
  e.radius_x = msg.radius_x;
  e.radius_y = msg.radius_y;
  return {msg.name, role, e};
}

/// The decision `msg` (number `index` of the bag) with the obstacles of its set (`last`, read
/// from an earlier decision unless it carries them); the error naming the field, or "".
std::string decisionFromMsg(const RecordedDecision& msg, std::size_t index,
                            std::shared_ptr<const app::ObstacleSnapshot>* last,
                            app::RecordedDecision* recorded) {
  const std::string where = "decisions[" + std::to_string(index) + "].";
  recorded->stamp_s = msg.header.stamp.toSec();
  if (!fromMsg(msg.decision, &recorded->decision)) {
    return where + "decision.action = '" + msg.decision.action + "': expected a gate action";
  }
  recorded->judged_scene = msg.judged_scene;
  recorded->complete = msg.complete;
  recorded->robot.position = Eigen::Vector2d(msg.robot.x, msg.robot.y);
  recorded->robot.yaw = msg.robot.theta;
  for (const Ellipse& link : msg.links.ellipses) {
    recorded->links.push_back(placedEllipse(link, core::EllipseRole::Link));
  }
  if (msg.obstacles_changed) {
    auto snapshot = std::make_shared<app::ObstacleSnapshot>();
    snapshot->id = msg.obstacle_set;
    for (const Ellipse& obstacle : msg.obstacles.ellipses) {
      snapshot->obstacles.push_back(placedEllipse(obstacle, core::EllipseRole::Obstacle));
    }
    *last = std::move(snapshot);
  } else if (msg.obstacle_set != (*last)->id) {
    return where + "obstacle_set = " + std::to_string(msg.obstacle_set) +
           ": expected the set of an earlier decision (" + std::to_string((*last)->id) +
           ") or obstacles_changed";
  }
  recorded->obstacles = *last;
  const std::size_t moving = msg.moving_obstacles.size();
  if (msg.moving_vx.size() != moving || msg.moving_vy.size() != moving ||
      msg.moving_angular_velocity.size() != moving || msg.moving_since.size() != moving) {
    return where + "moving_vx, moving_vy, moving_angular_velocity, moving_since: expected " +
           std::to_string(moving) + " each, as moving_obstacles";
  }
  for (std::size_t i = 0; i < moving; ++i) {
    if (msg.moving_obstacles[i] >= (*last)->obstacles.size()) {
      return where + "moving_obstacles[" + std::to_string(i) +
             "] = " + std::to_string(msg.moving_obstacles[i]) + ": expected an index below " +
             std::to_string((*last)->obstacles.size()) + " (the set's obstacles)";
    }
    core::Motion motion;
    motion.velocity = Eigen::Vector2d(msg.moving_vx[i], msg.moving_vy[i]);
    motion.angular_velocity = msg.moving_angular_velocity[i];
    recorded->motions.push_back({msg.moving_obstacles[i], motion, msg.moving_since[i]});
  }
  if (msg.judged_by_rules) {
    app::GateMemory memory;
    memory.base.velocity = {msg.base_velocity.linear.x, msg.base_velocity.linear.y,
                            msg.base_velocity.angular.z};
    memory.base.command_period = msg.command_period;
    memory.world_revision = msg.world_revision;
    if (msg.hold_active) {
      memory.hold = app::GateHold{fromMsg(msg.hold_input), msg.hold_scale, msg.hold_world_revision,
                                  msg.hold_free_distance};
    }
    recorded->memory = memory;
  }
  return "";
}

}  // namespace

std::string readIncidentBag(const std::string& path, ReplayInput* input) {
  try {
    rosbag::Bag bag(path, rosbag::bagmode::Read);
    bool have_settings = false;
    for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery("settings"))) {
      const auto settings = m.instantiate<std_msgs::String>();
      if (!settings) return path + ": settings is a " + m.getDataType() + ", not std_msgs/String";
      const std::string error = parseIncidentSettingsYaml(settings->data, &input->settings);
      if (!error.empty()) return path + ": " + error;
      have_settings = true;
      break;
    }
    if (!have_settings) return path + ": no settings topic: not an incident bag";
    const std::string md5 = ros::message_traits::md5sum<RecordedDecision>();
    auto last = std::make_shared<const app::ObstacleSnapshot>();
    std::size_t index = 0;
    for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery("decisions"))) {
      if (m.getDataType() != ros::message_traits::datatype<RecordedDecision>() ||
          m.getMD5Sum() != md5) {
        return path + ": decisions are " + m.getDataType() + " (md5 " + m.getMD5Sum() +
               "), not the " + ros::message_traits::datatype<RecordedDecision>() + " (md5 " + md5 +
               ") this version replays: the bag is of another format";
      }
      const auto msg = m.instantiate<RecordedDecision>();
      app::RecordedDecision recorded;
      const std::string error = decisionFromMsg(*msg, index++, &last, &recorded);
      if (!error.empty()) return path + ": " + error;
      input->decisions.push_back(std::move(recorded));
    }
    bag.close();
  } catch (const std::exception& error) {
    return path + ": " + error.what();
  }
  return "";
}

}  // namespace ellipse_collision

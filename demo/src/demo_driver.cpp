#include "demo_driver.h"

#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/unique_names.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/messages.h"
#include "ellipse_collision/ros/node_config.h"

namespace ellipse_collision {
namespace {

bool isZero(const core::Twist& twist) {
  return twist.vx == 0.0 && twist.vy == 0.0 && twist.wz == 0.0;
}

std::string fullName(const ros::NodeHandle& nh, const std::string& key) {
  return nh.resolveName(key);
}

/// The keys of the dict parameter `key`, refusing any not in `allowed` so that a typo cannot
/// silently leave a default in place. `key` empty means the private namespace itself.
std::set<std::string> dictKeys(const ros::NodeHandle& nh, const std::string& key,
                               const std::set<std::string>& allowed) {
  XmlRpc::XmlRpcValue value;
  const std::string name = key.empty() ? nh.getNamespace() : fullName(nh, key);
  if (!ros::param::get(name, value) || value.getType() != XmlRpc::XmlRpcValue::TypeStruct) {
    throw DemoConfigError("parameter " + name + ": expected a dict, got " +
                          (value.valid() ? "another type" : "nothing"));
  }
  std::set<std::string> keys;
  for (auto it = value.begin(); it != value.end(); ++it) {
    if (!allowed.empty() && !allowed.count(it->first)) {
      std::string expected;
      for (const std::string& a : allowed) expected += (expected.empty() ? "" : ", ") + a;
      throw DemoConfigError("parameter " + name + "/" + it->first +
                            ": unknown key (expected one of " + expected + ")");
    }
    keys.insert(it->first);
  }
  return keys;
}

/// A finite number; roscpp accepts YAML ints here too.
double number(const ros::NodeHandle& nh, const std::string& key) {
  double value = 0.0;
  if (!nh.getParam(key, value)) {
    throw DemoConfigError("parameter " + fullName(nh, key) + ": expected a number, got " +
                          (nh.hasParam(key) ? "another type" : "nothing"));
  }
  if (!std::isfinite(value)) {
    throw DemoConfigError("parameter " + fullName(nh, key) + ": expected a finite number, got " +
                          core::formatNumber(value));
  }
  return value;
}

double positive(const ros::NodeHandle& nh, const std::string& key) {
  const double value = number(nh, key);
  if (!(value > 0.0)) {
    throw DemoConfigError("parameter " + fullName(nh, key) + ": expected a number > 0, got " +
                          core::formatNumber(value));
  }
  return value;
}

/// A list of [x, y] points [m], at least one.
std::vector<Eigen::Vector2d> pointList(const ros::NodeHandle& nh, const std::string& key) {
  XmlRpc::XmlRpcValue value;
  const std::string name = fullName(nh, key);
  if (!nh.getParam(key, value) || value.getType() != XmlRpc::XmlRpcValue::TypeArray ||
      value.size() == 0) {
    throw DemoConfigError("parameter " + name + ": expected a non-empty list of [x, y] points");
  }
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < value.size(); ++i) {
    const std::string entry = name + "[" + std::to_string(i) + "]";
    XmlRpc::XmlRpcValue& point = value[i];
    if (point.getType() != XmlRpc::XmlRpcValue::TypeArray || point.size() != 2) {
      throw DemoConfigError("parameter " + entry + ": expected [x, y]");
    }
    Eigen::Vector2d p;
    for (int k = 0; k < 2; ++k) {
      XmlRpc::XmlRpcValue& c = point[k];
      if (c.getType() == XmlRpc::XmlRpcValue::TypeInt) {
        p[k] = static_cast<int>(c);
      } else if (c.getType() == XmlRpc::XmlRpcValue::TypeDouble && std::isfinite(double(c))) {
        p[k] = static_cast<double>(c);
      } else {
        throw DemoConfigError("parameter " + entry + ": expected finite numbers [x, y]");
      }
    }
    points.push_back(p);
  }
  return points;
}

std::string frameOr(const ros::NodeHandle& nh, const std::string& key,
                    const std::string& fallback) {
  if (!nh.hasParam(key)) return fallback;
  std::string frame;
  if (!nh.getParam(key, frame) || frame.empty() || frame.front() == '/') {
    throw DemoConfigError("parameter " + fullName(nh, key) +
                          ": expected a tf2 frame id (non-empty, no leading '/')");
  }
  return frame;
}

}  // namespace

DemoDriver::DemoDriver(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
    : nh_(nh), private_nh_(private_nh) {
  const ros::NodeHandle& p = private_nh_;
  dictKeys(p, "",
           {"rate", "odom_frame", "base_frame", "start", "route", "drive", "back_off", "joints",
            "static_obstacles", "moving_obstacle", "scanner", "planned_path"});
  const double rate_hz = p.hasParam("rate") ? positive(p, "rate") : 30.0;
  odom_frame_ = frameOr(p, "odom_frame", "odom");
  base_frame_ = frameOr(p, "base_frame", "base_link");

  dictKeys(p, "start", {"x", "y", "yaw"});
  base_.position = {number(p, "start/x"), number(p, "start/y")};
  base_.yaw = number(p, "start/yaw");
  dictKeys(p, "drive", {"speed", "turn_rate", "heading_gain", "tolerance"});
  dictKeys(p, "back_off", {"blocked_time", "speed", "turn_rate", "duration"});
  DriveSettings drive;
  BackOffSettings back_off;
  // Every one > 0 but the back-off's turn rate, which may turn either way or not at all.
  for (const auto& [key, field] : {std::pair<const char*, double*>{"drive/speed", &drive.speed},
                                   {"drive/turn_rate", &drive.turn_rate},
                                   {"drive/heading_gain", &drive.heading_gain},
                                   {"drive/tolerance", &drive.tolerance},
                                   {"back_off/blocked_time", &back_off.blocked_time},
                                   {"back_off/speed", &back_off.speed},
                                   {"back_off/duration", &back_off.duration}}) {
    *field = positive(p, key);
  }
  back_off.turn_rate = number(p, "back_off/turn_rate");
  base_script_ = std::make_unique<BaseScript>(pointList(p, "route"), drive, back_off);

  for (const std::string& joint : dictKeys(p, "joints", {})) {
    const std::string key = "joints/" + joint;
    dictKeys(p, key, {"offset", "amplitude", "period", "phase"});
    NamedJointMotion motion;
    motion.joint = joint;
    motion.motion.offset = number(p, key + "/offset");
    motion.motion.amplitude = number(p, key + "/amplitude");
    motion.motion.period_s = positive(p, key + "/period");
    motion.motion.phase = number(p, key + "/phase");
    trajectory_.joints.push_back(motion);
  }

  const std::string o = "moving_obstacle";
  dictKeys(
      p, o,
      {"name", "radius_x", "radius_y", "angle", "start_x", "start_y", "end_x", "end_y", "period"});
  if (!p.getParam(o + "/name", moving_name_) || moving_name_.empty()) {
    throw DemoConfigError("parameter " + fullName(p, o + "/name") + ": expected a non-empty name");
  }
  world_.moving.radius_x = positive(p, o + "/radius_x");
  world_.moving.radius_y = positive(p, o + "/radius_y");
  world_.moving.angle = number(p, o + "/angle");
  world_.shuttle.start = {number(p, o + "/start_x"), number(p, o + "/start_y")};
  world_.shuttle.end = {number(p, o + "/end_x"), number(p, o + "/end_y")};
  world_.shuttle.period_s = positive(p, o + "/period");

  // The static obstacles, in the format of the collision node's `obstacles` (the same parser),
  // fixed in the odom frame; their names and the moving obstacle's are distinct.
  XmlRpc::XmlRpcValue static_list;
  if (!p.getParam("static_obstacles", static_list)) {
    throw DemoConfigError("parameter " + fullName(p, "static_obstacles") +
                          ": expected a list of ellipses, got nothing");
  }
  std::vector<app::EllipseSpec> statics;
  try {
    statics = parseEllipseList(static_list, "static_obstacles", 0.0);
  } catch (const ConfigError& error) {
    throw DemoConfigError(std::string(error.what()) + " (in " + p.getNamespace() + ")");
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < statics.size(); ++i) {
    const std::string where = fullName(p, "static_obstacles") + "[" + std::to_string(i) + "]";
    if (statics[i].frame_id != odom_frame_) {
      throw DemoConfigError("parameter " + where + "/frame: expected the odom frame '" +
                            odom_frame_ + "', got '" + statics[i].frame_id + "'");
    }
    names.push_back(statics[i].name);
    world_.static_obstacles.push_back(app::paddedEllipse(statics[i], 0.0));
  }
  names.push_back(moving_name_);
  if (const auto problem = core::findNameProblem(names)) {
    throw DemoConfigError("parameter " + fullName(p, "static_obstacles") + ": the name '" +
                          names[problem->index] + "' is given twice (static_obstacles and " +
                          o + "/name share one name space)");
  }

  scanner_frame_ = "laser";
  if (p.hasParam("scanner")) {
    dictKeys(p, "scanner", {"frame", "beams", "range_min", "range_max"});
    scanner_frame_ = frameOr(p, "scanner/frame", scanner_frame_);
    if (p.hasParam("scanner/beams")) {
      const double beams = positive(p, "scanner/beams");
      if (beams != std::floor(beams) || beams < 2 || beams > 100000) {
        throw DemoConfigError("parameter " + fullName(p, "scanner/beams") +
                              ": expected an integer within [2, 100000], got " +
                              core::formatNumber(beams));
      }
      scanner_.beams = static_cast<int>(beams);
      scanner_.angle_increment = 2.0 * M_PI / scanner_.beams;
    }
    if (p.hasParam("scanner/range_min")) scanner_.range_min = positive(p, "scanner/range_min");
    if (p.hasParam("scanner/range_max")) scanner_.range_max = positive(p, "scanner/range_max");
    if (!(scanner_.range_max > scanner_.range_min)) {
      throw DemoConfigError("parameter " + fullName(p, "scanner/range_max") +
                            ": expected a number > range_min");
    }
  }

  double check_rate_hz = 5.0;
  if (p.hasParam("planned_path")) {
    dictKeys(p, "planned_path", {"horizon", "step", "check_rate"});
    if (p.hasParam("planned_path/horizon"))
      planned_horizon_s_ = positive(p, "planned_path/horizon");
    if (p.hasParam("planned_path/step")) planned_step_s_ = positive(p, "planned_path/step");
    if (p.hasParam("planned_path/check_rate"))
      check_rate_hz = positive(p, "planned_path/check_rate");
    if (planned_horizon_s_ / planned_step_s_ > 10000.0) {
      throw DemoConfigError("parameter " + fullName(p, "planned_path/step") +
                            ": expected at most 10000 poses per plan (horizon / step)");
    }
  }
  planned_path_pub_ = nh_.advertise<nav_msgs::Path>("planned_path", 1);
  path_check_markers_pub_ =
      private_nh_.advertise<visualization_msgs::MarkerArray>("path_check_markers", 1, true);
  check_path_ = nh_.serviceClient<CheckPath>("ellipse_collision/check_path");
  path_check_timer_ =
      nh_.createTimer(ros::Duration(1.0 / check_rate_hz), &DemoDriver::onPathCheckTimer, this);

  joint_states_pub_ = nh_.advertise<sensor_msgs::JointState>("joint_states", 10);
  cmd_vel_pub_ = nh_.advertise<geometry_msgs::Twist>("cmd_vel", 1);
  gated_sub_ = nh_.subscribe("cmd_vel_gated", 1, &DemoDriver::onGatedCommand, this,
                             ros::TransportHints().tcpNoDelay());
  scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 10);
  pause_service_ = private_nh_.advertiseService("pause", &DemoDriver::onPause, this);

  started_ = ros::Time::now();
  launched_ = started_;
  last_cycle_ = started_;
  timer_ = nh_.createTimer(ros::Duration(1.0 / rate_hz), &DemoDriver::onTimer, this);
  ROS_INFO_STREAM("demo_driver: driving " << base_frame_ << " in " << odom_frame_
                                          << " through the gate (cmd_vel -> cmd_vel_gated), "
                                         << trajectory_.joints.size() << " joints and obstacle '"
                                         << moving_name_ << "' among "
                                         << world_.static_obstacles.size()
                                         << " static obstacles at " << rate_hz << " Hz");
}

double DemoDriver::demoTime(const ros::Time& now) const {
  return paused_ ? clock_at_start_s_ : clock_at_start_s_ + (now - started_).toSec();
}

bool DemoDriver::onPause(std_srvs::SetBool::Request& request,
                         std_srvs::SetBool::Response& response) {
  const ros::Time now = ros::Time::now();
  // Freeze or resume the clock where it stands, so the motion continues without a jump.
  clock_at_start_s_ = demoTime(now);
  started_ = now;
  paused_ = request.data;
  // Paused, the driver sends nothing and the base stands; resumed, it moves again only by a
  // gated command for a new command.
  gated_ = core::Twist();
  gated_since_command_ = false;
  response.success = true;
  response.message = std::string(paused_ ? "paused" : "running") + " at demo time " +
                     core::formatNumber(clock_at_start_s_) + " s";
  ROS_INFO_STREAM("demo_driver: " << response.message);
  return true;
}

void DemoDriver::onGatedCommand(const geometry_msgs::Twist& gated) {
  if (paused_) return;
  gated_.vx = gated.linear.x;
  gated_.vy = gated.linear.y;
  gated_.wz = gated.angular.z;
  gated_since_command_ = true;
}

void DemoDriver::onTimer(const ros::TimerEvent&) {
  const ros::Time now = ros::Time::now();
  const double t = demoTime(now);

  // The base has moved by the gated command since the last cycle (the gate judged it at the
  // pose of that cycle): the exact arc.
  const double elapsed_s = std::max(0.0, (now - last_cycle_).toSec());
  last_cycle_ = now;
  if (!paused_) base_ = poseAfterArc(base_, gated_, elapsed_s);
  const Pose2D& base = base_;
  geometry_msgs::TransformStamped odom_to_base;
  odom_to_base.header.stamp = now;
  odom_to_base.header.frame_id = odom_frame_;
  odom_to_base.child_frame_id = base_frame_;
  odom_to_base.transform.translation.x = base.position.x();
  odom_to_base.transform.translation.y = base.position.y();
  odom_to_base.transform.rotation.z = std::sin(base.yaw / 2);
  odom_to_base.transform.rotation.w = std::cos(base.yaw / 2);
  tf_broadcaster_.sendTransform(odom_to_base);

  sensor_msgs::JointState joints;
  joints.header.stamp = now;
  for (const NamedJointMotion& joint : trajectory_.joints) {
    joints.name.push_back(joint.joint);
    joints.position.push_back(joint.motion.at(t));
  }
  joint_states_pub_.publish(joints);

  publishScan(now, base, world_.at(t));

  if (!paused_) {
    // The gate stopped the last command: it answered, with zero, a command that was not zero.
    const bool gate_stopped = gated_since_command_ && isZero(gated_) && !isZero(command_);
    command_ = base_script_->command(base_, t, gate_stopped);
    gated_since_command_ = false;
    geometry_msgs::Twist cmd;
    cmd.linear.x = command_.vx;
    cmd.linear.y = command_.vy;
    cmd.angular.z = command_.wz;
    cmd_vel_pub_.publish(cmd);
  }
  last_plan_ = plannedPath(now, paused_ ? core::Twist() : command_);
  planned_path_pub_.publish(last_plan_);
}

nav_msgs::Path DemoDriver::plannedPath(const ros::Time& now, const core::Twist& command) const {
  nav_msgs::Path path;
  path.header.stamp = now;
  path.header.frame_id = odom_frame_;
  const int steps = static_cast<int>(std::round(planned_horizon_s_ / planned_step_s_));
  for (int k = 0; k <= steps; ++k) {
    const double ahead = k * planned_step_s_;
    // While paused the command is zero: the plan is the same pose, with rising stamps.
    const Pose2D pose = poseAfterArc(base_, command, ahead);
    geometry_msgs::PoseStamped stamped;
    stamped.header.stamp = now + ros::Duration(ahead);
    stamped.header.frame_id = odom_frame_;
    stamped.pose.position.x = pose.position.x();
    stamped.pose.position.y = pose.position.y();
    stamped.pose.orientation.z = std::sin(pose.yaw / 2);
    stamped.pose.orientation.w = std::cos(pose.yaw / 2);
    path.poses.push_back(stamped);
  }
  return path;
}

void DemoDriver::onPathCheckTimer(const ros::TimerEvent&) {
  if (last_plan_.poses.empty() || !check_path_.exists()) return;
  CheckPath srv;
  srv.request.path = last_plan_;
  srv.request.moving_frame = base_frame_;
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker contact;
  contact.header.frame_id = odom_frame_;
  contact.header.stamp = last_plan_.header.stamp;
  contact.ns = "planned_path_contact";
  contact.id = 0;
  contact.pose.orientation.w = 1.0;
  if (!check_path_.call(srv) || !srv.response.success) {
    // At start-up the collision node has not yet received the first odom transform this driver
    // sends: not worth a warning in the user's terminal until it has had kStartUpS.
    if (!path_check_succeeded_ && (ros::Time::now() - launched_).toSec() < kStartUpS) {
      ROS_DEBUG_STREAM("demo_driver: ~check_path not ready yet: " << srv.response.message);
    } else {
      ROS_WARN_STREAM_THROTTLE(5.0, "demo_driver: ~check_path failed: " << srv.response.message);
    }
    return;
  }
  path_check_succeeded_ = true;
  if (srv.response.collision_free) {
    contact.action = visualization_msgs::Marker::DELETE;
  } else {
    // The base's pose at the first contact, on the segment's straight line.
    const auto& from = last_plan_.poses[srv.response.segment].pose.position;
    const auto& to =
        last_plan_
            .poses[std::min<std::size_t>(srv.response.segment + 1, last_plan_.poses.size() - 1)]
            .pose.position;
    const double f = srv.response.fraction;
    // A thin magenta ring: apart from the node's red, orange, yellow and green, and covering
    // few pixels of the ellipses beneath it.
    contact.type = visualization_msgs::Marker::LINE_STRIP;
    contact.action = visualization_msgs::Marker::ADD;
    const double cx = from.x + f * (to.x - from.x), cy = from.y + f * (to.y - from.y);
    for (int k = 0; k <= 24; ++k) {
      geometry_msgs::Point p;
      p.x = cx + 0.15 * std::cos(2.0 * M_PI * k / 24);
      p.y = cy + 0.15 * std::sin(2.0 * M_PI * k / 24);
      p.z = 0.05;
      contact.points.push_back(p);
    }
    contact.scale.x = 0.03;
    contact.color.r = 1.0f;
    contact.color.g = 0.0f;
    contact.color.b = 1.0f;
    contact.color.a = 1.0f;
    ROS_INFO_STREAM_THROTTLE(2.0, "demo_driver: planned path meets "
                                      << srv.response.name_b << " with " << srv.response.name_a
                                      << " in " << core::formatNumber(srv.response.time) << " s");
  }
  markers.markers.push_back(contact);
  path_check_markers_pub_.publish(markers);
}

void DemoDriver::publishScan(const ros::Time& now, const Pose2D& base,
                             const std::vector<core::Ellipse>& world) {
  // Where the scanner sits on the base: a static transform from robot_state_publisher.
  geometry_msgs::TransformStamped mount;
  try {
    mount = tf_buffer_.lookupTransform(base_frame_, scanner_frame_, ros::Time(0));
  } catch (const tf2::TransformException& error) {
    // robot_state_publisher's static transforms take a moment to arrive after start-up.
    if ((now - launched_).toSec() < kStartUpS) {
      ROS_DEBUG_STREAM("demo_driver: no scan yet: " << error.what());
    } else {
      ROS_WARN_STREAM_THROTTLE(5.0, "demo_driver: no scan yet: " << error.what());
    }
    return;
  }
  const double c = std::cos(base.yaw), s = std::sin(base.yaw);
  const double mx = mount.transform.translation.x, my = mount.transform.translation.y;
  Pose2D sensor;
  sensor.position = base.position + Eigen::Vector2d(c * mx - s * my, s * mx + c * my);
  sensor.yaw = base.yaw + tf2::getYaw(mount.transform.rotation);

  sensor_msgs::LaserScan scan;
  scan.header.stamp = now;
  scan.header.frame_id = scanner_frame_;
  scan.angle_min = static_cast<float>(scanner_.angle_min);
  scan.angle_increment = static_cast<float>(scanner_.angle_increment);
  scan.angle_max = static_cast<float>(scanner_.angle_min + (scanner_.beams - 1) * scanner_.angle_increment);
  scan.range_min = static_cast<float>(scanner_.range_min);
  scan.range_max = static_cast<float>(scanner_.range_max);
  // Beam angles as the message gives them (float increment), so that the points scan_obstacles
  // computes are where the rays went.
  ScannerModel as_sent = scanner_;
  as_sent.angle_min = scan.angle_min;
  as_sent.angle_increment = scan.angle_increment;
  scan.ranges = rayCastScan(sensor, world, as_sent);
  scan_pub_.publish(scan);
}

}  // namespace ellipse_collision

#include "demo_driver.h"

#include <sensor_msgs/JointState.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <urdf/model.h>
#include <visualization_msgs/MarkerArray.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "ellipse_collision/app/gate_config.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/unique_names.h"
#include "ellipse_collision/core/velocity_gate.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/messages.h"
#include "ellipse_collision/ros/node_config.h"
#include "ellipse_collision/ros/urdf_links.h"

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

/// The links of `specs` that the driven joints move, with their chains from `base_frame` read
/// from the URDF `urdf_xml`; links no driven joint moves (the base itself) are left out. Each
/// ellipse is placed in its frame's plane as the node places it (padding included). Throws
/// DemoConfigError for a chain the guard cannot follow: not below base_frame, a joint that
/// moves but is not driven, or one that turns about anything but z.
std::vector<ArmLink> armLinks(const std::string& urdf_xml,
                              const std::vector<app::EllipseSpec>& specs, double global_padding,
                              const std::string& base_frame,
                              const std::vector<NamedJointMotion>& driven) {
  urdf::Model model;
  if (!model.initString(urdf_xml)) {
    throw DemoConfigError("arm_guard: the URDF in robot_description does not parse");
  }
  std::vector<ArmLink> links;
  for (const app::EllipseSpec& spec : specs) {
    const std::string where = "arm_guard: link '" + spec.name + "' (frame '" + spec.frame_id + "')";
    std::vector<ArmChainStep> chain;
    bool moved = false;
    urdf::LinkConstSharedPtr link = model.getLink(spec.frame_id);
    if (!link) throw DemoConfigError(where + ": its frame is not a link of the URDF");
    while (link->name != base_frame) {
      const urdf::JointConstSharedPtr joint = link->parent_joint;
      if (!joint) throw DemoConfigError(where + ": not below '" + base_frame + "' in the URDF");
      ArmChainStep step;
      const urdf::Pose& origin = joint->parent_to_joint_origin_transform;
      double roll = 0.0, pitch = 0.0, yaw = 0.0;
      origin.rotation.getRPY(roll, pitch, yaw);
      if (std::abs(roll) > 1e-9 || std::abs(pitch) > 1e-9) {
        throw DemoConfigError(where + ": joint '" + joint->name +
                              "' tilts its child (roll or pitch not 0): the arm guard needs a "
                              "planar arm");
      }
      step.origin.position = {origin.position.x, origin.position.y};
      step.origin.yaw = yaw;
      if (joint->type != urdf::Joint::FIXED) {
        const auto it = std::find_if(driven.begin(), driven.end(), [&](const NamedJointMotion& m) {
          return m.joint == joint->name;
        });
        const bool about_z =
            (joint->type == urdf::Joint::REVOLUTE || joint->type == urdf::Joint::CONTINUOUS) &&
            std::abs(joint->axis.x) < 1e-9 && std::abs(joint->axis.y) < 1e-9 &&
            std::abs(std::abs(joint->axis.z) - 1.0) < 1e-9;
        if (it == driven.end() || !about_z) {
          throw DemoConfigError(
              where + ": joint '" + joint->name + "' moves but is not " +
              (it == driven.end() ? "one of the driver's joints" : "revolute about z"));
        }
        step.joint = static_cast<int>(it - driven.begin());
        step.axis = joint->axis.z > 0.0 ? 1.0 : -1.0;
        moved = true;
      }
      chain.insert(chain.begin(), step);
      link = model.getLink(joint->parent_link_name);
      if (!link) throw DemoConfigError(where + ": not below '" + base_frame + "' in the URDF");
    }
    if (!moved) continue;
    const core::ProjectionResult shape =
        app::placeInPlane(spec, global_padding, Eigen::Isometry3d::Identity());
    if (!shape.ok()) throw DemoConfigError(where + ": " + shape.error);
    links.push_back({spec.name, shape.ellipse, chain});
  }
  return links;
}

/// A ring of `ellipse`'s rim as LINE_STRIP points at height z [m].
void addRim(const core::Ellipse& ellipse, double z, visualization_msgs::Marker* marker) {
  const double c = std::cos(ellipse.angle), s = std::sin(ellipse.angle);
  for (int k = 0; k <= 36; ++k) {
    const double u = ellipse.radius_x * std::cos(2.0 * M_PI * k / 36);
    const double v = ellipse.radius_y * std::sin(2.0 * M_PI * k / 36);
    geometry_msgs::Point p;
    p.x = ellipse.center.x() + c * u - s * v;
    p.y = ellipse.center.y() + s * u + c * v;
    p.z = z;
    marker->points.push_back(p);
  }
}

}  // namespace

DemoDriver::DemoDriver(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
    : nh_(nh), private_nh_(private_nh) {
  const ros::NodeHandle& p = private_nh_;
  dictKeys(p, "",
           {"rate", "odom_frame", "base_frame", "start", "route", "drive", "back_off", "joints",
            "static_obstacles", "moving_obstacle", "scanner", "planned_path", "arm_guard", "base"});
  const double rate_hz = p.hasParam("rate") ? positive(p, "rate") : 30.0;
  odom_frame_ = frameOr(p, "odom_frame", "odom");
  base_frame_ = frameOr(p, "base_frame", "base_link");

  dictKeys(p, "start", {"x", "y", "yaw"});
  base_.position = {number(p, "start/x"), number(p, "start/y")};
  base_.yaw = number(p, "start/yaw");
  readBaseDynamics();
  base_sim_.emplace(base_dynamics_,
                    core::PathPose{base_.position.x(), base_.position.y(), base_.yaw, 0.0});
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
    joint_motions_.push_back(motion.motion);
  }
  setUpArmGuard();

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
  odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 10);
  pause_service_ = private_nh_.advertiseService("pause", &DemoDriver::onPause, this);

  started_ = ros::Time::now();
  launched_ = started_;
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
  // A pause freezes the base where it stands (no braking: the demo's clock stops); it starts
  // again at rest.
  base_sim_.emplace(base_dynamics_, core::PathPose{base_.position.x(), base_.position.y(),
                                                   base_.yaw, clock_at_start_s_});
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
  base_sim_->command(demoTime(ros::Time::now()), gated_);
}

void DemoDriver::readBaseDynamics() {
  const ros::NodeHandle& p = private_nh_;
  if (!p.hasParam("base")) return;
  dictKeys(p, "base", {"reaction_time", "max_linear_deceleration", "max_angular_deceleration"});
  for (const auto& [key, field] :
       {std::pair<const char*, double*>{"reaction_time", &base_dynamics_.reaction_time},
        {"max_linear_deceleration", &base_dynamics_.linear_deceleration},
        {"max_angular_deceleration", &base_dynamics_.angular_deceleration}}) {
    const std::string name = std::string("base/") + key;
    if (p.hasParam(name)) *field = number(p, name);
  }
  // The node's gate/ parameters of the same names have the same ranges: one home for both.
  if (const auto violation = core::findInvalidBaseDynamics(base_dynamics_)) {
    const app::FieldError error = app::gateFieldError(*violation, fullName(p, "base") + "/");
    throw DemoConfigError("parameter " + error.key + ": expected " + error.expected + ", got " +
                          error.actual);
  }
}

void DemoDriver::publishOdometry(const ros::Time& now) {
  nav_msgs::Odometry odom;
  odom.header.stamp = now;
  odom.header.frame_id = odom_frame_;
  odom.child_frame_id = base_frame_;
  odom.pose.pose.position.x = base_.position.x();
  odom.pose.pose.position.y = base_.position.y();
  odom.pose.pose.orientation.z = std::sin(base_.yaw / 2);
  odom.pose.pose.orientation.w = std::cos(base_.yaw / 2);
  // The twist of nav_msgs/Odometry is in its child frame: the base's own.
  const core::Twist velocity = paused_ ? core::Twist() : base_sim_->velocity();
  odom.twist.twist.linear.x = velocity.vx;
  odom.twist.twist.linear.y = velocity.vy;
  odom.twist.twist.angular.z = velocity.wz;
  odom_pub_.publish(odom);
}

void DemoDriver::onTimer(const ros::TimerEvent&) {
  const ros::Time now = ros::Time::now();
  const double t = demoTime(now);

  // The base has moved since the last cycle as a real one follows the gated commands: late, and
  // changing speed at bounded rates (demo time, which stands while paused).
  if (!paused_) {
    base_sim_->advanceTo(t);
    base_.position = {base_sim_->pose().x, base_sim_->pose().y};
    base_.yaw = base_sim_->pose().yaw;
  }
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
  publishOdometry(now);

  // The arm: by the demo clock, or (arm_guard) by its own clock, which stands while the joints
  // hold.
  if (!arm_guard_enabled_) {
    arm_clock_s_ = t;
  } else if (!paused_) {
    guardArm(now, std::max(0.0, t - last_demo_t_s_));
  }
  last_demo_t_s_ = t;
  sensor_msgs::JointState joints;
  joints.header.stamp = now;
  for (const NamedJointMotion& joint : trajectory_.joints) {
    joints.name.push_back(joint.joint);
    joints.position.push_back(joint.motion.at(arm_clock_s_));
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
    plan_log_.shouldLog("", ros::Time::now().toSec());
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
    // Once when a contact appears or its pair changes, not 5 times a second while it lasts.
    std::ostringstream line;
    line << "demo_driver: planned path meets " << srv.response.name_b << " with "
         << srv.response.name_a << " in " << core::formatNumber(srv.response.time) << " s";
    if (plan_log_.shouldLog(srv.response.name_a + " / " + srv.response.name_b,
                            ros::Time::now().toSec())) {
      ROS_INFO_STREAM(line.str());
    } else {
      ROS_DEBUG_STREAM(line.str());
    }
  }
  markers.markers.push_back(contact);
  path_check_markers_pub_.publish(markers);
}

void DemoDriver::setUpArmGuard() {
  const ros::NodeHandle& p = private_nh_;
  if (p.hasParam("arm_guard")) {
    dictKeys(p, "arm_guard",
             {"enabled", "horizon", "step", "clearance", "retreat_after", "retreat"});
    if (p.hasParam("arm_guard/enabled") && !p.getParam("arm_guard/enabled", arm_guard_enabled_)) {
      throw DemoConfigError("parameter " + fullName(p, "arm_guard/enabled") +
                            ": expected true or false");
    }
    if (p.hasParam("arm_guard/horizon")) arm_guard_.horizon_s = positive(p, "arm_guard/horizon");
    if (p.hasParam("arm_guard/step")) arm_guard_.step_s = positive(p, "arm_guard/step");
    if (p.hasParam("arm_guard/retreat_after")) {
      arm_guard_.retreat_after_s = positive(p, "arm_guard/retreat_after");
    }
    if (p.hasParam("arm_guard/retreat")) arm_guard_.retreat_s = positive(p, "arm_guard/retreat");
    if (p.hasParam("arm_guard/clearance")) {
      arm_guard_.clearance_m = number(p, "arm_guard/clearance");
      if (arm_guard_.clearance_m < 0.0) {
        throw DemoConfigError("parameter " + fullName(p, "arm_guard/clearance") +
                              ": expected a number >= 0, got " +
                              core::formatNumber(arm_guard_.clearance_m));
      }
    }
    if (arm_guard_.step_s > arm_guard_.horizon_s ||
        arm_guard_.horizon_s / arm_guard_.step_s > 1000.0) {
      throw DemoConfigError("parameter " + fullName(p, "arm_guard/step") +
                            ": expected a number within [horizon / 1000, horizon], got " +
                            core::formatNumber(arm_guard_.step_s));
    }
  }
  if (!arm_guard_enabled_) return;
  // The collision node's configuration, as it reads it: its links (never obstacles), their
  // ellipses and its warning distance.
  const ros::NodeHandle node(nh_.resolveName("ellipse_collision"));
  NodeConfig config;
  try {
    config = loadNodeConfig(node, fitUrdfLinksFromParam);
  } catch (const std::exception& error) {
    throw DemoConfigError("arm_guard: the collision node's parameters (" + node.getNamespace() +
                          "): " + error.what());
  }
  warning_distance_m_ = config.monitor.check.rules.warning_distance;
  if (!(warning_distance_m_ > 0.0)) {
    throw DemoConfigError(
        "arm_guard: expected the collision node's warning_distance > 0 (its "
        "answer gives distances only that close), got " +
        core::formatNumber(warning_distance_m_));
  }
  for (const app::EllipseSpec& link : config.links) node_links_.insert(link.name);
  std::string urdf;
  try {
    urdf = readUrdfParam("robot_description");
  } catch (const std::exception& error) {
    throw DemoConfigError(std::string("arm_guard: ") + error.what());
  }
  arm_links_ = armLinks(urdf, config.links, config.monitor.check.global_padding_m, base_frame_, trajectory_.joints);
  // Persistent: one connection for the 30 calls a second (re-made when the node restarts).
  check_collisions_ =
      nh_.serviceClient<CheckCollisions>("ellipse_collision/check_collisions", true);
  std::string names;
  for (const ArmLink& link : arm_links_) names += (names.empty() ? "" : ", ") + link.name;
  ROS_INFO_STREAM("demo_driver: the arm (" << names << ") holds while a link would come within "
                                           << core::formatNumber(arm_guard_.clearance_m)
                                           << " m of an obstacle in the next "
                                           << core::formatNumber(arm_guard_.horizon_s) << " s");
}

std::string DemoDriver::armHoldReason(double direction, std::optional<ArmHold>* hold) {
  const std::vector<ArmSample> sweep = armSweep(arm_links_, joint_motions_, arm_clock_s_, direction,
                                                base_, base_sim_->velocity(), arm_guard_);
  if (const auto undecided = undecidedSample(sweep, arm_guard_.clearance_m, warning_distance_m_)) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "arm held: %s moves up to %.2f m around its pose in %.2f s, beyond what the "
                  "check's warning distance (%.2f m) decides",
                  undecided->link.c_str(), undecided->sweep_m, undecided->time_s,
                  warning_distance_m_);
    return text;
  }
  CheckCollisions srv;
  for (const ArmSample& sample : sweep) {
    Ellipse query;
    query.name = sample.name;
    query.frame_id = odom_frame_;
    query.x = sample.ellipse.center.x();
    query.y = sample.ellipse.center.y();
    query.angle = sample.ellipse.angle;
    query.radius_x = sample.ellipse.radius_x;
    query.radius_y = sample.ellipse.radius_y;
    srv.request.query.push_back(query);
    srv.request.names.push_back(sample.name);
  }
  if (!check_collisions_.isValid()) {
    check_collisions_ =
        nh_.serviceClient<CheckCollisions>("ellipse_collision/check_collisions", true);
  }
  if (!check_collisions_.call(srv)) return "arm held: no answer from ~check_collisions";
  if (!srv.response.success) return "arm held: ~check_collisions: " + srv.response.message;
  // Obstacles the node could not place would be missed: hold, as the gate does.
  if (!srv.response.complete)
    return "arm held: the check is incomplete (" + srv.response.message + ")";
  std::vector<ArmContact> contacts;
  const auto add = [&](const std::string& a, const std::string& b, double distance) {
    // name_a is the query (Query < Link < Obstacle); the node's links are not obstacles.
    if (!node_links_.count(b)) contacts.push_back({a, b, distance});
  };
  for (const CollisionPair& pair : srv.response.collisions) add(pair.name_a, pair.name_b, 0.0);
  for (const ClearancePair& pair : srv.response.warnings) {
    add(pair.name_a, pair.name_b, pair.distance);
  }
  *hold = firstHold(sweep, contacts, arm_guard_.clearance_m);
  return *hold ? holdText(**hold, arm_guard_.clearance_m) : "";
}

void DemoDriver::guardArm(const ros::Time& now, double dt_s) {
  // The check covered the next horizon_s; a longer stall moves on at most that far.
  const double step_s = std::min(dt_s, arm_guard_.horizon_s);
  std::optional<ArmHold> hold;
  std::string text;
  if (arm_retreat_left_s_ > 0.0) {
    // Backing off along the sweep, as far as that way is clear.
    text = armHoldReason(-1.0, &hold);
    if (text.empty()) {
      arm_clock_s_ -= step_s;
      arm_retreat_left_s_ -= step_s;
      text = arm_retreat_text_;
    } else {
      arm_retreat_left_s_ = 0.0;
    }
  } else {
    text = armHoldReason(1.0, &hold);
    if (text.empty()) {
      arm_clock_s_ += step_s;
      arm_held_s_ = 0.0;
    } else if (hold && (arm_held_s_ += dt_s) >= arm_guard_.retreat_after_s) {
      // Held this long, the arm may be what keeps the base stuck too (the gate moves every link
      // rigidly with the base): it backs off along the way it came.
      arm_held_s_ = 0.0;
      arm_retreat_left_s_ = arm_guard_.retreat_s;
      arm_retreat_text_ = "arm backs off: " + hold->link + " held near " + hold->obstacle;
    }
  }
  const bool starting_up = (now - launched_).toSec() < kStartUpS;
  if (arm_log_.shouldLog(hold ? hold->link + " / " + hold->obstacle : text, now.toSec())) {
    if (starting_up && !hold) {
      ROS_DEBUG_STREAM("demo_driver: " << text);
    } else {
      ROS_INFO_STREAM("demo_driver: " << text);
    }
  } else if (!text.empty()) {
    ROS_DEBUG_STREAM("demo_driver: " << text);
  }
  publishArmHold(now, text, hold);
}

void DemoDriver::publishArmHold(const ros::Time& now, const std::string& text,
                                const std::optional<ArmHold>& hold) {
  // On a change, else (the base may move while the arm holds) every 0.2 s while held.
  const bool changed = text != arm_hold_text_;
  if (!changed && (text.empty() || (now - arm_marker_sent_).toSec() < 0.2)) return;
  arm_hold_text_ = text;
  arm_marker_sent_ = now;
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker outline, label;
  for (visualization_msgs::Marker* m : {&outline, &label}) {
    m->header.frame_id = odom_frame_;
    m->header.stamp = now;
    m->ns = "arm_hold";
    m->pose.orientation.w = 1.0;
    m->action = visualization_msgs::Marker::DELETE;
    // Magenta, as the planned path's contact ring.
    m->color.r = 1.0f;
    m->color.b = 1.0f;
    m->color.a = 1.0f;
  }
  outline.id = 0;
  label.id = 1;
  if (!text.empty()) {
    // The text above the link where it would touch (or above the base).
    Eigen::Vector2d at = base_.position + Eigen::Vector2d(0.0, 0.6);
    if (hold) {
      outline.action = visualization_msgs::Marker::ADD;
      outline.type = visualization_msgs::Marker::LINE_STRIP;
      outline.scale.x = 0.03;
      addRim(hold->ellipse, 0.06, &outline);
      at = hold->ellipse.center + Eigen::Vector2d(0.0, core::boundingRadius(hold->ellipse) + 0.15);
    }
    label.action = visualization_msgs::Marker::ADD;
    label.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    label.text = text;
    label.scale.z = 0.12;
    label.pose.position.x = at.x();
    label.pose.position.y = at.y();
    label.pose.position.z = 0.5;
  }
  markers.markers.push_back(outline);  // DELETE when no link is held
  markers.markers.push_back(label);
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

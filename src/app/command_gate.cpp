#include "ellipse_collision/app/command_gate.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace ellipse_collision::app {
namespace {

/// A 2D rigid motion: from the fixed frame's plane into the robot frame at t = 0, and back.
struct PlaneTransform {
  Eigen::Matrix2d rotation;  ///< robot axes in the fixed frame
  Eigen::Vector2d origin;
  double yaw;
  explicit PlaneTransform(const PlanarPose& robot)
      : origin(robot.position), yaw(robot.yaw) {
    rotation << std::cos(yaw), -std::sin(yaw), std::sin(yaw), std::cos(yaw);
  }
  core::Ellipse toRobot(core::Ellipse e) const {
    e.center = rotation.transpose() * (e.center - origin);
    e.angle -= yaw;
    return e;
  }
  core::Ellipse toFixed(core::Ellipse e) const {
    e.center = rotation * e.center + origin;
    e.angle += yaw;
    return e;
  }
  Eigen::Vector2d pointToFixed(const Eigen::Vector2d& p) const { return rotation * p + origin; }
  core::Motion toRobot(core::Motion m) const {
    m.velocity = rotation.transpose() * m.velocity;
    return m;
  }
};

GateAction fromCore(core::GateAction action) {
  switch (action) {
    case core::GateAction::Pass:
      return GateAction::Pass;
    case core::GateAction::Slow:
      return GateAction::Slow;
    case core::GateAction::Escape:
      return GateAction::Escape;
    case core::GateAction::Stop:
      break;
  }
  return GateAction::Stop;
}

}  // namespace

const char* toString(OnIncomplete policy) {
  return policy == OnIncomplete::Stop ? "stop" : "pass";
}

std::optional<FieldError> parseOnIncomplete(const std::string& text, OnIncomplete* policy) {
  for (const OnIncomplete candidate : {OnIncomplete::Stop, OnIncomplete::Pass}) {
    if (text == toString(candidate)) {
      *policy = candidate;
      return std::nullopt;
    }
  }
  return FieldError{"gate/on_incomplete", "'stop' or 'pass'", "'" + text + "'"};
}

std::optional<FieldError> findInvalidGateSetting(const GateConfig& config) {
  if (config.robot_frame.empty()) {
    return FieldError{"gate/robot_frame", "a non-empty tf frame id", "''"};
  }
  if (config.robot_frame.front() == '/') {
    return FieldError{"gate/robot_frame", "a tf2 frame id without a leading '/'",
                      "'" + config.robot_frame + "'"};
  }
  const core::GateSettings& t = config.timing;
  if (auto e = findOutsideRange("gate/horizon", t.horizon, 0.0, kMaxGateHorizonS, true)) return e;
  if (auto e =
          findOutsideRange("gate/time_before_collision", t.time_before_collision, 0.0, t.horizon)) {
    e->expected += " (at most gate/horizon)";
    return e;
  }
  if (auto e = findOutsideRange("gate/stop_time", t.stop_time, 0.0, t.time_before_collision)) {
    e->expected += " (at most gate/time_before_collision)";
    return e;
  }
  if (auto e = findOutsideRange("gate/margin", t.margin, 0.0, core::kMaxRadius)) return e;
  if (auto e = findOutsideRange("gate/resolution", t.resolution, kMinGateResolution, 1.0)) return e;
  if (auto e = findOutsideRange("gate/cmd_vel_timeout", config.cmd_vel_timeout_s, 0.0,
                                kMaxGateHorizonS)) {
    return e;
  }
  if (auto e = findOutsideRange("gate/max_linear_speed", config.max_linear_speed, 0.0,
                                kMaxGateSpeed, true)) {
    return e;
  }
  if (auto e = findOutsideRange("gate/max_angular_speed", config.max_angular_speed, 0.0,
                                kMaxGateTurnRate, true)) {
    return e;
  }
  return std::nullopt;
}

VelocityCommand scaledCommand(const VelocityCommand& command, double k) {
  return {command.linear * k, command.angular * k};
}

std::optional<FieldError> findInvalidCommand(const VelocityCommand& command,
                                             const GateConfig& config) {
  static const char* const kAxes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (auto e = findOutsideRange(std::string("linear.") + kAxes[i], command.linear[i],
                                  -config.max_linear_speed, config.max_linear_speed)) {
      return e;
    }
  }
  for (int i = 0; i < 3; ++i) {
    if (auto e = findOutsideRange(std::string("angular.") + kAxes[i], command.angular[i],
                                  -config.max_angular_speed, config.max_angular_speed)) {
      return e;
    }
  }
  return std::nullopt;
}

const char* toString(GateAction action) {
  switch (action) {
    case GateAction::Pass:
      return "PASS";
    case GateAction::Slow:
      return "SLOW";
    case GateAction::Stop:
      return "STOP";
    case GateAction::Escape:
      return "ESCAPE";
    case GateAction::Timeout:
      return "TIMEOUT";
    case GateAction::Incomplete:
      return "INCOMPLETE";
    case GateAction::Disabled:
      return "DISABLED";
  }
  return "STOP";
}

GateDecision stoppedDecision(GateAction action, const VelocityCommand& input, std::string reason) {
  GateDecision decision;
  decision.action = action;
  decision.scale = 0.0;
  decision.input = input;
  decision.output = VelocityCommand();
  decision.reason = std::move(reason);
  return decision;
}

GateDecision decideOnScene(const VelocityCommand& command, const core::Scene& placed,
                           const std::vector<core::Motion>& obstacle_motions,
                           const PlanarPose& robot, const core::AllowedPairs& allowed,
                           const GateConfig& config) {
  const PlaneTransform frame(robot);
  const core::Twist twist{command.linear.x(), command.linear.y(), command.angular.z()};
  const double horizon = config.timing.horizon;
  core::PathScene scene;
  scene.allowed = allowed;
  double reach = 0.0;  // every link stays within this of the robot frame's origin at t = 0
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (placed.role(i) == core::EllipseRole::Obstacle) continue;
    core::NamedEllipse link = placed.entry(i);
    link.ellipse = frame.toRobot(link.ellipse);
    reach = std::max(reach, link.ellipse.center.norm() + core::boundingRadius(link.ellipse));
    scene.links.push_back(std::move(link));
  }
  // Only obstacles that can come within reach are handed on (their names copied): the core's own
  // broadphase would rule the others out, so the answer is the same. The robot's origin moves at
  // most |v| horizon (an arc is no longer than its chord's path), a link point at most
  // |v| horizon + reach from the origin at t = 0.
  reach += std::hypot(twist.vx, twist.vy) * horizon + config.timing.margin;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (placed.role(i) != core::EllipseRole::Obstacle) continue;
    const core::Ellipse& e = placed.ellipse(i);
    const core::Motion& motion = obstacle_motions[i];
    const double sweep = motion.velocity.norm() * horizon;
    if ((e.center - frame.origin).norm() > reach + core::boundingRadius(e) + sweep) continue;
    scene.obstacles.push_back({placed.name(i), core::EllipseRole::Obstacle, frame.toRobot(e)});
    scene.obstacle_motions.push_back(frame.toRobot(motion));
  }
  const core::GateResult result = core::gateCommand(scene, twist, config.timing);
  if (!result.ok()) {
    return stoppedDecision(GateAction::Stop, command,
                           "stopped: the command could not be judged: " + result.error);
  }
  GateDecision decision;
  decision.action = fromCore(result.action);
  decision.scale = result.scale;
  decision.input = command;
  decision.output = scaledCommand(command, result.scale);
  decision.reason = result.reason;
  const core::GateContact& shown = result.contact.found ? result.contact : result.limiting;
  if (shown.found) {
    decision.contact_predicted = true;
    decision.time_to_contact_s = shown.time;
    decision.link = shown.link;
    decision.obstacle = shown.obstacle;
    decision.contact_point = frame.pointToFixed(shown.point);
    for (const core::NamedEllipse& obstacle : scene.obstacles) {
      if (obstacle.name == shown.obstacle) decision.obstacle_ellipse = frame.toFixed(obstacle.ellipse);
    }
  }
  // The robot where the output command takes it: at the contact, or at the horizon.
  const core::Twist output = core::scaled(twist, result.scale);
  const double at = result.contact.found ? result.contact.time : horizon;
  for (core::NamedEllipse& link : core::linksAtTime(scene.links, output, at)) {
    link.ellipse = frame.toFixed(link.ellipse);
    decision.outline.push_back(std::move(link));
  }
  return decision;
}

}  // namespace ellipse_collision::app

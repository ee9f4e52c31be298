#include "ellipse_collision/app/velocity_gate.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/velocity_gate.h"

namespace ellipse_collision::app {
namespace {

/// A 2D rigid motion: from the fixed frame's plane into the robot frame at t = 0, and back.
struct PlaneTransform {
  Eigen::Matrix2d rotation;  ///< robot axes in the fixed frame
  Eigen::Vector2d origin;
  double yaw;
  explicit PlaneTransform(const PlanarPose& robot) : origin(robot.position), yaw(robot.yaw) {
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

}  // namespace

GateDecision stoppedDecision(GateAction action, const VelocityCommand& input, std::string reason) {
  GateDecision decision;
  decision.action = action;
  decision.scale = 0.0;
  decision.input = input;
  decision.output = VelocityCommand();
  decision.reason = std::move(reason);
  return decision;
}

GateDecision gateOnScene(const VelocityCommand& command, const core::Scene& placed,
                         const std::vector<PlacedMotion>& moving, const PlanarPose& robot,
                         const core::AllowedPairs& allowed, const GateConfig& config,
                         const core::BaseState& base, const core::IndexedObstacles* standing) {
  if (standing && standing->obstacles().size() > placed.size()) {
    return stoppedDecision(GateAction::Stop, command,
                           "stopped: the command could not be judged: the obstacles' grid is not "
                           "the scene's");
  }
  const PlaneTransform frame(robot);
  const core::Twist twist{command.linear.x(), command.linear.y(), command.angular.z()};
  const double horizon = config.timing.horizon;
  core::PathScene scene;
  scene.allowed = allowed;
  // With the grid, the scene's obstacles are its last entries: only links come before them.
  const std::size_t first_gridded =
      standing ? placed.size() - standing->obstacles().size() : placed.size();
  double reach = 0.0;  // every link stays within this of the robot frame's origin at t = 0
  for (std::size_t i = 0; i < first_gridded; ++i) {
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
  const PlacedMotion still;
  auto next_moving = moving.begin();
  const auto motionOf = [&](std::size_t i) -> const PlacedMotion& {
    while (next_moving != moving.end() && next_moving->index < i) ++next_moving;
    return next_moving != moving.end() && next_moving->index == i ? *next_moving : still;
  };
  // Each candidate in increasing index, the order of a scan of every entry.
  const auto consider = [&](std::size_t i) {
    if (placed.role(i) != core::EllipseRole::Obstacle) return;
    const PlacedMotion& placed_motion = motionOf(i);
    const core::Motion& motion = placed_motion.motion;
    // A moving obstacle is judged where its motion has taken it since its message: the gate
    // decides for now, and a footprint 0.1 s old is 4 cm behind a robot at 0.4 m/s.
    const core::Ellipse e = placed_motion.since_s > 0.0
                                ? core::movedBy(placed.ellipse(i), motion, placed_motion.since_s)
                                : placed.ellipse(i);
    if (!core::mayComeWithin(e, motion.velocity.norm() * horizon, frame.origin, reach)) return;
    scene.obstacles.push_back({placed.name(i), core::EllipseRole::Obstacle, frame.toRobot(e)});
    scene.obstacle_motions.push_back(frame.toRobot(motion));
  };
  if (!standing) {
    for (std::size_t i = 0; i < placed.size(); ++i) consider(i);
  } else {
    // The grid finds those that stand within reach; the moving ones, whose sweep its query
    // leaves out, are added and tested with it.
    std::vector<std::size_t> candidates;
    standing->within(frame.origin, reach, &candidates);
    for (std::size_t& k : candidates) k += first_gridded;
    const auto gridded_end = static_cast<std::ptrdiff_t>(candidates.size());
    for (const PlacedMotion& m : moving) {
      if (m.index >= first_gridded && m.index < placed.size()) candidates.push_back(m.index);
    }
    std::inplace_merge(candidates.begin(), candidates.begin() + gridded_end, candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (const std::size_t i : candidates) consider(i);
  }
  const core::GateResult result = core::gateTwist(scene, twist, config.timing, base);
  if (!result.ok()) {
    return stoppedDecision(GateAction::Stop, command,
                           "stopped: the command could not be judged: " + result.error);
  }
  GateDecision decision;
  decision.action = result.action;
  decision.scale = result.scale;
  decision.input = command;
  decision.output = scaledCommand(command, result.scale);
  decision.reason = result.reason;
  decision.braking_distance_m = result.braking_distance;
  decision.free_distance_m = result.free_distance;
  decision.unavoidable = result.unavoidable;
  decision.impact_speed = result.impact_speed;
  const core::GateContact& shown = result.contact.found ? result.contact : result.limiting;
  if (shown.found) {
    decision.contact_predicted = true;
    decision.time_to_contact_s = shown.time;
    decision.link = shown.link;
    decision.obstacle = shown.obstacle;
    decision.contact_point = frame.pointToFixed(shown.point);
    for (const core::NamedEllipse& obstacle : scene.obstacles) {
      if (obstacle.name == shown.obstacle)
        decision.obstacle_ellipse = frame.toFixed(obstacle.ellipse);
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

namespace {

/// The no-stop-and-go rule (braking rule on): while the input and the world stay the same and the
/// free way ahead has not grown by more than kHoldHysteresisM, the scale never rises after it has
/// fallen. `hold` is the memory before the decision; the memory after it is returned.
std::optional<GateHold> holdScale(GateDecision& decision, const std::optional<GateHold>& hold,
                                  const std::vector<PlacedMotion>& moving,
                                  std::uint64_t world_revision, const GateConfig& config) {
  constexpr double kHoldHysteresisM = 0.1;
  const bool judged = decision.action == GateAction::Pass || decision.action == GateAction::Slow ||
                      decision.action == GateAction::Stop || decision.action == GateAction::Escape;
  // Only the braking rule makes a larger scale safe again as the base slows down; the ideal
  // base's rule does not (its answers stay as they were).
  if (!judged || config.base.ideal()) return std::nullopt;
  bool world_moves = false;
  for (const PlacedMotion& placed : moving) {
    const core::Motion& m = placed.motion;
    world_moves |= m.velocity.x() != 0.0 || m.velocity.y() != 0.0 || m.angular_velocity != 0.0;
  }
  const VelocityCommand& input = decision.input;
  const bool same = hold && !world_moves && hold->world_revision == world_revision &&
                    hold->input.linear == input.linear && hold->input.angular == input.angular;
  // The way ahead opened (the limiting obstacle passed or turned away from): no longer the
  // situation in which the scale fell.
  const bool opened = same && decision.free_distance_m > hold->free_distance_m + kHoldHysteresisM;
  if (same && !opened && decision.scale > hold->scale) {
    // The base slowing down makes a larger scale safe again; taking it would start the base
    // again toward what stopped it: stop-and-go.
    const double held = hold->scale;
    decision.reason += "; held at " + core::formatNumber(held) + " (from " +
                       core::formatNumber(decision.scale) +
                       "): input, world and the free way ahead are as when the scale fell, so "
                       "it does not rise again";
    decision.scale = held;
    decision.output = scaledCommand(input, held);
    if (held == 0.0) {
      decision.action = GateAction::Stop;
    } else if (decision.action == GateAction::Pass) {
      decision.action = GateAction::Slow;
    }
  }
  // The free way ahead is remembered at its shortest while the situation lasts.
  const double free = same && !opened ? std::min(hold->free_distance_m, decision.free_distance_m)
                                      : decision.free_distance_m;
  return GateHold{input, decision.scale, world_revision, free};
}

}  // namespace

GateDecision judgeOnScene(const VelocityCommand& command, const core::Scene& placed,
                          const std::vector<PlacedMotion>& moving, const PlanarPose& robot,
                          const core::AllowedPairs& allowed, const GateConfig& config,
                          const GateMemory& memory, std::optional<GateHold>* hold,
                          const core::IndexedObstacles* standing) {
  GateDecision decision =
      gateOnScene(command, placed, moving, robot, allowed, config, memory.base, standing);
  std::optional<GateHold> next =
      holdScale(decision, memory.hold, moving, memory.world_revision, config);
  if (hold) *hold = std::move(next);
  return decision;
}

VelocityGate::VelocityGate(GateConfig config) : config_(std::move(config)) {}

GateDecision VelocityGate::record(GateDecision decision) {
  last_output_ = decision.output;
  last_action_ = toString(decision.action);
  last_reason_ = decision.reason;
  if (stops(decision.action)) ++stops_;
  if (decision.action == GateAction::Slow) ++slowdowns_;
  return decision;
}

std::optional<GateDecision> VelocityGate::screen(const VelocityCommand& command, double now_s) {
  if (last_command_at_ && now_s >= *last_command_at_) {
    intervals_.push_back(now_s - *last_command_at_);
    if (intervals_.size() > 20) intervals_.pop_front();
  }
  last_command_at_ = now_s;
  heard_ = true;
  last_command_s_ = now_s;
  timeout_sent_ = false;
  if (!config_.enabled) {
    GateDecision decision;
    decision.action = GateAction::Disabled;
    decision.scale = 1.0;
    decision.input = command;
    decision.output = command;
    decision.reason = "the gate is disabled: commands pass unchanged";
    return record(std::move(decision));
  }
  if (const auto invalid = findInvalidCommand(command, config_)) {
    return record(
        stoppedDecision(GateAction::Stop, command,
                        "stopped: refused command: " + describeFieldError("cmd_vel", *invalid)));
  }
  return std::nullopt;
}

PlanarPose planarPose(const Eigen::Isometry3d& pose) {
  PlanarPose planar;
  planar.position = pose.translation().head<2>();
  planar.yaw = std::atan2(pose.linear()(1, 0), pose.linear()(0, 0));
  return planar;
}

GateDecision VelocityGate::decide(const VelocityCommand& command, const GateView& view) {
  last_memory_.reset();
  const CheckOutcome& outcome = *view.outcome;
  if (!outcome.error.empty()) {
    return record(
        stoppedDecision(GateAction::Stop, command, "stopped: the check failed: " + outcome.error));
  }
  const FrameTransform& robot = view.robot;
  if (!robot.ok || isStale(robot, view.freshness)) {
    // Without the robot's own pose there is nothing to gate on, whatever on_incomplete says.
    return record(stoppedDecision(
        GateAction::Incomplete, command,
        "stopped: robot_frame '" + config_.robot_frame + "': " +
            (robot.ok ? "its transform to '" + view.fixed_frame + "' is " +
                            core::formatNumber(ageOf(robot, view.freshness)) +
                            " s old, older than max_transform_age " +
                            core::formatNumber(view.freshness.max_age_s) + " s"
                      : "no transform to '" + view.fixed_frame + "' (" + robot.error + ")")));
  }
  std::vector<std::string> missing;
  if (!outcome.unavailable_frames.empty()) {
    missing.push_back("frames unavailable: " + joinText(outcome.unavailable_frames, ", "));
  }
  if (!outcome.stale_frames.empty()) {
    missing.push_back("frames stale: " + joinText(outcome.stale_frames, ", "));
  }
  if (!outcome.skipped.empty() && missing.empty()) {
    missing.push_back("skipped: " + joinText(outcome.skipped, "; "));
  }
  missing.insert(missing.end(), view.silent_sources.begin(), view.silent_sources.end());
  if (!missing.empty() && config_.on_incomplete == OnIncomplete::Stop) {
    return record(stoppedDecision(
        GateAction::Incomplete, command,
        "stopped: incomplete data (on_incomplete: stop): " + joinText(missing, "; ")));
  }
  // The robot frame's pose in the fixed frame's plane (its heading from its x axis).
  const PlanarPose planar = planarPose(robot.fixed_from_frame);
  last_memory_ = GateMemory{baseAt(view.freshness.reference_s), hold_, view.world_revision};
  GateDecision decision =
      judgeOnScene(command, outcome.placed, view.obstacle_motions, planar, *view.allowed, config_,
                   *last_memory_, &hold_, outcome.standing.get());
  if (!missing.empty()) {
    decision.reason +=
        " (incomplete data, passed by on_incomplete: pass: " + joinText(missing, "; ") + ")";
  }
  return record(std::move(decision));
}

void VelocityGate::measuredVelocity(const VelocityCommand& twist, double stamp_s) {
  measured_ = std::make_pair(twist, stamp_s);
}

core::BaseState VelocityGate::baseAt(double now_s) const {
  core::BaseState base;
  base.dynamics = config_.base;
  const double timeout = config_.cmd_vel_timeout_s;
  VelocityCommand velocity = last_output_;
  if (measured_ && now_s - measured_->second <= std::max(0.5, timeout)) {
    velocity = measured_->first;
  }
  base.velocity = {velocity.linear.x(), velocity.linear.y(), velocity.angular.z()};
  // The output acts until the next command, or until the watchdog's zero (its timer runs at a
  // quarter of the timeout).
  const double longest = timeout > 0.0 ? 1.25 * timeout : std::numeric_limits<double>::infinity();
  if (intervals_.empty()) {
    base.command_period = timeout > 0.0 ? longest : 0.1;
  } else {
    base.command_period =
        std::min(longest, *std::max_element(intervals_.begin(), intervals_.end()));
  }
  return base;
}

std::optional<GateDecision> VelocityGate::watchdog(double now_s) {
  const double timeout = config_.cmd_vel_timeout_s;
  if (!config_.enabled || !(timeout > 0.0)) return std::nullopt;
  if (!heard_ || now_s < last_command_s_) {  // the first call, or time jumped back
    heard_ = true;
    last_command_s_ = now_s;
    return std::nullopt;
  }
  if (timeout_sent_ || now_s - last_command_s_ < timeout) return std::nullopt;
  timeout_sent_ = true;
  return record(stoppedDecision(GateAction::Timeout, VelocityCommand(),
                                "stopped: no command on ~cmd_vel_in within cmd_vel_timeout " +
                                    core::formatNumber(timeout) + " s of the last one"));
}

std::vector<std::pair<std::string, std::string>> VelocityGate::healthValues() const {
  const std::string ideal = idealBaseWarning(config_);
  return {{"gate", !config_.enabled ? "disabled" : last_action_},
          {"gate reason", last_reason_},
          {"gate stops", std::to_string(stops_)},
          {"gate slow-downs", std::to_string(slowdowns_)},
          {"gate base model",
           ideal.empty() ? "reaction " + core::formatNumber(config_.base.reaction_time) + " s, " +
                               core::formatNumber(config_.base.linear_deceleration) + " m/s^2, " +
                               core::formatNumber(config_.base.angular_deceleration) + " rad/s^2"
                         : ideal}};
}

}  // namespace ellipse_collision::app

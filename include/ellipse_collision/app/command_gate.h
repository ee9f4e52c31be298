#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/core/scene_check.h"
#include "ellipse_collision/core/velocity_gate.h"

namespace ellipse_collision::app {

/// What the gate does when not every stored ellipse is placed from fresh data (a frame
/// unavailable or stale, obstacles dropped by obstacle_timeout, the robot frame unknown).
enum class OnIncomplete { Stop, Pass };
/// "stop" or "pass", as the `gate/on_incomplete` key spells them.
const char* toString(OnIncomplete policy);
/// The policy `text` names ("stop", "pass"), or a FieldError of key `gate/on_incomplete`.
std::optional<FieldError> parseOnIncomplete(const std::string& text, OnIncomplete* policy);

/// The velocity gate's parameters (the node's `gate/` keys, config/ellipse_collision.yaml).
struct GateConfig {
  bool enabled{false};                   ///< off: commands pass unchanged (DISABLED)
  std::string robot_frame{"base_link"};  ///< the frame the command moves [tf frame]
  /// horizon, time_before_collision, stop_time, margin, resolution (core::GateSettings).
  core::GateSettings timing;
  double cmd_vel_timeout_s{0.5};  ///< no command for this long publishes one zero [s]; 0 = off
  OnIncomplete on_incomplete{OnIncomplete::Stop};
  double max_linear_speed{5.0};   ///< a command faster along any axis is refused (STOP) [m/s]
  double max_angular_speed{5.0};  ///< a command turning faster about any axis is refused [rad/s]
};

/// Accepted ranges (refused, never clamped), and their one home: horizon within (0,
/// kMaxGateHorizonS]; 0 <= stop_time <= time_before_collision <= horizon; margin within [0,
/// core::kMaxRadius]; resolution within [kMinGateResolution, 1]; cmd_vel_timeout within [0,
/// kMaxGateHorizonS]; max_linear_speed within (0, kMaxGateSpeed]; max_angular_speed within (0,
/// kMaxGateTurnRate]; robot_frame a non-empty frame without a leading '/'.
constexpr double kMaxGateHorizonS = 60.0;
constexpr double kMinGateResolution = 1e-3;
constexpr double kMaxGateSpeed = 100.0;    ///< [m/s]
constexpr double kMaxGateTurnRate = 20.0;  ///< [rad/s]; * horizon stays within core::kMaxTurn

/// The first gate setting outside its range, its key as in YAML ("gate/stop_time"), or nothing.
std::optional<FieldError> findInvalidGateSetting(const GateConfig& config);

/// A velocity command as geometry_msgs/Twist holds it.
struct VelocityCommand {
  Eigen::Vector3d linear{0.0, 0.0, 0.0};   ///< [m/s]
  Eigen::Vector3d angular{0.0, 0.0, 0.0};  ///< [rad/s]
};

/// `command` with every component times `k`.
VelocityCommand scaledCommand(const VelocityCommand& command, double k);

/// A command's own rule: every component finite, each linear one within +-max_linear_speed and
/// each angular one within +-max_angular_speed. The violation names the field as in the message
/// ("linear.x", "nan", "a number within [-5, 5]"; the caller names the message), or nothing.
std::optional<FieldError> findInvalidCommand(const VelocityCommand& command,
                                             const GateConfig& config);

/// What the gate did with one command (the node's ~gate_state).
enum class GateAction { Pass, Slow, Stop, Escape, Timeout, Incomplete, Disabled };

/// "PASS", "SLOW", "STOP", "ESCAPE", "TIMEOUT", "INCOMPLETE", "DISABLED".
const char* toString(GateAction action);

struct GateDecision {
  GateAction action{GateAction::Stop};
  double scale{0.0};  ///< output = scale * input (1 for DISABLED)
  VelocityCommand input;
  VelocityCommand output;
  /// A contact within the horizon under the output command (for STOP: of a moving obstacle with
  /// the standing robot), else the limiting one that set the scale.
  bool contact_predicted{false};
  double time_to_contact_s{0.0};  ///< [s] from the command, when contact_predicted
  std::string link;               ///< the limiting link and obstacle ("" when none)
  std::string obstacle;
  Eigen::Vector2d contact_point{0.0, 0.0};  ///< in the fixed frame [m], when contact_predicted
  /// The links in the fixed frame at the predicted contact (or at the horizon when none), under
  /// the output command: the robot's outline to draw. Empty when nothing was predicted (DISABLED,
  /// refused commands, TIMEOUT, INCOMPLETE).
  std::vector<core::NamedEllipse> outline;
  /// The limiting obstacle where it stands at the command, in the fixed frame (when `obstacle`).
  core::Ellipse obstacle_ellipse;
  std::string reason;  ///< why, in words a user reads
};

/// A zero-output decision of `action` for `input` with `reason`.
GateDecision stoppedDecision(GateAction action, const VelocityCommand& input, std::string reason);

/// The robot frame's pose in the fixed frame's plane: position [m] and heading [rad].
struct PlanarPose {
  Eigen::Vector2d position{0.0, 0.0};
  double yaw{0.0};
};

/// The gate on a placed scene: `placed` (links and obstacles in the fixed frame, as a check placed
/// them) moved into the robot frame at `robot` (links rigidly with it, obstacles by
/// `obstacle_motions`, one per placed entry, zero for links, in the fixed frame), then
/// core::gateCommand() on the command's planar part (linear.x, linear.y, angular.z) and its answer
/// put back into the fixed frame. The action maps PASS, SLOW, STOP, ESCAPE one to one; a core
/// error stops (an internal failure never passes).
GateDecision decideOnScene(const VelocityCommand& command, const core::Scene& placed,
                           const std::vector<core::Motion>& obstacle_motions,
                           const PlanarPose& robot, const core::AllowedPairs& allowed,
                           const GateConfig& config);

}  // namespace ellipse_collision::app

#pragma once

#include <optional>
#include <string>

#include "ellipse_collision/app/field_error.h"
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
  /// How the base follows the output: reaction_time [s], max_linear_deceleration [m/s^2],
  /// max_angular_deceleration [rad/s^2]. All 0: the base is taken to follow at once (the braking
  /// rule is off, and the node says so).
  core::BaseDynamics base;
  /// nav_msgs/Odometry of the base: its measured twist is the base's velocity now ("" = the
  /// gate's last output is).
  std::string odom_topic;
};

/// The gate's decisions assume an ideal base (every deceleration 0, no reaction time): what the
/// log and /diagnostics say then, or "".
std::string idealBaseWarning(const GateConfig& config);

/// Accepted ranges (refused, never clamped) besides core::findInvalidGateSettings()' for
/// `timing`: cmd_vel_timeout within [0, core::kMaxGateHorizonS]; max_linear_speed within (0,
/// kMaxGateSpeed]; max_angular_speed within (0, kMaxGateTurnRate]; robot_frame a non-empty frame
/// without a leading '/'; `base` within core::findInvalidBaseDynamics()' ranges; odom_topic any
/// (a ROS name, checked by ROS).
constexpr double kMaxGateSpeed = 100.0;    ///< [m/s]
constexpr double kMaxGateTurnRate = 20.0;  ///< [rad/s]; * horizon stays within core::kMaxTurn

/// The first gate setting outside its range, its key as in YAML ("gate/stop_time"), or nothing.
std::optional<FieldError> findInvalidGateSetting(const GateConfig& config);

/// A core range violation (core::findInvalidGateSettings, core::findInvalidBaseDynamics) as the
/// configuration error of the key `prefix` + its field ("gate/reaction_time").
FieldError gateFieldError(const core::GateSettingViolation& v, const std::string& prefix = "gate/");

}  // namespace ellipse_collision::app

#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "demo_trajectory.h"
#include "ellipse_collision/core/velocity_gate.h"

namespace ellipse_collision {

/// The base's pose after `t_s` [s] of `twist` (in the base frame) held from `pose`: the exact arc
/// (core::poseAfter(), the motion the velocity gate predicts), composed onto `pose`.
Pose2D poseAfterArc(const Pose2D& pose, const core::Twist& twist, double t_s);

/// How the base drives to its next waypoint.
struct DriveSettings {
  double speed{0.4};         ///< forward speed when heading at the waypoint [m/s], > 0
  double turn_rate{0.8};     ///< largest turn rate [rad/s], > 0
  double heading_gain{1.5};  ///< turn rate per heading error [1/s], > 0
  double tolerance{0.3};     ///< a waypoint this close is reached [m], > 0
};

/// What the base does when the gate holds it: after `blocked_time` [s] of commands the gate
/// stopped, it reverses at `speed` [m/s] while turning at `turn_rate` [rad/s] (counter-clockwise
/// positive) for `duration` [s], then drives on to the next waypoint.
struct BackOffSettings {
  double blocked_time{1.0};  ///< [s], > 0
  double speed{0.25};        ///< [m/s], > 0
  double turn_rate{0.6};     ///< [rad/s]
  double duration{2.5};      ///< [s], > 0
};

/// The demo base's script: drive to each waypoint of a closed route in turn (turning toward it,
/// slower the more it lies to the side), and when the velocity gate stops the base, back out
/// with a turn and go on to the next waypoint. It only writes commands; the base moves by what
/// the gate lets through.
class BaseScript {
 public:
  /// `route` [m, odom frame]: at least one waypoint, visited in order and then from the first.
  BaseScript(std::vector<Eigen::Vector2d> route, DriveSettings drive, BackOffSettings back_off);

  /// The command for the base at `pose` at demo time `t_s`. `gate_stopped`: the gate's output
  /// for the last command was zero although the command was not.
  core::Twist command(const Pose2D& pose, double t_s, bool gate_stopped);

  std::size_t waypoint() const { return next_; }     ///< index of the waypoint it drives to
  bool backingOff(double t_s) const { return t_s < back_off_until_s_; }

 private:
  std::vector<Eigen::Vector2d> route_;
  DriveSettings drive_;
  BackOffSettings back_off_;
  std::size_t next_{0};
  std::optional<double> blocked_since_s_;  ///< demo time since which the gate holds the base
  double back_off_until_s_{-1.0};
};

}  // namespace ellipse_collision

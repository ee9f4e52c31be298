#pragma once

#include <deque>
#include <utility>

#include "ellipse_collision/core/base_braking.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/twist_motion.h"

namespace ellipse_collision::core {

/// A base that moves as a real one, to drive against the gate (its tests and the demo): it answers
/// `reaction_time` late and changes speed at bounded rates. Commands queue for the reaction time;
/// then the velocity moves toward the newest command it has seen along a straight line in twist
/// space, as fast as the slower of the two limits allows (so a twist scaled down keeps its arc, as
/// a velocity smoother that keeps the ratio does); a limit of 0 changes that part at once.
/// Speeding up uses the same limits (slower than the gate's model, which takes a rise at once).
/// The pose is integrated in steps of at most 1 ms, each the exact arc of the step's mean twist.
class SimulatedBase {
 public:
  /// At rest at `start` (start.time is the clock [s]), or moving at `velocity`.
  SimulatedBase(const BaseDynamics& dynamics, const PathPose& start, const Twist& velocity = {});

  /// A command sent at `t` [s]: the base acts on it from t + reaction_time.
  void command(double t, const Twist& twist);
  /// Moves the clock on to `t` [s] (an earlier `t` does nothing).
  void advanceTo(double t);

  /// Where the base is; pose().time is the clock [s].
  const PathPose& pose() const { return pose_; }
  const Twist& velocity() const { return velocity_; }
  double speed() const;
  double now() const { return pose_.time; }
  double travelled() const { return travelled_; }  ///< path of the origin [m]
  bool moving() const { return velocity_.vx != 0.0 || velocity_.vy != 0.0 || velocity_.wz != 0.0; }

 private:
  /// Moves the velocity toward the target for `dt` [s]; returns how long of it the ramp took [s].
  double rampToward(double dt);

  BaseDynamics dynamics_;
  PathPose pose_;
  Twist velocity_;
  Twist target_;
  std::deque<std::pair<double, Twist>> queue_;
  double travelled_{0.0};
};

}  // namespace ellipse_collision::core

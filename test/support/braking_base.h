#pragma once

// A simulated base that moves as a real one: it answers late and sheds speed at bounded rates.
// Commands queue for the reaction time; then the velocity moves toward the newest command it has
// seen along a straight line in twist space, as fast as the slower of the two limits allows (so a
// twist scaled down keeps its arc, as a velocity smoother that keeps the ratio does); a limit of
// 0 changes that part at once. Speeding up uses the same limits (slower than the gate's model,
// which takes a rise at once). The pose is integrated in 1 ms steps, each the exact arc of the
// step's mean twist.
#include <cmath>
#include <deque>
#include <utility>

#include "ellipse_collision/core/base_braking.h"
#include "ellipse_collision/core/twist_motion.h"

namespace ellipse_collision::test {

struct BasePose {
  double x{0.0};
  double y{0.0};
  double yaw{0.0};
};

class BrakingBase {
 public:
  BrakingBase(const core::BaseDynamics& dynamics, const BasePose& start,
              const core::Twist& velocity = {})
      : dynamics_(dynamics), pose_(start), velocity_(velocity), target_(velocity) {}

  /// A command sent at `t` [s] (the base acts on it from t + reaction_time).
  void command(double t, const core::Twist& twist) { queue_.emplace_back(t, twist); }

  /// Moves the clock to `t` [s], integrating the pose in steps of at most 1 ms.
  void advanceTo(double t) {
    while (now_ < t) {
      const double dt = std::min(1e-3, t - now_);
      while (!queue_.empty() && queue_.front().first + dynamics_.reaction_time <= now_) {
        target_ = queue_.front().second;
        queue_.pop_front();
      }
      const core::Twist before = velocity_;
      rampToward(dt);
      const core::Twist mean{0.5 * (before.vx + velocity_.vx), 0.5 * (before.vy + velocity_.vy),
                             0.5 * (before.wz + velocity_.wz)};
      const core::PathPose step = core::poseAfter(mean, dt);
      const double c = std::cos(pose_.yaw), s = std::sin(pose_.yaw);
      pose_.x += c * step.x - s * step.y;
      pose_.y += s * step.x + c * step.y;
      pose_.yaw += step.yaw;
      travelled_ += std::hypot(step.x, step.y);
      now_ += dt;
    }
  }

  const BasePose& pose() const { return pose_; }
  const core::Twist& velocity() const { return velocity_; }
  double speed() const { return std::hypot(velocity_.vx, velocity_.vy); }
  double now() const { return now_; }
  double travelled() const { return travelled_; }  ///< path of the origin [m]
  bool moving() const { return velocity_.vx != 0.0 || velocity_.vy != 0.0 || velocity_.wz != 0.0; }

 private:
  void rampToward(double dt) {
    const double dl = std::hypot(target_.vx - velocity_.vx, target_.vy - velocity_.vy);
    const double dw = std::fabs(target_.wz - velocity_.wz);
    double need = 0.0;  // seconds to reach the target at the limits
    if (dynamics_.linear_deceleration > 0.0)
      need = std::max(need, dl / dynamics_.linear_deceleration);
    if (dynamics_.angular_deceleration > 0.0) {
      need = std::max(need, dw / dynamics_.angular_deceleration);
    }
    const double f = need > dt ? dt / need : 1.0;
    velocity_.vx += f * (target_.vx - velocity_.vx);
    velocity_.vy += f * (target_.vy - velocity_.vy);
    velocity_.wz += f * (target_.wz - velocity_.wz);
    if (f == 1.0) velocity_ = target_;
  }

  core::BaseDynamics dynamics_;
  BasePose pose_;
  core::Twist velocity_;
  core::Twist target_;
  std::deque<std::pair<double, core::Twist>> queue_;
  double now_{0.0};
  double travelled_{0.0};
};

}  // namespace ellipse_collision::test

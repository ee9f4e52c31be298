#include "ellipse_collision/core/simulated_base.h"

#include <algorithm>
#include <cmath>

namespace ellipse_collision::core {

SimulatedBase::SimulatedBase(const BaseDynamics& dynamics, const PathPose& start,
                             const Twist& velocity)
    : dynamics_(dynamics), pose_(start), velocity_(velocity), target_(velocity) {}

void SimulatedBase::command(double t, const Twist& twist) { queue_.emplace_back(t, twist); }

double SimulatedBase::speed() const { return std::hypot(velocity_.vx, velocity_.vy); }

void SimulatedBase::advanceTo(double t) {
  while (pose_.time < t) {
    const double dt = std::min(1e-3, t - pose_.time);
    while (!queue_.empty() && queue_.front().first + dynamics_.reaction_time <= pose_.time) {
      target_ = queue_.front().second;
      queue_.pop_front();
    }
    const Twist before = velocity_;
    // The velocity is linear in time while it ramps (for `ramp` [s]), then constant: the mean
    // over the step is exact.
    const double ramp = rampToward(dt);
    const double w = ramp / (2 * dt);  // the weight of `before` in the mean
    const Twist mean{w * before.vx + (1 - w) * velocity_.vx, w * before.vy + (1 - w) * velocity_.vy,
                     w * before.wz + (1 - w) * velocity_.wz};
    const PathPose step = poseAfter(mean, dt);
    const double c = std::cos(pose_.yaw), s = std::sin(pose_.yaw);
    pose_.x += c * step.x - s * step.y;
    pose_.y += s * step.x + c * step.y;
    pose_.yaw += step.yaw;
    travelled_ += std::hypot(step.x, step.y);
    // A step shorter than 1 ms ends exactly at t, so the clock lands on it.
    pose_.time = dt < 1e-3 ? t : pose_.time + dt;
  }
}

double SimulatedBase::rampToward(double dt) {
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
  return std::min(need, dt);
}

}  // namespace ellipse_collision::core

#include "demo_base_control.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace ellipse_collision {

Pose2D poseAfterArc(const Pose2D& pose, const core::Twist& twist, double t_s) {
  const core::PathPose step = core::poseAfter(twist, t_s);
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  Pose2D after;
  after.position = pose.position + Eigen::Vector2d(c * step.x - s * step.y, s * step.x + c * step.y);
  after.yaw = std::remainder(pose.yaw + step.yaw, 2.0 * M_PI);
  return after;
}

BaseScript::BaseScript(std::vector<Eigen::Vector2d> route, DriveSettings drive,
                       BackOffSettings back_off)
    : route_(std::move(route)), drive_(drive), back_off_(back_off) {
  if (route_.empty()) throw std::invalid_argument("BaseScript: the route has no waypoint");
}

core::Twist BaseScript::command(const Pose2D& pose, double t_s, bool gate_stopped) {
  if (backingOff(t_s)) return {-back_off_.speed, 0.0, back_off_.turn_rate};
  if (!gate_stopped) {
    blocked_since_s_.reset();
  } else if (!blocked_since_s_) {
    blocked_since_s_ = t_s;
  } else if (t_s - *blocked_since_s_ >= back_off_.blocked_time) {
    // Held in front of something: back out, and give this waypoint up for the next one.
    blocked_since_s_.reset();
    back_off_until_s_ = t_s + back_off_.duration;
    next_ = (next_ + 1) % route_.size();
    return {-back_off_.speed, 0.0, back_off_.turn_rate};
  }
  if ((route_[next_] - pose.position).norm() < drive_.tolerance) {
    next_ = (next_ + 1) % route_.size();
  }
  const Eigen::Vector2d to = route_[next_] - pose.position;
  const double error = std::remainder(std::atan2(to.y(), to.x()) - pose.yaw, 2.0 * M_PI);
  core::Twist twist;
  twist.wz = std::clamp(drive_.heading_gain * error, -drive_.turn_rate, drive_.turn_rate);
  // Forward only while roughly facing the waypoint; turn on the spot otherwise.
  twist.vx = drive_.speed * std::max(0.0, std::cos(error));
  return twist;
}

}  // namespace ellipse_collision

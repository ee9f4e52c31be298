#include "demo_trajectory.h"

#include <cmath>

namespace ellipse_collision {
namespace {
constexpr double kTwoPi = 2.0 * M_PI;
}  // namespace

double SineMotion::at(double t_s) const {
  return offset + amplitude * std::sin(kTwoPi * t_s / period_s + phase);
}

Pose2D LoopPath::at(double t_s) const {
  const double phase = kTwoPi * t_s / period_s;
  Pose2D pose;
  pose.position = center + Eigen::Vector2d(radius_x * std::cos(phase), radius_y * std::sin(phase));
  // Direction of d(position)/dt; the positive factor 2 pi / period_s does not change it.
  pose.yaw = std::atan2(radius_y * std::cos(phase), -radius_x * std::sin(phase));
  return pose;
}

Eigen::Vector2d ShuttleMotion::at(double t_s) const {
  const double s = 0.5 - 0.5 * std::cos(kTwoPi * t_s / period_s);
  return start + s * (end - start);
}

}  // namespace ellipse_collision

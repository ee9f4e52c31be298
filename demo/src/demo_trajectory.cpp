#include "demo_trajectory.h"

#include <cmath>

namespace ellipse_collision {
namespace {
constexpr double kTwoPi = 2.0 * M_PI;
}  // namespace

double SineMotion::at(double t_s) const {
  return offset + amplitude * std::sin(kTwoPi * t_s / period_s + phase);
}

Eigen::Vector2d ShuttleMotion::at(double t_s) const {
  const double s = 0.5 - 0.5 * std::cos(kTwoPi * t_s / period_s);
  return start + s * (end - start);
}

}  // namespace ellipse_collision

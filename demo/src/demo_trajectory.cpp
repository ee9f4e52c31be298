#include "demo_trajectory.h"

#include <algorithm>
#include <cmath>

namespace ellipse_collision {
namespace {
constexpr double kTwoPi = 2.0 * M_PI;
}  // namespace

double SineMotion::at(double t_s) const {
  return offset + amplitude * std::sin(kTwoPi * t_s / period_s + phase);
}

double SineMotion::travel(double t0_s, double t1_s) const {
  // Between turning points (phase pi/2 + k pi) the joint moves one way: sum those stretches.
  const double a = kTwoPi * std::min(t0_s, t1_s) / period_s + phase;
  const double b = kTwoPi * std::max(t0_s, t1_s) / period_s + phase;
  double sum = 0.0;
  double from = a;
  for (double turn = M_PI / 2 + std::ceil((a - M_PI / 2) / M_PI) * M_PI; turn < b; turn += M_PI) {
    sum += std::abs(std::sin(turn) - std::sin(from));
    from = turn;
  }
  sum += std::abs(std::sin(b) - std::sin(from));
  return std::abs(amplitude) * sum;
}

Eigen::Vector2d ShuttleMotion::at(double t_s) const {
  const double s = 0.5 - 0.5 * std::cos(kTwoPi * t_s / period_s);
  return start + s * (end - start);
}

}  // namespace ellipse_collision

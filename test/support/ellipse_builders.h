#pragma once

// Builders of core::Ellipse for the tests: a given one, and a random one from a seeded source.

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "random_source.h"

namespace ellipse_collision::test {

/// The ellipse centred at (x, y) [m] with semi-axes radius_x, radius_y [m], turned by `angle`
/// [rad].
inline core::Ellipse makeEllipse(double x, double y, double radius_x, double radius_y,
                                 double angle = 0.0) {
  core::Ellipse e;
  e.center = Eigen::Vector2d(x, y);
  e.radius_x = radius_x;
  e.radius_y = radius_y;
  e.angle = angle;
  return e;
}

/// A random ellipse: centre uniform in the square of half-width `half_width` [m] about the
/// origin, major semi-axis log-uniform in [min_major, max_major) [m], axis ratio log-uniform in
/// [1, max_ratio), either axis the major one, angle uniform in [-max_angle, max_angle) [rad]
/// (drawn in that order).
inline core::Ellipse randomEllipse(RandomSource& random, double half_width, double min_major,
                                   double max_major, double max_ratio,
                                   double max_angle = 3.14159265358979323846) {
  core::Ellipse e;
  e.center = {random.uniform(-half_width, half_width), random.uniform(-half_width, half_width)};
  const double major = random.logUniform(min_major, max_major);
  const double minor = major / random.logUniform(1.0, max_ratio);
  const bool x_is_major = random.coin();
  e.radius_x = x_is_major ? major : minor;
  e.radius_y = x_is_major ? minor : major;
  e.angle = random.uniform(-max_angle, max_angle);
  return e;
}

/// `ellipses` given in a body's frame, placed in the world where the body is at (x, y) [m] turned
/// by `yaw` [rad].
inline std::vector<core::Ellipse> placedAt(const std::vector<core::Ellipse>& ellipses, double x,
                                           double y, double yaw) {
  std::vector<core::Ellipse> placed;
  placed.reserve(ellipses.size());
  for (core::Ellipse e : ellipses) {
    const Eigen::Vector2d c = e.center;
    e.center = {x + std::cos(yaw) * c.x() - std::sin(yaw) * c.y(),
                y + std::sin(yaw) * c.x() + std::cos(yaw) * c.y()};
    e.angle += yaw;
    placed.push_back(e);
  }
  return placed;
}

}  // namespace ellipse_collision::test

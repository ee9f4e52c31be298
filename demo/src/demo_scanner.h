#pragma once

#include <vector>

#include "demo_trajectory.h"
#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision {

/// The simulated planar laser scanner of the demo: beam i at angle_min + i angle_increment [rad]
/// in the sensor's frame, `beams` beams, ranges within [range_min, range_max] [m].
struct ScannerModel {
  int beams{720};
  double angle_min{-3.14159265358979323846};
  double angle_increment{2.0 * 3.14159265358979323846 / 720.0};
  double range_min{0.05};
  double range_max{8.0};
};

/// Distance [m] along the ray origin + t direction (direction of unit length), t >= 0, to the
/// first point of `ellipse`'s rim, or infinity when the ray misses it or starts inside it.
double rayHit(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
              const core::Ellipse& ellipse);

/// The ranges [m] a scanner at `sensor` (pose in the world frame) measures of `world` ellipses
/// (in the same world frame): the nearest hit per beam, +infinity where a beam hits nothing
/// within range_max (sensor_msgs/LaserScan's convention for "no return").
std::vector<float> rayCastScan(const Pose2D& sensor, const std::vector<core::Ellipse>& world,
                               const ScannerModel& model);

}  // namespace ellipse_collision

#pragma once

#include <vector>

#include "demo_trajectory.h"
#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision {

/// The demo's world as its simulated scanner sees it, in the odom frame: the static obstacles
/// (demo_driver.yaml's `static_obstacles`) and the moving one (`moving_obstacle`) on its shuttle.
/// The collision node knows none of them but through the scan.
struct DemoWorld {
  std::vector<core::Ellipse> static_obstacles;
  core::Ellipse moving;  ///< the moving obstacle's shape; its centre is where `shuttle` puts it
  ShuttleMotion shuttle;
  /// Every obstacle at demo time t [s]: the static ones, then the moving one.
  std::vector<core::Ellipse> at(double t_s) const;
};

}  // namespace ellipse_collision

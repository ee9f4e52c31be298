#pragma once

// Obstacles strewn over a square floor, the same for every benchmark that places them (the
// application layer's, the node's through ROS): centres uniform in [-half_side, half_side]^2
// outside a clearing about the origin, angles uniform, radius_x in [0.05, 0.4] m and radius_y half
// of it. The draws come in a fixed order from one seeded generator, so a benchmark's scene is the
// same from run to run and from commit to commit.

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"

namespace ellipse_collision::bench {

struct FloorObstacle {
  double x, y, angle, radius_x, radius_y;  ///< [m], [rad]
};

inline std::vector<FloorObstacle> floorObstacles(int count, double half_side, double clearing,
                                                 unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> position(-half_side, half_side), radius(0.05, 0.4),
      angle(-3.1, 3.1);
  std::vector<FloorObstacle> obstacles;
  obstacles.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    FloorObstacle o{};
    do {
      o.x = position(rng);
      o.y = position(rng);
    } while (clearing > 0.0 && std::hypot(o.x, o.y) < clearing);
    o.angle = angle(rng);
    o.radius_x = radius(rng);
    o.radius_y = 0.5 * o.radius_x;
    obstacles.push_back(o);
  }
  return obstacles;
}

/// floorObstacles() as the application layer stores them: named obstacle_0, obstacle_1, ... in
/// `frame`.
inline std::vector<app::EllipseSpec> floorObstacleSpecs(int count, double half_side,
                                                        double clearing, unsigned seed,
                                                        const std::string& frame) {
  std::vector<app::EllipseSpec> specs;
  int i = 0;
  for (const FloorObstacle& o : floorObstacles(count, half_side, clearing, seed)) {
    app::EllipseSpec spec;
    spec.name = "obstacle_" + std::to_string(i++);
    spec.frame_id = frame;
    spec.x = o.x;
    spec.y = o.y;
    spec.angle = o.angle;
    spec.radius_x = o.radius_x;
    spec.radius_y = o.radius_y;
    specs.push_back(spec);
  }
  return specs;
}

}  // namespace ellipse_collision::bench

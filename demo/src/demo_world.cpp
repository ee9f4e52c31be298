#include "demo_world.h"

namespace ellipse_collision {

std::vector<core::Ellipse> DemoWorld::at(double t_s) const {
  std::vector<core::Ellipse> world = static_obstacles;
  core::Ellipse moved = moving;
  moved.center = shuttle.at(t_s);
  world.push_back(moved);
  return world;
}

}  // namespace ellipse_collision

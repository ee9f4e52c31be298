#pragma once

// Helpers shared by the scene-check tests: building named ellipses and the pair rules restated as
// a table, written independently of scene_check.cpp so that the tests compare against it.
#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core::scene_test {

/// The ellipse centred at (x, y) [m] with semi-axes rx, ry [m], turned by `angle` [rad].
inline Ellipse ellipse(double x, double y, double rx, double ry, double angle = 0.0) {
  Ellipse e;
  e.center = Eigen::Vector2d(x, y);
  e.radius_x = rx;
  e.radius_y = ry;
  e.angle = angle;
  return e;
}

inline NamedEllipse ellipse(const std::string& name, EllipseRole role, double x, double y,
                            double rx, double ry, double angle = 0.0) {
  return NamedEllipse{name, role, ellipse(x, y, rx, ry, angle)};
}

inline NamedEllipse circle(const std::string& name, EllipseRole role, double x, double y,
                           double r) {
  return ellipse(name, role, x, y, r, r);
}

using Names = std::vector<std::pair<std::string, std::string>>;

/// Which role combinations are checked, as a table.
inline bool rolesChecked(EllipseRole a, EllipseRole b, bool self_collision) {
  const std::map<std::pair<EllipseRole, EllipseRole>, bool> table = {
      {{EllipseRole::Link, EllipseRole::Link}, self_collision},
      {{EllipseRole::Link, EllipseRole::Obstacle}, true},
      {{EllipseRole::Obstacle, EllipseRole::Link}, true},
      {{EllipseRole::Obstacle, EllipseRole::Obstacle}, false},
      {{EllipseRole::Query, EllipseRole::Link}, true},
      {{EllipseRole::Link, EllipseRole::Query}, true},
      {{EllipseRole::Query, EllipseRole::Obstacle}, true},
      {{EllipseRole::Obstacle, EllipseRole::Query}, true},
      {{EllipseRole::Query, EllipseRole::Query}, false}};
  return table.at({a, b});
}

/// `scene` as the node places it: role by role, each role in name order (its registry is a
/// std::map, names unique), so that the movers come already ranked.
inline std::vector<NamedEllipse> inRegistryOrder(std::vector<NamedEllipse> scene) {
  std::sort(scene.begin(), scene.end(), [](const NamedEllipse& a, const NamedEllipse& b) {
    return a.role != b.role ? a.role < b.role : a.name < b.name;
  });
  return scene;
}

/// The order in which a pair's members are reported: query, then link, then obstacle.
inline int roleRank(EllipseRole role) {
  switch (role) {
    case EllipseRole::Query:
      return 0;
    case EllipseRole::Link:
      return 1;
    case EllipseRole::Obstacle:
      return 2;
  }
  return -1;
}

}  // namespace ellipse_collision::core::scene_test

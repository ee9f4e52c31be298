#pragma once

// Builders of the application layer's EllipseSpec for the app tests.

#include <string>

#include "ellipse_collision/app/ellipse_spec.h"

namespace ellipse_collision::test {

/// A circle of `radius` [m] at (x, y) [m] in `frame`.
inline app::EllipseSpec circle(const std::string& name, const std::string& frame, double x,
                               double y, double radius) {
  app::EllipseSpec spec;
  spec.name = name;
  spec.frame_id = frame;
  spec.x = x;
  spec.y = y;
  spec.radius_x = radius;
  spec.radius_y = radius;
  return spec;
}

}  // namespace ellipse_collision::test

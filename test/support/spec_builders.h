#pragma once

// Builders of the application layer's EllipseSpec and FrameTransform for the app tests.

#include <Eigen/Core>
#include <map>
#include <string>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/transform_lookup.h"

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

/// `frame`'s transform from a table of frames translated in the plane [m]; frames not in the
/// table are unavailable.
inline app::FrameTransform translated(const std::map<std::string, Eigen::Vector2d>& table,
                                      const std::string& frame) {
  app::FrameTransform t;
  const auto found = table.find(frame);
  if (found == table.end()) {
    t.error = "frame '" + frame + "' does not exist";
    return t;
  }
  t.ok = true;
  t.fixed_from_frame.translation() << found->second, 0.0;
  return t;
}

}  // namespace ellipse_collision::test

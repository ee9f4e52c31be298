#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <string>

namespace ellipse_collision::app {

/// The pose of one frame in the fixed frame, or why there is none.
struct FrameTransform {
  bool ok{false};
  Eigen::Isometry3d fixed_from_frame{Eigen::Isometry3d::Identity()};
  std::string error;  ///< why not, when !ok (the tf error)
};

/// How the application layer asks for transforms. The ROS layer binds tf, the fixed frame, the
/// time and the timeout into one of these; tests and fuzzers pass a table of poses. A frame is its
/// own identity transform, so ellipses given in the fixed frame need no lookup at all.
using TransformLookup = std::function<FrameTransform(const std::string& frame)>;

}  // namespace ellipse_collision::app

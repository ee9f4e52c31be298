#pragma once

#include <ros/duration.h>
#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include <Eigen/Geometry>
#include <map>
#include <string>

#include "ellipse_collision/ros/ellipse_spec.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision {

/// Places ellipses attached to tf frames into the fixed frame's plane for one check: each frame is
/// looked up once (lookupTransformSafe()), then the core projects the ellipse (projectToPlane()).
class ScenePlacement {
 public:
  enum class Status { Placed, FrameUnavailable, Degenerate };

  struct Placement {
    Status status{Status::Placed};
    core::NamedEllipse ellipse;  ///< in the fixed frame, when Placed
    std::string error;     ///< the tf error or the projection error otherwise
  };

  /// `time` zero = latest transforms; `timeout` bounds the wait for each frame [s].
  ScenePlacement(const tf2_ros::Buffer& buffer, std::string fixed_frame, double global_padding_m,
                 ros::Time time, ros::Duration timeout);

  Placement place(const EllipseSpec& spec, core::EllipseRole role);

 private:
  struct FrameLookup {
    bool ok{false};
    Eigen::Isometry3d fixed_from_frame{Eigen::Isometry3d::Identity()};
    std::string error;
  };
  const FrameLookup& lookup(const std::string& frame);

  const tf2_ros::Buffer& buffer_;
  std::string fixed_frame_;
  double global_padding_m_;
  ros::Time time_;
  ros::Duration timeout_;
  std::map<std::string, FrameLookup> frames_;
};

}  // namespace ellipse_collision

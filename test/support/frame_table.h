#pragma once

// A tf stand-in for the application-layer tests: frames by name, each optionally stamped.

#include <Eigen/Geometry>
#include <map>
#include <string>

#include "ellipse_collision/app/transform_lookup.h"

namespace ellipse_collision::test {

/// The pose (x, y) [m], turned by `yaw` [rad] about z.
inline Eigen::Isometry3d yawedPose(double x, double y, double yaw) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Eigen::Vector3d(x, y, 0.0));
  pose.rotate(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return pose;
}

/// Frames by name (fixed_from_frame), changeable between lookups, with a stamp [s] where one is
/// given (none: timeless); counts lookups per frame in *lookups. An unknown frame is unavailable
/// with the error "no frame '<name>'".
struct FrameTable {
  std::map<std::string, Eigen::Isometry3d> poses;
  std::map<std::string, double> stamps;
  std::map<std::string, int>* lookups;
  app::FrameTransform operator()(const std::string& frame) const {
    ++(*lookups)[frame];
    app::FrameTransform transform;
    const auto found = poses.find(frame);
    if (found == poses.end()) {
      transform.error = "no frame '" + frame + "'";
      return transform;
    }
    transform.ok = true;
    transform.fixed_from_frame = found->second;
    if (stamps.count(frame)) transform.stamp_s = stamps.at(frame);
    return transform;
  }
};

}  // namespace ellipse_collision::test

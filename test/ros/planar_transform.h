#pragma once

// The tf of a pose in the plane, for the ROS-layer tests that play a robot's base or a sensor.

#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>

#include <cmath>
#include <string>

namespace ellipse_collision::test {

/// `child` at (x, y) [m] in `parent`, turned by `yaw` [rad] about z, at `stamp`.
inline geometry_msgs::TransformStamped planarTransform(const std::string& parent,
                                                       const std::string& child, double x, double y,
                                                       double yaw, const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.frame_id = parent;
  t.header.stamp = stamp;
  t.child_frame_id = child;
  t.transform.translation.x = x;
  t.transform.translation.y = y;
  t.transform.rotation.z = std::sin(yaw / 2);
  t.transform.rotation.w = std::cos(yaw / 2);
  return t;
}

}  // namespace ellipse_collision::test

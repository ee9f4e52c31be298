#pragma once

#include <ros/time.h>
#include <visualization_msgs/Marker.h>

#include <cstdint>
#include <string>

namespace ellipse_collision {

/// A marker with only its identity set (frame, stamp, namespace, id) and an identity pose: what
/// every marker the node publishes starts from (the caller sets type, action and geometry).
inline visualization_msgs::Marker blankMarker(const std::string& frame_id, const ros::Time& stamp,
                                              const std::string& ns, std::int32_t id) {
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame_id;
  marker.header.stamp = stamp;
  marker.ns = ns;
  marker.id = id;
  marker.pose.orientation.w = 1.0;
  return marker;
}

}  // namespace ellipse_collision

#pragma once

// A sensor_msgs/PointCloud2 of float32 x, y, z points for the ROS-layer tests.

#include <ros/time.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ellipse_collision::test {

/// `points` [m] in `frame` at `stamp`, as an unorganised cloud (height 1).
inline sensor_msgs::PointCloud2 xyzCloud(const std::vector<Eigen::Vector3f>& points,
                                         const std::string& frame, const ros::Time& stamp) {
  sensor_msgs::PointCloud2 cloud;
  cloud.header.frame_id = frame;
  cloud.header.stamp = stamp;
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  modifier.setPointCloud2FieldsByString(1, "xyz");
  modifier.resize(points.size());
  sensor_msgs::PointCloud2Iterator<float> x(cloud, "x"), y(cloud, "y"), z(cloud, "z");
  for (const Eigen::Vector3f& p : points) {
    *x = p.x(), *y = p.y(), *z = p.z();
    ++x, ++y, ++z;
  }
  return cloud;
}

}  // namespace ellipse_collision::test

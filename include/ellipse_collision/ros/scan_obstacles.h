#pragma once

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_ros/buffer.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ellipse_collision/app/scan_obstacles.h"
#include "ellipse_collision/app/sensor_obstacle_series.h"
#include "ellipse_collision/ros/messages.h"
#include "ellipse_collision/ros/tf_listener.h"

namespace ellipse_collision {

/// The x, y, z fields of every point of `cloud` [m], in the cloud's frame (any layout
/// sensor_msgs::PointCloud2ConstIterator reads). Throws std::runtime_error when a field is missing.
std::vector<Eigen::Vector3f> cloudPoints(const sensor_msgs::PointCloud2& cloud);

/// The obstacles of one sensor message as an EllipseArray with the sensor's header.
EllipseArray toMsg(const app::SensorObstacles& obstacles, const std_msgs::Header& header);

/// The ellipses of one LaserScan (its header's frame).
app::SensorObstacles scanObstacles(const sensor_msgs::LaserScan& scan,
                                   const app::ScanObstacleSettings& settings);
/// The ellipses of the next LaserScan of `series` (its header's frame).
app::SensorObstacles scanObstacles(const sensor_msgs::LaserScan& scan,
                                   app::SensorObstacleSeries& series);

/// Puts the tracked velocities on `obstacles`, the last scan's (or, `cloud`, cloud's) of `series`
/// with `header`: the sensor's pose in series.tracking().fixed_frame from tf at the stamp, waiting
/// up to `wait` for it, else tf's latest within 0.1 s of the stamp (app::ObstacleTracker).
/// Without either every obstacle stands and the reason is returned; "" when tracked or tracking
/// is off.
std::string trackSensorObstacles(const tf2_ros::Buffer& tf, app::SensorObstacleSeries& series,
                                 app::SensorObstacles& obstacles, const std_msgs::Header& header,
                                 bool cloud, const ros::Duration& wait);

/// scan_obstacles: turns `scan` (sensor_msgs/LaserScan) and `cloud` (sensor_msgs/PointCloud2,
/// points within a z band) into obstacle ellipses on `obstacles` (EllipseArray, header = the
/// sensor's frame and stamp): every return inside an ellipse, no ellipse in the free part of any
/// beam, each contour in as few ellipses as that allows (README: scan_obstacles). With `tracking`
/// on (the default) each obstacle carries the velocity of the thing it was cut from, tracked in
/// tracking/fixed_frame through tf (app::ObstacleTracker).
class ScanObstaclesNode {
 public:
  /// Reads and validates the private parameters first; throws ConfigError naming the key.
  ScanObstaclesNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh);

 private:
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan);
  void onCloud(const sensor_msgs::PointCloud2::ConstPtr& cloud);
  /// Puts the tracked velocities on `obstacles` (the sensor's pose from tf at the stamp); without
  /// that transform every obstacle stands, and the log says why.
  void track(app::SensorObstacles& obstacles, const std_msgs::Header& header, bool cloud);
  void publish(const app::SensorObstacles& obstacles, const std_msgs::Header& header);

  ros::NodeHandle nh_;
  app::SensorObstacleSeries series_;  ///< settings, and cuts and names kept from message to message
  ros::Publisher obstacles_pub_;
  ros::Subscriber scan_sub_;
  ros::Subscriber cloud_sub_;
  tf2_ros::Buffer tf_buffer_;
  TfListener tf_listener_{tf_buffer_};
};

}  // namespace ellipse_collision

#include "ellipse_collision/ros/scan_obstacles.h"

#include <sensor_msgs/point_cloud2_iterator.h>

#include <boost/make_shared.hpp>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/ros/conversions.h"
#include "ellipse_collision/ros/param_reading.h"
#include "ellipse_collision/ros/scan_params.h"
#include "ellipse_collision/ros/tf_lookup.h"

namespace ellipse_collision {

std::vector<Eigen::Vector3f> cloudPoints(const sensor_msgs::PointCloud2& cloud) {
  std::vector<Eigen::Vector3f> points;
  points.reserve(static_cast<std::size_t>(cloud.width) * cloud.height);
  // The iterator throws std::runtime_error for a missing field.
  sensor_msgs::PointCloud2ConstIterator<float> x(cloud, "x"), y(cloud, "y"), z(cloud, "z");
  for (; x != x.end(); ++x, ++y, ++z) points.emplace_back(*x, *y, *z);
  return points;
}

EllipseArray toMsg(const app::SensorObstacles& obstacles, const std_msgs::Header& header) {
  EllipseArray msg;
  msg.header = header;
  msg.ellipses.reserve(obstacles.ellipses.size());
  for (const app::EllipseSpec& spec : obstacles.ellipses) msg.ellipses.push_back(toMsg(spec));
  return msg;
}

app::SensorObstacles scanObstacles(const sensor_msgs::LaserScan& scan,
                                   const app::ScanObstacleSettings& settings) {
  return app::scanObstacles(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min,
                            scan.range_max, scan.header.frame_id, settings);
}

std::string trackSensorObstacles(const tf2_ros::Buffer& tf, app::SensorObstacleSeries& series,
                                 app::SensorObstacles& obstacles, const std_msgs::Header& header,
                                 bool cloud, const ros::Duration& wait) {
  if (!series.tracking().enabled) return "";
  Eigen::Isometry3d fixed_from_sensor;
  std::string error;
  // The sensor's pose at the message's stamp: its own motion taken out of the centroids. When tf
  // has not caught up with the stamp, its latest pose if within kLatestPoseSlackS of it: a lag
  // that stays the same shifts every centroid alike and leaves the velocities as they are.
  constexpr double kLatestPoseSlackS = 0.1;
  const std::string& fixed = series.tracking().fixed_frame;
  bool found = lookupTransformSafe(tf, fixed, header.frame_id, header.stamp, wait,
                                   fixed_from_sensor, &error);
  if (!found) {
    ros::Time latest;
    found = lookupTransformSafe(tf, fixed, header.frame_id, ros::Time(0), ros::Duration(0),
                                fixed_from_sensor, nullptr, &latest) &&
            (latest.isZero() || std::abs((latest - header.stamp).toSec()) <= kLatestPoseSlackS);
  }
  if (!found) {
    app::standStill(obstacles);
    return "no velocities (every obstacle stands): " + error;
  }
  const Eigen::Vector3d x_axis = fixed_from_sensor.linear().col(0);
  const core::PathPose sensor{fixed_from_sensor.translation().x(),
                              fixed_from_sensor.translation().y(),
                              std::atan2(x_axis.y(), x_axis.x()), 0.0};
  if (cloud) {
    series.trackCloud(header.stamp.toSec(), sensor, obstacles);
  } else {
    series.trackScan(header.stamp.toSec(), sensor, obstacles);
  }
  return "";
}

app::SensorObstacles scanObstacles(const sensor_msgs::LaserScan& scan,
                                   app::SensorObstacleSeries& series) {
  return series.scan(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min,
                     scan.range_max, scan.header.frame_id);
}

namespace {

/// The private namespace read once, the pipeline's and the tracking's settings parsed from it.
app::SensorObstacleSeries seriesFromParameters(const ros::NodeHandle& private_nh) {
  const XmlRpc::XmlRpcValue parameters = params::privateNamespace(private_nh);
  app::ScanObstacleSettings settings = parseScanObstacleSettings(parameters);
  return app::SensorObstacleSeries(std::move(settings), parseTrackingSettings(parameters));
}

}  // namespace

ScanObstaclesNode::ScanObstaclesNode(const ros::NodeHandle& nh, const ros::NodeHandle& private_nh)
    : nh_(nh), series_(seriesFromParameters(private_nh)) {
  obstacles_pub_ = nh_.advertise<EllipseArray>("obstacles", 1);
  scan_sub_ = nh_.subscribe<sensor_msgs::LaserScan>("scan", 1, &ScanObstaclesNode::onScan, this);
  cloud_sub_ =
      nh_.subscribe<sensor_msgs::PointCloud2>("cloud", 1, &ScanObstaclesNode::onCloud, this);
  const app::ScanObstacleSettings& s = series_.settings();
  ROS_INFO_STREAM("scan_obstacles: contours of >= "
                  << s.min_cluster_points << " returns (breakpoints for range noise "
                  << s.range_noise_sigma << " m, always joined closer than " << s.cluster_distance
                  << " m), min_radius " << s.min_radius << " m, free space up to "
                  << s.free_space_tolerance << " m before each return, cloud z within ["
                  << s.z_min << ", " << s.z_max << "] m");
  const app::TrackingSettings& t = series_.tracking();
  if (t.enabled) {
    ROS_INFO_STREAM("scan_obstacles: tracking in "
                    << t.fixed_frame << ": velocities once seen " << t.confirm_count
                    << " times, at least " << t.min_speed << " m/s, things up to " << t.max_size
                    << " m from their centre");
  }
}

void ScanObstaclesNode::onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
  app::SensorObstacles obstacles = scanObstacles(*scan, series_);
  track(obstacles, scan->header, false);
  publish(obstacles, scan->header);
}

void ScanObstaclesNode::track(app::SensorObstacles& obstacles, const std_msgs::Header& header,
                              bool cloud) {
  const std::string error =
      trackSensorObstacles(tf_buffer_, series_, obstacles, header, cloud, ros::Duration(0.05));
  if (!error.empty()) ROS_WARN_STREAM_THROTTLE(5.0, "scan_obstacles: " << error);
}

void ScanObstaclesNode::onCloud(const sensor_msgs::PointCloud2::ConstPtr& cloud) {
  try {
    app::SensorObstacles obstacles = series_.cloud(cloudPoints(*cloud), cloud->header.frame_id);
    track(obstacles, cloud->header, true);
    publish(obstacles, cloud->header);
  } catch (const std::runtime_error& error) {
    ROS_WARN_STREAM_THROTTLE(5.0, "scan_obstacles: refused a cloud: " << error.what());
  }
}

void ScanObstaclesNode::publish(const app::SensorObstacles& obstacles,
                                const std_msgs::Header& header) {
  if (!obstacles.skipped.empty()) {
    ROS_WARN_STREAM_THROTTLE(5.0, "scan_obstacles: skipped " << app::joinText(obstacles.skipped, "; "));
  }
  // As a shared_ptr: a subscriber in the same nodelet manager (CollisionNodelet) gets this very
  // message, not a serialised copy (roscpp serialises a message published by reference).
  obstacles_pub_.publish(boost::make_shared<EllipseArray>(toMsg(obstacles, header)));
}

}  // namespace ellipse_collision

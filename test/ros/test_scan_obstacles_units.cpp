// scan_obstacles without a master: its parameters (defaults, types, ranges naming the key), the
// PointCloud2 conversion and z band, the EllipseArray with the sensor's header.
#include <gtest/gtest.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <cmath>
#include <limits>
#include <string>

#include "ellipse_collision/ros/node_config.h"
#include "ellipse_collision/ros/scan_obstacles.h"

namespace ellipse_collision {
namespace {

std::string settingsError(const XmlRpc::XmlRpcValue& params) {
  try {
    parseScanObstacleSettings(params);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(ScanObstacleSettings, DefaultsAndOverrides) {
  const app::ScanObstacleSettings defaults = parseScanObstacleSettings(XmlRpc::XmlRpcValue());
  EXPECT_EQ(defaults.cluster_distance, 0.1);
  EXPECT_EQ(defaults.min_cluster_points, 3);
  EXPECT_EQ(defaults.min_radius, 0.05);
  EXPECT_EQ(defaults.z_min, 0.0);
  EXPECT_EQ(defaults.z_max, 2.0);
  XmlRpc::XmlRpcValue params;
  params["cluster_distance"] = 1;  // ints are numbers
  params["min_cluster_points"] = 1;
  params["z_min"] = -0.5;
  const auto settings = parseScanObstacleSettings(params);
  EXPECT_EQ(settings.cluster_distance, 1.0);
  EXPECT_EQ(settings.min_cluster_points, 1);
  EXPECT_EQ(settings.z_min, -0.5);
}

TEST(ScanObstacleSettings, BadValuesNameTheKey) {
  XmlRpc::XmlRpcValue params;
  params["cluster_distance"] = -0.1;
  EXPECT_EQ(settingsError(params),
            "parameter ~cluster_distance, key 'cluster_distance': expected a number within "
            "[1e-06, 1000], got -0.1");
  params = XmlRpc::XmlRpcValue();
  params["min_cluster_points"] = 2.5;
  EXPECT_NE(settingsError(params).find("key 'min_cluster_points': expected an integer"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["min_radius"] = 0.0;
  EXPECT_NE(settingsError(params).find("key 'min_radius'"), std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["z_min"] = 1.0;
  params["z_max"] = 0.5;
  EXPECT_NE(settingsError(params).find("key 'z_max': expected a number >= z_min = 1"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["cluster_distanse"] = 0.1;
  EXPECT_NE(settingsError(params).find("parameter ~cluster_distanse: unknown key"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["z_max"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(settingsError(params).find("key 'z_max'"), std::string::npos);
}

sensor_msgs::PointCloud2 cloudOf(const std::vector<Eigen::Vector3f>& points) {
  sensor_msgs::PointCloud2 cloud;
  cloud.header.frame_id = "camera";
  cloud.header.stamp = ros::Time(7, 8);
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  modifier.setPointCloud2FieldsByString(1, "xyz");
  modifier.resize(points.size());
  sensor_msgs::PointCloud2Iterator<float> x(cloud, "x"), y(cloud, "y"), z(cloud, "z");
  for (const auto& p : points) {
    *x = p.x(), *y = p.y(), *z = p.z();
    ++x, ++y, ++z;
  }
  return cloud;
}

TEST(ScanObstaclesCloud, PointsWithinTheZBandMakeEllipsesWithTheSensorHeader) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 10; ++i) {
    points.emplace_back(1.0f + 0.01f * i, 0.02f * (i % 3), 0.5f);  // a blob at (1, 0)
    points.emplace_back(-1.0f, 0.01f * i, 3.0f);                   // above z_max: ignored
    points.emplace_back(-2.0f, 0.01f * i, -0.2f);                  // below z_min: ignored
  }
  points.emplace_back(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.5f);
  const sensor_msgs::PointCloud2 cloud = cloudOf(points);
  ASSERT_EQ(cloudPoints(cloud).size(), points.size());
  const auto obstacles =
      app::cloudObstacles(cloudPoints(cloud), cloud.header.frame_id, app::ScanObstacleSettings{});
  const EllipseArray msg = toMsg(obstacles, cloud.header);
  EXPECT_EQ(msg.header.frame_id, "camera");
  EXPECT_EQ(msg.header.stamp, ros::Time(7, 8));
  ASSERT_EQ(msg.ellipses.size(), 1u);
  EXPECT_EQ(msg.ellipses[0].name, "scan_0");
  EXPECT_EQ(msg.ellipses[0].frame_id, "camera");
  EXPECT_NEAR(msg.ellipses[0].x, 1.045, 0.01);
}

TEST(ScanObstaclesCloud, CloudWithoutXyzIsAnErrorNotACrash) {
  sensor_msgs::PointCloud2 cloud;
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  modifier.setPointCloud2FieldsByString(1, "rgb");
  modifier.resize(3);
  EXPECT_THROW(cloudPoints(cloud), std::runtime_error);
}

TEST(ScanObstaclesScan, HostileRangesAreSkipped) {
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";
  scan.angle_min = 0.0f;
  scan.angle_increment = 0.01f;
  scan.range_min = 0.1f;
  scan.range_max = 5.0f;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  scan.ranges = {1.0f, 1.0f, nan, 1.0f, inf, -inf, 0.0f, 9.0f, 1.0f};
  const auto obstacles = scanObstacles(scan, app::ScanObstacleSettings{});
  ASSERT_EQ(obstacles.ellipses.size(), 1u);  // the four 1 m returns, one cluster
  EXPECT_EQ(obstacles.ellipses[0].frame_id, "laser");
  EXPECT_TRUE(scanObstacles(sensor_msgs::LaserScan(), app::ScanObstacleSettings{}).ellipses.empty());
}

}  // namespace
}  // namespace ellipse_collision

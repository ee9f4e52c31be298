// scan_obstacles without a master: its parameters (defaults, types, ranges naming the key), the
// PointCloud2 conversion and z band, the EllipseArray with the sensor's header.
#include <gtest/gtest.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ellipse_collision/ros/param_reading.h"
#include "ellipse_collision/ros/scan_obstacles.h"
#include "ellipse_collision/ros/scan_params.h"
#include "xyz_cloud.h"

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

std::string trackingError(const XmlRpc::XmlRpcValue& params) {
  try {
    parseTrackingSettings(params);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(TrackingSettings, DefaultsOverridesAndBadValuesNamingTheKey) {
  const app::TrackingSettings defaults = parseTrackingSettings(XmlRpc::XmlRpcValue());
  EXPECT_TRUE(defaults.enabled);
  EXPECT_EQ(defaults.fixed_frame, "odom");
  EXPECT_EQ(defaults.confirm_count, 8);
  XmlRpc::XmlRpcValue params;
  params["tracking"]["enabled"] = false;
  params["tracking"]["fixed_frame"] = "map";
  params["tracking"]["max_speed"] = 2;  // ints are numbers
  params["tracking"]["confirm_count"] = 4;
  const app::TrackingSettings set = parseTrackingSettings(params);
  EXPECT_FALSE(set.enabled);
  EXPECT_EQ(set.fixed_frame, "map");
  EXPECT_EQ(set.max_speed, 2.0);
  EXPECT_EQ(set.confirm_count, 4);
  // The scan keys accept `tracking` beside them.
  EXPECT_EQ(settingsError(params), "");

  params = XmlRpc::XmlRpcValue();
  params["tracking"]["min_speed"] = 4.0;  // above max_speed 3
  EXPECT_EQ(trackingError(params),
            "parameter ~tracking/min_speed, key 'tracking/min_speed': expected a number within "
            "[0, 3], got 4");
  params = XmlRpc::XmlRpcValue();
  params["tracking"]["confirm_count"] = 1.5;
  EXPECT_NE(trackingError(params).find("key 'tracking/confirm_count': expected an integer"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["tracking"]["fixed_frame"] = "/odom";
  EXPECT_NE(trackingError(params).find("key 'tracking/fixed_frame'"), std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["tracking"]["max_sped"] = 1.0;
  EXPECT_NE(trackingError(params).find("parameter ~tracking/max_sped, key 'tracking/max_sped': "
                                       "expected one of enabled, fixed_frame"),
            std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["tracking"] = 1.0;
  EXPECT_NE(trackingError(params).find("expected a dict"), std::string::npos);
}

TEST(ScanObstacleSettings, DefaultsAndOverrides) {
  const app::ScanObstacleSettings defaults = parseScanObstacleSettings(XmlRpc::XmlRpcValue());
  EXPECT_EQ(defaults.cluster_distance, 0.1);
  EXPECT_EQ(defaults.min_cluster_points, 1);
  EXPECT_EQ(defaults.min_radius, 0.05);
  EXPECT_EQ(defaults.range_noise_sigma, 0.01);
  EXPECT_EQ(defaults.free_space_tolerance, 0.1);
  EXPECT_EQ(defaults.z_min, 0.0);
  EXPECT_EQ(defaults.z_max, 2.0);
  XmlRpc::XmlRpcValue params;
  params["cluster_distance"] = 1;  // ints are numbers
  params["min_cluster_points"] = 1;
  params["z_min"] = -0.5;
  params["range_noise_sigma"] = 0;
  params["free_space_tolerance"] = 0.03;
  const auto settings = parseScanObstacleSettings(params);
  EXPECT_EQ(settings.range_noise_sigma, 0.0);
  EXPECT_EQ(settings.free_space_tolerance, 0.03);
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
  params["free_space_tolerance"] = 0.0;
  EXPECT_EQ(settingsError(params),
            "parameter ~free_space_tolerance, key 'free_space_tolerance': expected a number "
            "within [0.001, 10], got 0");
  params = XmlRpc::XmlRpcValue();
  params["range_noise_sigma"] = -0.01;
  EXPECT_EQ(settingsError(params),
            "parameter ~range_noise_sigma, key 'range_noise_sigma': expected a number within "
            "[0, 1], got -0.01");
  params = XmlRpc::XmlRpcValue();
  params["range_noise_sigma"] = "0.01";
  EXPECT_NE(settingsError(params).find("key 'range_noise_sigma'"), std::string::npos);
  params = XmlRpc::XmlRpcValue();
  params["z_max"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(settingsError(params).find("key 'z_max'"), std::string::npos);
}

TEST(ScanObstaclesCloud, PointsWithinTheZBandMakeEllipsesWithTheSensorHeader) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 10; ++i) {
    points.emplace_back(1.0f + 0.01f * i, 0.02f * (i % 3), 0.5f);  // a blob at (1, 0)
    points.emplace_back(-1.0f, 0.01f * i, 3.0f);                   // above z_max: ignored
    points.emplace_back(-2.0f, 0.01f * i, -0.2f);                  // below z_min: ignored
  }
  points.emplace_back(std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.5f);
  const sensor_msgs::PointCloud2 cloud = test::xyzCloud(points, "camera", ros::Time(7, 8));
  ASSERT_EQ(cloudPoints(cloud).size(), points.size());
  const auto obstacles =
      app::cloudObstacles(cloudPoints(cloud), cloud.header.frame_id, app::ScanObstacleSettings{});
  const EllipseArray msg = toMsg(obstacles, cloud.header);
  EXPECT_EQ(msg.header.frame_id, "camera");
  EXPECT_EQ(msg.header.stamp, ros::Time(7, 8));
  ASSERT_EQ(msg.ellipses.size(), 1u);
  // Named by the angular bin of its first point in angular order: (1, 0) at angle 0, bin 8192
  // of 16384 from -pi.
  EXPECT_EQ(msg.ellipses[0].name, "scan_8192");
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
  const float nan = std::numeric_limits<float>::quiet_NaN(),
              inf = std::numeric_limits<float>::infinity();
  scan.ranges = {1.0f, 1.0f, nan, 1.0f, inf, -inf, 0.0f, 9.0f, 1.0f};
  const auto obstacles = scanObstacles(scan, app::ScanObstacleSettings{});
  // The four 1 m returns (beams 0, 1, 3, 8) are each inside an ellipse near 1 m; beams 4 (inf)
  // and 7 (above range_max) saw nothing up to range_max, so no ellipse crosses them at 1 m: the
  // returns are split around them (before: one cluster across them).
  const auto inside = [](const app::EllipseSpec& e, double angle, double r) {
    const double dx = r * std::cos(angle) - e.x, dy = r * std::sin(angle) - e.y;
    const double c = std::cos(e.angle), s = std::sin(e.angle);
    const double u = (c * dx + s * dy) / e.radius_x, v = (-s * dx + c * dy) / e.radius_y;
    return u * u + v * v <= 1.0;
  };
  ASSERT_FALSE(obstacles.ellipses.empty());
  for (const int beam : {0, 1, 3, 8}) {
    const double angle = beam * static_cast<double>(scan.angle_increment);
    EXPECT_TRUE(std::any_of(obstacles.ellipses.begin(), obstacles.ellipses.end(),
                            [&](const app::EllipseSpec& e) { return inside(e, angle, 1.0); }))
        << "beam " << beam;
  }
  for (const app::EllipseSpec& e : obstacles.ellipses) {
    EXPECT_EQ(e.frame_id, "laser");
    EXPECT_NEAR(std::hypot(e.x, e.y), 1.0, 0.06) << e.name;
    for (const int beam : {4, 7}) {
      EXPECT_FALSE(inside(e, beam * static_cast<double>(scan.angle_increment), 1.0)) << e.name;
    }
  }
  EXPECT_TRUE(
      scanObstacles(sensor_msgs::LaserScan(), app::ScanObstacleSettings{}).ellipses.empty());
}

}  // namespace
}  // namespace ellipse_collision

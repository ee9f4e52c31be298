// scan_obstacles' conversions without a master (src/ros/scan_obstacles.cpp): the PointCloud2
// conversion and z band, the EllipseArray with the sensor's header, hostile ranges (its
// parameters: test_scan_params.cpp).
#include <gtest/gtest.h>
#include <sensor_msgs/point_cloud2_iterator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ellipse_collision/ros/scan_obstacles.h"
#include "xyz_cloud.h"

namespace ellipse_collision {
namespace {

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

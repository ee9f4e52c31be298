// One sensor's messages in turn (app/sensor_obstacle_series.h): the first scan is the scan alone,
// a scene that stays keeps its ellipses and names, another frame starts afresh, and clouds keep
// their names apart from the scans'.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "ellipse_collision/app/sensor_obstacle_series.h"
#include "synthetic_scan.h"

namespace ellipse_collision::app {
namespace {

using test::ScanFields;

/// Same names, frames and geometry bit for bit, in the same order.
void expectSame(const SensorObstacles& a, const SensorObstacles& b, const std::string& what) {
  ASSERT_EQ(a.ellipses.size(), b.ellipses.size()) << what;
  for (std::size_t i = 0; i < a.ellipses.size(); ++i) {
    const EllipseSpec &x = a.ellipses[i], &y = b.ellipses[i];
    EXPECT_EQ(x.name, y.name) << what << " " << i;
    EXPECT_EQ(x.frame_id, y.frame_id) << what << " " << i;
    EXPECT_TRUE(x.x == y.x && x.y == y.y && x.radius_x == y.radius_x && x.radius_y == y.radius_y &&
                x.angle == y.angle)
        << what << " " << x.name;
  }
}

SensorObstacles alone(const ScanFields& scan, const std::string& frame) {
  return scanObstacles(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min,
                       scan.range_max, frame, ScanObstacleSettings{});
}

SensorObstacles next(SensorObstacleSeries& series, const ScanFields& scan,
                     const std::string& frame) {
  return series.scan(scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min,
                     scan.range_max, frame);
}

TEST(SensorObstacleSeries, TheFirstScanIsTheScanAloneAndAStillSceneSettlesUnderItsNames) {
  const ScanFields scan = test::castScan(test::roomWorld(), 720, 10.0, 0.0, 1);
  SensorObstacleSeries series{ScanObstacleSettings{}};
  const SensorObstacles first = next(series, scan, "laser");
  ASSERT_GT(first.ellipses.size(), 3u);
  expectSame(first, alone(scan, "laser"), "first scan");
  std::set<std::string> first_names;
  for (const EllipseSpec& e : first.ellipses) first_names.insert(e.name);
  // The same scan again and again: cuts that were not needed are let go after
  // ScanCutMemory::kUnneededMessages scans (two runs become one ellipse), then nothing changes;
  // no name is new, and there are never more ellipses than the first scan had.
  SensorObstacles before = first;
  for (int k = 1; k <= 8; ++k) {
    const SensorObstacles now = next(series, scan, "laser");
    EXPECT_LE(now.ellipses.size(), before.ellipses.size()) << "scan " << k;
    for (const EllipseSpec& e : now.ellipses) {
      EXPECT_EQ(first_names.count(e.name), 1u) << e.name << " is new in scan " << k;
    }
    if (k > static_cast<int>(ScanCutMemory::kUnneededMessages) + 2) {
      expectSame(now, before, "settled scan " + std::to_string(k));
    }
    before = now;
  }
}

TEST(SensorObstacleSeries, AnotherFrameIsAnotherSensorAndStartsAfresh) {
  const ScanFields scan = test::castScan(test::roomWorld(), 720, 10.0, 0.01, 3);
  const ScanFields other = test::castScan(test::objectRoomWorld(), 720, 10.0, 0.01, 4);
  SensorObstacleSeries series{ScanObstacleSettings{}};
  next(series, scan, "laser");
  next(series, scan, "laser");
  // Neither the cuts nor the names of "laser" are carried to "laser_rear".
  expectSame(next(series, other, "laser_rear"), alone(other, "laser_rear"), "new frame");
}

TEST(SensorObstacleSeries, CloudsKeepTheirNamesApartFromScans) {
  const std::vector<Eigen::Vector3f> points = test::castCloud(test::roomWorld(), 8, 720);
  const ScanFields scan = test::castScan(test::roomWorld(), 720, 10.0, 0.0, 1);
  const ScanObstacleSettings settings;
  SensorObstacleSeries series{settings};
  const SensorObstacles first_cloud = series.cloud(points, "lidar");
  ASSERT_FALSE(first_cloud.ellipses.empty());
  expectSame(first_cloud, cloudObstacles(points, "lidar", settings), "first cloud");
  const SensorObstacles first_scan = next(series, scan, "laser");
  expectSame(first_scan, alone(scan, "laser"), "a scan after a cloud");
  expectSame(series.cloud(points, "lidar"), first_cloud, "the cloud again");
  expectSame(next(series, scan, "laser"), first_scan, "the scan again");
}

TEST(SensorObstacleSeries, KeepsTheSettingsItWasGiven) {
  ScanObstacleSettings settings;
  settings.range_noise_sigma = 0.03;
  const SensorObstacleSeries series{settings};
  EXPECT_EQ(series.settings().range_noise_sigma, 0.03);
}

}  // namespace
}  // namespace ellipse_collision::app

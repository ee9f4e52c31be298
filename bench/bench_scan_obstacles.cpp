// scan_obstacles' cost per sensor message, the contour path of issue 32 beside the clustering it
// replaced, in one run:
// - 720-beam LaserScans through the node's own path (LaserScan -> app::scanObstacles ->
//   EllipseArray, all but the publish): an 8 m x 6 m room's walls and ten round objects with a
//   little range noise and a few NaN/inf beams, and the 6 m x 4 m room with a box, a
//   pillar and a doorway (test/support/synthetic_scan.h) with 1 cm range noise;
// - a ray-cast 16-ring lidar cloud of about 100,000 points of that room (app::cloudObstacles).
// "Old" is the previous path with its defaults: clusters of consecutive points closer than 0.1 m
// (single linkage for clouds), clusters under 3 points dropped, one minimum-area ellipse each.
// Counters: us per message, ellipses, and the share of one core at the sensor's rate (40 Hz
// scans: budget 2 %; 10 Hz clouds: budget 20 %).

#include <benchmark/benchmark.h>
#include <sensor_msgs/LaserScan.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "ellipse_collision/core/point_clusters.h"
#include "ellipse_collision/ros/scan_obstacles.h"
#include "synthetic_scan.h"

namespace {

/// A LaserScan message of ray-cast fields, in frame "laser".
sensor_msgs::LaserScan toLaserScan(const ellipse_collision::test::ScanFields& fields) {
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";
  scan.angle_min = static_cast<float>(fields.angle_min);
  scan.angle_increment = static_cast<float>(fields.angle_increment);
  scan.angle_max = scan.angle_min + static_cast<float>(fields.ranges.size() - 1) * scan.angle_increment;
  scan.range_min = static_cast<float>(fields.range_min);
  scan.range_max = static_cast<float>(fields.range_max);
  scan.ranges = fields.ranges;
  return scan;
}

/// objectRoomWorld() with 5 mm range noise and a few NaN and inf beams.
sensor_msgs::LaserScan objectRoomScan() {
  sensor_msgs::LaserScan scan = toLaserScan(
      ellipse_collision::test::castScan(ellipse_collision::test::objectRoomWorld(), 720, 30.0, 0.005, 40));
  for (const int i : {5, 200, 400}) scan.ranges[i] = std::numeric_limits<float>::quiet_NaN();
  scan.ranges[300] = std::numeric_limits<float>::infinity();
  return scan;
}

/// The room (a box, a pillar, a doorway), 1 cm range noise.
sensor_msgs::LaserScan doorwayRoomScan() {
  return toLaserScan(
      ellipse_collision::test::castScan(ellipse_collision::test::roomWorld(), 720, 10.0, 0.01, 41));
}

/// The previous naming: scan_ + the index.
ellipse_collision::app::SensorObstacles oldSpecs(const ellipse_collision::core::ClusterEllipses& fit,
                                                 const std::string& frame_id) {
  ellipse_collision::app::SensorObstacles result;
  for (std::size_t i = 0; i < fit.ellipses.size(); ++i) {
    const auto& e = fit.ellipses[i];
    ellipse_collision::app::EllipseSpec spec;
    spec.name = "scan_" + std::to_string(i);
    spec.frame_id = frame_id;
    spec.x = e.center.x(), spec.y = e.center.y(), spec.angle = e.angle;
    spec.radius_x = e.radius_x, spec.radius_y = e.radius_y;
    result.ellipses.push_back(spec);
  }
  return result;
}

/// The previous path of a scan, with its defaults.
ellipse_collision::app::SensorObstacles oldScanPath(const sensor_msgs::LaserScan& scan) {
  namespace core = ellipse_collision::core;
  const auto points = core::scanPoints(scan.ranges, scan.angle_min, scan.angle_increment,
                                       scan.range_min, scan.range_max);
  return oldSpecs(core::fitClusters(core::clusterPoints(points, 0.1, 3), 0.05),
                  scan.header.frame_id);
}

ellipse_collision::app::SensorObstacles oldCloudPath(const std::vector<Eigen::Vector3f>& cloud) {
  namespace core = ellipse_collision::core;
  std::vector<Eigen::Vector2d> band;
  for (const Eigen::Vector3f& p : cloud) {
    if (p.z() >= -0.3f && p.z() <= 1.5f) band.emplace_back(p.x(), p.y());
  }
  return oldSpecs(core::fitClusters(core::clusterUnorderedPoints(band, 0.1, 3), 0.05), "lidar");
}

void setCounters(benchmark::State& state, std::size_t ellipses, double rate_hz) {
  state.counters["ellipses"] = static_cast<double>(ellipses);
  // Inverted iteration-invariant rates: CPU seconds / (iterations x value). Seconds per message
  // x 1e6 = us per message; x rate x 100 = % of one core at that rate.
  const auto kPerMessage = benchmark::Counter::Flags(benchmark::Counter::kIsIterationInvariantRate |
                                                     benchmark::Counter::kInvert);
  state.counters["us_per_msg"] = benchmark::Counter(1e-6, kPerMessage);
  state.counters["core_pct"] = benchmark::Counter(1.0 / (rate_hz * 100.0), kPerMessage);
}

enum class ScanPath {
  Old,      ///< the clustering before contours
  Alone,    ///< app::scanObstacles(), each scan on its own
  New,      ///< the node's path (app::SensorObstacleSeries): each scan cut first where the last one
            ///< was, names carried over; the same scan again and again is its costliest case, every
            ///< cut a hint whose merge is tried
  Tracked,  ///< the node's path with tracking (ObstacleTracker), 25 ms between scans
};

template <ScanPath kPath>
void scanBenchmark(benchmark::State& state, const sensor_msgs::LaserScan& scan) {
  const ellipse_collision::app::ScanObstacleSettings settings;
  ellipse_collision::app::SensorObstacleSeries series{settings};
  std::size_t ellipses = 0;
  double stamp_s = 0.0;
  for (auto _ : state) {
    ellipse_collision::app::SensorObstacles obstacles =
        kPath == ScanPath::Old     ? oldScanPath(scan)
        : kPath == ScanPath::Alone ? ellipse_collision::scanObstacles(scan, settings)
                                   : ellipse_collision::scanObstacles(scan, series);
    if (kPath == ScanPath::Tracked) series.trackScan(stamp_s += 0.025, {}, obstacles);
    const ellipse_collision::EllipseArray msg = ellipse_collision::toMsg(obstacles, scan.header);
    ellipses = msg.ellipses.size();
    benchmark::DoNotOptimize(msg.ellipses.data());
  }
  setCounters(state, ellipses, 40.0);
}

void BM_Scan720ObjectRoom_Old(benchmark::State& state) { scanBenchmark<ScanPath::Old>(state, objectRoomScan()); }
void BM_Scan720ObjectRoom_Alone(benchmark::State& state) { scanBenchmark<ScanPath::Alone>(state, objectRoomScan()); }
void BM_Scan720ObjectRoom_New(benchmark::State& state) { scanBenchmark<ScanPath::New>(state, objectRoomScan()); }
void BM_Scan720ObjectRoom_Tracked(benchmark::State& state) {
  scanBenchmark<ScanPath::Tracked>(state, objectRoomScan());
}
void BM_Scan720DoorwayRoom_Old(benchmark::State& state) { scanBenchmark<ScanPath::Old>(state, doorwayRoomScan()); }
void BM_Scan720DoorwayRoom_Alone(benchmark::State& state) { scanBenchmark<ScanPath::Alone>(state, doorwayRoomScan()); }
void BM_Scan720DoorwayRoom_New(benchmark::State& state) { scanBenchmark<ScanPath::New>(state, doorwayRoomScan()); }
void BM_Scan720DoorwayRoom_Tracked(benchmark::State& state) {
  scanBenchmark<ScanPath::Tracked>(state, doorwayRoomScan());
}
BENCHMARK(BM_Scan720ObjectRoom_Old)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Scan720ObjectRoom_Alone)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Scan720ObjectRoom_New)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Scan720ObjectRoom_Tracked)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Scan720DoorwayRoom_Old)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Scan720DoorwayRoom_Alone)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Scan720DoorwayRoom_New)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Scan720DoorwayRoom_Tracked)->Unit(benchmark::kMicrosecond);

template <bool kOld>
void cloudBenchmark(benchmark::State& state) {
  // 16 rings x 7,300 columns of the doorway room: about 100,000 points, most within the band.
  const auto cloud = ellipse_collision::test::castCloud(ellipse_collision::test::roomWorld(), 16, 7300);
  ellipse_collision::app::ScanObstacleSettings settings;
  settings.z_min = -0.3;
  settings.z_max = 1.5;
  ellipse_collision::app::SensorObstacleSeries series{settings};  // the node's path
  std::size_t ellipses = 0;
  for (auto _ : state) {
    const auto obstacles = kOld ? oldCloudPath(cloud) : series.cloud(cloud, "lidar");
    ellipses = obstacles.ellipses.size();
    benchmark::DoNotOptimize(obstacles.ellipses.data());
  }
  state.counters["points"] = static_cast<double>(cloud.size());
  setCounters(state, ellipses, 10.0);
}
void BM_Cloud100k_Old(benchmark::State& state) { cloudBenchmark<true>(state); }
void BM_Cloud100k_New(benchmark::State& state) { cloudBenchmark<false>(state); }
BENCHMARK(BM_Cloud100k_Old)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Cloud100k_New)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

// scan_obstacles' cost per LaserScan: one 720-beam scan (a 8 m x 6 m room's walls and ten round
// objects, 0.1 m to 0.4 m in radius, with a little range noise and a few NaN/inf beams) through
// the node's own path: the message's points (core::scanPoints), clustering, the minimum-area
// ellipse of each cluster and the EllipseArray, all but the publish. Counters: us per scan,
// ellipses per scan and the share of one core at 40 Hz (the budget: under 5 %).

#include <benchmark/benchmark.h>
#include <sensor_msgs/LaserScan.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ellipse_collision/ros/scan_obstacles.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Circle {
  double x, y, r;
};

/// First hit along the beam at `angle` from the origin: the circles or the room's walls
/// (x within [-3, 5], y within [-3, 3]).
double rayCast(double angle, const std::vector<Circle>& circles) {
  const double dx = std::cos(angle), dy = std::sin(angle);
  double best = std::numeric_limits<double>::infinity();
  for (const Circle& c : circles) {
    const double b = dx * c.x + dy * c.y, disc = b * b - (c.x * c.x + c.y * c.y - c.r * c.r);
    if (disc >= 0.0 && b - std::sqrt(disc) > 0.0) best = std::min(best, b - std::sqrt(disc));
  }
  if (dx > 0.0) best = std::min(best, 5.0 / dx);
  if (dx < 0.0) best = std::min(best, -3.0 / dx);
  if (dy > 0.0) best = std::min(best, 3.0 / dy);
  if (dy < 0.0) best = std::min(best, -3.0 / dy);
  return best;
}

sensor_msgs::LaserScan roomScan() {
  std::mt19937_64 random(40);
  std::uniform_real_distribution<double> x(-2.5, 4.5), y(-2.5, 2.5), r(0.1, 0.4);
  std::normal_distribution<double> noise(0.0, 0.005);
  std::vector<Circle> circles;
  while (circles.size() < 10) {
    const Circle c{x(random), y(random), r(random)};
    if (std::hypot(c.x, c.y) > c.r + 0.3) circles.push_back(c);
  }
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";
  scan.angle_min = -kPi;
  scan.angle_increment = 2.0 * kPi / 720.0;
  scan.angle_max = scan.angle_min + 719 * scan.angle_increment;
  scan.range_min = 0.05;
  scan.range_max = 30.0;
  for (int i = 0; i < 720; ++i) {
    scan.ranges.push_back(static_cast<float>(
        rayCast(scan.angle_min + i * scan.angle_increment, circles) + noise(random)));
  }
  for (const int i : {5, 200, 400}) scan.ranges[i] = std::numeric_limits<float>::quiet_NaN();
  scan.ranges[300] = std::numeric_limits<float>::infinity();
  return scan;
}

void BM_ScanObstacles720(benchmark::State& state) {
  const sensor_msgs::LaserScan scan = roomScan();
  const ellipse_collision::app::ScanObstacleSettings settings;
  std::size_t ellipses = 0;
  for (auto _ : state) {
    const ellipse_collision::EllipseArray msg =
        ellipse_collision::toMsg(ellipse_collision::scanObstacles(scan, settings), scan.header);
    ellipses = msg.ellipses.size();
    benchmark::DoNotOptimize(msg.ellipses.data());
  }
  state.counters["ellipses"] = static_cast<double>(ellipses);
  // Inverted iteration-invariant rates: CPU seconds / (iterations x value). Seconds per scan x
  // 1e6 = us per scan; seconds per scan x 40 scans per second x 100 = % of one core at 40 Hz.
  const auto kPerScan =
      benchmark::Counter::Flags(benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["us_per_scan"] = benchmark::Counter(1e-6, kPerScan);
  state.counters["core_pct_at_40Hz"] = benchmark::Counter(1.0 / (40.0 * 100.0), kPerScan);
}
BENCHMARK(BM_ScanObstacles720)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

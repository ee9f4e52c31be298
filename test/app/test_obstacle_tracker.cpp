// Tracking scan obstacles: velocities through the whole sensor chain (a ray-cast laser, the scan
// pipeline, the tracker), against the true motion of what the laser sees.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "ellipse_collision/app/obstacle_tracker.h"
#include "ellipse_collision/app/sensor_obstacle_series.h"
#include "synthetic_scan.h"

namespace ellipse_collision::app {
namespace {

constexpr double kScanRateHz = 40.0;

/// `world` (fixed frame) as the sensor at `sensor` sees it: in the sensor's frame.
test::World seenFrom(const test::World& world, const core::PathPose& sensor) {
  const double c = std::cos(sensor.yaw), s = std::sin(sensor.yaw);
  const auto local = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d d = p - Eigen::Vector2d(sensor.x, sensor.y);
    return Eigen::Vector2d(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  };
  test::World seen;
  for (const test::WorldSegment& w : world.walls) seen.walls.push_back({local(w.a), local(w.b)});
  for (const test::WorldCircle& p : world.pillars)
    seen.pillars.push_back({local(p.centre), p.radius});
  return seen;
}

/// One scan's obstacles, tracked: the chain a scan source runs.
struct Chain {
  SensorObstacleSeries series{ScanObstacleSettings{}};
  ObstacleTracker tracker{TrackingSettings{}};
  std::vector<EllipseSpec> step(const test::World& world, const core::PathPose& sensor, double t_s,
                                double sigma, std::uint64_t seed) {
    const test::ScanFields scan = test::castScan(seenFrom(world, sensor), 720, 10.0, sigma, seed);
    SensorObstacles obstacles = series.scan(scan.ranges, scan.angle_min, scan.angle_increment,
                                            scan.range_min, scan.range_max, "laser");
    tracker.track(t_s, sensor, obstacles);
    return obstacles.ellipses;
  }
};

/// The obstacle whose centre (sensor frame) is nearest `point` (sensor frame).
const EllipseSpec* nearest(const std::vector<EllipseSpec>& obstacles, const Eigen::Vector2d& point,
                           double within) {
  const EllipseSpec* best = nullptr;
  double best_d = within;
  for (const EllipseSpec& o : obstacles) {
    const double d = std::hypot(o.x - point.x(), o.y - point.y());
    if (d < best_d) best_d = d, best = &o;
  }
  return best;
}

TEST(ObstacleTracker, AStaticRoomWithRangeNoiseStands) {
  // The room of the scan tests, 1 cm range noise, 200 scans from a standing sensor.
  const test::World room = test::objectRoomWorld();
  Chain chain;
  std::size_t obstacles = 0, slow = 0, names_kept = 0, names_before = 0;
  std::set<std::string> last;
  for (int k = 0; k < 200; ++k) {
    const auto result = chain.step(room, {}, k / kScanRateHz, 0.01, 100 + k);
    std::set<std::string> names;
    for (const EllipseSpec& o : result) {
      names.insert(o.name);
      if (k < 10) continue;  // the first scans: tracks not yet confirmed either way
      ++obstacles;
      if (std::hypot(o.vx, o.vy) < 0.05) ++slow;
    }
    if (k >= 10) {
      names_before += last.size();
      for (const std::string& n : last) names_kept += names.count(n);
    }
    last = names;
  }
  std::printf(
      "static room, 1 cm noise: %zu of %zu obstacles below 0.05 m/s, %zu of %zu names kept\n", slow,
      obstacles, names_kept, names_before);
  EXPECT_GE(slow, 0.99 * obstacles);
  // Names are ScanNameKeeper's (printed above, not the tracker's to keep).
  EXPECT_GT(names_kept, 0u);
}

TEST(ObstacleTracker, TheSensorsOwnMotionIsTakenOut) {
  // The sensor drives at 1 m/s turning at 0.5 rad/s through the room: what stands, stands.
  const test::World room = test::objectRoomWorld();
  Chain chain;
  std::size_t obstacles = 0, slow = 0;
  for (int k = 0; k < 120; ++k) {
    const double t = k / kScanRateHz;
    const core::PathPose sensor{t - 1.0, 0.3 * std::sin(t), 0.5 * t, 0.0};
    for (const EllipseSpec& o : chain.step(room, sensor, t, 0.01, 300 + k)) {
      if (k < 10) continue;
      ++obstacles;
      if (std::hypot(o.vx, o.vy) < 0.05) ++slow;
    }
  }
  std::printf("moving sensor in a static room: %zu of %zu obstacles below 0.05 m/s\n", slow,
              obstacles);
  EXPECT_GE(slow, 0.98 * obstacles);
}

/// The room of the scan tests without its box: a person's path 1.2-2.4 m ahead stays clear of
/// everything else.
test::World emptyRoom() {
  test::World world = test::roomWorld();
  world.walls.resize(world.walls.size() - 4);  // addBox() put the box's four walls last
  return world;
}

/// A 0.25 m circle crossing `ahead` m in front of the sensor (+x) toward +y at `speed` [m/s],
/// the sensor standing or driving toward its path at `drive` [m/s]: when the person is first
/// reported moving, and in how many scans after 0.5 s its velocity is within 30 % and 25 degrees.
struct Crossing {
  double reported_at{-1.0};
  int good{0};
  int counted{0};
};
Crossing cross(double ahead, double speed, double drive) {
  Chain chain;
  Crossing result;
  for (int k = 0; k < 60; ++k) {
    const double t = k / kScanRateHz;
    test::World world = emptyRoom();
    const Eigen::Vector2d person(ahead, -1.2 + speed * t);
    world.pillars.push_back({person, 0.25});
    const core::PathPose sensor{-1.0 + drive * t, 0.0, 0.0, 0.0};
    const auto seen_all = chain.step(world, sensor, t, 0.01, 500 + k);
    // The obstacle on the person: its centre within the circle (sensor frame: the sensor faces
    // +x, so only shifted).
    const EllipseSpec* seen = nearest(seen_all, person - Eigen::Vector2d(sensor.x, 0.0), 0.25);
    if (!seen) continue;
    const Eigen::Vector2d v(seen->vx, seen->vy);
    if (result.reported_at < 0 && v.norm() > 0.0) result.reported_at = t;
    if (t >= 0.5) {
      ++result.counted;
      if (std::abs(v.norm() - speed) < 0.3 * speed && v.y() > 0.9 * v.norm()) ++result.good;
    }
  }
  return result;
}

TEST(ObstacleTracker, APersonCrossingAheadIsReportedMovingWithinHalfASecond) {
  // 2.2-3.4 m ahead of the sensor at 0.5-1.5 m/s, the sensor standing or driving toward the
  // path at 0.8 m/s.
  for (const double drive : {0.0, 0.8}) {
    for (const double ahead : {1.2, 1.8, 2.4}) {
      for (const double speed : {0.5, 1.0, 1.5}) {
        const Crossing c = cross(ahead, speed, drive);
        std::printf(
            "sensor at %.1f m/s, person %.1f m ahead at %.1f m/s: moving from %.3f s, %d "
            "of %d scans after 0.5 s within 30 %% and 25 degrees\n",
            drive, ahead + 1.0, speed, c.reported_at, c.good, c.counted);
        EXPECT_GE(c.reported_at, 0.0);
        EXPECT_LE(c.reported_at, 0.5);
        EXPECT_GE(c.good, 0.9 * c.counted);
        EXPECT_GT(c.counted, 20);
      }
    }
  }
}

TEST(ObstacleTracker, ACartThatStartsRollingIsReportedMovingWithinHalfASecond) {
  // Stands for 2 s, then rolls toward the sensor at 0.5 m/s (reached within 0.1 s).
  Chain chain;
  double moving_from = -1.0;
  for (int k = 0; k < 140; ++k) {
    const double t = k / kScanRateHz;
    const double rolled = t < 2.0 ? 0.0 : 0.5 * (t - 2.0);
    test::World world = test::roomWorld();
    const Eigen::Vector2d cart(3.0 - rolled, -0.6);
    world.pillars.push_back({cart, 0.3});
    const EllipseSpec* seen = nearest(chain.step(world, {}, t, 0.01, 900 + k), cart, 0.3);
    ASSERT_NE(seen, nullptr) << t;
    const double speed = std::hypot(seen->vx, seen->vy);
    if (t < 2.0) {
      EXPECT_EQ(speed, 0.0) << "the standing cart reported moving at " << t << " s";
    } else if (moving_from < 0 && speed > 0.0) {
      moving_from = t;
      EXPECT_LT(seen->vx, 0.0);  // toward the sensor
    }
  }
  std::printf("cart starting at 2 s: reported moving from %.3f s\n", moving_from);
  EXPECT_GT(moving_from, 2.0);
  EXPECT_LE(moving_from, 2.5);
}

/// One object of one ellipse centred at `centre` (sensor frame), its returns within `extent`.
SensorObstacles oneObject(const Eigen::Vector2d& centre, double extent) {
  SensorObstacles obstacles;
  EllipseSpec e;
  e.frame_id = "laser";
  e.x = centre.x();
  e.y = centre.y();
  e.radius_x = e.radius_y = extent;
  obstacles.ellipses.push_back(e);
  obstacles.objects.push_back({centre, extent, {0}});
  return obstacles;
}

TEST(ObstacleTracker, VelocityIsGivenInTheSensorFramesAxes) {
  // The sensor faces +y (yaw pi/2); an object moving +x in the fixed frame at 0.8 m/s moves -y in
  // the sensor's axes. Centroids exact: the fitted slope is exact.
  ObstacleTracker tracker(TrackingSettings{});
  const core::PathPose sensor{1.0, 2.0, M_PI / 2, 0.0};
  SensorObstacles seen;
  for (int k = 0; k < 40; ++k) {
    const double t = k * 0.025;
    // Fixed-frame centre (3 + 0.8 t, 2): in the sensor frame (0, -(2 + 0.8 t)).
    seen = oneObject({0.0, -(2.0 + 0.8 * t)}, 0.2);
    tracker.track(t, sensor, seen);
    const TrackingSettings defaults;
    if (k + 1 < defaults.confirm_count) {
      EXPECT_EQ(seen.ellipses[0].vy, 0.0) << k;
    }
  }
  EXPECT_NEAR(seen.ellipses[0].vx, 0.0, 1e-9);
  EXPECT_NEAR(seen.ellipses[0].vy, -0.8, 1e-9);
}

TEST(ObstacleTracker, LargeObjectsStandAndATimeJumpStartsAfresh) {
  ObstacleTracker tracker(TrackingSettings{});
  for (int k = 0; k < 30; ++k) {
    // Both slide at 1 m/s (20 Hz): the wall (returns 2 m from its centroid) is not tracked.
    SensorObstacles wall = oneObject({1.0 + 0.05 * k, 3.0}, 2.0);
    SensorObstacles small = oneObject({1.0 + 0.05 * k, 0.0}, 0.2);
    tracker.track(k * 0.05, {}, wall);
    EXPECT_EQ(wall.ellipses[0].vx, 0.0);
    tracker.track(k * 0.05 + 0.01, {}, small);
    if (k == 29) {
      EXPECT_NEAR(small.ellipses[0].vx, 1.0, 1e-6);
    }
  }
  EXPECT_EQ(tracker.trackCount(), 1u);
  // Time runs back (a bag looped): every track starts afresh, unconfirmed.
  SensorObstacles again = oneObject({2.5, 0.0}, 0.2);
  tracker.track(0.0, {}, again);
  EXPECT_EQ(again.ellipses[0].vx, 0.0);
  EXPECT_EQ(tracker.trackCount(), 1u);
}

TEST(ObstacleTracker, SettingsOutOfRangeNameTheKey) {
  TrackingSettings s;
  EXPECT_FALSE(findInvalidSetting(s));
  s.max_speed = std::nan("");
  ASSERT_TRUE(findInvalidSetting(s));
  EXPECT_EQ(findInvalidSetting(s)->key, "tracking/max_speed");
  s = TrackingSettings{};
  s.confirm_count = 1;
  ASSERT_TRUE(findInvalidSetting(s));
  EXPECT_EQ(findInvalidSetting(s)->key, "tracking/confirm_count");
  EXPECT_EQ(findInvalidSetting(s)->actual, "1");
  s = TrackingSettings{};
  s.min_speed = 5.0;  // above max_speed 3
  ASSERT_TRUE(findInvalidSetting(s));
  EXPECT_EQ(findInvalidSetting(s)->key, "tracking/min_speed");
}

}  // namespace
}  // namespace ellipse_collision::app

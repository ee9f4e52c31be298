// scan_obstacles in a running system (test/ros/scan_obstacles.test): a synthetic 720-beam
// LaserScan of a circle and a wall, with NaN, inf and out-of-range beams; the ellipses that reach
// the collision node's ~obstacles (every hit point inside, sizes close to the shapes, the
// sensor's header, stable names) and the collisions they cause with the configured links, on
// ~collisions and in a ~check_collisions answer; a circle crossing carries its tracked velocity.
// The same client runs against the nodelet
// pipeline (test/ros/scan_pipeline_nodelets.test, with test_scan_pipeline_nodelets.cpp).
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>

#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <vector>

#include "ellipse_collision/ros/messages.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCircleX = 1.5, kCircleR = 0.3;        // circle centre (1.5, 0) in laser [m]
constexpr double kWallY = -2.0, kWallHalfLength = 1.0;  // wall y = -2, |x| <= 1 in laser [m]
constexpr double kRangeMax = 8.0;
// Ellipses are named after the beam of their first return (beams from -pi, 0.5 degrees apart):
// the wall's first return is beam 127, the circle's beam 337.
const char* const kWallName = "scan_127";
const char* const kCircleName = "scan_337";

/// Distance along the beam at `angle` to the first hit of the circle or the wall, or nothing.
std::optional<double> rayCast(double angle) {
  const double dx = std::cos(angle), dy = std::sin(angle);
  std::optional<double> best;
  // Circle: |t d - c|^2 = r^2, nearest root.
  const double b = dx * kCircleX, disc = b * b - (kCircleX * kCircleX - kCircleR * kCircleR);
  if (disc >= 0.0 && b - std::sqrt(disc) > 0.0) best = b - std::sqrt(disc);
  if (dy < 0.0) {
    const double t = kWallY / dy;
    if (std::abs(t * dx) <= kWallHalfLength && (!best || t < *best)) best = t;
  }
  return best;
}

sensor_msgs::LaserScan syntheticScan(const ros::Time& stamp) {
  sensor_msgs::LaserScan scan;
  scan.header.frame_id = "laser";
  scan.header.stamp = stamp;
  scan.angle_min = -kPi;
  scan.angle_increment = 2.0 * kPi / 720.0;
  scan.angle_max = scan.angle_min + 719 * scan.angle_increment;
  scan.range_min = 0.05;
  scan.range_max = kRangeMax;
  for (int i = 0; i < 720; ++i) {
    const auto hit = rayCast(scan.angle_min + i * scan.angle_increment);
    scan.ranges.push_back(hit ? static_cast<float>(*hit) : std::numeric_limits<float>::infinity());
  }
  // Hostile beams where nothing is (behind the scanner): NaN, -inf, below range_min, above
  // range_max. They must be skipped, not become obstacles, not crash the node.
  scan.ranges[10] = std::numeric_limits<float>::quiet_NaN();
  scan.ranges[11] = -std::numeric_limits<float>::infinity();
  scan.ranges[12] = 0.01f;
  scan.ranges[13] = 20.0f;
  return scan;
}

/// The beam end points of `scan` that hit something, in the laser frame (float ranges, as sent).
std::vector<std::pair<double, double>> hitPoints(const sensor_msgs::LaserScan& scan) {
  std::vector<std::pair<double, double>> points;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double r = scan.ranges[i];
    if (!(r >= scan.range_min && r <= scan.range_max)) continue;
    const double a = scan.angle_min + i * static_cast<double>(scan.angle_increment);
    points.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return points;
}

double quadraticForm(const Ellipse& e, double px, double py) {
  const double dx = px - e.x, dy = py - e.y, c = std::cos(e.angle), s = std::sin(e.angle);
  const double u = (c * dx + s * dy) / e.radius_x, v = (-s * dx + c * dy) / e.radius_y;
  return u * u + v * v;
}

bool collides(const std::vector<CollisionPair>& pairs, const std::string& a, const std::string& b) {
  return test::findPair(pairs, a, b) || test::findPair(pairs, b, a);
}
bool collides(const CollisionState& state, const std::string& a, const std::string& b) {
  return collides(state.collisions, a, b);
}

TEST(ScanObstacles, ScannedShapesReachTheCollisionNodeAsEnclosingEllipses) {
  ros::NodeHandle nh;
  std::mutex mutex;
  std::optional<EllipseArray> obstacles;
  std::optional<CollisionState> state;
  auto obstacles_sub = nh.subscribe<EllipseArray>(
      test::nodeTopic("obstacles"), 10, [&](const EllipseArray::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        obstacles = *msg;
      });
  auto state_sub = nh.subscribe<CollisionState>(
      test::nodeTopic("collisions"), 10, [&](const CollisionState::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex);
        state = *msg;
      });
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("/scan", 1);
  ros::AsyncSpinner spinner(2);
  spinner.start();

  const sensor_msgs::LaserScan scan = syntheticScan(ros::Time(1234, 5678));
  const bool arrived = test::waitUntil(
      [&] {
        scan_pub.publish(scan);
        std::lock_guard<std::mutex> lock(mutex);
        return obstacles && state && collides(*state, "arm", kCircleName) &&
               collides(*state, "side", kWallName);
      },
      40.0);
  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_TRUE(obstacles.has_value()) << "no EllipseArray reached the collision node's ~obstacles";
  ASSERT_TRUE(state.has_value()) << "no ~collisions from the collision node";
  EXPECT_TRUE(arrived) << "expected collisions (arm, " << kCircleName << ") and (side, "
                       << kWallName << "); got "
                       << state->collisions.size() << " collisions";

  // The sensor's header; contour order from -pi: the wall (around -pi/2) first, then the circle.
  EXPECT_EQ(obstacles->header.frame_id, "laser");
  EXPECT_EQ(obstacles->header.stamp, ros::Time(1234, 5678));
  ASSERT_EQ(obstacles->ellipses.size(), 2u);
  const Ellipse& wall = obstacles->ellipses[0];
  const Ellipse& circle = obstacles->ellipses[1];
  EXPECT_EQ(wall.name, kWallName);
  EXPECT_EQ(circle.name, kCircleName);
  EXPECT_EQ(circle.frame_id, "laser");

  // Every hit point inside the ellipse of its shape.
  for (const auto& [x, y] : hitPoints(scan)) {
    const Ellipse& e = std::abs(y - kWallY) < 1e-3 ? wall : circle;
    EXPECT_LE(quadraticForm(e, x, y), 1.0 + 1e-9) << "(" << x << ", " << y << ") outside " << e.name;
  }
  // The wall: a thin ellipse along it, grown to min_radius (0.05) across.
  EXPECT_NEAR(wall.x, 0.0, 0.02);
  EXPECT_NEAR(wall.y, kWallY, 1e-3);
  EXPECT_NEAR(std::sin(wall.angle), 0.0, 1e-3);
  EXPECT_NEAR(wall.radius_x, kWallHalfLength, 0.03);
  EXPECT_NEAR(wall.radius_y, 0.05, 1e-3);
  // The circle's visible arc is enclosed by the circle it lies on (the float ranges' rounding
  // aside), not by an ellipse bulging out in front of it into the space the beams saw free.
  EXPECT_NEAR(circle.y, 0.0, 1e-3);
  EXPECT_NEAR(circle.x, kCircleX, 2e-3);
  EXPECT_NEAR(circle.radius_x, kCircleR, 2e-3);
  EXPECT_NEAR(circle.radius_y, kCircleR, 2e-3);
  // The sensor is in no ellipse.
  for (const Ellipse& e : obstacles->ellipses) {
    EXPECT_GT(quadraticForm(e, 0.0, 0.0), 1.0) << e.name << " contains the sensor";
  }

  // Nothing where nothing was scanned; the hostile beams made no obstacle.
  EXPECT_FALSE(test::mentions(state->collisions, "far"));
}

TEST(ScanObstacles, CheckCollisionsNamesTheScannedObstacles) {
  // What a user's ~check_collisions call sees once scans arrive: the scanned obstacles by their
  // beam names, each against the link it touches, and only those when asked about one of them.
  ros::NodeHandle nh;
  ASSERT_TRUE(ros::service::waitForService(test::nodeTopic("check_collisions"), ros::Duration(30)));
  test::NodeServiceClient client;
  client.connectServices(nh);
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("/scan", 1);
  const sensor_msgs::LaserScan scan = syntheticScan(ros::Time(1234, 5678));

  CheckCollisions::Response all;
  const bool named = test::waitUntil(
      [&] {
        scan_pub.publish(scan);
        all = client.check();
        return all.success && collides(all.collisions, "arm", kCircleName) &&
               collides(all.collisions, "side", kWallName);
      },
      40.0);
  ASSERT_TRUE(named) << "~check_collisions never named (arm, " << kCircleName << ") and (side, "
                     << kWallName << "): " << all.message << ", " << all.collisions.size()
                     << " collisions";
  EXPECT_TRUE(all.in_collision);
  EXPECT_FALSE(test::mentions(all.collisions, "far"));
  EXPECT_EQ(all.collisions.size(), 2u);

  const CheckCollisions::Response circle_only = client.check({kCircleName});
  ASSERT_TRUE(circle_only.success) << circle_only.message;
  ASSERT_EQ(circle_only.collisions.size(), 1u);
  EXPECT_TRUE(collides(circle_only.collisions, "arm", kCircleName));
}

/// A scan of the wall and of a 0.2 m circle at (cx, cy) in the laser frame.
sensor_msgs::LaserScan movingCircleScan(const ros::Time& stamp, double cx, double cy) {
  sensor_msgs::LaserScan scan = syntheticScan(stamp);
  constexpr double kRadius = 0.2;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (i >= 10 && i <= 13) continue;  // the hostile beams stay
    const double a = scan.angle_min + i * static_cast<double>(scan.angle_increment);
    const double dx = std::cos(a), dy = std::sin(a);
    std::optional<double> best;
    const double b = dx * cx + dy * cy, disc = b * b - (cx * cx + cy * cy - kRadius * kRadius);
    if (disc >= 0.0 && b - std::sqrt(disc) > 0.0) best = b - std::sqrt(disc);
    if (dy < 0.0) {
      const double t = kWallY / dy;
      if (std::abs(t * dx) <= kWallHalfLength && (!best || t < *best)) best = t;
    }
    scan.ranges[i] = best ? static_cast<float>(*best) : std::numeric_limits<float>::infinity();
  }
  return scan;
}

TEST(ScanObstacles, AThingThatMovesCarriesItsVelocityAndTheWallStands) {
  // A 0.2 m circle crossing 1.5 m ahead of the laser at 0.8 m/s (+y in the laser frame), 40 scans
  // a second: tracked in odom through tf (laser turned 0.5 rad on base_link), its obstacle
  // carries (0, 0.8) in the laser's axes; the wall (1 m from its centroid) stands.
  ros::NodeHandle nh;
  std::mutex mutex;
  std::optional<EllipseArray> last;
  auto obstacles_sub = nh.subscribe<EllipseArray>(test::nodeTopic("obstacles"), 100,
                                                  [&](const EllipseArray::ConstPtr& msg) {
                                                    std::lock_guard<std::mutex> lock(mutex);
                                                    last = *msg;
                                                  });
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("/scan", 100);
  ros::AsyncSpinner spinner(2);
  spinner.start();
  ASSERT_TRUE(test::waitUntil([&] { return scan_pub.getNumSubscribers() > 0; }, 30.0));
  const ros::Time start = ros::Time::now();
  constexpr double kSpeed = 0.8, kRate = 40.0;
  constexpr int kScans = 48;
  for (int k = 0; k < kScans; ++k) {
    scan_pub.publish(
        movingCircleScan(start + ros::Duration(k / kRate), kCircleX, -0.4 + kSpeed * k / kRate));
    ros::Duration(1.0 / kRate).sleep();
  }
  const ros::Time last_stamp = start + ros::Duration((kScans - 1) / kRate);
  ASSERT_TRUE(test::waitUntil(
      [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return last && last->header.stamp == last_stamp;
      },
      10.0))
      << "the last scan's obstacles never arrived";
  std::lock_guard<std::mutex> lock(mutex);
  const double cy = -0.4 + kSpeed * (kScans - 1) / kRate;
  const Ellipse* moving = nullptr;
  const Ellipse* wall = nullptr;
  for (const Ellipse& e : last->ellipses) {
    if (std::hypot(e.x - kCircleX, e.y - cy) < 0.2) moving = &e;
    if (std::abs(e.y - kWallY) < 0.1) wall = &e;
  }
  ASSERT_NE(moving, nullptr) << "no obstacle on the circle";
  ASSERT_NE(wall, nullptr) << "no obstacle on the wall";
  EXPECT_NEAR(moving->vx, 0.0, 0.15);
  EXPECT_NEAR(moving->vy, kSpeed, 0.15);
  EXPECT_EQ(wall->vx, 0.0);
  EXPECT_EQ(wall->vy, 0.0);
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_scan_obstacles");
  ros::NodeHandle node;  // keeps the node up between tests (the last handle going shuts it down)
  return RUN_ALL_TESTS();
}

// Units behind the demo and its screenshot test that need no ROS master: the demo trajectory, the
// base's script and its arc, the arm guard's sweep and hold rule, the log-on-change rule, the rviz
// view reader and pixel mapping, and finding rviz's render panel in a picture.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "demo_arm_guard.h"
#include "demo_base_control.h"
#include "demo_log_on_change.h"
#include "demo_scanner.h"
#include "demo_trajectory.h"
#include "demo_world.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "rviz_top_down_view.h"
#include "screen_image.h"

namespace ellipse_collision {
namespace test {
namespace {

TEST(DemoScanner, RayHitsTheNearRimOfTiltedEllipsesAndMissesBehind) {
  core::Ellipse circle;
  circle.center = {2.0, 0.0};
  circle.radius_x = circle.radius_y = 0.5;
  EXPECT_NEAR(rayHit({0.0, 0.0}, {1.0, 0.0}, circle), 1.5, 1e-12);
  EXPECT_TRUE(std::isinf(rayHit({0.0, 0.0}, {-1.0, 0.0}, circle)));  // behind
  EXPECT_TRUE(std::isinf(rayHit({0.0, 0.0}, {0.0, 1.0}, circle)));   // beside
  EXPECT_TRUE(std::isinf(rayHit({2.0, 0.0}, {1.0, 0.0}, circle)));   // from inside
  // An ellipse 1 x 0.2 turned a quarter turn, centred at (0, 3): its near rim is at y = 2.
  core::Ellipse tall;
  tall.center = {0.0, 3.0};
  tall.radius_x = 1.0;
  tall.radius_y = 0.2;
  tall.angle = 1.5707963267948966;
  EXPECT_NEAR(rayHit({0.0, 0.0}, {0.0, 1.0}, tall), 2.0, 1e-9);
  // Oracle for a slanted beam: the hit lies on the rim.
  const Eigen::Vector2d d = Eigen::Vector2d(0.02, 1.0).normalized();
  const Eigen::Vector2d p = rayHit({0.0, 0.0}, d, tall) * d;
  EXPECT_NEAR(std::pow((p.y() - 3.0) / 1.0, 2) + std::pow(p.x() / 0.2, 2), 1.0, 1e-9);
}

TEST(DemoScanner, ScanSeesTheNearestEllipseInTheSensorsFrame) {
  core::Ellipse near_one, far_one;
  near_one.center = {1.0, 1.0};
  near_one.radius_x = near_one.radius_y = 0.25;
  far_one.center = {1.0, 4.0};
  far_one.radius_x = far_one.radius_y = 0.5;
  ScannerModel model;
  model.beams = 4;
  model.angle_min = 0.0;
  model.angle_increment = 1.5707963267948966;
  model.range_max = 8.0;
  Pose2D sensor;
  sensor.position = {1.0, 0.0};
  sensor.yaw = 1.5707963267948966;  // beam 0 points along the world's y
  const std::vector<float> ranges = rayCastScan(sensor, {near_one, far_one}, model);
  ASSERT_EQ(ranges.size(), 4u);
  EXPECT_NEAR(ranges[0], 0.75, 1e-6);  // the near one hides the far one
  EXPECT_TRUE(std::isinf(ranges[1]));
  EXPECT_TRUE(std::isinf(ranges[2]));
}

core::Ellipse ellipse(double x, double y, double angle, double radius_x, double radius_y) {
  core::Ellipse e;
  e.center = {x, y};
  e.angle = angle;
  e.radius_x = radius_x;
  e.radius_y = radius_y;
  return e;
}

// The demo's world (demo/config/demo_driver.yaml): the pillar, the crate and the wall, and the
// cart shuttling from (-4, -0.3) to (-2.2, -0.3) every 12 s. A scanner at (-1.2, -0.3) looking
// along x, four beams a quarter turn apart.
TEST(DemoWorld, TheScanSeesTheStaticObstaclesAndTheMovingOne) {
  DemoWorld world;
  world.static_obstacles = {ellipse(0.0, 0.0, 0.0, 0.40, 0.40), ellipse(2.3, 1.7, 0.5, 0.45, 0.30),
                            ellipse(-0.3, -2.1, 0.0, 1.30, 0.15)};
  world.moving = ellipse(0.0, 0.0, 0.0, 0.35, 0.25);
  world.shuttle.start = {-4.0, -0.3};
  world.shuttle.end = {-2.2, -0.3};
  world.shuttle.period_s = 12.0;
  ASSERT_EQ(world.at(0.0).size(), 4u);
  ScannerModel model;
  model.beams = 4;
  model.angle_min = 0.0;
  model.angle_increment = 0.5 * M_PI;
  Pose2D sensor;
  sensor.position = {-1.2, -0.3};

  const std::vector<float> start = rayCastScan(sensor, world.at(0.0), model);
  ASSERT_EQ(start.size(), 4u);
  // +x: the pillar's circle (radius 0.4) meets the line y = -0.3 at x = -sqrt(0.4^2 - 0.3^2).
  EXPECT_NEAR(start[0], 1.2 - std::sqrt(0.16 - 0.09), 1e-6);
  EXPECT_TRUE(std::isinf(start[1])) << start[1];  // +y: nothing (the crate is far to the right)
  // -x: the cart at its start, its rim 0.35 this side of x = -4.
  EXPECT_NEAR(start[2], 4.0 - 0.35 - 1.2, 1e-6);
  // -y: the wall's upper rim at x = -1.2, 0.9 from its centre: y = -2.1 + 0.15 sqrt(1 - (0.9/1.3)^2).
  EXPECT_NEAR(start[3], 2.1 - 0.15 * std::sqrt(1.0 - std::pow(0.9 / 1.3, 2)) - 0.3, 1e-6);

  // Half a period on, the cart is at its end, (-2.2, -0.3); the static obstacles stay.
  const std::vector<float> later = rayCastScan(sensor, world.at(6.0), model);
  EXPECT_NEAR(later[2], 2.2 - 0.35 - 1.2, 1e-6);
  EXPECT_EQ(later[0], start[0]);
  EXPECT_EQ(later[3], start[3]);
}

TEST(DemoBase, ArcPoseMatchesSmallStepsOfTheCommandFromAnyPose) {
  // Oracle: the unicycle integrated in 100,000 small steps (midpoint heading).
  Pose2D start;
  start.position = {1.5, -0.7};
  start.yaw = 2.5;
  for (const core::Twist& twist : {core::Twist{0.4, 0.0, 0.0}, core::Twist{-0.25, 0.0, 0.6},
                                   core::Twist{0.3, 0.1, -1.2}, core::Twist{0.0, 0.0, 0.8}}) {
    const double duration = 2.0;
    const int steps = 100000;
    const double dt = duration / steps;
    double x = start.position.x(), y = start.position.y(), yaw = start.yaw;
    for (int i = 0; i < steps; ++i) {
      const double mid = yaw + 0.5 * twist.wz * dt;
      x += (std::cos(mid) * twist.vx - std::sin(mid) * twist.vy) * dt;
      y += (std::sin(mid) * twist.vx + std::cos(mid) * twist.vy) * dt;
      yaw += twist.wz * dt;
    }
    const Pose2D after = poseAfterArc(start, twist, duration);
    EXPECT_NEAR(after.position.x(), x, 1e-9) << twist.vx << " " << twist.vy << " " << twist.wz;
    EXPECT_NEAR(after.position.y(), y, 1e-9);
    // The oracle's heading sums 100,000 steps: ~1e-11 of rounding.
    EXPECT_NEAR(std::remainder(after.yaw - yaw, 2.0 * M_PI), 0.0, 1e-10);
  }
}

BaseScript exampleScript() {
  DriveSettings drive;  // 0.4 m/s, 0.8 rad/s, gain 1.5, tolerance 0.3 m
  BackOffSettings back_off;  // blocked 1 s, then 0.25 m/s back turning 0.6 rad/s for 2.5 s
  return BaseScript({{2.0, 0.0}, {0.0, 2.0}}, drive, back_off);
}

TEST(DemoBase, DrivesStraightAtAWaypointAheadAndTurnsOnTheSpotForOneBehind) {
  BaseScript script = exampleScript();
  Pose2D pose;  // at the origin facing +x: the first waypoint is straight ahead
  core::Twist twist = script.command(pose, 0.0, false);
  EXPECT_NEAR(twist.vx, 0.4, 1e-12);
  EXPECT_NEAR(twist.wz, 0.0, 1e-12);
  pose.yaw = M_PI;  // facing away: turn (either way), no forward speed
  twist = script.command(pose, 0.1, false);
  EXPECT_NEAR(twist.vx, 0.0, 1e-12);
  EXPECT_NEAR(std::fabs(twist.wz), 0.8, 1e-12);
  pose.yaw = -0.2;  // the waypoint a little to the left: turn left at the gain
  twist = script.command(pose, 0.2, false);
  EXPECT_NEAR(twist.wz, 1.5 * 0.2, 1e-12);
  EXPECT_NEAR(twist.vx, 0.4 * std::cos(0.2), 1e-12);
}

TEST(DemoBase, AReachedWaypointGivesWayToTheNextAndTheRouteCloses) {
  BaseScript script = exampleScript();
  Pose2D pose;
  pose.position = {1.8, 0.0};  // within 0.3 m of the first
  script.command(pose, 0.0, false);
  EXPECT_EQ(script.waypoint(), 1u);
  pose.position = {0.1, 1.9};
  script.command(pose, 0.1, false);
  EXPECT_EQ(script.waypoint(), 0u);
}

TEST(DemoBase, HeldByTheGateItBacksOutTurningThenGoesOnToTheNextWaypoint) {
  BaseScript script = exampleScript();
  Pose2D pose;
  // Stopped for 0.9 s only, then let through: no back-off, the timer starts again.
  for (double t = 0.0; t < 0.95; t += 0.1) EXPECT_GT(script.command(pose, t, true).vx, 0.0);
  EXPECT_GT(script.command(pose, 1.0, false).vx, 0.0);
  for (double t = 1.1; t < 2.05; t += 0.1) EXPECT_GT(script.command(pose, t, true).vx, 0.0);
  // 1 s held: reverse while turning, for 2.5 s, whatever the gate does meanwhile.
  const core::Twist back = script.command(pose, 2.1, true);
  EXPECT_NEAR(back.vx, -0.25, 1e-12);
  EXPECT_NEAR(back.wz, 0.6, 1e-12);
  EXPECT_EQ(script.waypoint(), 1u);
  EXPECT_TRUE(script.backingOff(4.5));
  EXPECT_NEAR(script.command(pose, 4.5, false).vx, -0.25, 1e-12);
  // Then on to the next waypoint, (0, 2): to the left, so a left turn on the spot.
  EXPECT_FALSE(script.backingOff(4.7));
  const core::Twist on = script.command(pose, 4.7, false);
  EXPECT_NEAR(on.wz, 0.8, 1e-12);
  EXPECT_NEAR(on.vx, 0.0, 1e-9);
}

TEST(DemoTrajectory, ShuttleGoesToTheEndAndBackOncePerPeriod) {
  ShuttleMotion shuttle;
  shuttle.start = {-3.0, 1.0};
  shuttle.end = {-1.0, 0.0};
  shuttle.period_s = 12.0;
  EXPECT_NEAR((shuttle.at(0.0) - shuttle.start).norm(), 0.0, 1e-12);
  EXPECT_NEAR((shuttle.at(6.0) - shuttle.end).norm(), 0.0, 1e-12);
  EXPECT_NEAR((shuttle.at(3.0) - Eigen::Vector2d(-2.0, 0.5)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((shuttle.at(12.0) - shuttle.start).norm(), 0.0, 1e-12);
}

TEST(DemoTrajectory, SineJointPeaksAQuarterPeriodIn) {
  const SineMotion joint{-1.0, 1.5, 11.0, 0.0};
  EXPECT_NEAR(joint.at(0.0), -1.0, 1e-12);
  EXPECT_NEAR(joint.at(11.0 / 4), 0.5, 1e-12);
  EXPECT_NEAR(joint.at(3 * 11.0 / 4), -2.5, 1e-12);
}

TEST(DemoTrajectory, SineTravelIsTheSumOfItsSmallSteps) {
  const SineMotion joint{-1.0, 1.5, 11.0, 0.4};
  // Oracle: the sum of |change| over a million small steps.
  const auto summed = [&joint](double t0, double t1) {
    const int n = 1000000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      sum += std::abs(joint.at(t0 + (t1 - t0) * (i + 1) / n) - joint.at(t0 + (t1 - t0) * i / n));
    }
    return sum;
  };
  // Within one stretch, across one turning point, across several, and a sliver.
  for (const auto& [t0, t1] :
       {std::pair<double, double>{0.1, 0.5}, {1.5, 4.0}, {-3.0, 25.0}, {2.0, 2.001}}) {
    EXPECT_NEAR(joint.travel(t0, t1), summed(t0, t1), 1e-9) << t0 << " .. " << t1;
    EXPECT_DOUBLE_EQ(joint.travel(t1, t0), joint.travel(t0, t1));
  }
  // Two whole periods: four times 2 * amplitude.
  EXPECT_NEAR(joint.travel(3.0, 25.0), 4 * 2 * 1.5, 1e-12);
}

/// The demo robot's arm (demo/urdf/demo_robot.urdf): shoulder 0.15 m ahead of the base's origin,
/// elbow 0.6 m along the upper arm, wrist 0.5 m along the forearm, joints 0, 1, 2; ellipses about
/// the size the node fits to the links.
std::vector<ArmLink> demoArm() {
  const auto step = [](double x, int joint) {
    ArmChainStep s;
    s.origin.position = {x, 0.0};
    s.joint = joint;
    return s;
  };
  const auto shape = [](double cx, double rx, double ry) {
    core::Ellipse e;
    e.center = {cx, 0.0};
    e.radius_x = rx;
    e.radius_y = ry;
    return e;
  };
  return {{"upper_arm", shape(0.29, 0.34, 0.05), {step(0.15, 0)}},
          {"forearm", shape(0.24, 0.28, 0.045), {step(0.15, 0), step(0.6, 1)}},
          {"hand", shape(0.14, 0.16, 0.06), {step(0.15, 0), step(0.6, 1), step(0.5, 2)}}};
}

/// The demo's joint motions (demo/config/demo_driver.yaml).
std::vector<SineMotion> demoJoints() {
  return {{0.0, 1.5, 7.0, 0.0}, {-1.0, 1.5, 11.0, 0.0}, {0.0, 1.2, 5.0, 0.0}};
}

TEST(DemoArmGuard, LinkPosesFollowTheChain) {
  const std::vector<ArmLink> arm = demoArm();
  // Shoulder a quarter turn left, elbow a quarter turn right, wrist half a turn.
  const std::vector<double> q = {M_PI / 2, -M_PI / 2, M_PI};
  const Pose2D hand = linkPose(arm[2], q);
  EXPECT_NEAR(hand.position.x(), 0.15 + 0.5, 1e-12);
  EXPECT_NEAR(hand.position.y(), 0.6, 1e-12);
  EXPECT_NEAR(std::remainder(hand.yaw - M_PI, 2 * M_PI), 0.0, 1e-12);
  // A clockwise axis turns the other way.
  ArmLink flipped = arm[0];
  flipped.chain[0].axis = -1.0;
  EXPECT_NEAR(linkPose(flipped, q).yaw, -M_PI / 2, 1e-12);
  // The ellipse goes with the frame: the hand's centre 0.14 m along its x, which points back.
  const core::Ellipse placed = placedAt(arm[2].shape, hand);
  EXPECT_NEAR(placed.center.x(), 0.65 - 0.14, 1e-12);
  EXPECT_NEAR(placed.center.y(), 0.6, 1e-12);
}

TEST(DemoArmGuard, EverySampleCoversWhereItsLinkGoesWithinItsStretch) {
  const std::vector<ArmLink> arm = demoArm();
  const std::vector<SineMotion> joints = demoJoints();
  ArmGuardSettings settings;
  settings.horizon_s = 0.3;
  settings.step_s = 0.04;  // 8 steps of 0.0375 s
  Pose2D base;
  base.position = {1.0, -2.0};
  base.yaw = 0.7;
  const core::Twist twist{0.4, 0.1, -0.8};
  double worst_share = 0.0;  // largest displacement found / its bound
  // Forward along the sweep, and back along it (the arm retracing it).
  for (const double direction : {1.0, -1.0}) {
    for (double clock = 0.0; clock < 77.0; clock += 0.61) {
      const std::vector<ArmSample> sweep =
          armSweep(arm, joints, clock, direction, base, twist, settings);
      ASSERT_EQ(sweep.size(), 9u * arm.size());
      EXPECT_EQ(sweep.front().name, "upper_arm@0");
      EXPECT_EQ(sweep.back().name, "hand@8");
      EXPECT_DOUBLE_EQ(sweep.back().to_s, 0.3);
      for (const ArmSample& sample : sweep) {
        const ArmLink& link = *std::find_if(
            arm.begin(), arm.end(), [&](const ArmLink& l) { return l.name == sample.link; });
        // Oracle: where points of the link really are, its frame from the chain at that time.
        const auto pointAt = [&](double t, const Eigen::Vector2d& in_link) {
          std::vector<double> q;
          for (const SineMotion& j : joints) q.push_back(j.at(clock + direction * t));
          const Pose2D frame = linkPose(link, q);
          const Eigen::Vector2d in_base = frame.position + Eigen::Rotation2Dd(frame.yaw) * in_link;
          const Pose2D base_then = poseAfterArc(base, twist, t);
          return Eigen::Vector2d(base_then.position + Eigen::Rotation2Dd(base_then.yaw) * in_base);
        };
        // The sampled ellipse is the link at time_s.
        const Eigen::Vector2d centre = pointAt(sample.time_s, link.shape.center);
        EXPECT_NEAR((sample.ellipse.center - centre).norm(), 0.0, 1e-9) << sample.name;
        for (int k = 0; k <= 20; ++k) {
          const double t = sample.from_s + (sample.to_s - sample.from_s) * k / 20;
          for (int r = 0; r < 16; ++r) {
            const double a = 2 * M_PI * r / 16;
            const Eigen::Vector2d rim =
                link.shape.center + Eigen::Rotation2Dd(link.shape.angle) *
                                        Eigen::Vector2d(link.shape.radius_x * std::cos(a),
                                                        link.shape.radius_y * std::sin(a));
            const double moved = (pointAt(t, rim) - pointAt(sample.time_s, rim)).norm();
            ASSERT_LE(moved, sample.sweep_m + 1e-12) << sample.name << " at " << t;
            worst_share = std::max(worst_share, moved / sample.sweep_m);
          }
        }
      }
    }
  }
  // Not a vacuous bound: somewhere a point moves most of it.
  EXPECT_GT(worst_share, 0.5);
}

TEST(DemoArmGuard, HoldsForTheSoonestSampleWithinItsSweepPlusTheClearance) {
  std::vector<ArmSample> sweep(4);
  const char* names[] = {"forearm@0", "hand@0", "forearm@1", "hand@1"};
  for (int i = 0; i < 4; ++i) {
    sweep[i].name = names[i];
    sweep[i].link = i % 2 ? "hand" : "forearm";
    sweep[i].from_s = i < 2 ? 0.0 : 0.05;
    sweep[i].sweep_m = 0.02;
  }
  const double clearance = 0.05;
  // Farther than sweep + clearance (0.07): the arm may move.
  EXPECT_FALSE(firstHold(sweep, {{"hand@0", "scan_3", 0.071}}, clearance));
  // Queries the sweep does not have are ignored.
  EXPECT_FALSE(firstHold(sweep, {{"gripper@0", "scan_3", 0.0}}, clearance));
  EXPECT_FALSE(firstHold(sweep, {}, clearance));
  // Within it, or in collision (distance 0): held, by the soonest such sample.
  const auto hold = firstHold(
      sweep,
      {{"forearm@1", "scan_120", 0.0}, {"hand@0", "scan_3", 0.09}, {"hand@1", "scan_4", 0.06}},
      clearance);
  ASSERT_TRUE(hold);
  EXPECT_EQ(hold->link, "forearm");
  EXPECT_EQ(hold->obstacle, "scan_120");
  EXPECT_DOUBLE_EQ(hold->time_s, 0.05);
  EXPECT_EQ(holdText(*hold, clearance),
            "arm held: forearm would come within 0.05 m of scan_120 in 0.05 s");
  const auto now =
      firstHold(sweep, {{"hand@1", "scan_4", 0.0}, {"hand@0", "scan_3", 0.07}}, clearance);
  ASSERT_TRUE(now);
  EXPECT_EQ(holdText(*now, 0.0), "arm held: hand would touch scan_3 now");
  // A sample whose sweep and clearance reach the warning distance cannot be decided.
  EXPECT_FALSE(undecidedSample(sweep, clearance, 0.3));
  sweep[2].sweep_m = 0.25;
  ASSERT_TRUE(undecidedSample(sweep, clearance, 0.3));
  EXPECT_EQ(undecidedSample(sweep, clearance, 0.3)->name, "forearm@1");
}

/// The collision node's answer for `sweep` against `obstacles`, as ~check_collisions gives it
/// with a warning distance: collisions (distance 0) and warning pairs with their distance.
std::vector<ArmContact> answer(const std::vector<ArmSample>& sweep,
                               const std::vector<core::Ellipse>& obstacles, double warning) {
  std::vector<ArmContact> contacts;
  for (const ArmSample& sample : sweep) {
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      const core::Clearance c = core::distance(sample.ellipse, obstacles[i]);
      if (!c.separated || c.distance < warning) {
        contacts.push_back(
            {sample.name, "wall_" + std::to_string(i), c.separated ? c.distance : 0.0});
      }
    }
  }
  return contacts;
}

/// Sweeps the demo arm (the base standing) for 60 s against a wall in its way that is gone after
/// 40 s, guarded with `settings`.
void sweepIntoAWall(const ArmGuardSettings& settings) {
  SCOPED_TRACE("horizon " + std::to_string(settings.horizon_s) + " s, clearance " +
               std::to_string(settings.clearance_m) + " m");
  const std::vector<ArmLink> arm = demoArm();
  const std::vector<SineMotion> joints = demoJoints();
  const double warning = 0.3;  // the demo node's warning_distance
  Pose2D base;                 // standing at the origin
  core::Twist still;
  // A wall across the arm's reach ahead-left of the base, gone after 40 s.
  core::Ellipse wall;
  wall.center = {0.9, 1.1};
  wall.radius_x = 0.8;
  wall.radius_y = 0.1;
  wall.angle = 0.3;
  const double dt = 1.0 / 30, gone_s = 40.0;
  const auto linksAt = [&](double clock) {
    std::vector<double> q;
    for (const SineMotion& j : joints) q.push_back(j.at(clock));
    std::vector<core::Ellipse> placed;
    for (const ArmLink& link : arm) placed.push_back(placedAt(link.shape, linkPose(link, q)));
    return placed;
  };
  double clock = 0.0;
  int held = 0, held_after = 0, unguarded_hits = 0;
  double closest = 1e9;
  for (int cycle = 0; cycle * dt < 60.0; ++cycle) {
    const double t = cycle * dt;
    const bool wall_there = t < gone_s;
    const std::vector<core::Ellipse> world =
        wall_there ? std::vector<core::Ellipse>{wall} : std::vector<core::Ellipse>{};
    // Without the guard, by the clock alone, the arm would hit the wall.
    for (const core::Ellipse& link : linksAt(t)) {
      if (wall_there && core::overlap(link, wall)) ++unguarded_hits;
    }
    const std::vector<ArmSample> sweep = armSweep(arm, joints, clock, 1.0, base, still, settings);
    ASSERT_FALSE(undecidedSample(sweep, settings.clearance_m, warning)) << "at " << t;
    const auto hold = firstHold(sweep, answer(sweep, world, warning), settings.clearance_m);
    if (hold) {
      (wall_there ? held : held_after) += 1;
      continue;
    }
    // The arm moves on by one cycle: every pose on the way keeps the clearance.
    for (int k = 1; k <= 10; ++k) {
      for (const core::Ellipse& link : linksAt(clock + dt * k / 10)) {
        if (!wall_there) continue;
        const core::Clearance c = core::distance(link, wall);
        ASSERT_TRUE(c.separated) << "a link touched the wall at " << t;
        closest = std::min(closest, c.distance);
      }
    }
    clock += dt;
  }
  EXPECT_GT(unguarded_hits, 0) << "the wall is not in the arm's way";
  EXPECT_GT(held, 0) << "the arm never held";
  EXPECT_GE(closest, settings.clearance_m);
  EXPECT_EQ(held_after, 0) << "held with the wall gone";
  EXPECT_GT(clock, 15.0) << "the arm stopped for good";
}

TEST(DemoArmGuard, AGuardedArmStopsShortOfAWallAndSweepsOnWhenItIsGone) {
  sweepIntoAWall(
      ArmGuardSettings());  // the defaults: 0.3 s ahead, steps of 0.05 s, 0.05 m clearance
  // Looking one step ahead only, the sweep bound alone keeps the clearance between the samples.
  ArmGuardSettings one_step;
  one_step.horizon_s = one_step.step_s = 1.0 / 30;
  sweepIntoAWall(one_step);
  one_step.clearance_m = 0.0;
  sweepIntoAWall(one_step);
}

TEST(DemoLogOnChange, LogsANewSubjectOnceAndAReturnAtMostOncePerInterval) {
  LogOnChange log(5.0);
  EXPECT_TRUE(log.shouldLog("forearm / scan_3", 0.0));
  EXPECT_FALSE(log.shouldLog("forearm / scan_3", 0.2));  // still the same contact
  EXPECT_FALSE(log.shouldLog("forearm / scan_3", 9.0));
  EXPECT_FALSE(log.shouldLog("", 9.1));                 // over
  EXPECT_TRUE(log.shouldLog("forearm / scan_3", 9.2));  // back after it was over
  EXPECT_FALSE(log.shouldLog("", 9.3));
  EXPECT_FALSE(log.shouldLog("forearm / scan_3", 9.4));  // flickering: not within 5 s
  EXPECT_FALSE(log.shouldLog("hand / scan_3", 12.0));    // a change, but too soon
  EXPECT_TRUE(log.shouldLog("hand / scan_3", 14.2));     // then once
  EXPECT_FALSE(log.shouldLog("hand / scan_3", 30.0));
}

/// An .rviz file in the temporary directory, removed at the end of the test.
class RvizFile {
 public:
  explicit RvizFile(const std::string& text) {
    char name[] = "/tmp/test_demo_units_XXXXXX";
    const int fd = mkstemp(name);
    if (fd < 0) throw std::runtime_error("mkstemp failed");
    close(fd);
    path_ = name;
    std::ofstream(path_) << text;
  }
  ~RvizFile() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Shaped like a file rviz writes, with decoys: keys of the same name elsewhere and deeper down.
const char* const kTopDownConfig = R"(Panels:
  - Class: rviz/Displays
    Name: Displays
Visualization Manager:
  Class: ""
  Displays:
    - Alpha: 0.5
      Class: rviz/Grid
      Color: 160; 160; 164
      Offset:
        X: 7
        Y: 7
  Global Options:
    Background Color: 10; 20; 30
    Fixed Frame: odom
  Views:
    Current:
      Angle: 0
      Class: rviz/TopDownOrtho
      Enable Stereo Rendering:
        Scale: 99
      Scale: 125
      X: -0.5
      Y: 0.25
    Saved: ~
Window Geometry:
  X: 3
  Y: 4
)";

TEST(RvizTopDownView, ReadsTheCurrentViewAndBackground) {
  const RvizFile file(kTopDownConfig);
  const TopDownView view = readTopDownView(file.path());
  EXPECT_EQ(view.scale_px_per_m, 125.0);
  EXPECT_EQ(view.focal_m, Eigen::Vector2d(-0.5, 0.25));
  EXPECT_EQ(view.background, (std::array<int, 3>{{10, 20, 30}}));
}

TEST(RvizTopDownView, RefusesOtherViews) {
  std::string orbit = kTopDownConfig;
  orbit.replace(orbit.find("rviz/TopDownOrtho"), 17, "rviz/Orbit");
  const RvizFile file(orbit);
  EXPECT_THROW(readTopDownView(file.path()), std::runtime_error);
}

TEST(RvizTopDownView, RefusesARotatedView) {
  std::string rotated = kTopDownConfig;
  rotated.replace(rotated.find("Angle: 0"), 8, "Angle: 0.5");
  const RvizFile file(rotated);
  EXPECT_THROW(readTopDownView(file.path()), std::runtime_error);
}

TEST(RvizTopDownView, TheDemoConfigHasATopDownView) {
  EXPECT_GT(readTopDownView(DEMO_RVIZ_CONFIG).scale_px_per_m, 0.0);
}

TEST(RvizTopDownView, MapsMetresToPixelsXRightYUp) {
  TopDownView view;
  view.scale_px_per_m = 100.0;
  view.focal_m = {1.0, 2.0};
  const PanelRect panel{10, 20, 209, 119};  // 200 x 100 px, centre (110, 70)
  EXPECT_EQ(toPixel(view, panel, {1.0, 2.0}), Eigen::Vector2d(110.0, 70.0));
  EXPECT_EQ(toPixel(view, panel, {1.5, 2.0}), Eigen::Vector2d(160.0, 70.0));
  EXPECT_EQ(toPixel(view, panel, {1.0, 2.25}), Eigen::Vector2d(110.0, 45.0));
  const Eigen::Vector2d point(-0.3, 2.7);
  EXPECT_NEAR((toPoint(view, panel, toPixel(view, panel, point)) - point).norm(), 0.0, 1e-12);
}

TEST(ScreenImage, FindsTheAreaOfAColourDespiteStrayPixels) {
  const Rgb grey{{48, 48, 48}};
  ScreenImage image(300, 200, Rgb{{240, 240, 240}});
  for (int y = 50; y <= 149; ++y) {
    for (int x = 100; x <= 279; ++x) image.set(x, y, grey);
  }
  image.set(5, 5, grey);  // anti-aliased text elsewhere
  image.set(6, 180, grey);
  image.set(120, 60, Rgb{{200, 0, 0}});  // something drawn in the area
  const PanelRect area = image.findArea(grey, 20);
  EXPECT_EQ(area.left, 100);
  EXPECT_EQ(area.right, 279);
  EXPECT_EQ(area.top, 50);
  EXPECT_EQ(area.bottom, 149);
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision

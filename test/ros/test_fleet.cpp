// Robots that see each other through real nodes (fleet.test), on simulated time. Four collision
// nodes in namespaces r1..r4, each publishing its robot on /fleet/footprints and taking the others
// in through a robots source; the client is four bases that move as real ones (core::SimulatedBase:
// 0.1 s late, braking at 0.8 m/s^2), each driven through its own node's gate at 20 Hz and
// publishing its pose in map and its odometry. Contact between two robots is checked every 5 ms
// of the motion; a robot touching another while it moves is a failure.
#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <tf2_ros/transform_broadcaster.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_builders.h"
#include "ellipse_collision/GateState.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/simulated_base.h"
#include "node_test_utils.h"
#include "planar_transform.h"

namespace ellipse_collision {
namespace {

constexpr std::size_t kRobots = 4;
constexpr double kStep = 0.05;                  // [s] between commands
const core::BaseDynamics kBase{0.1, 0.8, 2.0};  // fleet_scene.yaml's
/// The links of fleet_scene.yaml, in <robot>/base_link.
const std::vector<core::Ellipse> kLinks = {{{0.15, 0.0}, 0.2, 0.22, 0.0},
                                           {{-0.15, 0.0}, 0.2, 0.22, 0.0}};

std::string robotName(std::size_t i) { return "r" + std::to_string(i + 1); }

/// One robot: its base, its node's topics and the last decision of its gate.
struct Robot {
  std::string name;
  std::optional<core::SimulatedBase> base;
  double cruise{0.0};  ///< [m/s] commanded forward speed (0: parked, no commands)
  ros::Publisher cmd_pub;
  ros::Publisher odom_pub;
  ros::Subscriber state_sub;
  std::size_t states{0};
  GateState last;
};

class Fleet : public ::testing::Test {
 protected:
  void SetUp() override {
    spinner_.start();
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 1, true);
    publishClock();
    for (std::size_t i = 0; i < kRobots; ++i) {
      Robot& robot = robots_[i];
      robot.name = robotName(i);
      robot.cmd_pub = nh_.advertise<geometry_msgs::Twist>(
          "/" + robot.name + "/ellipse_collision/cmd_vel_in", 10);
      robot.odom_pub = nh_.advertise<nav_msgs::Odometry>("/" + robot.name + "/odom", 10);
      robot.state_sub = nh_.subscribe<GateState>("/" + robot.name + "/ellipse_collision/gate_state",
                                                 100, [this, i](const GateState::ConstPtr& msg) {
                                                   std::lock_guard<std::mutex> lock(mutex_);
                                                   robots_[i].last = *msg;
                                                   ++robots_[i].states;
                                                 });
    }
    for (Robot& robot : robots_) {
      ASSERT_TRUE(test::waitUntil(
          [&] {
            return robot.cmd_pub.getNumSubscribers() > 0 &&
                   robot.odom_pub.getNumSubscribers() > 0 && robot.state_sub.getNumPublishers() > 0;
          },
          30.0))
          << robot.name << "'s node is not up";
    }
  }

  void publishClock() {
    rosgraph_msgs::Clock clock;
    clock.clock = ros::Time(now_);
    clock_pub_.publish(clock);
  }

  /// Places robot `i` at (x, y, yaw) at rest, commanded forward at `cruise` [m/s] (0: parked).
  void place(std::size_t i, double x, double y, double yaw, double cruise) {
    robots_[i].base.emplace(kBase, core::PathPose{x, y, yaw, now_});
    robots_[i].cruise = cruise;
  }

  void publishPoses() {
    std::vector<geometry_msgs::TransformStamped> poses;
    for (std::size_t i = 0; i < kRobots; ++i) {
      if (i == silent_) continue;
      Robot& robot = robots_[i];
      const core::PathPose& p = robot.base->pose();
      const geometry_msgs::TransformStamped t =
          test::planarTransform("map", robot.name + "/base_link", p.x, p.y, p.yaw, ros::Time(now_));
      poses.push_back(t);
      nav_msgs::Odometry odom;
      odom.header.stamp = ros::Time(now_);
      odom.header.frame_id = "map";
      odom.child_frame_id = robot.name + "/base_link";
      odom.twist.twist.linear.x = robot.base->velocity().vx;
      odom.twist.twist.linear.y = robot.base->velocity().vy;
      odom.twist.twist.angular.z = robot.base->velocity().wz;
      robot.odom_pub.publish(odom);
    }
    tf_.sendTransform(poses);
  }

  std::vector<core::Ellipse> linksOf(const Robot& robot) const {
    const core::PathPose& p = robot.base->pose();
    return test::placedAt(kLinks, p.x, p.y, p.yaw);
  }

  /// The smallest distance between a link of `a` and a link of `b` [m] (< 0 never: 0 = touching).
  double gap(const Robot& a, const Robot& b) const {
    double best = std::numeric_limits<double>::infinity();
    for (const core::Ellipse& la : linksOf(a)) {
      for (const core::Ellipse& lb : linksOf(b)) {
        if (core::overlap(la, lb)) return 0.0;
        best = std::min(best, core::distance(la, lb).distance);
      }
    }
    return best;
  }

  /// One command round: clock, poses and odometry out; each driven robot's command through its
  /// gate; then every base follows its output for kStep, contact checked every 5 ms.
  void step() {
    publishClock();
    publishPoses();
    // tf, odometry and the nodes' footprints travel on their own connections: a head start.
    ros::WallDuration(0.03).sleep();
    std::array<std::size_t, kRobots> before{};
    {
      std::lock_guard<std::mutex> lock(mutex_);
      for (std::size_t i = 0; i < kRobots; ++i) before[i] = robots_[i].states;
    }
    for (Robot& robot : robots_) {
      if (robot.cruise == 0.0) continue;
      geometry_msgs::Twist cmd;
      cmd.linear.x = robot.cruise;
      robot.cmd_pub.publish(cmd);
    }
    ASSERT_TRUE(test::waitUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          for (std::size_t i = 0; i < kRobots; ++i) {
            if (robots_[i].cruise != 0.0 && robots_[i].states <= before[i]) return false;
          }
          return true;
        },
        10.0))
        << "a gate did not answer";
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t i = 0; i < kRobots; ++i) {
      Robot& robot = robots_[i];
      if (robot.cruise == 0.0) continue;
      const geometry_msgs::Twist& out = robot.last.output;
      robot.base->command(now_, {out.linear.x, out.linear.y, out.angular.z});
    }
    for (int k = 1; k <= 10; ++k) {
      for (Robot& robot : robots_) robot.base->advanceTo(now_ + kStep * k / 10);
      for (std::size_t a = 0; a < kRobots; ++a) {
        for (std::size_t b = a + 1; b < kRobots; ++b) {
          const bool moving = robots_[a].base->moving() || robots_[b].base->moving();
          const double g = gap(robots_[a], robots_[b]);
          if (moving) closest_ = std::min(closest_, g);
          if (moving && g == 0.0 && !touched_) {
            touched_ = true;
            touch_ = robots_[a].name + " and " + robots_[b].name +
                     " at t = " + std::to_string(now_) + ", " + robots_[a].name + " at " +
                     std::to_string(robots_[a].base->speed()) + " m/s, " + robots_[b].name +
                     " at " + std::to_string(robots_[b].base->speed()) + " m/s";
          }
        }
      }
    }
    now_ += kStep;
  }

  GateState lastState(std::size_t i) {
    std::lock_guard<std::mutex> lock(mutex_);
    return robots_[i].last;
  }

  ros::NodeHandle nh_;
  ros::AsyncSpinner spinner_{2};
  ros::Publisher clock_pub_;
  tf2_ros::TransformBroadcaster tf_;
  std::mutex mutex_;
  std::array<Robot, kRobots> robots_;
  bool touched_{false};
  std::string touch_;
  double closest_{std::numeric_limits<double>::infinity()};
  std::size_t silent_{kRobots};  ///< the robot whose pose is not published (kRobots: none)
  /// The simulated clock [s], on across tests (tf must not go back).
  static inline double now_ = 100.0;
};

TEST_F(Fleet, RobotsCrossingAnIntersectionNeverTouchAndAllGetThrough) {
  // r1 east along y = 0, r2 north along x = 0 arriving 1.5 s later, r3 west along y = 0.6 from
  // far, r4 parked beside the crossing: every pair of routes meets near the origin.
  place(0, -4.0, 0.0, 0.0, 1.0);
  place(1, 0.0, -5.5, M_PI / 2, 1.0);
  place(2, 7.0, 0.6, M_PI, 1.0);
  place(3, 1.5, -1.2, M_PI / 2, 0.0);
  bool through = false;
  for (int i = 0; i < 400 && !through; ++i) {
    step();
    ASSERT_FALSE(HasFatalFailure());
    through = robots_[0].base->pose().x > 3.5 && robots_[1].base->pose().y > 3.5 &&
              robots_[2].base->pose().x < -3.5;
  }
  EXPECT_FALSE(touched_) << touch_;
  EXPECT_TRUE(through) << "r1 at x " << robots_[0].base->pose().x << " (" << lastState(0).reason
                       << "), r2 at y " << robots_[1].base->pose().y << " (" << lastState(1).reason
                       << "), r3 at x " << robots_[2].base->pose().x << " (" << lastState(2).reason
                       << ")";
  std::cout << "intersection: closest approach while moving " << closest_ << " m" << std::endl;
}

TEST_F(Fleet, HeadOnInACorridorBothStopApartNamingTheOther) {
  // r1 east and r2 west on one line, 6 m apart, closing at 2 m/s; r3 and r4 parked far away.
  place(0, -3.0, 20.0, 0.0, 1.0);
  place(1, 3.0, 20.0, M_PI, 1.0);
  place(2, -10.0, -20.0, 0.0, 0.0);
  place(3, 10.0, -20.0, 0.0, 0.0);
  int resting = 0;
  for (int i = 0; i < 300 && resting < 20; ++i) {
    step();
    ASSERT_FALSE(HasFatalFailure());
    const bool moving = robots_[0].base->moving() || robots_[1].base->moving();
    resting = moving ? 0 : resting + 1;
  }
  EXPECT_FALSE(touched_) << touch_;
  EXPECT_FALSE(robots_[0].base->moving());
  EXPECT_FALSE(robots_[1].base->moving());
  const double apart = gap(robots_[0], robots_[1]);
  EXPECT_GT(apart, 0.0);
  EXPECT_LT(apart, 2.0) << "stopped absurdly early";
  // Each gate says why: the other robot's link, named as that robot published it.
  const GateState r1 = lastState(0);
  const GateState r2 = lastState(1);
  EXPECT_NE(r1.action, "PASS");
  EXPECT_NE(r2.action, "PASS");
  EXPECT_EQ(r1.obstacle.rfind("r2/", 0), 0u) << r1.action << ": " << r1.reason;
  EXPECT_EQ(r2.obstacle.rfind("r1/", 0), 0u) << r2.action << ": " << r2.reason;
  EXPECT_NE(r1.reason.find("r2/"), std::string::npos) << r1.reason;
  std::cout << "corridor: at rest " << apart << " m apart; r1: " << r1.action << " " << r1.reason
            << "; r2: " << r2.action << " " << r2.reason << std::endl;
}

TEST_F(Fleet, ARobotThatFallsSilentIsDroppedNotIncomplete) {
  // r1 keeps driving away from the others; the test stops publishing r4's pose, so its node
  // sends no footprint (its links cannot be placed in map): after the 1 s timeout r1's node
  // drops r4, says so in /diagnostics, and r1's gate goes on passing.
  place(0, -20.0, 40.0, 0.0, 0.5);
  place(1, 20.0, 40.0, 0.0, 0.0);
  place(2, 20.0, 45.0, 0.0, 0.0);
  place(3, 20.0, 50.0, 0.0, 0.0);
  std::mutex diag_mutex;
  std::string robots_value, dropped_value;
  ros::Subscriber diag = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
      "/diagnostics", 20, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
        for (const auto& status : msg->status) {
          if (status.name != "/r1/ellipse_collision: fleet") continue;
          std::lock_guard<std::mutex> lock(diag_mutex);
          for (const auto& kv : status.values) {
            if (kv.key == "source 'robots' robots") robots_value = kv.value;
            if (kv.key.rfind("source 'robots' dropped", 0) == 0) dropped_value = kv.value;
          }
        }
      });
  for (int i = 0; i < 40; ++i) step();  // 2 s: everyone heard from
  {
    std::lock_guard<std::mutex> lock(diag_mutex);
    EXPECT_NE(robots_value.find("r4 ("), std::string::npos) << robots_value;
  }
  // r4 vanishes: its pose is no longer published; past max_transform_age (0.5 s) its node sends
  // no footprint, and 1 s later r1's node drops it.
  silent_ = 3;
  for (int i = 0; i < 60; ++i) step();  // 3 s
  {
    std::lock_guard<std::mutex> lock(diag_mutex);
    EXPECT_EQ(robots_value.find("r4 ("), std::string::npos) << robots_value;
    EXPECT_NE(dropped_value.find("r4"), std::string::npos) << dropped_value;
  }
  const GateState r1 = lastState(0);
  EXPECT_EQ(r1.action, "PASS") << r1.reason;
}

TEST_F(Fleet, SoakFourRobotsShuttlingAcrossFourCrossings) {
  // Off in the suite: FLEET_SOAK_S=120 rostest ellipse_collision fleet_soak.test runs it.
  const char* soak = std::getenv("FLEET_SOAK_S");
  if (soak == nullptr) GTEST_SKIP() << "set FLEET_SOAK_S [s] to run";
  const double duration = std::atof(soak);
  // Four lines crossing in four places: r1 on y = 0 and r3 on y = 2.5 (east-west), r2 on x = 0 and
  // r4 on x = 2.5 (north-south). Each shuttles at 1 m/s between its line's ends at -4 and +6.5,
  // driving forward and back without turning. Its one planning rule: after 3 s without getting
  // anywhere it heads for the other end (resolving a standoff is the planner's job).
  struct Route {
    bool along_x;
    double at;
  };
  const std::array<Route, kRobots> routes = {Route{true, 0.0}, Route{false, 0.0}, Route{true, 2.5},
                                             Route{false, 2.5}};
  const double low = -4.0, high = 6.5;
  std::array<double, kRobots> progress_at{}, best{}, stuck_longest{};
  std::array<int, kRobots> reached{};
  for (std::size_t i = 0; i < kRobots; ++i) {
    const double start = low + 1.5 * static_cast<double>(i);  // staggered
    if (routes[i].along_x) {
      place(i, start, routes[i].at, 0.0, 1.0);
    } else {
      place(i, routes[i].at, start, M_PI / 2, 1.0);
    }
    progress_at[i] = now_;
    best[i] = start;
  }
  const auto position = [&](std::size_t i) {
    const core::PathPose& p = robots_[i].base->pose();
    return routes[i].along_x ? p.x : p.y;
  };
  const double end = now_ + duration;
  while (now_ < end) {
    step();
    ASSERT_FALSE(HasFatalFailure());
    for (std::size_t i = 0; i < kRobots; ++i) {
      Robot& robot = robots_[i];
      const double s = position(i);
      const bool forward = robot.cruise > 0.0;
      if ((forward && s >= high) || (!forward && s <= low)) {
        ++reached[i];
        robot.cruise = -robot.cruise;
        progress_at[i] = now_;
        best[i] = s;
      } else if (forward ? s > best[i] + 0.05 : s < best[i] - 0.05) {
        best[i] = s;
        progress_at[i] = now_;
      } else if (now_ - progress_at[i] > 3.0) {
        stuck_longest[i] = std::max(stuck_longest[i], now_ - progress_at[i]);
        robot.cruise = -robot.cruise;  // give way: back to the other end
        progress_at[i] = now_;
        best[i] = s;
      }
    }
  }
  EXPECT_FALSE(touched_) << touch_;
  std::cout << "soak " << duration << " s: closest approach while moving " << closest_ << " m";
  for (std::size_t i = 0; i < kRobots; ++i) {
    std::cout << "; " << robots_[i].name << " reached " << reached[i] << " ends, travelled "
              << robots_[i].base->travelled() << " m";
    // Each shuttle end is 10.5 m away: at 1 m/s a free robot reaches one every ~11 s.
    EXPECT_GE(reached[i], static_cast<int>(duration / 11.0 / 3.0)) << robots_[i].name << " stuck";
  }
  std::cout << std::endl;
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_fleet");
  return RUN_ALL_TESTS();
}

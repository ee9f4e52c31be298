// The velocity gate through the real node (gate.test), on simulated time. The client is the
// robot: it publishes /clock and base_link's pose in map, sends a command on ~cmd_vel_in, waits
// for the one ~cmd_vel_out it causes, and integrates that command exactly (an arc) over 0.1 s
// before the next. After every step the robot's links are checked against the obstacles with the
// core's overlap(): the gate must never let them touch.
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_srvs/SetBool.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "node_test_utils.h"

namespace ellipse_collision {
namespace {

using test::nodeTopic;
using test::waitUntil;

constexpr double kStep = 0.1;  // [s] between commands (10 Hz)

/// The links of gate_scene.yaml, in base_link.
const std::vector<core::Ellipse> kLinks = {{{0.15, 0.0}, 0.2, 0.22, 0.0},
                                           {{-0.15, 0.0}, 0.2, 0.22, 0.0}};

struct Pose {
  double x{0.0}, y{0.0}, yaw{0.0};
};

struct Obstacle {
  std::string name;
  core::Ellipse ellipse;  ///< in map
  double vx{0.0};         ///< [m/s] in map, given to the node as the obstacle's own velocity
};

class GateTest : public ::testing::Test, protected test::NodeServiceClient {
 protected:
  void SetUp() override {
    spinner_.start();
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 1, true);
    publishClock();
    cmd_pub_ = nh_.advertise<geometry_msgs::Twist>(nodeTopic("cmd_vel_in"), 10);
    out_sub_ = nh_.subscribe(nodeTopic("cmd_vel_out"), 100, &GateTest::onOutput, this);
    state_sub_ = nh_.subscribe(nodeTopic("gate_state"), 100, &GateTest::onState, this);
    connectServices(nh_);
    enable_ = nh_.serviceClient<std_srvs::SetBool>(nodeTopic("gate/set_enabled"));
    ASSERT_TRUE(enable_.waitForExistence(ros::Duration(30.0)));
    ASSERT_TRUE(waitUntil([&] { return cmd_pub_.getNumSubscribers() > 0; }, 30.0));
    ASSERT_TRUE(waitUntil([&] { return out_sub_.getNumPublishers() > 0; }, 30.0));
    setEnabled(true);
    pose_ = Pose();  // published with the first step (tf refuses a second pose at one stamp)
  }
  void TearDown() override {
    std::vector<std::string> names;
    for (const Obstacle& o : obstacles_) names.push_back(o.name);
    if (!names.empty()) remove(names);
    obstacles_.clear();
  }

  void publishClock() {
    rosgraph_msgs::Clock clock;
    clock.clock = ros::Time(now_);
    clock_pub_.publish(clock);
  }
  void publishPose() {
    geometry_msgs::TransformStamped t;
    t.header.stamp = ros::Time(now_);
    t.header.frame_id = "map";
    t.child_frame_id = "base_link";
    t.transform.translation.x = pose_.x;
    t.transform.translation.y = pose_.y;
    t.transform.rotation.z = std::sin(pose_.yaw / 2);
    t.transform.rotation.w = std::cos(pose_.yaw / 2);
    tf_.sendTransform(t);
  }
  void setEnabled(bool enabled) {
    std_srvs::SetBool srv;
    srv.request.data = enabled;
    ASSERT_TRUE(enable_.call(srv));
    ASSERT_TRUE(srv.response.success);
  }
  void addObstacle(const Obstacle& o) {
    Ellipse msg = test::ellipseMsg(o.name, "map", o.ellipse.center.x(), o.ellipse.center.y(),
                                   o.ellipse.radius_x, o.ellipse.radius_y, o.ellipse.angle);
    msg.vx = o.vx;
    ASSERT_TRUE(add({msg}).success);
    bool known = false;
    for (Obstacle& kept : obstacles_) {
      if (kept.name == o.name) {
        kept = o;
        known = true;
      }
    }
    if (!known) obstacles_.push_back(o);
  }

  /// One command: the clock and the pose at now_, the command, the node's answer; then the robot
  /// moves by the answer for kStep. Returns the decision.
  GateState step(double vx, double vy, double wz, bool publish_pose = true) {
    publishClock();
    if (publish_pose) publishPose();
    // tf and the command travel on separate connections: give tf a head start.
    ros::WallDuration(0.02).sleep();
    const std::size_t before = outputCount();
    geometry_msgs::Twist cmd;
    cmd.linear.x = vx;
    cmd.linear.y = vy;
    cmd.angular.z = wz;
    cmd_pub_.publish(cmd);
    EXPECT_TRUE(waitUntil([&] { return outputCount() > before && stateCount() > before; }, 10.0))
        << "no ~cmd_vel_out for the command";
    const geometry_msgs::Twist out = lastOutput();
    integrate(out);
    now_ += kStep;
    return lastState();
  }

  /// The pose after kStep of `out` held (exact arc).
  void integrate(const geometry_msgs::Twist& out) {
    const double w = out.angular.z;
    const double a = w * kStep;
    // Local displacement: (vx + i vy) (e^{i a} - 1) / (i w).
    double dx = out.linear.x * kStep, dy = out.linear.y * kStep;
    if (std::fabs(a) > 1e-12) {
      dx = (out.linear.x * std::sin(a) + out.linear.y * (std::cos(a) - 1.0)) / w;
      dy = (out.linear.x * (1.0 - std::cos(a)) + out.linear.y * std::sin(a)) / w;
    }
    pose_.x += std::cos(pose_.yaw) * dx - std::sin(pose_.yaw) * dy;
    pose_.y += std::sin(pose_.yaw) * dx + std::cos(pose_.yaw) * dy;
    pose_.yaw += a;
  }

  std::vector<core::Ellipse> linksAt(const Pose& p) const {
    std::vector<core::Ellipse> placed;
    for (core::Ellipse e : kLinks) {
      const Eigen::Vector2d c = e.center;
      e.center = {p.x + std::cos(p.yaw) * c.x() - std::sin(p.yaw) * c.y(),
                  p.y + std::sin(p.yaw) * c.x() + std::cos(p.yaw) * c.y()};
      e.angle += p.yaw;
      placed.push_back(e);
    }
    return placed;
  }
  /// Whether any link overlaps any obstacle at the robot's pose now.
  bool touching() const {
    for (const core::Ellipse& link : linksAt(pose_)) {
      for (const Obstacle& o : obstacles_) {
        if (core::overlap(link, o.ellipse)) return true;
      }
    }
    return false;
  }
  /// The smallest distance between a link and an obstacle now [m].
  double clearance() const {
    double best = std::numeric_limits<double>::infinity();
    for (const core::Ellipse& link : linksAt(pose_)) {
      for (const Obstacle& o : obstacles_) {
        best = std::min(best, core::distance(link, o.ellipse).distance);
      }
    }
    return best;
  }

  void onOutput(const geometry_msgs::Twist::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    outputs_.push_back(*msg);
  }
  void onState(const GateState::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    states_.push_back(*msg);
  }
  std::size_t outputCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return outputs_.size();
  }
  std::size_t stateCount() {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.size();
  }
  geometry_msgs::Twist lastOutput() {
    std::lock_guard<std::mutex> lock(mutex_);
    return outputs_.back();
  }
  GateState lastState() {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.back();
  }

  ros::NodeHandle nh_;
  ros::AsyncSpinner spinner_{2};
  ros::Publisher clock_pub_;
  ros::Publisher cmd_pub_;
  ros::Subscriber out_sub_;
  ros::Subscriber state_sub_;
  ros::ServiceClient enable_;
  tf2_ros::TransformBroadcaster tf_;
  std::mutex mutex_;
  std::vector<geometry_msgs::Twist> outputs_;
  std::vector<GateState> states_;
  std::vector<Obstacle> obstacles_;
  Pose pose_;
  static double now_;  ///< the simulated clock [s], on across tests (tf must not go back)
};

double GateTest::now_ = 100.0;

TEST_F(GateTest, DrivingAtAWallItSlowsAndStopsWithoutTouchingAndNotAbsurdlyEarly) {
  addObstacle({"wall", {{3.0, 0.0}, 0.05, 2.0, 0.0}});
  bool slowed = false;
  GateState last;
  for (int i = 0; i < 80; ++i) {
    last = step(1.0, 0.0, 0.0);
    ASSERT_FALSE(touching()) << "step " << i << " x = " << pose_.x;
    slowed = slowed || last.action == "SLOW";
    EXPECT_LE(last.scale, 1.0);
  }
  EXPECT_TRUE(slowed);
  EXPECT_EQ(last.action, "STOP") << last.reason;
  EXPECT_EQ(lastOutput().linear.x, 0.0);
  EXPECT_EQ(last.obstacle, "wall");
  EXPECT_EQ(last.link, "front");
  // Full speed 1 m/s and stop_time 0.3 s: it stops once the wall is 0.3 s away at full speed.
  const double gap = clearance();
  std::cout << "wall: stopped " << gap << " m from the wall at x = " << pose_.x << std::endl;
  EXPECT_GT(gap, 0.0);
  EXPECT_LT(gap, 0.45) << "stopped absurdly early";
  EXPECT_GT(gap, 0.25) << "the full command would reach the wall within stop_time";
}

TEST_F(GateTest, AThinPoleAtTwoMetresPerSecondIsNeverCrossed) {
  addObstacle({"pole", {{4.0, 0.1}, 0.005, 0.005, 0.0}});
  for (int i = 0; i < 50; ++i) {
    step(2.0, 0.0, 0.0);
    ASSERT_FALSE(touching()) << "step " << i << " x = " << pose_.x;
  }
  EXPECT_LT(pose_.x + 0.35, 4.0 - 0.005) << "crossed the pole";
  std::cout << "pole: stopped " << clearance() << " m before it" << std::endl;
  EXPECT_EQ(lastState().action, "STOP");
}

TEST_F(GateTest, ARectangularRobotTurningIntoACornerIsSlowedInTime) {
  // A corner at the top right: a wall along y = 1.2 and one along x = 2.0.
  addObstacle({"top", {{1.0, 1.2}, 3.0, 0.02, 0.0}});
  addObstacle({"right", {{2.0, -1.0}, 0.02, 3.0, 0.0}});
  bool slowed = false;
  for (int i = 0; i < 120; ++i) {
    const GateState state = step(0.5, 0.0, 0.3);
    ASSERT_FALSE(touching()) << "step " << i << " at (" << pose_.x << ", " << pose_.y << ", "
                             << pose_.yaw << ")";
    slowed = slowed || state.action == "SLOW";
  }
  EXPECT_TRUE(slowed);
  EXPECT_EQ(lastState().action, "STOP") << lastState().reason;
  std::cout << "corner: stopped " << clearance() << " m from it, yaw " << pose_.yaw << std::endl;
  EXPECT_LT(clearance(), 0.3);
}

TEST_F(GateTest, InContactItCannotPushInButBacksOutAndTurnsAway) {
  // The box overlaps the front link (which reaches x = 0.35).
  addObstacle({"box", {{0.53, 0.0}, 0.2, 0.2, 0.0}});
  ASSERT_TRUE(touching());
  const GateState push = step(0.3, 0.0, 0.0);
  EXPECT_EQ(push.action, "STOP") << push.reason;
  EXPECT_EQ(lastOutput().linear.x, 0.0);
  EXPECT_NE(push.reason.find("box"), std::string::npos) << push.reason;
  const GateState back = step(-0.3, 0.0, 0.0);
  EXPECT_EQ(back.action, "ESCAPE") << back.reason;
  EXPECT_GT(lastOutput().linear.x, -0.31);
  EXPECT_LT(lastOutput().linear.x, 0.0);
  for (int i = 0; i < 10; ++i) step(-0.3, 0.0, 0.4);
  EXPECT_FALSE(touching()) << "backed out";
  EXPECT_LT(pose_.x, -0.2);
}

TEST_F(GateTest, AnObstacleComingTowardTheRobotStopsItEarlierThanAStandingOne) {
  // The same box 4 m ahead, standing, then coming at 0.5 m/s (its position updated each step).
  double stop_time_standing = 0.0, stop_time_moving = 0.0;
  for (const double box_vx : {0.0, -0.5}) {
    pose_ = Pose();
    Obstacle box{"box", {{4.0, 0.0}, 0.2, 0.2, 0.0}, box_vx};
    addObstacle(box);
    double elapsed = 0.0;
    for (int i = 0; i < 60; ++i) {
      const GateState state = step(1.0, 0.0, 0.0);
      ASSERT_FALSE(touching()) << "step " << i;
      if (state.action == "STOP") break;
      elapsed += kStep;
      box.ellipse.center.x() += box_vx * kStep;
      addObstacle(box);
    }
    (box_vx == 0.0 ? stop_time_standing : stop_time_moving) = elapsed;
    remove({"box"});
    obstacles_.clear();
  }
  std::cout << "stop after " << stop_time_standing << " s (standing box), " << stop_time_moving
            << " s (box coming at 0.5 m/s)" << std::endl;
  EXPECT_GT(stop_time_standing, 0.0);
  EXPECT_LT(stop_time_moving, stop_time_standing - 0.5);
}

TEST_F(GateTest, NanSilenceStaleTfAndDisablingAreHandled) {
  addObstacle({"far", {{10.0, 0.0}, 0.2, 0.2, 0.0}});
  EXPECT_EQ(step(0.5, 0.0, 0.0).action, "PASS");
  EXPECT_EQ(lastOutput().linear.x, 0.5);

  const GateState nan = step(std::nan(""), 0.0, 0.0);
  EXPECT_EQ(nan.action, "STOP");
  EXPECT_NE(nan.reason.find("cmd_vel.linear.x = nan"), std::string::npos) << nan.reason;
  EXPECT_EQ(lastOutput().linear.x, 0.0);
  const GateState absurd = step(0.0, 0.0, 1e6);
  EXPECT_EQ(absurd.action, "STOP");
  EXPECT_NE(absurd.reason.find("cmd_vel.angular.z"), std::string::npos) << absurd.reason;

  // Silence: one zero command after cmd_vel_timeout (0.5 s), then nothing more.
  step(0.5, 0.0, 0.0);
  const std::size_t before = outputCount();
  for (int i = 0; i < 15; ++i) {
    publishClock();
    publishPose();
    now_ += kStep;
    ros::WallDuration(0.03).sleep();
  }
  ASSERT_TRUE(waitUntil([&] { return outputCount() == before + 1; }, 5.0));
  ros::WallDuration(0.3).sleep();
  EXPECT_EQ(outputCount(), before + 1) << "one zero, not a stream";
  EXPECT_EQ(lastOutput().linear.x, 0.0);
  EXPECT_EQ(lastState().action, "TIMEOUT");

  // A stale robot transform (no tf for 1 s): zero.
  step(0.5, 0.0, 0.0);
  GateState stale;
  for (int i = 0; i < 10; ++i) stale = step(0.5, 0.0, 0.0, /*publish_pose=*/false);
  EXPECT_EQ(stale.action, "INCOMPLETE") << stale.reason;
  EXPECT_NE(stale.reason.find("old"), std::string::npos) << stale.reason;
  EXPECT_EQ(lastOutput().linear.x, 0.0);

  // Disabled: commands pass unchanged.
  setEnabled(false);
  const GateState disabled = step(0.7, 0.1, -0.2);
  EXPECT_EQ(disabled.action, "DISABLED");
  EXPECT_EQ(lastOutput().linear.x, 0.7);
  EXPECT_EQ(lastOutput().linear.y, 0.1);
  EXPECT_EQ(lastOutput().angular.z, -0.2);
  setEnabled(true);
  EXPECT_EQ(step(0.5, 0.0, 0.0).action, "PASS");
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_gate");
  return RUN_ALL_TESTS();
}

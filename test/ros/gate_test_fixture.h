#pragma once

// The fixture of the velocity gate's rostests on simulated time (gate.test, gate_braking.test):
// the client is the robot. It publishes /clock and base_link's pose in map, sends a command on
// ~cmd_vel_in, waits for the one ~cmd_vel_out it causes, and follows it for kStep (follow()).
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

#include "ellipse_builders.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "node_test_utils.h"
#include "planar_transform.h"

namespace ellipse_collision::gate_test {

using test::nodeTopic;
using test::waitUntil;

inline double kStep = 0.1;  // [s] between commands (10 Hz; a fixture may change it)

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
    tf_.sendTransform(
        test::planarTransform("map", "base_link", pose_.x, pose_.y, pose_.yaw, ros::Time(now_)));
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
    beforeCommand();
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
    follow(out);
    now_ += kStep;
    return lastState();
  }

  /// The robot follows the node's answer for kStep: at once, on its exact arc (integrate()).
  /// A fixture of a base that lags and brakes overrides this.
  virtual void follow(const geometry_msgs::Twist& out) { integrate(out); }
  /// Called after the clock and the pose went out, before the command (odometry, say).
  virtual void beforeCommand() {}

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
    return test::placedAt(kLinks, p.x, p.y, p.yaw);
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
  /// The simulated clock [s], on across tests (tf must not go back).
  static inline double now_ = 100.0;
};

}  // namespace ellipse_collision::gate_test

// The braking rule through the real node (gate_braking.test), on simulated time, with a base that
// moves as a real one: commands reach it 0.1 s late and it sheds speed at 0.8 m/s^2 and 2 rad/s^2
// (core::SimulatedBase, the same limits as the node's gate/ parameters), its velocity published as
// odometry. Commands at 20 Hz; contact is checked every 5 ms of the motion.
#include <dynamic_reconfigure/Reconfigure.h>
#include <nav_msgs/Odometry.h>

#include <algorithm>
#include <iostream>

#include "ellipse_collision/core/simulated_base.h"
#include "gate_test_fixture.h"

namespace ellipse_collision {
namespace {

using gate_test::GateTest;
using gate_test::Obstacle;
using gate_test::Pose;

const core::BaseDynamics kBase{0.1, 0.8, 2.0};  // gate_braking_scene.yaml's
constexpr double kCruise = 1.5;                 // [m/s]

class BrakingGateTest : public GateTest {
 protected:
  void SetUp() override {
    GateTest::SetUp();
    gate_test::kStep = 0.05;
    odom_pub_ = nh_.advertise<nav_msgs::Odometry>("/odom", 10);
    ASSERT_TRUE(test::waitUntil([&] { return odom_pub_.getNumSubscribers() > 0; }, 30.0));
    start_ = now_;
    base_.emplace(kBase, core::PathPose{}, core::Twist{kCruise, 0.0, 0.0});
    pose_ = Pose();
  }

  void beforeCommand() override {
    nav_msgs::Odometry odom;
    odom.header.stamp = ros::Time(now_);
    odom.header.frame_id = "map";
    odom.child_frame_id = "base_link";
    odom.twist.twist.linear.x = base_->velocity().vx;
    odom.twist.twist.linear.y = base_->velocity().vy;
    odom.twist.twist.angular.z = base_->velocity().wz;
    odom_pub_.publish(odom);
  }

  void follow(const geometry_msgs::Twist& out) override {
    base_->command(now_ - start_, {out.linear.x, out.linear.y, out.angular.z});
    for (int i = 1; i <= 10; ++i) {
      base_->advanceTo(now_ - start_ + gate_test::kStep * i / 10);
      pose_ = {base_->pose().x, base_->pose().y, base_->pose().yaw};
      if (base_->moving() && touching() && !touched_) {
        touched_ = true;
        touch_speed_ = base_->speed();
      }
    }
  }

  /// Drives at kCruise until the base has rested for 1 s (or `steps` commands): whether it
  /// touched while moving, and the outputs' linear speeds.
  std::vector<double> driveUntilRest(int steps, const std::function<void(int)>& at_step = {}) {
    std::vector<double> outputs;
    int resting = 0;
    for (int i = 0; i < steps && resting < 20; ++i) {
      if (at_step) at_step(i);
      const GateState state = step(kCruise, 0.0, 0.0);
      outputs.push_back(state.output.linear.x);
      last_ = state;
      resting = base_->moving() ? 0 : resting + 1;
    }
    return outputs;
  }

  /// The gate's base model through dynamic_reconfigure (the node's own rule accepts it or not).
  void setDecelerations(double linear, double angular, double reaction) {
    dynamic_reconfigure::Reconfigure srv;
    for (const auto& [name, value] :
         {std::pair<const char*, double>{"max_linear_deceleration", linear},
          {"max_angular_deceleration", angular},
          {"reaction_time", reaction}}) {
      dynamic_reconfigure::DoubleParameter p;
      p.name = name;
      p.value = value;
      srv.request.config.doubles.push_back(p);
    }
    ASSERT_TRUE(ros::service::call(test::nodeTopic("gate/set_parameters"), srv));
  }

  ros::Publisher odom_pub_;
  std::optional<core::SimulatedBase> base_;
  double start_{0.0};
  bool touched_{false};
  double touch_speed_{0.0};
  GateState last_;
};

TEST_F(BrakingGateTest, AWallApproachedAtOnePointFiveIsNotTouchedNorStoppedAbsurdlyEarly) {
  addObstacle({"wall", {{5.05, 0.0}, 0.05, 2.0, 0.0}});
  const std::vector<double> outputs = driveUntilRest(400);
  EXPECT_FALSE(touched_) << "touched the wall at " << touch_speed_ << " m/s";
  EXPECT_FALSE(base_->moving()) << last_.reason;
  const double gap = clearance();
  std::cout << "braking wall: at rest " << gap << " m from the wall, " << base_->travelled()
            << " m travelled; last: " << last_.reason << std::endl;
  EXPECT_GT(gap, 0.0);
  EXPECT_LE(gap, 0.6) << "stopped absurdly early";
  // Input and world constant: once the output fell, it never rises again (no stop-and-go).
  double lowest = outputs.front();
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    EXPECT_LE(outputs[i], lowest + 1e-12) << "command " << i << " rose";
    lowest = std::min(lowest, outputs[i]);
  }
  EXPECT_GT(last_.braking_distance + 1.0, 0.0);
  EXPECT_TRUE(std::isfinite(last_.free_distance) || last_.free_distance > 0.0);
}

TEST_F(BrakingGateTest, ABoxAppearingAtOnePointTwoStoppingDistancesIsNotHit) {
  // From the moment a command is judged: 0.1 s reaction + 0.05 s of the output, then braking.
  const double stopping = kCruise * 0.15 + kCruise * kCruise / (2.0 * kBase.linear_deceleration);
  driveUntilRest(400, [&](int i) {
    if (i != 20) return;
    const double front = pose_.x + 0.35;  // the front link's reach
    const double near_face = front + 1.2 * stopping;
    addObstacle({"box", {{near_face + 0.2, 0.0}, 0.2, 0.2, 0.0}});
  });
  EXPECT_FALSE(touched_) << "hit the box at " << touch_speed_ << " m/s";
  std::cout << "box at 1.2 x " << stopping << " m: at rest " << clearance() << " m from it"
            << std::endl;
}

TEST_F(BrakingGateTest, TheGateThatAssumesAnInstantBaseDrivesThisBaseIntoTheWall) {
  // The same wall and base with the node told the base stops at once (every limit 0): it touches.
  setDecelerations(0.0, 0.0, 0.0);
  addObstacle({"wall", {{5.05, 0.0}, 0.05, 2.0, 0.0}});
  driveUntilRest(400);
  EXPECT_TRUE(touched_) << "the ideal-base gate was expected to touch; rest gap " << clearance();
  std::cout << "ideal-base gate: touched the wall at " << touch_speed_ << " m/s" << std::endl;
  setDecelerations(kBase.linear_deceleration, kBase.angular_deceleration, kBase.reaction_time);
}

}  // namespace
}  // namespace ellipse_collision

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_gate_braking");
  return RUN_ALL_TESTS();
}

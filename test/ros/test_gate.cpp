// The velocity gate through the real node (gate.test), on simulated time, with a robot that
// follows every output at once on its exact arc (gate_test_fixture.h). After every step the
// robot's links are checked against the obstacles with the core's overlap(): the gate must never
// let them touch.
#include <iostream>

#include "gate_test_fixture.h"

namespace ellipse_collision {
namespace {

using gate_test::GateTest;
using gate_test::kStep;
using gate_test::Obstacle;
using gate_test::Pose;
using test::nodeTopic;
using test::waitUntil;

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

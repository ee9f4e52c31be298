// The simulated base the gate is driven against: where it comes to rest, checked against the
// closed forms of a base that reacts late and brakes at a constant rate.
#include <gtest/gtest.h>

#include <cmath>

#include "ellipse_collision/core/simulated_base.h"

namespace ellipse_collision::core {
namespace {

TEST(SimulatedBase, StraightStopRestsAtReactionDistancePlusBrakingDistance) {
  // v r + v^2 / (2 a): the velocity held for the reaction time, then a linear ramp to rest.
  for (const double v : {0.5, 1.5, 2.0}) {
    for (const double a : {0.5, 0.8, 2.0}) {
      for (const double r : {0.0, 0.05, 0.2}) {
        SimulatedBase base({r, a, 2.0}, PathPose{}, Twist{v, 0.0, 0.0});
        base.command(0.0, Twist{});
        base.advanceTo(r + v / a + 0.5);
        EXPECT_FALSE(base.moving());
        EXPECT_NEAR(base.pose().x, v * r + v * v / (2 * a), 1e-9) << v << " " << a << " " << r;
        EXPECT_NEAR(base.pose().y, 0.0, 1e-12);
      }
    }
  }
}

TEST(SimulatedBase, KeepsTheCommandForTheReactionTime) {
  SimulatedBase base({0.1, 1.0, 1.0}, PathPose{}, Twist{1.0, 0.0, 0.0});
  base.command(0.0, Twist{});
  base.advanceTo(0.1);
  EXPECT_DOUBLE_EQ(base.velocity().vx, 1.0);
  EXPECT_NEAR(base.pose().x, 0.1, 1e-12);
  base.advanceTo(0.3);
  EXPECT_NEAR(base.velocity().vx, 0.8, 1e-9);
}

TEST(SimulatedBase, BrakingOnAnArcStaysOnItsCircle) {
  // A twist scaled down uniformly keeps its centre of rotation: the base rests on the circle of
  // radius v / w about the centre it started turning about, however the ramp times it.
  const double v = 1.2, w = 0.8;
  SimulatedBase base({0.1, 0.7, 0.5}, PathPose{}, Twist{v, 0.0, w});
  base.command(0.0, Twist{});
  base.advanceTo(10.0);
  EXPECT_FALSE(base.moving());
  const double radius = v / w;
  EXPECT_NEAR(std::hypot(base.pose().x, base.pose().y - radius), radius, 1e-9);
  // The arc's length (the heading turned times the radius) is the straight stopping distance at
  // the slower of the two rates; travelled() sums the 1 ms steps' chords, a hair shorter.
  const double rate = std::min(0.7 / v, 0.5 / w);  // [1/s] the scale shed per second
  const double arc = v * 0.1 + v / (2 * rate);
  EXPECT_NEAR(base.pose().yaw * radius, arc, 1e-9);
  EXPECT_NEAR(base.travelled(), arc, 1e-7);
  EXPECT_LE(base.travelled(), arc);
}

TEST(SimulatedBase, ZeroLimitsFollowAtOnce) {
  SimulatedBase base({0.0, 0.0, 0.0}, PathPose{}, Twist{1.0, 0.0, 0.0});
  base.command(0.0, Twist{});
  base.advanceTo(0.5);
  EXPECT_FALSE(base.moving());
  EXPECT_NEAR(base.pose().x, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(base.now(), 0.5);
}

}  // namespace
}  // namespace ellipse_collision::core

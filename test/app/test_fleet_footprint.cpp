// A robot's footprint for the fleet: its links renamed into the fleet's name space, with the
// velocity each link had over the last interval.
#include <gtest/gtest.h>

#include <cmath>

#include "ellipse_collision/app/fleet_footprint.h"

namespace ellipse_collision::app {
namespace {

core::NamedEllipse link(const std::string& name, double x, double y, double angle) {
  return {name, core::EllipseRole::Link, core::Ellipse{{x, y}, 0.4, 0.2, angle}};
}

TEST(FleetFootprint, LinksTakeTheRobotsNameAndTheirMotionOverTheLastInterval) {
  FleetFootprint footprint;
  const auto first = footprint.update(10.0, {link("base_link", 1.0, 2.0, 0.1)}, "r1", "map");
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].name, "r1/base_link");
  EXPECT_EQ(first[0].frame_id, "map");
  EXPECT_EQ(first[0].radius_x, 0.4);
  EXPECT_EQ(first[0].vx, 0.0);  // nothing to compare with yet: stands
  // 0.1 s later: moved by (0.08, -0.03) and turned by 0.05 rad.
  const auto second = footprint.update(10.1, {link("base_link", 1.08, 1.97, 0.15)}, "r1", "map");
  EXPECT_NEAR(second[0].vx, 0.8, 1e-9);
  EXPECT_NEAR(second[0].vy, -0.3, 1e-9);
  EXPECT_NEAR(second[0].angular_velocity, 0.5, 1e-9);
}

TEST(FleetFootprint, TurnsAcrossPiTakeTheShortWayAndLongGapsStand) {
  FleetFootprint footprint;
  footprint.update(0.0, {link("arm", 0.0, 0.0, M_PI - 0.02)}, "r1", "map");
  const auto across = footprint.update(0.1, {link("arm", 0.0, 0.0, -M_PI + 0.02)}, "r1", "map");
  EXPECT_NEAR(across[0].angular_velocity, 0.4, 1e-9);  // +0.04 rad, not -2 pi + 0.04
  // Two seconds of silence: no velocity from so old a placement.
  const auto late = footprint.update(2.1, {link("arm", 5.0, 0.0, 0.0)}, "r1", "map");
  EXPECT_EQ(late[0].vx, 0.0);
  EXPECT_EQ(late[0].angular_velocity, 0.0);
  // Time running back (a bag looped) gives no velocity either.
  const auto back = footprint.update(1.0, {link("arm", 6.0, 0.0, 0.0)}, "r1", "map");
  EXPECT_EQ(back[0].vx, 0.0);
}

TEST(FleetFootprint, SettingsNameTheKey) {
  FleetSettings s;
  s.robot_name = "r1";
  EXPECT_FALSE(findInvalidSetting(s));
  s.robot_name = "";
  ASSERT_TRUE(findInvalidSetting(s));
  EXPECT_EQ(findInvalidSetting(s)->key, "fleet/robot_name");
  s.robot_name = "a/b";
  EXPECT_EQ(findInvalidSetting(s)->key, "fleet/robot_name");
  s.robot_name = "r1";
  s.frame = "/map";
  EXPECT_EQ(findInvalidSetting(s)->key, "fleet/frame");
  s.frame = "map";
  s.rate = 0.0;
  ASSERT_TRUE(findInvalidSetting(s));
  EXPECT_EQ(findInvalidSetting(s)->key, "fleet/rate");
  EXPECT_EQ(findInvalidSetting(s)->actual, "0");
}

}  // namespace
}  // namespace ellipse_collision::app

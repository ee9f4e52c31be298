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
  // Sent again before tf moved on (same stamp, same placement): still moving, not standing.
  const auto again = footprint.update(10.1, {link("base_link", 1.08, 1.97, 0.15)}, "r1", "map");
  EXPECT_NEAR(again[0].vx, 0.8, 1e-9);
  EXPECT_NEAR(again[0].vy, -0.3, 1e-9);
  EXPECT_NEAR(again[0].angular_velocity, 0.5, 1e-9);
  // The next newer placement is measured from the last one that moved on.
  const auto third = footprint.update(10.2, {link("base_link", 1.18, 1.97, 0.15)}, "r1", "map");
  EXPECT_NEAR(third[0].vx, 1.0, 1e-9);
  EXPECT_NEAR(third[0].vy, 0.0, 1e-9);
}

TEST(FleetFootprint, TurnsAcrossPiTakeTheShortWayAndLongGapsStand) {
  FleetFootprint footprint;
  footprint.update(0.0, {link("arm", 0.0, 0.0, M_PI - 0.02)}, "r1", "map");
  const auto across = footprint.update(0.1, {link("arm", 0.0, 0.0, -M_PI + 0.02)}, "r1", "map");
  EXPECT_NEAR(across[0].angular_velocity, 0.4, 1e-9);  // +0.04 rad, not -2 pi + 0.04
  // Placements report angles in (-pi/2, pi/2]: a link turning on through pi/2 jumps from just
  // below pi/2 to just above -pi/2, a turn of +0.04 rad, not of almost -pi.
  footprint.update(0.2, {link("arm", 0.0, 0.0, M_PI / 2 - 0.02)}, "r1", "map");
  const auto half = footprint.update(0.3, {link("arm", 0.0, 0.0, -M_PI / 2 + 0.02)}, "r1", "map");
  EXPECT_NEAR(half[0].angular_velocity, 0.4, 1e-9);
  // Two seconds of silence: no velocity from so old a placement.
  const auto late = footprint.update(2.4, {link("arm", 5.0, 0.0, 0.0)}, "r1", "map");
  EXPECT_EQ(late[0].vx, 0.0);
  EXPECT_EQ(late[0].angular_velocity, 0.0);
  // Time running back (a bag looped) gives no velocity either.
  const auto back = footprint.update(1.0, {link("arm", 6.0, 0.0, 0.0)}, "r1", "map");
  EXPECT_EQ(back[0].vx, 0.0);
}

TEST(FleetFootprint, TheDefaultRobotNameIsTheNamespaceOrInTheRootTheNodesName) {
  EXPECT_EQ(defaultFleetRobotName("/r1", "/r1/ellipse_collision"), "r1");
  EXPECT_EQ(defaultFleetRobotName("/site/r1/", "/site/r1/collision"), "site_r1");
  EXPECT_EQ(defaultFleetRobotName("/", "/ellipse_collision"), "ellipse_collision");
  EXPECT_EQ(defaultFleetRobotName("", "collision_b"), "collision_b");
  FleetSettings s;
  s.robot_name = defaultFleetRobotName("/site/r1", "/site/r1/collision");
  EXPECT_FALSE(findInvalidSetting(s));
}

TEST(FleetFootprint, LinksArePlacedPaddedInTheFleetFrameOrSayWhyNot) {
  EllipseSpec front;
  front.name = "front";
  front.frame_id = "base_link";
  front.x = 0.5;
  front.radius_x = 0.3;
  front.radius_y = 0.2;
  front.padding = 0.05;
  Eigen::Isometry3d map_from_base = Eigen::Isometry3d::Identity();
  map_from_base.translate(Eigen::Vector3d(2.0, 1.0, 0.0));
  map_from_base.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  FrameTransform base;
  base.ok = true;
  base.fixed_from_frame = map_from_base;
  base.stamp_s = 9.9;
  const TransformLookup lookup = [&](const std::string& frame) {
    if (frame == "base_link") return base;
    FrameTransform missing;
    missing.error = "no frame '" + frame + "'";
    return missing;
  };
  const PlacedLinks placed = placeLinks({front}, 0.1, lookup, Freshness{0.5, 10.0});
  ASSERT_EQ(placed.error, "");
  ASSERT_EQ(placed.links.size(), 1u);
  // (0.5, 0) in base_link turned a quarter and moved to (2, 1): (2, 1.5); radii + 0.05 + 0.1.
  EXPECT_NEAR(placed.links[0].ellipse.center.x(), 2.0, 1e-12);
  EXPECT_NEAR(placed.links[0].ellipse.center.y(), 1.5, 1e-12);
  EXPECT_NEAR(placed.links[0].ellipse.radius_x, 0.45, 1e-12);
  EXPECT_NEAR(placed.links[0].ellipse.radius_y, 0.35, 1e-12);
  EXPECT_EQ(placed.stamp_s, 9.9);
  // A transform older than max_transform_age: not placed where it was, silent instead.
  const PlacedLinks stale = placeLinks({front}, 0.1, lookup, Freshness{0.5, 10.5});
  EXPECT_TRUE(stale.links.empty());
  EXPECT_EQ(stale.error,
            "link 'front': its frame 'base_link' was last placed 0.6 s ago, more than 0.5 s "
            "(max_transform_age)");
  front.frame_id = "arm";
  EXPECT_EQ(placeLinks({front}, 0.1, lookup, Freshness{0.5, 10.0}).error,
            "link 'front': no frame 'arm'");
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

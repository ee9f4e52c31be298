// The other robots as this node keeps them: grouped by name, its own ignored, replaced message by
// message, dropped when silent, refused whole when a name or a field is wrong.
#include <gtest/gtest.h>

#include <cmath>

#include "ellipse_collision/app/fleet_roster.h"

namespace ellipse_collision::app {
namespace {

EllipseSpec link(const std::string& name, double x, double vx = 0.0) {
  EllipseSpec e;
  e.name = name;
  e.frame_id = "map";
  e.x = x;
  e.radius_x = e.radius_y = 0.3;
  e.vx = vx;
  return e;
}

std::vector<std::string> names(const std::vector<EllipseSpec>& specs) {
  std::vector<std::string> out;
  for (const EllipseSpec& s : specs) out.push_back(s.name);
  return out;
}

TEST(FleetRoster, KeepsEachOtherRobotsLatestLinksAndIgnoresItsOwn) {
  FleetRoster roster("r1", 1.0);
  EXPECT_FALSE(roster.receive(
      0.0, {link("r1/base_link", 0.0), link("r2/base_link", 3.0, -1.0), link("r2/arm", 3.2)}));
  EXPECT_FALSE(roster.receive(0.1, {link("r3/base_link", -2.0, 0.5)}));
  EXPECT_EQ(names(roster.obstacles()),
            (std::vector<std::string>{"r2/base_link", "r2/arm", "r3/base_link"}));
  EXPECT_EQ(roster.obstacles()[0].vx, -1.0);  // velocities kept
  // r2's next footprint replaces its links (the arm is gone from it).
  EXPECT_FALSE(roster.receive(0.2, {link("r2/base_link", 2.9, -1.0)}));
  EXPECT_EQ(names(roster.obstacles()), (std::vector<std::string>{"r2/base_link", "r3/base_link"}));
  EXPECT_EQ(roster.obstacles()[0].x, 2.9);
  // r3's footprint (0.1 s) is advanced to r2's (0.2 s) by its velocity: both as of 0.2 s.
  EXPECT_EQ(roster.stamp(), 0.2);
  EXPECT_NEAR(roster.obstacles()[1].x, -2.0 + 0.5 * 0.1, 1e-15);
  const auto robots = roster.robots(0.5);
  ASSERT_EQ(robots.size(), 2u);
  EXPECT_EQ(robots[0].name, "r2");
  EXPECT_NEAR(robots[0].age_s, 0.3, 1e-12);
  EXPECT_EQ(robots[0].links, 1u);
}

TEST(FleetRoster, RobotsSilentPastTheTimeoutAreDropped) {
  FleetRoster roster("r1", 1.0);
  roster.receive(0.0, {link("r2/base_link", 3.0)});
  roster.receive(0.8, {link("r3/base_link", 4.0)});
  EXPECT_TRUE(roster.dropSilent(1.0).empty());  // r2 exactly 1 s: kept
  EXPECT_EQ(roster.dropSilent(1.5), std::vector<std::string>{"r2"});
  EXPECT_EQ(names(roster.obstacles()), std::vector<std::string>{"r3/base_link"});
  // /diagnostics names the robot kept and the one dropped, until it is heard from again.
  const auto health = roster.healthValues(1.5);
  ASSERT_EQ(health.size(), 2u);
  EXPECT_EQ(health[0].second, "r3 (0.7 s ago, 1 links)");
  EXPECT_EQ(health[1].first, "dropped (silent past 1 s)");
  EXPECT_EQ(health[1].second, "r2");
  roster.receive(1.6, {link("r2/base_link", 2.0)});
  EXPECT_EQ(roster.healthValues(1.6)[1].second, "none");
}

// A simulation restarted: the clock went from 100 s back to 5 s. The robots heard at 100 s are
// kept for one timeout from the jump, not until the clock reaches 101 s again.
TEST(FleetRoster, AfterTheClockJumpsBackASilentRobotGoesAfterOneTimeout) {
  FleetRoster roster("r1", 1.0);
  roster.receive(100.0, {link("r2/base_link", 3.0)});
  EXPECT_TRUE(roster.dropSilent(5.0).empty());
  ASSERT_EQ(roster.robots(5.0).size(), 1u);
  EXPECT_EQ(roster.robots(5.0)[0].age_s, 0.0);
  EXPECT_TRUE(roster.dropSilent(6.0).empty());  // 1 s since the jump: kept
  EXPECT_EQ(roster.dropSilent(6.5), std::vector<std::string>{"r2"});
  EXPECT_TRUE(roster.obstacles().empty());
}

TEST(FleetRoster, AMessageWithABadEntryIsRefusedWholeNamingIt) {
  FleetRoster roster("r1", 1.0);
  roster.receive(0.0, {link("r2/base_link", 3.0)});
  EXPECT_EQ(roster.receive(0.1, {link("r2/base_link", 2.0), link("base_link", 1.0)}),
            "ellipses[1].name = 'base_link': expected '<robot>/<link>'");
  EllipseSpec bad = link("r2/arm", std::nan(""));
  const auto refused = roster.receive(0.1, {bad});
  ASSERT_TRUE(refused);
  EXPECT_NE(refused->find("ellipses[0].x = nan"), std::string::npos) << *refused;
  EXPECT_EQ(roster.receive(0.1, {link("r2/base_link", 2.0), link("r2/base_link", 2.5)}),
            "ellipses[1].name = 'r2/base_link': expected a name used once");
  // Nothing of these messages was taken.
  ASSERT_EQ(roster.obstacles().size(), 1u);
  EXPECT_EQ(roster.obstacles()[0].x, 3.0);
}

TEST(FleetRoster, FootprintsHeardAtDifferentTimesAreGivenAsOfTheNewestStamp) {
  // Stamps are when the robots were where they say (their tf), not when they were heard: r2's
  // footprint 0.3 s older than r3's has moved on by 0.3 s of its velocity and turn.
  FleetRoster roster("r1", 1.0);
  EllipseSpec turning = link("r2/arm", 3.0, -1.0);
  turning.vy = 0.5;
  turning.angular_velocity = 2.0;
  EXPECT_FALSE(roster.receive(10.0, {turning}, 9.6));
  EXPECT_EQ(roster.stamp(), 9.6);
  EXPECT_EQ(roster.obstacles()[0].x, 3.0) << "alone, it is as of its own stamp";
  EXPECT_FALSE(roster.receive(10.05, {link("r3/base_link", -2.0, 0.5)}, 9.9));
  EXPECT_EQ(roster.stamp(), 9.9);
  const std::vector<EllipseSpec> both = roster.obstacles();
  ASSERT_EQ(both.size(), 2u);
  EXPECT_NEAR(both[0].x, 3.0 - 0.3, 1e-12);
  EXPECT_NEAR(both[0].y, 0.5 * 0.3, 1e-12);
  EXPECT_NEAR(both[0].angle, 2.0 * 0.3, 1e-12);
  EXPECT_EQ(both[0].vx, -1.0);
  EXPECT_EQ(both[1].x, -2.0);
  // An unstamped footprint counts as seen when heard.
  EXPECT_FALSE(roster.receive(10.2, {link("r4/base_link", 1.0)}));
  EXPECT_EQ(roster.stamp(), 10.2);
  EXPECT_TRUE(FleetRoster("r1", 1.0).obstacles().empty());
  EXPECT_EQ(FleetRoster("r1", 1.0).stamp(), 0.0);
}

}  // namespace
}  // namespace ellipse_collision::app

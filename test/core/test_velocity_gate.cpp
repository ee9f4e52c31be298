// The velocity gate's decision (core/velocity_gate.h) against a dense overlap() scan of the exact
// arc (the twist oracle), and its refusals.
#include <gtest/gtest.h>
#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/simulated_base.h"
#include "ellipse_collision/core/velocity_gate.h"
#include "first_contact_oracle.h"
#include "grazing_tally.h"
#include "random_source.h"
#include "rotating_contact.h"
#include "scene_test_helpers.h"
#include "twist_oracle.h"

namespace ellipse_collision::core {
namespace {

using scene_test::ellipse;
using namespace twist_oracle;

// The scan's verdict on a gate's scale: no contact before T_b under scale * twist, and one
// contact before T_b one resolution step faster (the largest safe scale on the grid).
void expectLargestSafeScale(const PathScene& scene, const Twist& twist, const GateSettings& s,
                            double scale) {
  const double under_output = scannedSceneContact(scene, scaled(twist, scale), s.horizon);
  EXPECT_TRUE(under_output < 0.0 || under_output >= s.time_before_collision) << under_output;
  const double faster = scannedSceneContact(scene, scaled(twist, scale + s.resolution), s.horizon);
  EXPECT_GE(faster, 0.0);
  EXPECT_LT(faster, s.time_before_collision);
}

PathScene sceneOf(std::vector<NamedEllipse> links, std::vector<NamedEllipse> obstacles,
                  std::vector<Motion> motions = {}) {
  PathScene scene;
  scene.links = std::move(links);
  scene.obstacles = std::move(obstacles);
  scene.obstacle_motions = motions.empty() ? std::vector<Motion>(scene.obstacles.size()) : motions;
  return scene;
}

NamedEllipse link(const std::string& name, const Ellipse& e) {
  return {name, EllipseRole::Link, e};
}
NamedEllipse obstacle(const std::string& name, const Ellipse& e) {
  return {name, EllipseRole::Obstacle, e};
}

GateSettings settings(double horizon, double before, double stop, double margin = 0.0,
                      double resolution = 0.01) {
  GateSettings s;
  s.horizon = horizon;
  s.time_before_collision = before;
  s.stop_time = stop;
  s.margin = margin;
  s.resolution = resolution;
  return s;
}

// ---- the gate -------------------------------------------------------------------------------

// A round robot of radius 0.3 at the origin and a wall whose near face is at x = 2.
PathScene robotAndWall(Motion wall_motion = {}) {
  return sceneOf({link("base", ellipse(0.0, 0.0, 0.3, 0.3))},
                 {obstacle("wall", ellipse(2.05, 0.0, 0.05, 3.0))}, {wall_motion});
}

TEST(Gate, StandingWallScaleIsTheClosedFormRoundedDown) {
  // t1 = 1.7 m / v; the scale is floor(t1 / T_b / res) res (speeds chosen off the grid: a time
  // on it may round one step down, never late). Mutation tried: rounding to nearest without the
  // t_s / k >= T_b guard -> fails (0.62 for 0.61 at v = 1.1).
  for (double v : {0.5, 1.1, 1.3, 2.3}) {
    const GateResult r = gateTwist(robotAndWall(), {v, 0.0, 0.0}, settings(4.0, 2.5, 0.2));
    ASSERT_TRUE(r.ok()) << r.error;
    const double t1 = 1.7 / v;
    const double ideal = t1 / 2.5;
    if (ideal >= 1.0) {
      EXPECT_EQ(r.action, GateAction::Pass) << v;
      continue;
    }
    EXPECT_EQ(r.action, GateAction::Slow) << v << " " << r.reason;
    EXPECT_NEAR(r.scale, std::floor(ideal / 0.01) * 0.01, 1e-12) << v;
    ASSERT_TRUE(r.contact.found);
    EXPECT_GE(r.contact.time, 2.5) << v;
    EXPECT_NEAR(r.contact.time, t1 / r.scale, 1e-6) << v;
    EXPECT_EQ(r.limiting.link, "base");
    EXPECT_EQ(r.limiting.obstacle, "wall");
    EXPECT_NEAR(r.limiting.time, t1, 1e-6);
    EXPECT_NEAR(r.contact.point.x(), 2.0, 1e-5);
    EXPECT_NEAR(r.contact.point.y(), 0.0, 1e-5);
  }
}

TEST(Gate, ReasonNamesThePairTheTimesAndTheScale) {
  // Mutation tried: rounding the scale to nearest -> "0.36".
  const GateResult r = gateTwist(robotAndWall(), {1.7 / 0.43, 0.0, 0.0}, settings(3.0, 1.2, 0.1));
  EXPECT_EQ(r.reason,
            "contact of link 'base' with 'wall' in 0.43 s under the full command; slowed to 0.35 "
            "so that it comes no sooner than time_before_collision 1.2 s");
  EXPECT_STREQ(toString(r.action), "SLOW");
}

TEST(Gate, ContactWithinStopTimeStopsAndNoContactWithinTimeBeforeCollisionPasses) {
  const GateResult stop = gateTwist(robotAndWall(), {10.0, 0.0, 0.0}, settings(3.0, 1.5, 0.3));
  EXPECT_EQ(stop.action, GateAction::Stop);
  EXPECT_EQ(stop.scale, 0.0);
  EXPECT_FALSE(stop.contact.found);  // the wall stands: nothing reaches the stopped robot
  EXPECT_NEAR(stop.limiting.time, 0.17, 1e-9);
  EXPECT_NE(stop.reason.find("within stop_time 0.3 s"), std::string::npos) << stop.reason;
  // Mutation tried: a standing contact at exactly T_b capping the scale -> fails. The contact time
  // has to be exact in doubles: robotAndWall()'s 2.05 - 0.05 - 0.3 is 1.69999999999999983, below
  // the double 1.7 by half an ulp (an exact firstContact() rounds it to the double below 1.7).
  // Here the distance and radii are dyadic: 2 - 0.0625 - 0.25 = 1.6875 exactly.
  const PathScene dyadic = sceneOf({link("base", ellipse(0.0, 0.0, 0.25, 0.25))},
                                   {obstacle("wall", ellipse(2.0, 0.0, 0.0625, 3.0))}, {Motion{}});
  const GateResult pass = gateTwist(dyadic, {1.0, 0.0, 0.0}, settings(3.0, 1.6875, 0.3));
  EXPECT_EQ(pass.action, GateAction::Pass) << pass.reason;
  EXPECT_EQ(pass.scale, 1.0);
  const GateResult away = gateTwist(robotAndWall(), {-1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.3));
  EXPECT_EQ(away.action, GateAction::Pass);
  EXPECT_FALSE(away.contact.found);
  EXPECT_EQ(away.reason, "no contact within horizon 3 s under the full command");
}

TEST(Gate, ThinObstacleAtTwoMetresPerSecondIsNeverPassedThrough) {
  // A 2 cm caster and a 1 cm board: at 2 m/s they overlap for 15 ms, between samples of any
  // 20 Hz check. Mutations tried: every obstacle taken as standing (the moving board then
  // never reaches the robot), the broadphase's link reach without |v_c| H -> both fail.
  const PathScene scene = sceneOf({link("caster", ellipse(0.0, 0.0, 0.01, 0.01))},
                                  {obstacle("board", ellipse(1.003, 0.0, 0.005, 0.5))});
  const GateResult r = gateTwist(scene, {2.0, 0.0, 0.0}, settings(2.0, 1.0, 0.1));
  EXPECT_EQ(r.action, GateAction::Slow) << r.reason;
  EXPECT_EQ(r.limiting.obstacle, "board");
  EXPECT_NEAR(r.limiting.time, 0.494 / 1.0, 1e-6);
  EXPECT_GE(r.contact.time, 1.0);
  // The board moving at 2 m/s against a standing caster: stopping cannot avoid it, it is said.
  const PathScene moving =
      sceneOf({link("caster", ellipse(0.0, 0.0, 0.01, 0.01))},
              {obstacle("board", ellipse(1.003, 0.0, 0.005, 0.5))}, {Motion{{-2.0, 0.0}, 0.0}});
  const GateResult hit = gateTwist(moving, {0.0, 0.0, 0.0}, settings(2.0, 1.0, 0.1));
  EXPECT_EQ(hit.action, GateAction::Stop);
  ASSERT_TRUE(hit.contact.found);
  EXPECT_NEAR(hit.contact.time, 0.494, 1e-6);
  EXPECT_NE(hit.reason.find("stopping cannot avoid it"), std::string::npos) << hit.reason;
}

// A 0.8 x 0.5 m rectangle of six ellipses, driving at 0.5 m/s turning left at 0.3 rad/s toward
// the corner of two walls.
PathScene rectangularRobotAtCorner() {
  std::vector<NamedEllipse> links;
  for (int i = 0; i < 3; ++i) {
    const double x = -0.27 + 0.27 * i;
    links.push_back(link("left_" + std::to_string(i), ellipse(x, 0.14, 0.16, 0.12)));
    links.push_back(link("right_" + std::to_string(i), ellipse(x, -0.14, 0.16, 0.12)));
  }
  return sceneOf(links, {obstacle("wall_x", ellipse(1.6, 0.5, 0.05, 1.5)),
                         obstacle("wall_y", ellipse(0.3, 1.5, 1.5, 0.05))});
}

TEST(Gate, RectangularRobotTurningTowardACornerIsSlowedInTime) {
  // Independent check by the scan: under the output command no link touches a wall before T_b,
  // and one resolution step faster one does (the scale is not absurdly low).
  // Mutation tried: poseAfter() turning the wrong way (signs of `across`) -> fails.
  const PathScene scene = rectangularRobotAtCorner();
  const Twist twist{0.5, 0.0, 0.3};
  const GateSettings s = settings(6.0, 3.0, 0.2);
  const GateResult r = gateTwist(scene, twist, s);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.action, GateAction::Slow) << r.reason;
  const double full = scannedSceneContact(scene, twist, s.horizon);
  ASSERT_GT(full, 0.0);
  EXPECT_LE(r.limiting.time, full + 1e-9);
  EXPECT_NEAR(r.limiting.time, full, 1e-6);
  expectLargestSafeScale(scene, twist, s, r.scale);
  // The robot drawn at the predicted contact touches there.
  ASSERT_TRUE(r.contact.found);
  const std::vector<NamedEllipse> at =
      linksAtTime(scene.links, scaled(twist, r.scale), r.contact.time);
  const auto hit = std::find_if(at.begin(), at.end(),
                                [&](const NamedEllipse& l) { return l.name == r.contact.link; });
  ASSERT_NE(hit, at.end());
  const auto wall = r.contact.obstacle == "wall_x" ? scene.obstacles[0] : scene.obstacles[1];
  EXPECT_LT(distance(hit->ellipse, wall.ellipse).distance, 1e-6);
}

TEST(Gate, RobotInContactBacksOutAndTurnsAwayButCannotPushIn) {
  // The base overlaps the wall by 2 cm. Mutations tried: the sign of the witness normal flipped
  // -> pushing in passes and backing out stops; ignoring wz in the rim point's velocity -> the
  // bar's tip turning into the post passes. Both fail.
  const PathScene scene = sceneOf(
      {link("base", ellipse(0.0, 0.0, 0.3, 0.3)), link("arm", ellipse(0.3, 0.6, 0.1, 0.05))},
      {obstacle("wall", ellipse(0.33, -0.02, 0.05, 0.05))});
  const GateSettings s = settings(3.0, 1.5, 0.2, 0.05);
  const GateResult back = gateTwist(scene, {-0.3, 0.0, 0.0}, s);
  EXPECT_EQ(back.action, GateAction::Escape) << back.reason;
  EXPECT_EQ(back.scale, 1.0);
  EXPECT_EQ(back.clearance, 0.0);
  EXPECT_EQ(back.clearance_obstacle, "wall");
  const GateResult in = gateTwist(scene, {0.3, 0.0, 0.0}, s);
  EXPECT_EQ(in.action, GateAction::Stop);
  EXPECT_EQ(in.scale, 0.0);
  EXPECT_EQ(in.reason.rfind("pushes into 'wall'", 0), 0u) << in.reason;
  EXPECT_EQ(in.limiting.link, "base");
  // The contact is at the base's right, slightly below its centre: turning left (wz > 0) moves
  // that rim point down and to the right... into the wall; turning right moves it out.
  const GateResult turn_in = gateTwist(scene, {0.0, 0.0, 1.0}, s);
  const GateResult turn_out = gateTwist(scene, {0.0, 0.0, -1.0}, s);
  // A round base turning in place slides along its rim: neither in nor out (rate 0), and passes.
  EXPECT_EQ(turn_in.action, GateAction::Escape) << turn_in.reason;
  EXPECT_EQ(turn_out.action, GateAction::Escape) << turn_out.reason;
  // Sideways away from the wall while turning: out.
  EXPECT_EQ(gateTwist(scene, {-0.2, 0.1, 0.5}, s).action, GateAction::Escape);
  // An elongated link in contact at its tip: turning one way pushes the tip in, the other backs.
  const PathScene tip = sceneOf({link("bar", ellipse(0.0, 0.0, 0.5, 0.05))},
                                {obstacle("post", ellipse(0.0, 0.09, 0.05, 0.05))});
  // The bar's upper rim touches the post above its centre; turning left lifts the rim's point
  // at x > 0 ... the post sits at x = 0 where the rim's velocity under pure rotation is radial
  // (along x), so add a lateral push: vy > 0 pushes in, vy < 0 backs out.
  EXPECT_EQ(gateTwist(tip, {0.0, 0.2, 0.0}, s).action, GateAction::Stop);
  EXPECT_EQ(gateTwist(tip, {0.0, -0.2, 0.0}, s).action, GateAction::Escape);
  // Overlapping, so the escape rule alone judges it (the contact rule skips overlapping pairs).
  const PathScene end = sceneOf({link("bar", ellipse(0.0, 0.0, 0.5, 0.05))},
                                {obstacle("post", ellipse(0.4, 0.075, 0.05, 0.05))});
  EXPECT_EQ(gateTwist(end, {0.0, 0.0, 0.5}, s).action, GateAction::Stop);     // tip rises into it
  EXPECT_EQ(gateTwist(end, {0.0, 0.0, -0.5}, s).action, GateAction::Escape);  // tip drops away
}

TEST(Gate, CloseButSeparatedPairMayLeaveButMeetsNothingNew) {
  // 3 cm from the wall with a 5 cm margin: backing away passes as an escape; backing into a
  // second obstacle behind is slowed by the contact rule like any other command. Mutations
  // tried: the witness normal's sign flipped; wz ignored at the rim point -> both fail.
  const PathScene scene = sceneOf({link("base", ellipse(0.0, 0.0, 0.3, 0.3))},
                                  {obstacle("wall", ellipse(0.38, 0.0, 0.05, 1.0)),
                                   obstacle("crate", ellipse(-1.055, 0.0, 0.2, 0.2))});
  const GateSettings s = settings(3.0, 2.0, 0.2, 0.05);
  const GateResult r = gateTwist(scene, {-0.5, 0.0, 0.0}, s);
  EXPECT_EQ(r.action, GateAction::Escape) << r.reason;
  EXPECT_NEAR(r.clearance, 0.03, 1e-9);
  EXPECT_EQ(r.limiting.obstacle, "crate");
  EXPECT_NEAR(r.scale, 0.55, 1e-12);  // t1 = 1.11 s, T_b = 2 s
  EXPECT_EQ(gateTwist(scene, {0.1, 0.0, 0.0}, s).action, GateAction::Stop);
}

TEST(Gate, ObstacleMovingTowardTheRobotStopsItEarlierThanAStandingOne) {
  // Mutation tried: every obstacle taken as standing (t1 / k) -> fails.
  // Standing: 1.7 m at 0.5 m/s, beyond T_b = 2.5 s. Coming at 0.3 m/s: 1.7 / (0.5 k + 0.3) >= 2.5
  // needs k <= 0.76 (a little less on the arc).
  const GateSettings s = settings(4.0, 2.5, 0.1);
  const Twist twist{0.5, 0.0, 0.1};
  const GateResult still = gateTwist(robotAndWall(), twist, s);
  const PathScene scene = robotAndWall(Motion{{-0.3, 0.0}, 0.0});
  const GateResult coming = gateTwist(scene, twist, s);
  ASSERT_TRUE(coming.ok()) << coming.error;
  EXPECT_EQ(coming.action, GateAction::Slow) << coming.reason;
  EXPECT_LT(coming.scale, still.scale);
  expectLargestSafeScale(scene, twist, s, coming.scale);
}

// The scan's verdict on a gate's answer: no contact before T_b under scale * twist (scale > 0).
void expectNoContactBeforeTimeBeforeCollision(const PathScene& scene, const Twist& twist,
                                              const GateSettings& s, const GateResult& r,
                                              int samples, int scene_index) {
  if (!(r.scale > 0.0)) return;
  const double t =
      scannedSceneContact(scene, scaled(twist, r.scale), s.time_before_collision, samples);
  EXPECT_LT(t, 0.0) << scene_index << ": contact at " << t << " under " << r.scale << ", "
                    << r.reason;
}

// `count` links "l0", "l1", ... centred within +-half.x() by +-half.y() [m], radius_x and radius_y
// in the given [min, max] ranges [m], at any angle.
std::vector<NamedEllipse> randomLinks(ellipse_collision::test::RandomSource& rng, int count,
                                      const Eigen::Vector2d& half, const Eigen::Vector2d& radius_x,
                                      const Eigen::Vector2d& radius_y) {
  std::vector<NamedEllipse> links;
  for (int l = 0; l < count; ++l) {
    links.push_back(link("l" + std::to_string(l),
                         ellipse(rng.uniform(-half.x(), half.x()), rng.uniform(-half.y(), half.y()),
                                 rng.uniform(radius_x[0], radius_x[1]),
                                 rng.uniform(radius_y[0], radius_y[1]), rng.uniform(-3.0, 3.0))));
  }
  return links;
}

TEST(Gate, RandomScenesNeverLetAContactComeBeforeTimeBeforeCollision) {
  // Property against the scan, over random robots, twists and partly moving obstacles.
  // Mutations tried: every obstacle standing; rounding the scale to nearest -> both fail.
  ellipse_collision::test::RandomSource rng(73);
  const GateSettings s = settings(3.0, 1.5, 0.2, 0.0, 0.05);
  int slowed = 0;
  for (int i = 0; i < 150; ++i) {
    std::vector<NamedEllipse> links, obstacles;
    std::vector<Motion> motions;
    links = randomLinks(rng, 3, {0.4, 0.3}, {0.05, 0.25}, {0.05, 0.25});
    for (int o = 0; o < 4; ++o) {
      const double angle = rng.uniform(-3.2, 3.2), range = rng.uniform(1.0, 3.0);
      obstacles.push_back(
          obstacle("o" + std::to_string(o),
                   ellipse(range * std::cos(angle), range * std::sin(angle), rng.uniform(0.02, 0.5),
                           rng.uniform(0.02, 0.5), rng.uniform(-3.0, 3.0))));
      Motion m;
      if (rng.coin(0.3))
        m.velocity = Eigen::Vector2d(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5));
      motions.push_back(m);
    }
    const PathScene scene = sceneOf(links, obstacles, motions);
    const Twist twist{rng.uniform(-1.0, 1.5), rng.uniform(-0.5, 0.5), rng.uniform(-1.0, 1.0)};
    const GateResult r = gateTwist(scene, twist, s);
    ASSERT_TRUE(r.ok()) << r.error;
    if (r.action == GateAction::Escape) continue;  // overlapping at the start
    expectNoContactBeforeTimeBeforeCollision(scene, twist, s, r, 600, i);
    if (r.action == GateAction::Slow) ++slowed;
  }
  EXPECT_GT(slowed, 10);
}

// The earliest of every pair's twistContact() over the horizon, among standing (or moving, or
// all) obstacles, pair by pair: what the gate's pruned search must reproduce exactly.
struct EveryPair {
  bool found{false};
  double time{0.0};
  std::string link, obstacle;
};
EveryPair everyPairFirst(const PathScene& scene, const Twist& twist, double horizon, int which) {
  EveryPair best;
  for (const NamedEllipse& l : scene.links) {
    for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
      const Motion& m = scene.obstacle_motions[o];
      const bool moving = !m.velocity.isZero() || m.angular_velocity != 0.0;
      if ((which == 0 && moving) || (which == 1 && !moving)) continue;
      const FirstContact c = twistContact(l.ellipse, twist, scene.obstacles[o].ellipse, m, horizon);
      if (c.contact && (!best.found || c.time < best.time)) {
        best = {true, c.time, l.name, scene.obstacles[o].name};
      }
    }
  }
  return best;
}

TEST(Gate, CrowdedScenesFindTheContactsOfEveryPairSearchedOverTheHorizon) {
  // Dozens of obstacles within reach of every link: the gate searches a pair only up to the
  // earliest contact found so far and skips pairs whose bounding circles cannot close in time.
  // Its first contacts must be those of every pair searched over the whole horizon, to the bit,
  // and its scale the largest the scan finds safe. Mutations tried: the bound without the
  // obstacle's speed; the search stopped at time_before_collision -> both fail.
  ellipse_collision::test::RandomSource rng(91);
  const GateSettings s = settings(3.0, 1.5, 0.1, 0.0, 0.05);
  int slowed = 0, passed_with_contact = 0, moving_limited = 0;
  for (int i = 0; i < 24; ++i) {
    std::vector<NamedEllipse> links, obstacles;
    std::vector<Motion> motions;
    links = randomLinks(rng, 4, {0.3, 0.2}, {0.05, 0.2}, {0.03, 0.1});
    const bool with_moving = i % 2 == 1;
    for (int o = 0; o < 60; ++o) {
      const double angle = rng.uniform(-3.2, 3.2), range = rng.uniform(0.9, 4.0);
      const double r = rng.uniform(0.03, 0.3);
      obstacles.push_back(obstacle("o" + std::to_string(o),
                                   ellipse(range * std::cos(angle), range * std::sin(angle), r,
                                           0.5 * r, rng.uniform(-3.0, 3.0))));
      Motion m;
      if (with_moving && rng.coin(0.3)) {
        m.velocity = Eigen::Vector2d(rng.uniform(-0.6, 0.6), rng.uniform(-0.6, 0.6));
        if (rng.coin(0.5)) m.angular_velocity = rng.uniform(-1.0, 1.0);
      }
      motions.push_back(m);
    }
    const PathScene scene = sceneOf(links, obstacles, motions);
    const Twist twist{rng.uniform(-0.3, 1.2), rng.uniform(-0.2, 0.2), rng.uniform(-0.6, 0.6)};
    const GateResult r = gateTwist(scene, twist, s);
    ASSERT_TRUE(r.ok()) << r.error;
    if (r.action == GateAction::Escape) continue;
    const EveryPair full = everyPairFirst(scene, twist, s.horizon, 2);
    const EveryPair still = everyPairFirst(scene, twist, s.horizon, 0);
    if (r.scale == 1.0 || (full.found && full.time <= s.stop_time)) {
      // The limiting contact is the first under the full command, over the whole horizon.
      ASSERT_EQ(r.limiting.found, full.found) << i << " " << r.reason;
      if (full.found) {
        EXPECT_EQ(r.limiting.time, full.time) << i;
        EXPECT_EQ(r.limiting.link, full.link) << i;
        EXPECT_EQ(r.limiting.obstacle, full.obstacle) << i;
        passed_with_contact += r.scale == 1.0;
      }
    } else if (r.limiting.scale == 1.0) {
      // Slowed for a standing obstacle: t_s is the first standing contact of every pair.
      ASSERT_TRUE(still.found) << i << " " << r.reason;
      EXPECT_EQ(r.limiting.time, still.time) << i;
      EXPECT_EQ(r.limiting.obstacle, still.obstacle) << i;
    } else {
      ++moving_limited;
    }
    if (r.scale == 1.0) {
      EXPECT_EQ(r.contact.found, full.found) << i;
      EXPECT_EQ(r.contact.time, full.found ? full.time : 0.0) << i;
    }
    expectNoContactBeforeTimeBeforeCollision(scene, twist, s, r, 400, i);
    if (r.scale > 0.0 && r.scale < 1.0) {
      ++slowed;
      const double faster = scannedSceneContact(scene, scaled(twist, r.scale + s.resolution),
                                                s.time_before_collision, 400);
      EXPECT_GE(faster, 0.0) << i << ": " << r.scale + s.resolution << " was safe too";
    }
  }
  EXPECT_GT(slowed, 6);
  EXPECT_GT(passed_with_contact + moving_limited, 2);
}

TEST(Gate, AllowedPairsAndFarObstaclesAreNotLookedAt) {
  PathScene scene = robotAndWall();
  scene.allowed.add("base", "wall");
  const GateResult allowed = gateTwist(scene, {2.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2));
  EXPECT_EQ(allowed.action, GateAction::Pass);
  EXPECT_EQ(allowed.pair_tests, 0u);
  // 10,000 obstacles beyond reach: no pair test. Mutations tried: no allowed-pair check; every
  // obstacle standing (the incoming one below is then missed) -> both fail.
  PathScene far = robotAndWall();
  far.obstacles.clear();
  far.obstacle_motions.clear();
  for (int i = 0; i < 10000; ++i) {
    far.obstacles.push_back(
        obstacle("far" + std::to_string(i), ellipse(50.0 + i % 100, 50.0 + i / 100, 0.3, 0.2)));
    far.obstacle_motions.push_back({});
  }
  far.obstacles.push_back(obstacle("near", ellipse(2.05, 0.0, 0.05, 3.0)));
  far.obstacle_motions.push_back({});
  const GateResult r = gateTwist(far, {1.0, 0.0, 0.2}, settings(3.0, 2.5, 0.2));
  EXPECT_EQ(r.limiting.obstacle, "near");
  EXPECT_LE(r.pair_tests, 3u);
  // An obstacle coming from afar at speed is a candidate: its capsule reaches the robot.
  far.obstacles[0].ellipse = ellipse(30.0, 0.0, 0.3, 0.3);
  far.obstacle_motions[0].velocity = Eigen::Vector2d(-12.0, 0.0);
  const GateResult incoming = gateTwist(far, {0.0, 0.0, 0.0}, settings(3.0, 2.5, 0.2));
  EXPECT_EQ(incoming.action, GateAction::Stop) << incoming.reason << incoming.error;
  EXPECT_EQ(incoming.contact.obstacle, "far0");
}

TEST(Gate, InvalidInputsStopWithTheFieldAndValue) {
  // Mutation tried: the broadphase skipping what is not provably near (a NaN obstacle too) ->
  // fails.
  const PathScene scene = robotAndWall();
  const auto error = [&](const PathScene& sc, const Twist& t, const GateSettings& s) {
    const GateResult r = gateTwist(sc, t, s);
    if (!r.ok()) {
      EXPECT_EQ(r.action, GateAction::Stop);
      EXPECT_EQ(r.scale, 0.0);
    }
    EXPECT_EQ(r.error, invalidGateReason(sc, t, s));
    return r.error;
  };
  EXPECT_EQ(error(scene, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2)), "");
  EXPECT_EQ(error(scene, {NAN, 0.0, 0.0}, settings(3.0, 1.5, 0.2)),
            "twist.vx = nan must be finite");
  EXPECT_EQ(error(scene, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 2.0)),
            "settings: stop_time = 2 must be within [0, 1.5] (at most time_before_collision)");
  EXPECT_EQ(error(scene, {1.0, 0.0, 0.0}, settings(1.0, 1.5, 0.2)),
            "settings: time_before_collision = 1.5 must be within [0, 1] (at most horizon)");
  EXPECT_EQ(error(scene, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2, -1.0)),
            "settings: margin = -1 must be within [0, 1e+09]");
  EXPECT_EQ(error(scene, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2, 0.0, 0.0)),
            "settings: resolution = 0 must be within [0.001, 1]");
  EXPECT_EQ(error(scene, {1.0, 0.0, 0.0}, settings(INFINITY, 1.5, 0.2)),
            "settings: horizon = inf must be within (0, 60]");
  // The ranges are the node's (one home: findInvalidGateSettings()): a grid finer than 1e-3 and a
  // horizon beyond a minute are refused here as at start-up.
  EXPECT_EQ(error(scene, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2, 0.0, 5e-4)),
            "settings: resolution = 5e-04 must be within [0.001, 1]");
  EXPECT_EQ(error(scene, {1.0, 0.0, 0.0}, settings(61.0, 1.5, 0.2)),
            "settings: horizon = 61 must be within (0, 60]");
  PathScene bad = scene;
  bad.obstacles[0].ellipse.center.x() = NAN;  // never skipped by the broadphase
  EXPECT_EQ(error(bad, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2)),
            "obstacle 'wall': center.x = nan is not finite");
  bad = scene;
  bad.obstacle_motions.clear();
  EXPECT_EQ(error(bad, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2)),
            "obstacle_motions has 0 entries for 1 obstacles");
  bad = scene;
  bad.links[0].ellipse.radius_y = -1.0;
  EXPECT_EQ(error(bad, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2)),
            "link 'base': radius_y = -1 must be > 0");
  bad = scene;
  bad.obstacles.push_back(bad.obstacles[0]);
  bad.obstacle_motions.push_back({});
  EXPECT_EQ(invalidGateReason(bad, {1.0, 0.0, 0.0}, settings(3.0, 1.5, 0.2)),
            "obstacle 1: name 'wall' repeats obstacle 0");
}

// ---- the braking rule: a base that answers late and brakes at bounded rates ------------------

struct Course {
  NamedEllipse obstacle;
  Motion motion;          ///< in the world frame
  double appears_s{0.0};  ///< seen from this time on
};

struct Drive {
  bool touched_while_moving{false};
  double touch_time{0.0};
  double touch_speed{0.0};
  bool came_to_rest{false};
  double rest_gap{0.0};  ///< distance of the robot to the nearest obstacle when it came to rest
  bool said_unavoidable{false};
  std::string reason;  ///< the last decision's
};

/// The robot (links in its frame) driven by `input` at 20 Hz through gateTwist() for `duration`,
/// the simulated base (core::SimulatedBase) following the outputs late and braking
/// at its limits, its velocity now (as odometry gives it) the gate's BaseState. Contact is checked
/// every 5 ms of the simulated motion against the obstacles where they are then.
Drive drive(const std::vector<NamedEllipse>& links, const std::vector<Course>& course,
            const Twist& input, const BaseDynamics& dynamics, double duration,
            const GateSettings& s) {
  constexpr double kPeriod = 0.05;
  core::SimulatedBase base(dynamics, {}, input);  // cruising at the input
  Drive result;
  const auto worldLink = [&](const Ellipse& link) {
    const core::PathPose& p = base.pose();
    return placeAt(link, {p.x, p.y}, p.yaw);
  };
  const auto obstacleAt = [&](const Course& c, double t) {
    return movedBy(c.obstacle.ellipse, c.motion, t);
  };
  for (double t = 0.0; t < duration; t += kPeriod) {
    PathScene scene;
    scene.links = links;
    const core::PathPose& p = base.pose();
    const double c = std::cos(p.yaw), sn = std::sin(p.yaw);
    for (const Course& o : course) {
      if (t < o.appears_s) continue;
      Ellipse e = obstacleAt(o, t);
      const Eigen::Vector2d d = e.center - Eigen::Vector2d(p.x, p.y);
      e.center = {c * d.x() + sn * d.y(), -sn * d.x() + c * d.y()};
      e.angle -= p.yaw;
      scene.obstacles.push_back({o.obstacle.name, EllipseRole::Obstacle, e});
      const Eigen::Vector2d v = o.motion.velocity;
      scene.obstacle_motions.push_back(
          {{c * v.x() + sn * v.y(), -sn * v.x() + c * v.y()}, o.motion.angular_velocity});
    }
    BaseState state;
    state.dynamics = dynamics;
    state.velocity = base.velocity();
    state.command_period = kPeriod;
    const GateResult r = gateTwist(scene, input, s, state);
    EXPECT_TRUE(r.ok()) << r.error;
    result.reason = r.reason;
    result.said_unavoidable |= r.unavoidable;
    base.command(t, scaled(input, r.scale));
    for (int sub = 1; sub <= 10; ++sub) {
      const double at = t + kPeriod * sub / 10;
      base.advanceTo(at);
      for (const Course& o : course) {
        if (at < o.appears_s) continue;
        for (const NamedEllipse& link : links) {
          if (base.moving() && overlap(worldLink(link.ellipse), obstacleAt(o, at)) &&
              !result.touched_while_moving) {
            result.touched_while_moving = true;
            result.touch_time = at;
            result.touch_speed = base.speed();
          }
        }
      }
    }
    if (!base.moving() && t > 0.5) {
      result.came_to_rest = true;
      double gap = std::numeric_limits<double>::infinity();
      for (const Course& o : course) {
        for (const NamedEllipse& link : links) {
          gap = std::min(gap, distance(worldLink(link.ellipse), obstacleAt(o, t)).distance);
        }
      }
      result.rest_gap = gap;
      break;
    }
  }
  return result;
}

GateSettings brakingSettings() { return settings(4.0, 1.0, 0.3, 0.05, 0.01); }

TEST(GateBraking, WallsAreNeverTouchedAtAnySpeedDecelerationAndReaction) {
  const std::vector<NamedEllipse> robot = {link("base", ellipse(0.0, 0.0, 0.3, 0.3))};
  for (double speed : {0.5, 1.0, 1.5, 2.0}) {
    for (double decel : {0.5, 1.0, 2.0}) {
      for (double reaction : {0.05, 0.1, 0.2}) {
        const double stopping = speed * (reaction + 0.05) + speed * speed / (2.0 * decel);
        const double wall = 0.3 + 1.5 * stopping + 1.0;  // its near face
        const Drive d = drive(robot, {{obstacle("wall", ellipse(wall + 0.05, 0.0, 0.05, 3.0)), {}}},
                              {speed, 0.0, 0.0}, {reaction, decel, 2.0}, 20.0, brakingSettings());
        const std::string what = std::to_string(speed) + " m/s, " + std::to_string(decel) +
                                 " m/s^2, " + std::to_string(reaction) + " s";
        EXPECT_FALSE(d.touched_while_moving)
            << what << ": touched at " << d.touch_time << " s, " << d.touch_speed << " m/s";
        EXPECT_TRUE(d.came_to_rest) << what << ": " << d.reason;
        EXPECT_GE(d.rest_gap, 0.0) << what;
        if (speed == 1.5) {
          EXPECT_LE(d.rest_gap, 0.6) << what << ": rests absurdly early";
        }
      }
    }
  }
}

TEST(GateBraking, ABoxAppearingAtOnePointTwoStoppingDistancesIsNotHit) {
  const std::vector<NamedEllipse> robot = {link("base", ellipse(0.0, 0.0, 0.3, 0.3))};
  const double speed = 1.5, decel = 0.8, reaction = 0.1;
  // The robot's front travels this far from the moment a command is judged until it rests.
  const double stopping = speed * (reaction + 0.05) + speed * speed / (2.0 * decel);
  const double appears = 1.0;
  const double front_then = 0.3 + speed * appears;
  const double box = front_then + 1.2 * stopping;  // the box's near face, when it appears
  const Drive d = drive(robot, {{obstacle("box", ellipse(box + 0.2, 0.0, 0.2, 0.2)), {}, appears}},
                        {speed, 0.0, 0.0}, {reaction, decel, 2.0}, 10.0, brakingSettings());
  EXPECT_FALSE(d.touched_while_moving) << d.touch_time << " s at " << d.touch_speed << " m/s";
  EXPECT_TRUE(d.came_to_rest) << d.reason;
}

TEST(GateBraking, ABoxAppearingTooCloseStopsAndSaysItIsUnavoidable) {
  const std::vector<NamedEllipse> robot = {link("base", ellipse(0.0, 0.0, 0.3, 0.3))};
  // 0.5 m ahead at 1.5 m/s with 0.8 m/s^2: braking needs 1.6 m.
  const Drive d =
      drive(robot, {{obstacle("box", ellipse(1.5 + 0.3 + 0.5 + 0.2, 0.0, 0.2, 0.2)), {}, 1.0}},
            {1.5, 0.0, 0.0}, {0.1, 0.8, 2.0}, 4.0, brakingSettings());
  EXPECT_TRUE(d.said_unavoidable) << d.reason;
}

TEST(GateBraking, AOneCentimetrePlateAtTwoMetresPerSecond) {
  const std::vector<NamedEllipse> robot = {link("base", ellipse(0.0, 0.0, 0.3, 0.3))};
  const Drive d = drive(robot, {{obstacle("plate", ellipse(6.0, 0.0, 0.005, 0.5)), {}}},
                        {2.0, 0.0, 0.0}, {0.1, 1.0, 2.0}, 10.0, brakingSettings());
  EXPECT_FALSE(d.touched_while_moving) << d.touch_time << " s at " << d.touch_speed << " m/s";
  EXPECT_TRUE(d.came_to_rest) << d.reason;
}

TEST(GateBraking, TurningIntoAPostAtOnePointTwoRadiansPerSecond) {
  // The origin circles (0, 0.5) at radius 0.5; the post stands on that circle, a half turn on.
  const std::vector<NamedEllipse> robot = {link("base", ellipse(0.0, 0.0, 0.25, 0.15))};
  const Drive d = drive(robot, {{obstacle("post", ellipse(0.0, 1.0, 0.05, 0.05)), {}}},
                        {0.6, 0.0, 1.2}, {0.15, 0.5, 0.6}, 10.0, brakingSettings());
  EXPECT_FALSE(d.touched_while_moving) << d.touch_time << " s at " << d.touch_speed << " m/s";
  EXPECT_TRUE(d.came_to_rest) << d.reason;
}

TEST(GateBraking, AnOncomingCartIsNotTouchedWhileTheBaseMoves) {
  const std::vector<NamedEllipse> robot = {link("base", ellipse(0.0, 0.0, 0.3, 0.3))};
  const Drive d =
      drive(robot, {{obstacle("cart", ellipse(9.0, 0.0, 0.4, 0.3)), {{-0.5, 0.0}, 0.0}}},
            {1.5, 0.0, 0.0}, {0.2, 0.5, 2.0}, 12.0, brakingSettings());
  EXPECT_FALSE(d.touched_while_moving) << d.touch_time << " s at " << d.touch_speed << " m/s";
}

}  // namespace
}  // namespace ellipse_collision::core

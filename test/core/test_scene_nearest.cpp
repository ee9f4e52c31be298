// The nearest wanted partner of one ellipse of a scene (nearestTo(), src/core/scene_nearest.cpp):
// circles worked out by hand, the pair rules, ties settled in CollidingPair order, refusals
// named; both overloads alike. (Random scenes against brute force over distance() are in
// test_scene_clearance.cpp, beside the clearance pass that shares that brute force.)
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ellipse_collision/core/scene_check.h"
#include "scene_test_helpers.h"

namespace ellipse_collision::core {
namespace {

using namespace scene_test;

TEST(NearestTo, TwoCirclesGiveTheHandComputedDistanceWithTheAskedEllipseFirst) {
  // box (an obstacle) is asked about: it comes first although a pair names the link first.
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0),
                                           circle("far", EllipseRole::Link, 10.0, 0.0, 1.0),
                                           circle("box", EllipseRole::Obstacle, 3.0, 0.0, 0.5)};
  const NearestResult r = nearestTo(scene, SceneRules{}, "box");
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.nearest.name_a, "box");
  EXPECT_EQ(r.nearest.name_b, "arm");
  EXPECT_NEAR(r.nearest.distance, 1.5, 1e-12);
  EXPECT_NEAR(r.nearest.point_a.x(), 2.5, 1e-12);
  EXPECT_NEAR(r.nearest.point_b.x(), 1.0, 1e-12);
  // The link's nearest partner: links pair with each other too (far is 8 m away, box 1.5 m).
  const NearestResult arm = nearestTo(scene, SceneRules{}, "arm");
  EXPECT_EQ(arm.nearest.name_b, "box");
}

TEST(NearestTo, CollidingPartnerOfSmallestContactScaleWinsAtDistanceZero) {
  // deep: centres 0.5 m apart (scale 0.25); shallow: 1.5 m apart (scale 0.75); near: 0.1 m away.
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0),
                                           circle("shallow", EllipseRole::Obstacle, 1.5, 0.0, 1.0),
                                           circle("deep", EllipseRole::Obstacle, 0.0, 0.5, 1.0),
                                           circle("near", EllipseRole::Obstacle, -2.1, 0.0, 1.0)};
  const NearestResult r = nearestTo(scene, SceneRules{}, "arm");
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.nearest.name_b, "deep");
  EXPECT_EQ(r.nearest.distance, 0.0);
}

TEST(NearestTo, FollowsThePairRules) {
  const std::vector<NamedEllipse> scene = {circle("o1", EllipseRole::Obstacle, 0.0, 0.0, 0.5),
                                           circle("o2", EllipseRole::Obstacle, 1.5, 0.0, 0.5),
                                           circle("l1", EllipseRole::Link, 4.0, 0.0, 0.5),
                                           circle("l2", EllipseRole::Link, 5.5, 0.0, 0.5)};
  SceneRules rules;
  EXPECT_EQ(nearestTo(scene, rules, "o1").nearest.name_b, "l1");  // never obstacle-obstacle
  EXPECT_EQ(nearestTo(scene, rules, "l2").nearest.name_b, "l1");
  rules.self_collision = false;
  EXPECT_EQ(nearestTo(scene, rules, "l2").nearest.name_b, "o2");
  rules.allowed.add("l2", "o2");
  EXPECT_EQ(nearestTo(scene, rules, "l2").nearest.name_b, "o1");
  rules.allowed.add("o1", "l2");
  EXPECT_FALSE(nearestTo(scene, rules, "l2").found);
  EXPECT_TRUE(nearestTo(scene, rules, "l2").ok());
}

TEST(NearestTo, UnknownNameIsRefused) {
  const NearestResult r =
      nearestTo({circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0)}, SceneRules{}, "ghost");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("'ghost'"), std::string::npos) << r.error;
}

TEST(NearestTo, EqualDistancesGoToTheLowerRoleThenTheLowerName) {
  // Three partners exactly 1 m from a query circle's rim: the link wins over the obstacles, and
  // of the obstacles "a" over "b".
  const std::vector<NamedEllipse> scene = {circle("probe", EllipseRole::Query, 0.0, 0.0, 1.0),
                                           circle("b", EllipseRole::Obstacle, 3.0, 0.0, 1.0),
                                           circle("a", EllipseRole::Obstacle, -3.0, 0.0, 1.0),
                                           circle("z", EllipseRole::Link, 0.0, 3.0, 1.0)};
  const NearestResult r = nearestTo(scene, SceneRules{}, "probe");
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.nearest.name_b, "z");
  EXPECT_EQ(r.nearest.distance, 1.0);
  const std::vector<NamedEllipse> obstacles_only(scene.begin(), scene.begin() + 3);
  EXPECT_EQ(nearestTo(obstacles_only, SceneRules{}, "probe").nearest.name_b, "a");
  // Colliding at the same contact scale: the same order.
  const std::vector<NamedEllipse> deep = {circle("probe", EllipseRole::Query, 0.0, 0.0, 1.0),
                                          circle("b", EllipseRole::Obstacle, 1.0, 0.0, 1.0),
                                          circle("a", EllipseRole::Obstacle, -1.0, 0.0, 1.0)};
  const NearestResult colliding = nearestTo(deep, SceneRules{}, "probe");
  EXPECT_EQ(colliding.nearest.name_b, "a");
  EXPECT_EQ(colliding.nearest.distance, 0.0);
}

TEST(NearestTo, RefusalsNameWhatIsWrong) {
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0),
                                           circle("box", EllipseRole::Obstacle, 3.0, 0.0, 0.5)};
  EXPECT_EQ(nearestTo(scene, SceneRules{}, "ghost").error, "name = 'ghost' is not in the scene");
  EXPECT_EQ(nearestTo(std::vector<NamedEllipse>{}, SceneRules{}, "arm").error,
            "name = 'arm' is not in the scene");
  SceneRules negative;
  negative.warning_distance = -0.5;
  EXPECT_EQ(nearestTo(scene, negative, "arm").error,
            "warning_distance = -0.5 must be finite and >= 0");
  std::vector<NamedEllipse> twice = scene;
  twice.push_back(circle("arm", EllipseRole::Obstacle, 9.0, 0.0, 0.5));
  EXPECT_EQ(nearestTo(twice, SceneRules{}, "box").error, "ellipses[2].name = 'arm' is a duplicate");
  std::vector<NamedEllipse> broken = scene;
  broken[1].ellipse.radius_y = NAN;
  const NearestResult r = nearestTo(broken, SceneRules{}, "arm");
  EXPECT_FALSE(r.found);
  EXPECT_EQ(r.error.rfind("ellipses[1] ('box'): ", 0), 0u) << r.error;
  // A lone ellipse has no partner, and that is no error.
  const NearestResult lone = nearestTo({scene[0]}, SceneRules{}, "arm");
  EXPECT_TRUE(lone.ok());
  EXPECT_FALSE(lone.found);
}

TEST(NearestTo, TheSceneOverloadGivesTheSameAnswerBitForBit) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0), radius(0.05, 1.0), angle(-3.0, 3.0);
  for (int round = 0; round < 50; ++round) {
    std::vector<NamedEllipse> entries;
    for (int i = 0; i < 15; ++i) {
      const EllipseRole role = i < 3   ? EllipseRole::Query
                               : i < 7 ? EllipseRole::Link
                                       : EllipseRole::Obstacle;
      entries.push_back(
          {"e" + std::to_string(i), role,
           Ellipse{{coordinate(rng), coordinate(rng)}, radius(rng), radius(rng), angle(rng)}});
    }
    const Scene scene(entries);
    for (const NamedEllipse& e : entries) {
      const NearestResult a = nearestTo(entries, SceneRules{}, e.name);
      const NearestResult b = nearestTo(scene, SceneRules{}, e.name);
      ASSERT_EQ(a.found, b.found);
      EXPECT_EQ(a.nearest.name_a, e.name);
      EXPECT_EQ(a.nearest.name_b, b.nearest.name_b);
      EXPECT_EQ(a.nearest.distance, b.nearest.distance);
      EXPECT_EQ(a.nearest.point_a, b.nearest.point_a);
      EXPECT_EQ(a.nearest.point_b, b.nearest.point_b);
    }
  }
}

}  // namespace
}  // namespace ellipse_collision::core

// Obstacles validated, prepared and gridded once (core/indexed_obstacles.h): every entry refused
// naming it, the index holding the obstacles as given, and checkMoversAgainst() answering as the
// brute force over every wanted pair (test/support/brute_force_scene.h) with the same bits.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "brute_force_scene.h"
#include "ellipse_collision/core/indexed_obstacles.h"

namespace ellipse_collision::core {
namespace {

TEST(SceneBroadphase, IndexedObstaclesRefuseBadEntriesAndTheCheckSaysSo) {
  const Ellipse bad{{0.0, 0.0}, -1.0, 1.0, 0.0};
  const IndexedObstacles refused(
      {{"crate", EllipseRole::Obstacle, {{1, 0}, 1, 1, 0}}, {"rock", EllipseRole::Obstacle, bad}});
  EXPECT_EQ(refused.error().rfind("obstacles[1] ('rock'): radius_x", 0), 0u) << refused.error();
  EXPECT_TRUE(refused.obstacles().empty());
  EXPECT_EQ(refused.batch().size(), 0u);  // the crate before the rock kept nothing either
  const std::vector<NamedEllipse> arm = {{"arm", EllipseRole::Link, {{0, 0}, 1, 1, 0}}};
  SceneCheckResult result = checkMoversAgainst(arm, refused, SceneRules{});
  EXPECT_EQ(result.error.rfind("obstacles refused: obstacles[1] ('rock')", 0), 0u) << result.error;

  const IndexedObstacles link_among_obstacles({{"arm2", EllipseRole::Link, {{0, 0}, 1, 1, 0}}});
  EXPECT_EQ(link_among_obstacles.error(), "obstacles[0] ('arm2'): role must be Obstacle");

  const IndexedObstacles crate({{"crate", EllipseRole::Obstacle, {{1, 0}, 1, 1, 0}}});
  ASSERT_TRUE(crate.error().empty());
  result = checkMoversAgainst({{"crate2", EllipseRole::Obstacle, {{0, 0}, 1, 1, 0}}}, crate,
                              SceneRules{});
  EXPECT_EQ(result.error, "movers[0] ('crate2') is an obstacle");
  result = checkMoversAgainst({{"arm", EllipseRole::Link, bad}}, crate, SceneRules{});
  EXPECT_EQ(result.error.rfind("movers[0] ('arm'): radius_x", 0), 0u) << result.error;
  SceneRules negative;
  negative.warning_distance = -1.0;
  EXPECT_NE(checkMoversAgainst(arm, crate, negative).error.find("warning_distance"),
            std::string::npos);
  // And a good one answers: the arm meets the crate.
  result = checkMoversAgainst(arm, crate, SceneRules{});
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_EQ(result.collisions.size(), 1u);
  EXPECT_EQ(result.collisions[0].name_b, "crate");
}

TEST(IndexedObstacles, AGoodSetIsKeptAsGivenWithABatchAndGridOfIt) {
  const std::vector<NamedEllipse> given = {{"b", EllipseRole::Obstacle, {{1, 0}, 1, 0.5, 0.3}},
                                           {"a", EllipseRole::Obstacle, {{-4, 2}, 0.2, 0.2, 0}}};
  const IndexedObstacles index(given);
  ASSERT_EQ(index.error(), "");
  ASSERT_EQ(index.obstacles().size(), 2u);
  EXPECT_EQ(index.obstacles()[0].name, "b") << "kept in the order given";
  EXPECT_EQ(index.obstacles()[1].ellipse.center, Eigen::Vector2d(-4, 2));
  EXPECT_EQ(index.batch().size(), 2u);
  EXPECT_EQ(index.batch().centerX()[1], -4.0);
  EXPECT_EQ(index.batch().boundingRadius()[0], 1.0);
  EXPECT_EQ(index.batch().inscribedRadius()[0], 0.5);
  const IndexedObstacles none;
  EXPECT_EQ(none.error(), "");
  EXPECT_TRUE(none.obstacles().empty());
  EXPECT_EQ(none.batch().size(), 0u);
  // Movers against no obstacles: only their own pairs.
  const SceneCheckResult alone = checkMoversAgainst(
      {{"l1", EllipseRole::Link, {{0, 0}, 1, 1, 0}}, {"l2", EllipseRole::Link, {{1, 0}, 1, 1, 0}}},
      none, SceneRules{});
  ASSERT_TRUE(alone.ok()) << alone.error;
  ASSERT_EQ(alone.collisions.size(), 1u);
  EXPECT_EQ(alone.collisions[0].name_a, "l1");
}

TEST(IndexedObstacles, MoversAgainstTheIndexAnswerAsTheBruteForce) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> coordinate(-6.0, 6.0), radius(0.05, 0.8), angle(-3, 3);
  const auto random_entry = [&](const std::string& name, EllipseRole role) {
    return NamedEllipse{
        name, role, {{coordinate(rng), coordinate(rng)}, radius(rng), radius(rng), angle(rng)}};
  };
  std::vector<NamedEllipse> obstacles;
  for (int i = 0; i < 300; ++i)
    obstacles.push_back(random_entry("o" + std::to_string(i), EllipseRole::Obstacle));
  const IndexedObstacles index(obstacles);
  ASSERT_EQ(index.error(), "");
  std::size_t collisions = 0, warnings = 0;
  for (int check = 0; check < 20; ++check) {
    std::vector<NamedEllipse> movers;
    for (int i = 0; i < 8; ++i) {
      movers.push_back(
          random_entry("m" + std::to_string(i), i < 2 ? EllipseRole::Query : EllipseRole::Link));
    }
    SceneRules rules;
    rules.self_collision = check % 2 == 0;
    rules.warning_distance = check % 3 == 0 ? 0.0 : 0.3;
    rules.allowed.add("m3", "o" + std::to_string(check));
    std::set<std::string> only;
    if (check % 4 == 3) only = {"m2", "o7"};
    std::vector<NamedEllipse> scene = movers;
    scene.insert(scene.end(), obstacles.begin(), obstacles.end());
    const SceneCheckResult expected = test::bruteForceScene(scene, rules, only);
    const SceneCheckResult actual = checkMoversAgainst(movers, index, rules, only);
    ASSERT_TRUE(actual.ok()) << actual.error;
    ASSERT_EQ(actual.collisions.size(), expected.collisions.size()) << "check " << check;
    for (std::size_t k = 0; k < expected.collisions.size(); ++k) {
      EXPECT_EQ(actual.collisions[k].name_a, expected.collisions[k].name_a);
      EXPECT_EQ(actual.collisions[k].name_b, expected.collisions[k].name_b);
      EXPECT_EQ(actual.collisions[k].contact_scale, expected.collisions[k].contact_scale);
    }
    ASSERT_EQ(actual.warnings.size(), expected.warnings.size()) << "check " << check;
    for (std::size_t k = 0; k < expected.warnings.size(); ++k) {
      EXPECT_EQ(actual.warnings[k].name_b, expected.warnings[k].name_b);
      EXPECT_EQ(actual.warnings[k].distance, expected.warnings[k].distance);
      EXPECT_EQ(actual.warnings[k].point_a, expected.warnings[k].point_a);
    }
    EXPECT_LT(actual.pair_tests, movers.size() * obstacles.size() / 4) << "the grid culls";
    collisions += expected.collisions.size();
    warnings += expected.warnings.size();
  }
  EXPECT_GT(collisions, 40u);
  EXPECT_GT(warnings, 40u);
}

TEST(IndexedObstacles, WithinGivesTheScansObstaclesEvenOnTheBoundary) {
  // The velocity gate's cull through the grid: the same obstacles, in the same order, as a scan
  // of every obstacle with mayComeWithin(), for obstacles from pebbles to a few that span many
  // cells, points inside and outside the floor, reaches from 0 to beyond the floor, and reaches
  // that put an obstacle on the boundary of the test (up to rounding).
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0), small(0.02, 0.5),
      angle(-3.0, 3.0);
  std::vector<NamedEllipse> obstacles;
  for (int i = 0; i < 3000; ++i) {
    const double r = i % 500 == 0 ? 15.0 : small(rng);
    obstacles.push_back({"o" + std::to_string(i),
                         EllipseRole::Obstacle,
                         {{coordinate(rng), coordinate(rng)}, r, small(rng), angle(rng)}});
  }
  const IndexedObstacles index(obstacles);
  ASSERT_TRUE(index.error().empty()) << index.error();
  std::size_t found = 0, on_boundary = 0;
  std::vector<std::size_t> within;
  for (int trial = 0; trial < 600; ++trial) {
    const Eigen::Vector2d point(1.3 * coordinate(rng), 1.3 * coordinate(rng));
    double reach = trial % 3 == 0 ? 0.0 : std::pow(10.0, angle(rng) / 1.5);
    if (trial % 5 == 1) {
      // The reach at which obstacle k sits on the boundary of the test (up to rounding), and
      // one ulp below it.
      const Ellipse& e = obstacles[static_cast<std::size_t>(trial) % obstacles.size()].ellipse;
      reach = (e.center - point).norm() - boundingRadius(e);
      if (trial % 10 == 6) reach = std::nextafter(reach, -1.0);
    }
    std::vector<std::size_t> scanned;
    for (std::size_t k = 0; k < obstacles.size(); ++k) {
      if (mayComeWithin(obstacles[k].ellipse, 0.0, point, reach)) scanned.push_back(k);
    }
    index.within(point, reach, &within);
    EXPECT_EQ(within, scanned) << "trial " << trial << ", reach " << reach;
    found += scanned.size();
    on_boundary += trial % 5 == 1 && !scanned.empty();
  }
  EXPECT_GT(found, 2000u) << "the trials must find obstacles";
  EXPECT_GT(on_boundary, 50u);
}

}  // namespace
}  // namespace ellipse_collision::core

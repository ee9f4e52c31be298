// Scene checking against a brute force written here: circles, whose overlap (d <= r1 + r2) and
// contact scale (d / (r1 + r2)) are exact, with the pair rules spelled out as a table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "ellipse_collision/core/scene_check.h"
#include "scene_test_helpers.h"

namespace ellipse_collision::core {
namespace {

using namespace scene_test;

std::vector<std::pair<std::string, std::string>> namesOf(const SceneCheckResult& result) {
  std::vector<std::pair<std::string, std::string>> names;
  for (const CollidingPair& p : result.collisions) names.emplace_back(p.name_a, p.name_b);
  return names;
}

struct Expected {
  int rank_a;
  std::string name_a;
  int rank_b;
  std::string name_b;
  double contact_scale;
};

std::vector<Expected> bruteForce(const std::vector<NamedEllipse>& scene, bool self_collision,
                                 const std::set<std::pair<std::string, std::string>>& allowed,
                                 const std::set<std::string>& only) {
  std::vector<Expected> out;
  for (const NamedEllipse& a : scene) {
    for (const NamedEllipse& b : scene) {
      // Visit each unordered pair once, in the orientation the spec reports.
      if (std::make_pair(roleRank(a.role), a.name) >= std::make_pair(roleRank(b.role), b.name)) {
        continue;
      }
      if (!rolesChecked(a.role, b.role, self_collision)) continue;
      if (allowed.count({a.name, b.name}) || allowed.count({b.name, a.name})) continue;
      if (!only.empty() && !only.count(a.name) && !only.count(b.name)) continue;
      const double d = (a.ellipse.center - b.ellipse.center).norm();
      const double radius_sum = a.ellipse.radius_x + b.ellipse.radius_x;
      if (d <= radius_sum) {
        out.push_back({roleRank(a.role), a.name, roleRank(b.role), b.name, d / radius_sum});
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const Expected& x, const Expected& y) {
    return std::tie(x.rank_a, x.name_a, x.rank_b, x.name_b) <
           std::tie(y.rank_a, y.name_a, y.rank_b, y.name_b);
  });
  return out;
}

/// Random circles on a quarter-metre grid, none within 1e-3 m of tangency with another, so the
/// overlap decision is never a rounding question.
std::vector<NamedEllipse> randomScene(std::mt19937& rng, int count) {
  std::uniform_int_distribution<int> grid(0, 40);
  std::uniform_int_distribution<int> radius_steps(1, 8);
  std::uniform_int_distribution<int> role(0, 2);
  std::vector<NamedEllipse> scene;
  while (static_cast<int>(scene.size()) < count) {
    const NamedEllipse candidate =
        circle("e" + std::to_string(scene.size()), static_cast<EllipseRole>(role(rng)),
               0.25 * grid(rng), 0.25 * grid(rng), 0.25 * radius_steps(rng));
    const bool near_tangent = std::any_of(scene.begin(), scene.end(), [&](const NamedEllipse& e) {
      const double d = (e.ellipse.center - candidate.ellipse.center).norm();
      return std::abs(d - (e.ellipse.radius_x + candidate.ellipse.radius_x)) < 1e-3;
    });
    if (!near_tangent) scene.push_back(candidate);
  }
  return scene;
}

TEST(SceneCheck, MatchesBruteForceOnRandomCircleScenes) {
  std::mt19937 rng(12345);
  std::bernoulli_distribution coin(0.5);
  std::size_t total_collisions = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<NamedEllipse> scene = randomScene(rng, 25);
    std::uniform_int_distribution<std::size_t> pick(0, scene.size() - 1);
    SceneRules rules;
    rules.self_collision = coin(rng);
    std::set<std::pair<std::string, std::string>> allowed;
    for (int k = 0; k < 10; ++k) {
      const std::string a = scene[pick(rng)].name;
      const std::string b = scene[pick(rng)].name;
      rules.allowed.add(a, b);
      allowed.insert({a, b});
    }
    std::set<std::string> only;
    if (coin(rng)) {
      for (int k = 0; k < 3; ++k) only.insert(scene[pick(rng)].name);
      only.insert("not_in_scene");
    }

    const SceneCheckResult result = checkScene(scene, rules, only);
    ASSERT_TRUE(result.ok()) << result.error;
    const std::vector<Expected> expected = bruteForce(scene, rules.self_collision, allowed, only);
    ASSERT_EQ(result.collisions.size(), expected.size()) << "trial " << trial;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_EQ(result.collisions[i].name_a, expected[i].name_a) << "trial " << trial;
      EXPECT_EQ(result.collisions[i].name_b, expected[i].name_b) << "trial " << trial;
      EXPECT_NEAR(result.collisions[i].contact_scale, expected[i].contact_scale, 1e-12)
          << result.collisions[i].name_a << " / " << result.collisions[i].name_b;
    }
    total_collisions += expected.size();
  }
  // The scenes are dense enough that the comparison is not vacuous.
  EXPECT_GT(total_collisions, 1000u);
}

/// checkValidatedScene() of the entries, stored by column.
SceneCheckResult checkValidated(const std::vector<NamedEllipse>& entries, std::size_t first_obstacle,
                              const SceneRules& rules) {
  return checkValidatedScene(Scene(entries), first_obstacle, rules);
}

TEST(SceneCheck, ValidatedEntryPointRefusesWhatCostsNothingPerObstacle) {
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0, 0, 1),
                                           circle("rock", EllipseRole::Obstacle, 1.5, 0, 1)};
  EXPECT_TRUE(checkValidated(scene, 1, SceneRules{}).ok());
  EXPECT_EQ(checkValidated(scene, 1, SceneRules{}).collisions.size(), 1u);
  SceneRules rules;
  rules.warning_distance = -1.0;
  SceneCheckResult result = checkValidated(scene, 1, rules);
  EXPECT_NE(result.error.find("warning_distance = -1"), std::string::npos) << result.error;
  result = checkValidated(scene, 3, SceneRules{});
  EXPECT_EQ(result.error, "first_obstacle = 3 is beyond the 2 ellipses");
  result = checkValidated(scene, 2, SceneRules{});
  EXPECT_EQ(result.error, "ellipses[1] ('rock') is an obstacle before first_obstacle = 2");
}

TEST(SceneCheck, ValidatedEntryPointRefusesInvalidMoversAndInvalidObstaclesNearThem) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  const NamedEllipse arm = circle("arm", EllipseRole::Link, 0, 0, 1);
  const NamedEllipse stone = circle("stone", EllipseRole::Obstacle, 0.5, 0, 1);
  SceneCheckResult result = checkValidated(
      {arm, {"hand", EllipseRole::Link, {{nan, 0.0}, 1.0, 1.0, 0.0}}, stone}, 2, SceneRules{});
  EXPECT_EQ(result.error.rfind("ellipses[1] ('hand'): center.x", 0), 0u) << result.error;
  // A zero radius near the arm: refused before any pair work divides by it.
  result = checkValidated({arm, stone, {"rock", EllipseRole::Obstacle, {{0.5, 0.0}, 1.0, 0.0, 0.0}}},
                             1, SceneRules{});
  EXPECT_EQ(result.error.rfind("ellipses[2] ('rock'): radius_y", 0), 0u) << result.error;
  result = checkValidated({arm, {"rock", EllipseRole::Obstacle, {{0.5, 0.0}, inf, 1.0, 0.0}}},
                             1, SceneRules{});
  EXPECT_EQ(result.error.rfind("ellipses[1] ('rock'): radius_x", 0), 0u) << result.error;
}

TEST(SceneCheck, ValidatedEntryPointAnswersWithoutObstaclesItNeverMeets) {
  // The rest of a broken promise: invalid obstacles far from every mover (or nowhere) are not
  // tested at all, so the answer is that of the scene without them.
  const double nan = std::nan("");
  const NamedEllipse arm = circle("arm", EllipseRole::Link, 0, 0, 1);
  const NamedEllipse stone = circle("stone", EllipseRole::Obstacle, 0.5, 0, 1);
  const SceneCheckResult expected = checkScene({arm, stone}, SceneRules{});
  ASSERT_EQ(expected.collisions.size(), 1u);
  const SceneCheckResult result = checkValidated(
      {arm, stone,
       {"far", EllipseRole::Obstacle, {{50.0, 0.0}, 0.0, -1.0, 0.0}},
       {"nowhere", EllipseRole::Obstacle, {{nan, nan}, 1.0, 1.0, nan}}},
      1, SceneRules{});
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_EQ(result.collisions.size(), 1u);
  EXPECT_EQ(result.collisions[0].name_b, "stone");
  EXPECT_EQ(result.collisions[0].contact_scale, expected.collisions[0].contact_scale);
}

TEST(SceneCheck, ResultDoesNotDependOnInputOrder) {
  std::mt19937 rng(99);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<NamedEllipse> scene = randomScene(rng, 20);
    SceneRules rules;
    rules.allowed.add(scene[0].name, scene[1].name);
    const SceneCheckResult reference = checkScene(scene, rules);
    ASSERT_TRUE(reference.ok());
    std::shuffle(scene.begin(), scene.end(), rng);
    const SceneCheckResult shuffled = checkScene(scene, rules);
    ASSERT_EQ(namesOf(shuffled), namesOf(reference));
    for (std::size_t i = 0; i < reference.collisions.size(); ++i) {
      // Bitwise equal: the pair is always evaluated in the same orientation.
      EXPECT_EQ(shuffled.collisions[i].contact_scale, reference.collisions[i].contact_scale);
    }
  }
}

TEST(SceneCheck, ObstaclesAreNeverCheckedAgainstEachOther) {
  const std::vector<NamedEllipse> scene = {circle("table", EllipseRole::Obstacle, 0, 0, 1),
                                           circle("chair", EllipseRole::Obstacle, 0.5, 0, 1)};
  const SceneCheckResult result = checkScene(scene, SceneRules{});
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result.collisions.empty());
}

TEST(SceneCheck, LinksCollideWithEachOtherOnlyWithSelfCollision) {
  const std::vector<NamedEllipse> scene = {circle("upper_arm", EllipseRole::Link, 0, 0, 1),
                                           circle("forearm", EllipseRole::Link, 1.5, 0, 1)};
  SceneRules rules;
  rules.self_collision = true;
  EXPECT_EQ(namesOf(checkScene(scene, rules)), (Names{{"forearm", "upper_arm"}}));
  rules.self_collision = false;
  EXPECT_TRUE(checkScene(scene, rules).collisions.empty());
}

TEST(SceneCheck, LinkIsNamedBeforeObstacleWhateverTheNames) {
  const std::vector<NamedEllipse> scene = {circle("a_box", EllipseRole::Obstacle, 0, 0, 1),
                                           circle("z_arm", EllipseRole::Link, 1, 0, 1)};
  const SceneCheckResult result = checkScene(scene, SceneRules{});
  ASSERT_EQ(result.collisions.size(), 1u);
  EXPECT_EQ(result.collisions[0].name_a, "z_arm");
  EXPECT_EQ(result.collisions[0].name_b, "a_box");
  EXPECT_DOUBLE_EQ(result.collisions[0].contact_scale, 0.5);
}

TEST(SceneCheck, AllowedPairIsNeverReportedWhicheverWayItIsListed) {
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0, 0, 1),
                                           circle("tool", EllipseRole::Obstacle, 0.5, 0, 1),
                                           circle("wall", EllipseRole::Obstacle, -0.5, 0, 1)};
  SceneRules rules;
  rules.allowed.add("tool", "arm");
  EXPECT_EQ(namesOf(checkScene(scene, rules)), (Names{{"arm", "wall"}}));
  EXPECT_TRUE(rules.allowed.contains("arm", "tool"));
}

TEST(SceneCheck, NameFilterKeepsOnlyPairsInvolvingListedNames) {
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0, 0, 1),
                                           circle("leg", EllipseRole::Link, 10, 0, 1),
                                           circle("box", EllipseRole::Obstacle, 0.5, 0, 1),
                                           circle("rock", EllipseRole::Obstacle, 10.5, 0, 1)};
  EXPECT_EQ(namesOf(checkScene(scene, SceneRules{}, {"leg"})), (Names{{"leg", "rock"}}));
  EXPECT_EQ(namesOf(checkScene(scene, SceneRules{}, {"box", "rock"})),
            (Names{{"arm", "box"}, {"leg", "rock"}}));
  EXPECT_TRUE(checkScene(scene, SceneRules{}, {"unknown"}).collisions.empty());
}

TEST(SceneCheck, QueryIsCheckedAgainstLinksAndObstaclesButNotOtherQueries) {
  const std::vector<NamedEllipse> scene = {
      circle("probe", EllipseRole::Query, 0, 0, 1), circle("probe2", EllipseRole::Query, 0.1, 0, 1),
      circle("arm", EllipseRole::Link, 1, 0, 1), circle("box", EllipseRole::Obstacle, -0.9, 0, 1)};
  SceneRules rules;
  rules.self_collision = false;  // does not apply to queries
  EXPECT_EQ(namesOf(checkScene(scene, rules)), (Names{{"probe", "arm"},
                                                      {"probe", "box"},
                                                      {"probe2", "arm"},
                                                      {"probe2", "box"},
                                                      {"arm", "box"}}));
}

TEST(SceneCheck, ContainedEllipseIsReportedWithScaleBelowOne) {
  NamedEllipse inner = circle("pebble", EllipseRole::Obstacle, 0.2, 0.1, 0.1);
  NamedEllipse outer = circle("hull", EllipseRole::Link, 0, 0, 1);
  outer.ellipse.radius_x = 2.0;
  outer.ellipse.angle = 0.7;
  const SceneCheckResult result = checkScene({inner, outer}, SceneRules{});
  ASSERT_EQ(namesOf(result), (Names{{"hull", "pebble"}}));
  EXPECT_LT(result.collisions[0].contact_scale, 1.0);
}

TEST(SceneCheck, CoincidentCentresHaveContactScaleZero) {
  const SceneCheckResult result = checkScene(
      {circle("a", EllipseRole::Link, 1, 1, 1), circle("b", EllipseRole::Obstacle, 1, 1, 2)},
      SceneRules{});
  ASSERT_EQ(result.collisions.size(), 1u);
  EXPECT_EQ(result.collisions[0].contact_scale, 0.0);
}

TEST(SceneCheck, SeparateEllipsesAreNotReported) {
  NamedEllipse a = circle("a", EllipseRole::Link, 0, 0, 1);
  a.ellipse.radius_x = 3.0;  // long along x, so it would reach b if it were a circle of radius 3
  NamedEllipse b = circle("b", EllipseRole::Obstacle, 0, 1.5, 0.4);
  EXPECT_TRUE(checkScene({a, b}, SceneRules{}).collisions.empty());
}

TEST(SceneCheck, DuplicateNameIsRefusedNamingTheEntry) {
  const SceneCheckResult result = checkScene(
      {circle("arm", EllipseRole::Link, 0, 0, 1), circle("arm", EllipseRole::Obstacle, 5, 0, 1)},
      SceneRules{});
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error.find("ellipses[1].name = 'arm'"), std::string::npos) << result.error;
  EXPECT_TRUE(result.collisions.empty());
}

TEST(SceneCheck, EmptyNameIsRefused) {
  const SceneCheckResult result =
      checkScene({circle("", EllipseRole::Link, 0, 0, 1)}, SceneRules{});
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error.find("ellipses[0].name"), std::string::npos) << result.error;
}

TEST(SceneCheck, InvalidEllipseIsRefusedNamingTheEntry) {
  NamedEllipse nan_centre = circle("ghost", EllipseRole::Obstacle, 0, 0, 1);
  nan_centre.ellipse.center.x() = std::numeric_limits<double>::quiet_NaN();
  SceneCheckResult result =
      checkScene({circle("arm", EllipseRole::Link, 0, 0, 1), nan_centre}, SceneRules{});
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error.find("ellipses[1] ('ghost')"), std::string::npos) << result.error;

  result = checkScene({circle("flat", EllipseRole::Link, 0, 0, 0.0)}, SceneRules{});
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error.find("radius"), std::string::npos) << result.error;
}

TEST(SceneCheck, EmptySceneHasNoCollisions) {
  const SceneCheckResult result = checkScene({}, SceneRules{});
  EXPECT_TRUE(result.ok());
  EXPECT_TRUE(result.collisions.empty());
}

}  // namespace
}  // namespace ellipse_collision::core

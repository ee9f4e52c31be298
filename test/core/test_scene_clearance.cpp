// The clearance pass of checkScene() (warning pairs), and nearestTo() on random scenes, against a
// brute force that calls distance() on every pair the rules allow, and circles worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <tuple>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/scene_check.h"
#include "scene_test_helpers.h"

namespace ellipse_collision::core {
namespace {

using namespace scene_test;

SceneRules warnWithin(double warning_distance) {
  SceneRules rules;
  rules.warning_distance = warning_distance;
  return rules;
}

Names namesOf(const std::vector<NearPair>& pairs) {
  Names names;
  for (const NearPair& p : pairs) names.emplace_back(p.name_a, p.name_b);
  return names;
}

// ---- brute force, written independently of scene_check.cpp (rule table: scene_test_helpers.h)

bool reportedFirst(const NamedEllipse& a, const NamedEllipse& b) {
  return std::make_pair(roleRank(a.role), a.name) < std::make_pair(roleRank(b.role), b.name);
}

struct BruteRules {
  bool self_collision{true};
  std::set<std::pair<std::string, std::string>> allowed;
  std::set<std::string> only;
  double warning_distance{0.0};

  SceneRules sceneRules() const {
    SceneRules rules;
    rules.self_collision = self_collision;
    for (const auto& pair : allowed) rules.allowed.add(pair.first, pair.second);
    rules.warning_distance = warning_distance;
    return rules;
  }
  /// Pair (a, b), a reported first; `only` is ignored when `use_only` is false.
  bool wanted(const NamedEllipse& a, const NamedEllipse& b, bool use_only) const {
    if (!rolesChecked(a.role, b.role, self_collision)) return false;
    if (allowed.count({a.name, b.name}) || allowed.count({b.name, a.name})) return false;
    return !use_only || only.empty() || only.count(a.name) || only.count(b.name);
  }
};

/// distance() of every wanted pair, in reporting order: collisions and warnings.
struct BruteScene {
  Names collisions;
  std::vector<NearPair> warnings;
  int separated_beyond{0};     // wanted, separated, not closer than the warning distance
  int missed_by_inscribed{0};  // warnings a bound from the inscribed circles would have missed
};

BruteScene bruteForce(const std::vector<NamedEllipse>& scene, const BruteRules& rules) {
  BruteScene out;
  for (const NamedEllipse& a : scene) {
    for (const NamedEllipse& b : scene) {
      if (!reportedFirst(a, b) || !rules.wanted(a, b, true)) continue;
      const Clearance c = distance(a.ellipse, b.ellipse);
      if (!c.separated) {
        out.collisions.emplace_back(a.name, b.name);
      } else if (c.distance < rules.warning_distance) {
        out.warnings.push_back({a.name, b.name, c.distance, c.point_a, c.point_b});
        const double inscribed_gap = (a.ellipse.center - b.ellipse.center).norm() -
                                     inscribedRadius(a.ellipse) - inscribedRadius(b.ellipse);
        if (inscribed_gap >= rules.warning_distance) ++out.missed_by_inscribed;
      } else {
        ++out.separated_beyond;
      }
    }
  }
  const auto order = [&scene](const auto& x, const auto& y) {
    const auto rank = [&scene](const std::string& name) {
      for (const NamedEllipse& e : scene) {
        if (e.name == name) return roleRank(e.role);
      }
      return -1;
    };
    return std::make_tuple(rank(x.first), x.first, rank(x.second), x.second) <
           std::make_tuple(rank(y.first), y.first, rank(y.second), y.second);
  };
  std::sort(out.collisions.begin(), out.collisions.end(), order);
  std::sort(out.warnings.begin(), out.warnings.end(),
            [&order](const NearPair& x, const NearPair& y) {
              return order(std::make_pair(x.name_a, x.name_b), std::make_pair(y.name_a, y.name_b));
            });
  return out;
}

/// The nearest wanted partner of `name` by distance() on every pair; colliding partners first,
/// the smallest contact scale among them; ties to the partner reported first.
NearestResult bruteNearest(const std::vector<NamedEllipse>& scene, const BruteRules& rules,
                           const std::string& name) {
  const NamedEllipse& target = *std::find_if(scene.begin(), scene.end(),
                                             [&](const NamedEllipse& e) { return e.name == name; });
  NearestResult best;
  bool best_collides = false;
  double best_key = std::numeric_limits<double>::infinity();
  const NamedEllipse* best_partner = nullptr;
  for (const NamedEllipse& other : scene) {
    if (other.name == name) continue;
    const bool target_first = reportedFirst(target, other);
    const NamedEllipse& a = target_first ? target : other;
    const NamedEllipse& b = target_first ? other : target;
    if (!rules.wanted(a, b, false)) continue;
    const Clearance c = distance(a.ellipse, b.ellipse);
    const bool collides = !c.separated;
    const double key = collides ? contactScale(a.ellipse, b.ellipse) : c.distance;
    const bool better =
        !best.found || (collides && !best_collides) ||
        (collides == best_collides &&
         (key < best_key || (key == best_key && reportedFirst(other, *best_partner))));
    if (!better) continue;
    best.found = true;
    best_collides = collides;
    best_key = key;
    best_partner = &other;
    best.nearest = target_first ? NearPair{a.name, b.name, c.distance, c.point_a, c.point_b}
                                : NearPair{b.name, a.name, c.distance, c.point_b, c.point_a};
  }
  return best;
}

void expectSamePair(const NearPair& actual, const NearPair& expected, const std::string& where) {
  // The same function on the same inputs: equal to the last bit.
  EXPECT_EQ(actual.name_a, expected.name_a) << where;
  EXPECT_EQ(actual.name_b, expected.name_b) << where;
  EXPECT_EQ(actual.distance, expected.distance)
      << where << " " << actual.name_a << "-" << actual.name_b;
  EXPECT_EQ(actual.point_a, expected.point_a) << where;
  EXPECT_EQ(actual.point_b, expected.point_b) << where;
}

/// Ellipses of axis ratios up to 20 scattered so that gaps of a few tenths of a metre are common.
std::vector<NamedEllipse> randomScene(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> position(0.0, 6.0);
  std::uniform_real_distribution<double> radius(0.05, 1.0);
  std::uniform_real_distribution<double> ratio(1.0, 20.0);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_int_distribution<int> role(0, 2);
  std::vector<NamedEllipse> scene;
  for (int i = 0; i < count; ++i) {
    const double rx = radius(rng);
    scene.push_back(ellipse("e" + std::to_string(i), static_cast<EllipseRole>(role(rng)),
                            position(rng), position(rng), rx, rx / ratio(rng), angle(rng)));
  }
  return scene;
}

BruteRules randomRules(std::mt19937& rng, const std::vector<NamedEllipse>& scene) {
  std::bernoulli_distribution coin(0.5);
  std::uniform_int_distribution<std::size_t> pick(0, scene.size() - 1);
  std::uniform_real_distribution<double> warning(0.05, 1.0);
  BruteRules rules;
  rules.self_collision = coin(rng);
  rules.warning_distance = warning(rng);
  for (int k = 0; k < 3; ++k) {
    const std::size_t i = pick(rng);
    const std::size_t j = pick(rng);
    if (i != j) rules.allowed.insert({scene[i].name, scene[j].name});
  }
  if (coin(rng)) {
    rules.only.insert(scene[pick(rng)].name);
    rules.only.insert(scene[pick(rng)].name);
  }
  return rules;
}

// ---- the clearance pass of checkScene()

TEST(SceneClearance, WarningsMatchBruteForceOverDistanceOnRandomScenes) {
  std::mt19937 rng(2024);
  int warnings = 0;
  int beyond = 0;
  int missed_by_inscribed = 0;
  for (int round = 0; round < 300; ++round) {
    const std::vector<NamedEllipse> scene = randomScene(rng, 12);
    const BruteRules rules = randomRules(rng, scene);
    const SceneCheckResult result = checkScene(scene, rules.sceneRules(), rules.only);
    ASSERT_TRUE(result.ok()) << result.error;
    const BruteScene expected = bruteForce(scene, rules);
    const std::string where = "round " + std::to_string(round);
    Names collisions;
    for (const CollidingPair& p : result.collisions) collisions.emplace_back(p.name_a, p.name_b);
    EXPECT_EQ(collisions, expected.collisions) << where;
    ASSERT_EQ(namesOf(result.warnings), namesOf(expected.warnings)) << where;
    for (std::size_t i = 0; i < expected.warnings.size(); ++i) {
      expectSamePair(result.warnings[i], expected.warnings[i], where);
    }
    warnings += static_cast<int>(expected.warnings.size());
    beyond += expected.separated_beyond;
    missed_by_inscribed += expected.missed_by_inscribed;
  }
  // The scenes exercise both sides of the warning distance, and warnings that only a bound from
  // the bounding circles (not the inscribed ones) keeps.
  EXPECT_GT(warnings, 300);
  EXPECT_GT(beyond, 3000);
  EXPECT_GT(missed_by_inscribed, 20);
}

TEST(SceneClearance, ResultDoesNotDependOnInputOrder) {
  std::mt19937 rng(7);
  for (int round = 0; round < 50; ++round) {
    std::vector<NamedEllipse> scene = randomScene(rng, 10);
    const SceneRules rules = warnWithin(0.5);
    const SceneCheckResult first = checkScene(scene, rules);
    std::shuffle(scene.begin(), scene.end(), rng);
    const SceneCheckResult second = checkScene(scene, rules);
    ASSERT_EQ(namesOf(first.warnings), namesOf(second.warnings));
    for (std::size_t i = 0; i < first.warnings.size(); ++i) {
      expectSamePair(second.warnings[i], first.warnings[i], "round " + std::to_string(round));
    }
  }
}

TEST(SceneClearance, TwoCirclesWarnWithHandComputedDistanceAndWitnessPoints) {
  // Centres 3 m apart, radii 1 and 0.5: 1.5 m apart, closest at (1, 0) and (2.5, 0).
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0),
                                           circle("box", EllipseRole::Obstacle, 3.0, 0.0, 0.5)};
  const SceneCheckResult result = checkScene(scene, warnWithin(2.0));
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_TRUE(result.collisions.empty());
  ASSERT_EQ(result.warnings.size(), 1u);
  const NearPair& w = result.warnings[0];
  EXPECT_EQ(w.name_a, "arm");
  EXPECT_EQ(w.name_b, "box");
  EXPECT_NEAR(w.distance, 1.5, 1e-12);
  EXPECT_NEAR(w.point_a.x(), 1.0, 1e-12);
  EXPECT_NEAR(w.point_a.y(), 0.0, 1e-12);
  EXPECT_NEAR(w.point_b.x(), 2.5, 1e-12);
  EXPECT_NEAR(w.point_b.y(), 0.0, 1e-12);
}

TEST(SceneClearance, OnlyPairsStrictlyCloserThanTheWarningDistanceAreReported) {
  // 1.5 m apart (exact in binary): warned at 1.5 + 1e-9, not at 1.5 or below.
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0),
                                           circle("box", EllipseRole::Obstacle, 3.0, 0.0, 0.5)};
  EXPECT_EQ(checkScene(scene, warnWithin(1.5 + 1e-9)).warnings.size(), 1u);
  EXPECT_TRUE(checkScene(scene, warnWithin(1.5 - 1e-9)).warnings.empty());
  EXPECT_TRUE(checkScene(scene, warnWithin(1.0)).warnings.empty());
}

TEST(SceneClearance, PairsRightAtTheBoundOfTheirCirclesAgreeWithDistance) {
  // For circles the bound (centre distance minus radii) is the distance itself: with the warning
  // distance set to it, whether the pair is reported is up to the last bits of distance(), and
  // ruling it out by the bound alone would disagree whenever distance() rounds below it.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  std::uniform_real_distribution<double> radius(0.01, 3.0);
  int reported = 0;
  for (int i = 0; i < 20000; ++i) {
    const NamedEllipse a =
        circle("a", EllipseRole::Link, coordinate(rng), coordinate(rng), radius(rng));
    const NamedEllipse b =
        circle("b", EllipseRole::Obstacle, coordinate(rng), coordinate(rng), radius(rng));
    const double bound =
        (b.ellipse.center - a.ellipse.center).norm() - a.ellipse.radius_x - b.ellipse.radius_x;
    if (bound <= 0.0) continue;
    const Clearance expected = distance(a.ellipse, b.ellipse);
    const bool expect_warning = expected.separated && expected.distance < bound;
    const SceneCheckResult result = checkScene({a, b}, warnWithin(bound));
    ASSERT_EQ(result.warnings.size(), expect_warning ? 1u : 0u) << "pair " << i;
    reported += expect_warning;
  }
  EXPECT_GT(reported, 0);
}

TEST(SceneClearance, ElongatedEllipseIsMeasuredNotJudgedByItsNarrowSide) {
  // Upright 1 x 0.2 ellipse; a 0.25 m circle 1.5 m above its centre is 0.25 m from its tip. Its
  // inscribed circle (0.2 m) would put the pair 1.05 m apart; the horizontal twin really is.
  const NamedEllipse circle_above = circle("box", EllipseRole::Obstacle, 0.0, 1.5, 0.25);
  const SceneCheckResult upright =
      checkScene({ellipse("arm", EllipseRole::Link, 0.0, 0.0, 1.0, 0.2, M_PI / 2), circle_above},
                 warnWithin(0.3));
  ASSERT_EQ(upright.warnings.size(), 1u);
  EXPECT_NEAR(upright.warnings[0].distance, 0.25, 1e-12);
  EXPECT_NEAR(upright.warnings[0].point_a.y(), 1.0, 1e-12);
  EXPECT_NEAR(upright.warnings[0].point_b.y(), 1.25, 1e-12);
  EXPECT_NEAR(upright.warnings[0].point_a.x(), 0.0, 1e-12);

  const SceneCheckResult flat = checkScene(
      {ellipse("arm", EllipseRole::Link, 0.0, 0.0, 1.0, 0.2, 0.0), circle_above}, warnWithin(0.3));
  EXPECT_TRUE(flat.warnings.empty());
  EXPECT_EQ(checkScene({ellipse("arm", EllipseRole::Link, 0.0, 0.0, 1.0, 0.2, 0.0), circle_above},
                       warnWithin(1.1))
                .warnings.size(),
            1u);
}

TEST(SceneClearance, OverlappingPairIsACollisionAndNeverAWarning) {
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0),
                                           circle("box", EllipseRole::Obstacle, 1.5, 0.0, 1.0)};
  const SceneCheckResult result = checkScene(scene, warnWithin(10.0));
  EXPECT_EQ(result.collisions.size(), 1u);
  EXPECT_TRUE(result.warnings.empty());
}

TEST(SceneClearance, WarningsFollowThePairRules) {
  // 0.5 m circles: neighbours along each line are 0.5 m apart, diagonal ones 1.12 m.
  //   q2
  //   q  l1  l2  o1
  //              o2 above o1
  const std::vector<NamedEllipse> scene = {circle("q", EllipseRole::Query, 0.0, 0.0, 0.5),
                                           circle("q2", EllipseRole::Query, 0.0, 1.5, 0.5),
                                           circle("l1", EllipseRole::Link, 1.5, 0.0, 0.5),
                                           circle("l2", EllipseRole::Link, 3.0, 0.0, 0.5),
                                           circle("o1", EllipseRole::Obstacle, 4.5, 0.0, 0.5),
                                           circle("o2", EllipseRole::Obstacle, 4.5, 1.5, 0.5)};
  SceneRules rules = warnWithin(0.6);
  // Never query-query (q, q2) nor obstacle-obstacle (o1, o2).
  EXPECT_EQ(namesOf(checkScene(scene, rules).warnings),
            (Names{{"q", "l1"}, {"l1", "l2"}, {"l2", "o1"}}));
  EXPECT_EQ(namesOf(checkScene(scene, rules, {"o1"}).warnings), (Names{{"l2", "o1"}}));
  EXPECT_TRUE(checkScene(scene, rules, {"q2"}).warnings.empty());
  rules.self_collision = false;
  EXPECT_EQ(namesOf(checkScene(scene, rules).warnings), (Names{{"q", "l1"}, {"l2", "o1"}}));
  rules.self_collision = true;
  rules.allowed.add("o1", "l2");
  EXPECT_EQ(namesOf(checkScene(scene, rules).warnings), (Names{{"q", "l1"}, {"l1", "l2"}}));
}

TEST(SceneClearance, ZeroWarningDistanceReportsNoWarnings) {
  const std::vector<NamedEllipse> scene = {
      circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0),
      circle("box", EllipseRole::Obstacle, 2.0 + 1e-12, 0.0, 1.0)};
  EXPECT_TRUE(checkScene(scene, SceneRules{}).warnings.empty());
  EXPECT_EQ(checkScene(scene, warnWithin(1e-9)).warnings.size(), 1u);
}

TEST(SceneClearance, NegativeOrNonFiniteWarningDistanceIsRefused) {
  const std::vector<NamedEllipse> scene = {circle("arm", EllipseRole::Link, 0.0, 0.0, 1.0)};
  const std::pair<double, const char*> cases[] = {
      {-0.5, "warning_distance = -0.5"},
      {std::numeric_limits<double>::quiet_NaN(), "warning_distance = nan"},
      {std::numeric_limits<double>::infinity(), "warning_distance = inf"}};
  for (const auto& [value, message] : cases) {
    const SceneCheckResult result = checkScene(scene, warnWithin(value));
    EXPECT_FALSE(result.ok()) << message;
    EXPECT_NE(result.error.find(message), std::string::npos) << result.error;
    const NearestResult nearest = nearestTo(scene, warnWithin(value), "arm");
    EXPECT_NE(nearest.error.find(message), std::string::npos) << nearest.error;
  }
}

// ---- nearestTo()

TEST(NearestTo, MatchesBruteForceOverDistanceOnRandomScenes) {
  std::mt19937 rng(99);
  int found = 0;
  int colliding = 0;
  for (int round = 0; round < 300; ++round) {
    const std::vector<NamedEllipse> scene = randomScene(rng, 12);
    const BruteRules rules = randomRules(rng, scene);
    for (const NamedEllipse& e : scene) {
      const NearestResult actual = nearestTo(scene, rules.sceneRules(), e.name);
      ASSERT_TRUE(actual.ok()) << actual.error;
      const NearestResult expected = bruteNearest(scene, rules, e.name);
      const std::string where = "round " + std::to_string(round) + ", " + e.name;
      ASSERT_EQ(actual.found, expected.found) << where;
      if (!expected.found) continue;
      expectSamePair(actual.nearest, expected.nearest, where);
      ++found;
      if (expected.nearest.distance == 0.0) ++colliding;
    }
  }
  EXPECT_GT(found, 2000);
  EXPECT_GT(colliding, 200);
  EXPECT_GT(found - colliding, 1000);
}

}  // namespace
}  // namespace ellipse_collision::core

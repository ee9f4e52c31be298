// checkScene() finds its candidate pairs with a broadphase; these tests hold it to a brute force
// written here that calls overlap(), contactScale() and distance() on every pair the rules want:
// the same pairs in the same order with the same bits, warnings included, on random scenes from
// sparse to dense, with queries, name filters and allowed pairs, and far fewer exact pair tests;
// with either culling kernel of the narrow phase (scene_check_detail.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <numeric>
#include <random>
#include <tuple>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/scene_check.h"
#include "brute_force_scene.h"
#include "scene_check_detail.h"
#include "scene_test_helpers.h"

namespace ellipse_collision::core {
namespace {

SceneCheckResult bruteForce(const std::vector<NamedEllipse>& scene, const SceneRules& rules,
                            const std::set<std::string>& only_names) {
  return test::bruteForceScene(scene, rules, only_names);
}

using detail::BatchKernel;

/// The scene checked the node's way when its obstacles stay put: obstacles gridded once
/// (IndexedObstacles), the queries and links looked up in that grid; the narrow phase culling
/// with `kernel`.
SceneCheckResult checkIndexed(const std::vector<NamedEllipse>& scene, const SceneRules& rules,
                              const std::set<std::string>& only_names,
                              BatchKernel kernel = BatchKernel::Automatic) {
  std::vector<NamedEllipse> movers, obstacles;
  for (const NamedEllipse& entry : scene) {
    (entry.role == EllipseRole::Obstacle ? obstacles : movers).push_back(entry);
  }
  return detail::checkMoversAgainstWith(kernel, movers, IndexedObstacles(std::move(obstacles)),
                                        rules, only_names);
}

/// The scene checked the node's way when its obstacles move: movers first, vouched for.
SceneCheckResult checkValidated(const std::vector<NamedEllipse>& scene, const SceneRules& rules,
                                const std::set<std::string>& only_names,
                                BatchKernel kernel = BatchKernel::Automatic) {
  std::vector<NamedEllipse> ordered = scene;
  const auto first_obstacle =
      std::stable_partition(ordered.begin(), ordered.end(), [](const NamedEllipse& entry) {
        return entry.role != EllipseRole::Obstacle;
      });
  return detail::checkValidatedSceneWith(
      kernel, Scene(ordered), static_cast<std::size_t>(first_obstacle - ordered.begin()), rules,
      only_names);
}

bool sameBits(double x, double y) { return std::memcmp(&x, &y, sizeof(double)) == 0; }

/// Exactly the same answer: names, order and every bit of every number.
void expectSame(const SceneCheckResult& actual, const SceneCheckResult& expected,
                const std::string& label) {
  ASSERT_TRUE(actual.ok()) << label << ": " << actual.error;
  ASSERT_EQ(actual.collisions.size(), expected.collisions.size()) << label;
  for (std::size_t i = 0; i < expected.collisions.size(); ++i) {
    const CollidingPair& p = actual.collisions[i];
    const CollidingPair& q = expected.collisions[i];
    EXPECT_EQ(p.name_a, q.name_a) << label << " collision " << i;
    EXPECT_EQ(p.name_b, q.name_b) << label << " collision " << i;
    EXPECT_TRUE(sameBits(p.contact_scale, q.contact_scale))
        << label << " " << p.name_a << "/" << p.name_b << ": " << p.contact_scale << " vs "
        << q.contact_scale;
  }
  ASSERT_EQ(actual.warnings.size(), expected.warnings.size()) << label;
  for (std::size_t i = 0; i < expected.warnings.size(); ++i) {
    const NearPair& p = actual.warnings[i];
    const NearPair& q = expected.warnings[i];
    EXPECT_EQ(p.name_a, q.name_a) << label << " warning " << i;
    EXPECT_EQ(p.name_b, q.name_b) << label << " warning " << i;
    EXPECT_TRUE(sameBits(p.distance, q.distance) && sameBits(p.point_a.x(), q.point_a.x()) &&
                sameBits(p.point_a.y(), q.point_a.y()) && sameBits(p.point_b.x(), q.point_b.x()) &&
                sameBits(p.point_b.y(), q.point_b.y()))
        << label << " " << p.name_a << "/" << p.name_b;
  }
}

/// Pairs the rules want, whatever the geometry: what an all-pairs check would test.
std::size_t wantedPairs(const std::vector<NamedEllipse>& scene, const SceneRules& rules,
                        const std::set<std::string>& only_names) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    for (std::size_t j = i + 1; j < scene.size(); ++j) {
      count += pairWanted(scene[i], scene[j], rules, only_names);
    }
  }
  return count;
}

struct SceneShape {
  int queries;
  int links;
  int obstacles;
  double links_half_width;      ///< links' centres in [-w, w]^2 [m]
  double obstacles_half_width;  ///< obstacles' centres in [-w, w]^2 [m]
  double max_major;             ///< [m]
};

/// Ellipses of every role, with names that do not follow their roles (so the reporting order is
/// not the input order), axis ratios up to 20 and any angle.
std::vector<NamedEllipse> randomScene(std::mt19937_64& rng, const SceneShape& shape) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int count = shape.queries + shape.links + shape.obstacles;
  std::vector<int> labels(static_cast<std::size_t>(count));
  std::iota(labels.begin(), labels.end(), 0);
  std::shuffle(labels.begin(), labels.end(), rng);
  std::vector<NamedEllipse> scene;
  for (int i = 0; i < count; ++i) {
    NamedEllipse e;
    e.name = "e" + std::to_string(labels[static_cast<std::size_t>(i)]);
    e.role = i < shape.queries
                 ? EllipseRole::Query
                 : (i < shape.queries + shape.links ? EllipseRole::Link : EllipseRole::Obstacle);
    const double half_width =
        e.role == EllipseRole::Obstacle ? shape.obstacles_half_width : shape.links_half_width;
    e.ellipse.center =
        Eigen::Vector2d(half_width * (2.0 * unit(rng) - 1.0), half_width * (2.0 * unit(rng) - 1.0));
    const double major = shape.max_major * std::pow(1e-2, unit(rng));  // log-uniform, 2 decades
    e.ellipse.radius_x = major;
    e.ellipse.radius_y = major / std::pow(20.0, unit(rng));
    e.ellipse.angle = 6.283185307179586 * unit(rng) - 3.141592653589793;
    scene.push_back(e);
  }
  std::shuffle(scene.begin(), scene.end(), rng);
  return scene;
}

TEST(SceneBroadphase, MatchesBruteForceOnRandomScenesWithRulesAndWarnings) {
  std::mt19937_64 rng(20240607);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t collisions = 0, warnings = 0, allowed_hits = 0, filtered = 0;
  // Sparse and dense, few movers (the grid's plain list) and more than 64 (its cells).
  const SceneShape shapes[] = {{0, 8, 40, 1.0, 10.0, 1.0},     {2, 20, 200, 2.0, 20.0, 0.8},
                               {3, 50, 300, 1.0, 25.0, 0.5},   {5, 80, 150, 5.0, 5.0, 0.6},
                               {0, 120, 0, 3.0, 3.0, 0.5},     {10, 60, 400, 2.0, 4.0, 1.5},
                               {4, 100, 500, 20.0, 20.0, 2.0}, {1, 3, 1000, 0.5, 50.0, 0.3}};
  const double warning_distances[] = {0.0, 0.02, 0.3, 2.0};
  for (int trial = 0; trial < 64; ++trial) {
    const SceneShape& shape = shapes[trial % 8];
    const std::vector<NamedEllipse> scene = randomScene(rng, shape);
    SceneRules rules;
    rules.self_collision = trial % 3 != 0;
    rules.warning_distance = warning_distances[(trial / 8) % 4];
    std::set<std::string> only_names;
    std::uniform_int_distribution<std::size_t> pick(0, scene.size() - 1);
    if (trial % 4 == 1) {
      for (int k = 0; k < 5; ++k) only_names.insert(scene[pick(rng)].name);
      only_names.insert("not_in_scene");
    }
    // Allow some pairs that really collide or warn, so that the rule is put to the test.
    const SceneCheckResult unrestricted = bruteForce(scene, rules, only_names);
    if (trial % 2 == 0) {
      for (std::size_t i = 0; i < unrestricted.collisions.size(); i += 3) {
        rules.allowed.add(unrestricted.collisions[i].name_b, unrestricted.collisions[i].name_a);
      }
      for (std::size_t i = 0; i < unrestricted.warnings.size(); i += 3) {
        rules.allowed.add(unrestricted.warnings[i].name_a, unrestricted.warnings[i].name_b);
      }
      for (int k = 0; k < 10; ++k) rules.allowed.add(scene[pick(rng)].name, scene[pick(rng)].name);
    }

    const SceneCheckResult expected = bruteForce(scene, rules, only_names);
    const SceneCheckResult actual = checkScene(scene, rules, only_names);
    expectSame(actual, expected, "trial " + std::to_string(trial));
    if (HasFatalFailure()) return;
    // The entry point for scenes the node vouches for: the same bits.
    const SceneCheckResult vouched = checkValidated(scene, rules, only_names);
    expectSame(vouched, expected, "checkValidatedScene, trial " + std::to_string(trial));
    if (HasFatalFailure()) return;
    expectSame(checkValidated(scene_test::inRegistryOrder(scene), rules, only_names), expected,
               "checkValidatedScene in registry order, trial " + std::to_string(trial));
    if (HasFatalFailure()) return;
    // The obstacles gridded instead of streamed: the same bits and the same pairs tested.
    const SceneCheckResult indexed = checkIndexed(scene, rules, only_names);
    expectSame(indexed, expected, "checkMoversAgainst, trial " + std::to_string(trial));
    if (HasFatalFailure()) return;
    EXPECT_EQ(indexed.pair_tests, vouched.pair_tests) << "trial " << trial;
    collisions += expected.collisions.size();
    warnings += expected.warnings.size();
    allowed_hits += unrestricted.collisions.size() + unrestricted.warnings.size() -
                    expected.collisions.size() - expected.warnings.size();
    filtered += only_names.empty() ? 0 : 1;
  }
  // Not vacuous: many collisions and warnings, and the allowed pairs removed real ones.
  std::cout << "[          ] " << collisions << " collisions, " << warnings << " warnings, "
            << allowed_hits << " allowed away\n";
  EXPECT_GT(collisions, 400u);
  EXPECT_GT(warnings, 400u);
  EXPECT_GT(allowed_hits, 100u);
  EXPECT_EQ(filtered, 16u);
}

/// Obstacles that put the narrow phase's culling to the test, one per mover of `scene`: within
/// a few ulps of tangency (the offset of a random placement divided by its contact scale, so that
/// the bounding circles meet and only the exact stages decide), deep inside (the inscribed
/// circles meet: decided by the culling alone) or between the two circles' reach.
void addNearObstacles(std::mt19937_64& rng, std::vector<NamedEllipse>* scene) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t count = scene->size();
  for (std::size_t i = 0; i < count; ++i) {
    const NamedEllipse mover = (*scene)[i];
    if (mover.role == EllipseRole::Obstacle) continue;
    Ellipse obstacle = mover.ellipse;
    obstacle.radius_x = boundingRadius(mover.ellipse) * (0.2 + 2.0 * unit(rng));
    obstacle.radius_y = obstacle.radius_x / (1.0 + 9.0 * unit(rng));
    obstacle.angle = 6.283185307179586 * unit(rng) - 3.141592653589793;
    const double direction = 6.283185307179586 * unit(rng);
    const Eigen::Vector2d unit_offset(std::cos(direction), std::sin(direction));
    const double reach = boundingRadius(mover.ellipse) + boundingRadius(obstacle);
    const double inner = inscribedRadius(mover.ellipse) + inscribedRadius(obstacle);
    const int kind = static_cast<int>(i % 3);
    if (kind == 0) {
      obstacle.center = mover.ellipse.center + reach * unit_offset;
      const double scale = contactScale(mover.ellipse, obstacle);
      const double nudge = 1.0 + (unit(rng) - 0.5) * 1e-14;
      obstacle.center = mover.ellipse.center + (reach / scale * nudge) * unit_offset;
    } else if (kind == 1) {
      obstacle.center = mover.ellipse.center + (0.9 * inner * unit(rng)) * unit_offset;
    } else {
      obstacle.center = mover.ellipse.center + (inner + (reach - inner) * unit(rng)) * unit_offset;
    }
    scene->push_back({"near_" + mover.name, EllipseRole::Obstacle, obstacle});
  }
}

TEST(SceneBroadphase, NarrowPhaseOfEveryKernelAnswersAsPlainPairTests) {
  // The narrow phase gathers the candidate pairs a block at a time, culls them without a
  // branch per pair and sends only the open ones to the exact stages: every kernel, every entry
  // point, the same bits as overlap(), contactScale() and distance() on each pair. Scenes from
  // one mover to hundreds (one obstacle meeting 300 links: its pairs span several blocks), sparse
  // and crowded (thousands of pairs per check), with pairs near tangency and deep inside.
  std::vector<BatchKernel> kernels{BatchKernel::Automatic, BatchKernel::Portable};
  if (detail::avx2Supported()) kernels.push_back(BatchKernel::Avx2);
  std::mt19937_64 rng(31415);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const SceneShape shapes[] = {{0, 1, 30, 1.0, 2.0, 1.0},      {1, 7, 3, 1.0, 1.0, 0.5},
                               {2, 40, 1500, 2.0, 3.0, 0.4},   {0, 70, 600, 3.0, 3.0, 0.8},
                               {3, 20, 4000, 1.0, 25.0, 0.6},  {0, 300, 0, 2.0, 2.0, 0.3}};
  const double warning_distances[] = {0.0, 0.05, 0.6};
  std::size_t collisions = 0, warnings = 0, max_pair_tests = 0;
  for (int trial = 0; trial < 18; ++trial) {
    const SceneShape& shape = shapes[trial % 6];
    std::vector<NamedEllipse> scene = randomScene(rng, shape);
    addNearObstacles(rng, &scene);
    if (shape.obstacles == 0) {
      // One obstacle over every link.
      scene.push_back({"slab", EllipseRole::Obstacle, {Eigen::Vector2d(0, 0), 3.5, 3.0, 0.2}});
    }
    SceneRules rules;
    rules.self_collision = trial % 4 != 3;
    rules.warning_distance = warning_distances[(trial / 6) % 3];
    std::set<std::string> only_names;
    if (trial % 5 == 2) {
      std::uniform_int_distribution<std::size_t> pick(0, scene.size() - 1);
      for (int k = 0; k < 6; ++k) only_names.insert(scene[pick(rng)].name);
      only_names.insert("near_e0");
    }
    const SceneCheckResult expected = bruteForce(scene, rules, only_names);
    std::size_t pair_tests = 0;
    for (const BatchKernel kernel : kernels) {
      const std::string label = "trial " + std::to_string(trial) + ", kernel " +
                                std::to_string(static_cast<int>(kernel));
      const SceneCheckResult named = detail::checkSceneWith(kernel, scene, rules, only_names);
      expectSame(named, expected, "checkScene, " + label);
      if (HasFatalFailure()) return;
      const SceneCheckResult vouched = checkValidated(scene, rules, only_names, kernel);
      expectSame(vouched, expected, "checkValidatedScene, " + label);
      if (HasFatalFailure()) return;
      const SceneCheckResult indexed = checkIndexed(scene, rules, only_names, kernel);
      expectSame(indexed, expected, "checkMoversAgainst, " + label);
      if (HasFatalFailure()) return;
      // Each pair the broadphase leaves is tested once, whichever the kernel or entry point.
      if (pair_tests == 0) pair_tests = named.pair_tests;
      EXPECT_EQ(named.pair_tests, pair_tests) << label;
      EXPECT_EQ(vouched.pair_tests, pair_tests) << label;
      EXPECT_EQ(indexed.pair_tests, pair_tests) << label;
    }
    collisions += expected.collisions.size();
    warnings += expected.warnings.size();
    max_pair_tests = std::max(max_pair_tests, pair_tests);
  }
  std::cout << "[          ] " << collisions << " collisions, " << warnings
            << " warnings, at most " << max_pair_tests << " pair tests in one check\n";
  EXPECT_GT(collisions, 2000u);
  EXPECT_GT(warnings, 500u);
  EXPECT_GT(max_pair_tests, 1000u);  // many blocks of the narrow phase
}

TEST(SceneBroadphase, AnIndexReusedOverManyChecksAnswersAsPlainPairTests) {
  // The node builds IndexedObstacles once while its obstacles stand and checks moving links
  // against it check after check; the index prepares each obstacle and keeps its culling columns
  // once, for all of them. Every check, whatever its movers, kernel and rules, must answer the
  // same bits as plain pair tests: a robot among obstacles placed at tangency, deep inside and
  // between its circles, the same robot moved a little, and other movers few and many.
  std::vector<BatchKernel> kernels{BatchKernel::Automatic, BatchKernel::Portable};
  if (detail::avx2Supported()) kernels.push_back(BatchKernel::Avx2);
  std::mt19937_64 rng(271828);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<NamedEllipse> obstacles = randomScene(rng, {0, 0, 1500, 0.0, 6.0, 0.5});
  const std::vector<NamedEllipse> robot = randomScene(rng, {2, 30, 0, 2.0, 0.0, 0.6});
  std::vector<NamedEllipse> robot_and_near = robot;
  addNearObstacles(rng, &robot_and_near);
  for (const NamedEllipse& entry : robot_and_near) {
    if (entry.role == EllipseRole::Obstacle) obstacles.push_back(entry);
  }
  // At the edges of the two circle tests the index's columns decide: per link an obstacle with
  // its minor axis facing the link's on one line, a thousandth beyond the inscribed circles'
  // reach (apart: each ellipse keeps to its side of the line's normal through its minor axis'
  // tip), and one with its major axis facing the link's, a thousandth within the bounding
  // circles' reach (they overlap: each holds its major axis' tip).
  for (const NamedEllipse& link : robot) {
    const Ellipse& e = link.ellipse;
    const double direction = e.radius_y <= e.radius_x ? e.angle + 1.5707963267948966 : e.angle;
    const double other = direction + 1.5707963267948966;
    const Eigen::Vector2d minor_axis(std::cos(direction), std::sin(direction));
    const Eigen::Vector2d major_axis(std::cos(other), std::sin(other));
    const double minor = inscribedRadius(e), major = boundingRadius(e);
    Ellipse apart{{0, 0}, 0, 0, direction};
    apart.radius_x = minor * (0.5 + unit(rng));  // along the line: its minor axis
    apart.radius_y = apart.radius_x * (1.5 + 3.0 * unit(rng));
    apart.center = e.center + (minor + apart.radius_x) * (1.0 + 1e-3 * (0.1 + unit(rng))) * minor_axis;
    obstacles.push_back({"apart_" + link.name, EllipseRole::Obstacle, apart});
    Ellipse touching{{0, 0}, 0, 0, other};
    touching.radius_x = major * (0.5 + unit(rng));  // along the line: its major axis
    touching.radius_y = touching.radius_x / (1.5 + 3.0 * unit(rng));
    touching.center =
        e.center + (major + touching.radius_x) * (1.0 - 1e-3 * (0.1 + unit(rng))) * major_axis;
    obstacles.push_back({"touching_" + link.name, EllipseRole::Obstacle, touching});
  }
  const IndexedObstacles index(obstacles);
  ASSERT_TRUE(index.error().empty()) << index.error();
  const SceneShape mover_shapes[] = {{1, 10, 0, 1.0, 0.0, 0.6},
                                     {0, 50, 0, 3.0, 0.0, 0.8},
                                     {3, 80, 0, 6.0, 0.0, 0.4},
                                     {0, 1, 0, 5.0, 0.0, 2.0}};
  const double warning_distances[] = {0.0, 0.05, 0.4};
  std::size_t collisions = 0, warnings = 0;
  for (int check = 0; check < 24; ++check) {
    std::vector<NamedEllipse> movers;
    if (check % 3 == 0) {
      // The robot, moved by up to a centimetre from where the near obstacles were placed.
      movers = robot;
      const Eigen::Vector2d shift(0.01 * (unit(rng) - 0.5), 0.01 * (unit(rng) - 0.5));
      for (NamedEllipse& mover : movers) {
        if (check > 0) mover.ellipse.center += shift;
      }
    } else {
      movers = randomScene(rng, mover_shapes[check % 4]);
    }
    for (NamedEllipse& mover : movers) mover.name = "m" + mover.name;  // apart from obstacles'
    SceneRules rules;
    rules.self_collision = check % 4 != 1;
    rules.warning_distance = warning_distances[check % 3];
    std::set<std::string> only_names;
    if (check % 5 == 4) {
      for (int k = 0; k < 4; ++k) only_names.insert(movers[rng() % movers.size()].name);
      only_names.insert(obstacles[rng() % obstacles.size()].name);
    }
    std::vector<NamedEllipse> scene = movers;
    scene.insert(scene.end(), obstacles.begin(), obstacles.end());
    const SceneCheckResult expected = bruteForce(scene, rules, only_names);
    const SceneCheckResult vouched = checkValidated(scene, rules, only_names);
    for (const BatchKernel kernel : kernels) {
      const std::string label = "check " + std::to_string(check) + ", kernel " +
                                std::to_string(static_cast<int>(kernel));
      const SceneCheckResult indexed =
          detail::checkMoversAgainstWith(kernel, movers, index, rules, only_names);
      expectSame(indexed, expected, label);
      if (HasFatalFailure()) return;
      EXPECT_EQ(indexed.pair_tests, vouched.pair_tests) << label;
    }
    collisions += expected.collisions.size();
    warnings += expected.warnings.size();
  }
  std::cout << "[          ] " << collisions << " collisions, " << warnings << " warnings\n";
  EXPECT_GT(collisions, 1000u);
  EXPECT_GT(warnings, 300u);
}

TEST(SceneBroadphase, WarningsAtTheWarningDistanceMatchBruteForce) {
  // Obstacles placed so that their gap to a link is the warning distance give or take a few
  // ulps, in every direction: distance() decides, and the boxes must not have decided first.
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double warning_distance : {1e-3, 0.25, 3.0}) {
    std::vector<NamedEllipse> scene;
    for (int i = 0; i < 70; ++i) {  // more than 64 links: the grid's cells, not its plain list
      const double radius = 0.05 + 0.1 * unit(rng);
      const Eigen::Vector2d centre(20.0 * unit(rng), 20.0 * unit(rng));
      scene.push_back({"link" + std::to_string(i), EllipseRole::Link, {centre, radius, radius, 0}});
      const double direction = 6.283185307179586 * unit(rng);
      const double obstacle_radius = 0.02 + 0.3 * unit(rng);
      const double gap = warning_distance * (1.0 + (unit(rng) - 0.5) * 4e-15);
      const Eigen::Vector2d offset = (radius + obstacle_radius + gap) *
                                     Eigen::Vector2d(std::cos(direction), std::sin(direction));
      scene.push_back({"obstacle" + std::to_string(i),
                       EllipseRole::Obstacle,
                       {centre + offset, obstacle_radius, obstacle_radius, 0}});
    }
    SceneRules rules;
    rules.self_collision = false;
    rules.warning_distance = warning_distance;
    const SceneCheckResult expected = bruteForce(scene, rules, {});
    expectSame(checkScene(scene, rules), expected, "w = " + std::to_string(warning_distance));
    expectSame(checkIndexed(scene, rules, {}), expected,
               "checkMoversAgainst, w = " + std::to_string(warning_distance));
    expectSame(checkValidated(scene, rules, {}), expected,
               "checkValidatedScene, w = " + std::to_string(warning_distance));
    // The gaps fall on either side of the warning distance.
    std::size_t placed = 0;
    for (const NearPair& pair : expected.warnings) {
      placed += pair.name_a.substr(4) == pair.name_b.substr(8);
    }
    std::cout << "[          ] w = " << warning_distance << ": " << placed << " of 70\n";
    EXPECT_GT(placed, 5u);
    EXPECT_LT(placed, 65u);
  }
}

TEST(SceneBroadphase, WarningIsFoundBeyondTheLinksBox) {
  // The obstacle's box is 0.5 m from the link's box; only the warning distance joins them.
  const std::vector<NamedEllipse> scene = {
      {"arm", EllipseRole::Link, {Eigen::Vector2d(0, 0), 1.0, 0.2, 0.0}},
      {"crate", EllipseRole::Obstacle, {Eigen::Vector2d(2.0, 0), 0.5, 0.5, 0.0}},
      {"wall", EllipseRole::Obstacle, {Eigen::Vector2d(0, 5.0), 0.5, 0.5, 0.0}}};
  SceneRules rules;
  rules.warning_distance = 0.6;
  const SceneCheckResult result = checkScene(scene, rules);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].name_b, "crate");
  EXPECT_NEAR(result.warnings[0].distance, 0.5, 1e-12);
  EXPECT_EQ(result.pair_tests, 1u);  // the wall is too far for the boxes
}

TEST(SceneBroadphase, CountsEveryWantedPairWhenAllBoxesOverlap) {
  // Everything at the origin: the broadphase can rule nothing out, so the exact test runs on
  // every wanted pair: 3 x 4 link-obstacle, 3 link-link, 2 x 7 query; not query-query.
  std::vector<NamedEllipse> scene;
  for (int i = 0; i < 3; ++i) {
    scene.push_back({"l" + std::to_string(i), EllipseRole::Link, {Eigen::Vector2d(0, 0), 1, 1, 0}});
  }
  for (int i = 0; i < 4; ++i) {
    scene.push_back(
        {"o" + std::to_string(i), EllipseRole::Obstacle, {Eigen::Vector2d(0.1 * i, 0), 1, 1, 0}});
  }
  for (int i = 0; i < 2; ++i) {
    scene.push_back(
        {"q" + std::to_string(i), EllipseRole::Query, {Eigen::Vector2d(0, 0), 1, 1, 0}});
  }
  SceneRules rules;
  const SceneCheckResult result = checkScene(scene, rules);
  EXPECT_EQ(result.pair_tests, 12u + 3u + 14u);
  EXPECT_EQ(result.collisions.size(), 29u);
  rules.self_collision = false;
  EXPECT_EQ(checkScene(scene, rules).pair_tests, 12u + 14u);
}

TEST(SceneBroadphase, PairsAreInNameOrderWhateverTheNamesFirstBytes) {
  // The movers are ranked on their names' first 8 bytes before the whole names: names that tie
  // there, are prefixes of each other, hold a NUL or bytes above 127 must still come in
  // std::string order, as the brute force sorts them.
  const std::vector<std::string> names = {"a", "ab", std::string("ab\0", 3), std::string("ab\0c", 4),
                                          "abcdefgh1", "abcdefgh0", "abcdefgh", "\xff", "\x80x",
                                          "Z", "link_10", "link_9", "", "b"};
  std::vector<NamedEllipse> scene;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) continue;
    scene.push_back({names[i], i % 3 == 0 ? EllipseRole::Query : EllipseRole::Link,
                     {Eigen::Vector2d(0.01 * static_cast<double>(i), 0), 1, 1, 0}});
  }
  scene.push_back({"rock", EllipseRole::Obstacle, {Eigen::Vector2d(0.5, 0), 1, 1, 0}});
  scene.push_back({"rock2", EllipseRole::Obstacle, {Eigen::Vector2d(0.5, 0.1), 1, 1, 0}});
  // Far away, one link among 40 obstacles in shuffled name order: a mover with more pairs than
  // the insertion sort takes.
  scene.push_back({"far_link", EllipseRole::Link, {Eigen::Vector2d(100, 0), 1, 1, 0}});
  std::mt19937_64 rng(5);
  for (int i = 0; i < 40; ++i) {
    scene.push_back({"pile_" + std::to_string(rng() % 1000) + "_" + std::to_string(i),
                     EllipseRole::Obstacle, {Eigen::Vector2d(100.0 + 0.01 * i, 0.5), 1, 1, 0}});
  }
  SceneRules rules;
  const SceneCheckResult expected = bruteForce(scene, rules, {});
  ASSERT_GT(expected.collisions.size(), 120u);
  expectSame(checkScene(scene, rules), expected, "checkScene");
  expectSame(checkValidated(scene, rules, {}), expected, "checkValidatedScene");
  expectSame(checkIndexed(scene, rules, {}), expected, "checkMoversAgainst");
}

TEST(SceneBroadphase, FiftyLinksAmongTenThousandObstaclesTestFewPairs) {
  // A robot of 50 links within 1 m of its centre in a 50 m x 50 m warehouse.
  std::mt19937_64 rng(4242);
  const SceneShape shape{2, 50, 10000, 1.0, 25.0, 0.6};
  const std::vector<NamedEllipse> scene = randomScene(rng, shape);
  for (const double warning_distance : {0.0, 0.5}) {
    SceneRules rules;
    rules.warning_distance = warning_distance;
    const SceneCheckResult expected = bruteForce(scene, rules, {});
    const SceneCheckResult actual = checkScene(scene, rules);
    const std::string label = "w = " + std::to_string(warning_distance);
    expectSame(actual, expected, label);
    EXPECT_GT(expected.collisions.size(), 20u) << label;
    const std::size_t all_pairs = wantedPairs(scene, rules, {});
    EXPECT_GT(all_pairs, 500000u);
    // The ellipses near the robot and no more: under 1 % of the pairs an all-pairs check tests.
    EXPECT_LT(actual.pair_tests, all_pairs / 100) << label;
    EXPECT_GE(actual.pair_tests, actual.collisions.size() + actual.warnings.size()) << label;
    std::cout << "[          ] " << label << ": " << actual.pair_tests << " exact pair tests of "
              << all_pairs << " wanted pairs, " << actual.collisions.size() << " collisions, "
              << actual.warnings.size() << " warnings\n";
  }
}

TEST(SceneBroadphase, IndexedObstaclesRefuseBadEntriesAndTheCheckSaysSo) {
  const Ellipse bad{{0.0, 0.0}, -1.0, 1.0, 0.0};
  const IndexedObstacles refused({{"crate", EllipseRole::Obstacle, {{1, 0}, 1, 1, 0}},
                                  {"rock", EllipseRole::Obstacle, bad}});
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

TEST(SceneBroadphase, IndexedObstaclesWithinAreTheScansObstaclesEvenOnTheBoundary) {
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

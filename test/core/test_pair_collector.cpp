// The narrow phase of the scene checks (src/core/pair_collector.h) driven by hand: every
// mover-obstacle pair given to a PairCollector, over many blocks of pairs and with either culling
// kernel, answers as the brute force over overlap(), contactScale() and distance()
// (test/support/brute_force_scene.h), bit for bit, whatever order the pairs come in.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "brute_force_scene.h"
#include "pair_collector.h"

namespace ellipse_collision::core::detail {
namespace {

std::vector<NamedEllipse> randomEntries(std::mt19937_64& rng, const std::string& prefix,
                                        EllipseRole role, int count, double spread) {
  std::uniform_real_distribution<double> coordinate(-spread, spread), radius(0.05, 0.8),
      angle(-3.0, 3.0);
  std::vector<NamedEllipse> entries;
  for (int i = 0; i < count; ++i) {
    entries.push_back(
        {prefix + std::to_string(i), role,
         Ellipse{{coordinate(rng), coordinate(rng)}, radius(rng), radius(rng), angle(rng)}});
  }
  return entries;
}

SceneCheckResult collect(BatchKernel kernel, double warning_distance,
                         const std::vector<NamedEllipse>& links,
                         const std::vector<NamedEllipse>& obstacles, bool obstacle_major) {
  Movers movers;
  movers.reserve(links.size());
  for (const NamedEllipse& link : links) movers.add(refOf(link), warning_distance);
  PairCollector collector(kernel, warning_distance, movers);
  if (obstacle_major) {  // each obstacle's pairs side by side, as the streamed check gives them
    for (const NamedEllipse& obstacle : obstacles) {
      for (std::size_t i = 0; i < links.size(); ++i)
        collector.checkWithObstacle(i, refOf(obstacle));
    }
  } else {
    for (std::size_t i = 0; i < links.size(); ++i) {
      for (const NamedEllipse& obstacle : obstacles)
        collector.checkWithObstacle(i, refOf(obstacle));
    }
  }
  return collector.finish();
}

TEST(PairCollector, EveryPairGivenAnswersAsTheBruteForceInEitherOrder) {
  std::mt19937_64 rng(81);
  std::vector<BatchKernel> kernels{BatchKernel::Portable};
  if (useAvx2(BatchKernel::Automatic)) kernels.push_back(BatchKernel::Avx2);
  std::size_t collisions = 0, warnings = 0;
  for (int round = 0; round < 10; ++round) {
    const std::vector<NamedEllipse> links = randomEntries(rng, "l", EllipseRole::Link, 7, 3.0);
    std::vector<NamedEllipse> obstacles =
        randomEntries(rng, "o", EllipseRole::Obstacle, 40, 4.0);  // 280 pairs: five blocks
    const double warning_distance = round % 2 == 0 ? 0.0 : 0.4;
    SceneRules rules;
    rules.self_collision = false;  // the collector is given mover-obstacle pairs only
    rules.warning_distance = warning_distance;
    std::vector<NamedEllipse> scene = links;
    scene.insert(scene.end(), obstacles.begin(), obstacles.end());
    const SceneCheckResult expected = test::bruteForceScene(scene, rules, {});
    for (const BatchKernel kernel : kernels) {
      for (const bool obstacle_major : {true, false}) {
        std::shuffle(obstacles.begin(), obstacles.end(), rng);
        const SceneCheckResult actual =
            collect(kernel, warning_distance, links, obstacles, obstacle_major);
        ASSERT_TRUE(actual.ok()) << actual.error;
        EXPECT_EQ(actual.pair_tests, links.size() * obstacles.size());
        ASSERT_EQ(actual.collisions.size(), expected.collisions.size()) << "round " << round;
        for (std::size_t k = 0; k < expected.collisions.size(); ++k) {
          EXPECT_EQ(actual.collisions[k].name_a, expected.collisions[k].name_a);
          EXPECT_EQ(actual.collisions[k].name_b, expected.collisions[k].name_b);
          EXPECT_EQ(actual.collisions[k].contact_scale, expected.collisions[k].contact_scale);
        }
        ASSERT_EQ(actual.warnings.size(), expected.warnings.size()) << "round " << round;
        for (std::size_t k = 0; k < expected.warnings.size(); ++k) {
          EXPECT_EQ(actual.warnings[k].name_a, expected.warnings[k].name_a);
          EXPECT_EQ(actual.warnings[k].name_b, expected.warnings[k].name_b);
          EXPECT_EQ(actual.warnings[k].distance, expected.warnings[k].distance);
          EXPECT_EQ(actual.warnings[k].point_b, expected.warnings[k].point_b);
        }
      }
    }
    collisions += expected.collisions.size();
    warnings += expected.warnings.size();
  }
  EXPECT_GT(collisions, 50u);
  EXPECT_GT(warnings, 25u);
}

TEST(PairCollector, NoPairsGiveAnEmptyAnswer) {
  const std::vector<NamedEllipse> links = {{"arm", EllipseRole::Link, {{0, 0}, 1, 1, 0}}};
  const SceneCheckResult none = collect(BatchKernel::Portable, 0.5, links, {}, true);
  EXPECT_TRUE(none.ok());
  EXPECT_TRUE(none.collisions.empty());
  EXPECT_TRUE(none.warnings.empty());
  EXPECT_EQ(none.pair_tests, 0u);
}

}  // namespace
}  // namespace ellipse_collision::core::detail

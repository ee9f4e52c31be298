// The obstacles' grid kept while they stand still (app/standing_obstacles.h): built after
// kChecksBeforeIndexing unchanged checks from the scene's obstacle entries, kept while they stay,
// dropped at the first change; a refused set is streamed and tried again later.
#include <gtest/gtest.h>

#include <memory>

#include <string>

#include "ellipse_collision/app/standing_obstacles.h"

namespace ellipse_collision::app {
namespace {

/// Two links, then `obstacles` circles of radius `radius` along x.
core::Scene sceneWith(int obstacles, double radius = 0.2) {
  core::Scene scene;
  scene.push_back("body", core::EllipseRole::Link, core::Ellipse{{0.0, 0.0}, 0.5, 0.5, 0.0});
  scene.push_back("hand", core::EllipseRole::Link, core::Ellipse{{0.6, 0.0}, 0.1, 0.1, 0.0});
  for (int i = 0; i < obstacles; ++i) {
    scene.push_back("rock" + std::to_string(i), core::EllipseRole::Obstacle,
                    core::Ellipse{{1.0 + i, 2.0}, radius, radius, 0.0});
  }
  return scene;
}

constexpr std::size_t kStill = StandingObstacles::kChecksBeforeIndexing;

TEST(StandingObstacles, GriddedOnlyAfterEnoughStillChecksAndFromTheObstacleEntries) {
  const core::Scene scene = sceneWith(5);
  StandingObstacles standing;
  EXPECT_EQ(standing.update(false, scene, 2), nullptr) << "the first check has nothing to compare";
  for (std::size_t check = 1; check < kStill; ++check) {
    EXPECT_EQ(standing.update(true, scene, 2), nullptr) << check;
    EXPECT_EQ(standing.standingChecks(), check);
    EXPECT_FALSE(standing.indexed());
  }
  const std::shared_ptr<const core::IndexedObstacles> grid = standing.update(true, scene, 2);
  ASSERT_NE(grid, nullptr);
  EXPECT_TRUE(standing.indexed());
  EXPECT_EQ(grid->error(), "");
  ASSERT_EQ(grid->obstacles().size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(grid->obstacles()[k].name, scene.name(k + 2));
    EXPECT_EQ(grid->obstacles()[k].ellipse.center, scene.ellipse(k + 2).center);
  }
  // Kept, not rebuilt, while the obstacles stand.
  for (int check = 0; check < 5; ++check) EXPECT_EQ(standing.update(true, scene, 2), grid);
  EXPECT_EQ(standing.standingChecks(), kStill + 5);
}

TEST(StandingObstacles, AChangeDropsTheGridAndTheCountStartsOver) {
  const core::Scene scene = sceneWith(3);
  StandingObstacles standing;
  for (std::size_t check = 0; check < kStill; ++check) standing.update(true, scene, 2);
  ASSERT_TRUE(standing.indexed());
  EXPECT_EQ(standing.update(false, scene, 2), nullptr);
  EXPECT_FALSE(standing.indexed());
  EXPECT_EQ(standing.standingChecks(), 0u);
  for (std::size_t check = 1; check < kStill; ++check) {
    EXPECT_EQ(standing.update(true, scene, 2), nullptr) << check;
  }
  EXPECT_NE(standing.update(true, scene, 2), nullptr);
}

TEST(StandingObstacles, NoObstaclesMakeAnEmptyGrid) {
  const core::Scene scene = sceneWith(0);
  StandingObstacles standing;
  std::shared_ptr<const core::IndexedObstacles> grid;
  for (std::size_t check = 0; check < kStill; ++check) grid = standing.update(true, scene, 2);
  ASSERT_NE(grid, nullptr);
  EXPECT_TRUE(grid->obstacles().empty());
  EXPECT_EQ(grid->error(), "");
}

TEST(StandingObstacles, ARefusedSetIsStreamedAndTriedAgainAfterAsManyChecks) {
  // A link among the entries given as obstacles: the grid refuses it.
  const core::Scene scene = sceneWith(3);
  StandingObstacles standing;
  for (std::size_t check = 0; check < kStill; ++check) {
    EXPECT_EQ(standing.update(true, scene, 1), nullptr) << check;
  }
  EXPECT_FALSE(standing.indexed());
  EXPECT_EQ(standing.standingChecks(), 0u) << "counted afresh after the refusal";
  for (std::size_t check = 1; check < kStill; ++check) standing.update(true, scene, 2);
  EXPECT_NE(standing.update(true, scene, 2), nullptr) << "a good set is gridded in its turn";
}

}  // namespace
}  // namespace ellipse_collision::app

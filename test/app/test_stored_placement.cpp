// Every stored ellipse of a check placed in the fixed frame (app/stored_placement.h): links
// before obstacles, each skipped one said why, the frames listed once and sorted; with the cache
// the same scene and the obstacles that stood still counted as reused.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/stored_placement.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

using test::circle;

/// Frames translated along x, some with a stamp [s]; unknown frames are unavailable.
struct ShiftTable {
  std::map<std::string, double> shifts;
  std::map<std::string, double> stamps;
  FrameTransform operator()(const std::string& frame) const {
    FrameTransform transform;
    if (!shifts.count(frame)) {
      transform.error = "no frame '" + frame + "'";
      return transform;
    }
    transform.ok = true;
    transform.fixed_from_frame.translation().x() = shifts.at(frame);
    if (stamps.count(frame)) transform.stamp_s = stamps.at(frame);
    return transform;
  }
};

std::vector<std::string> names(const core::Scene& scene) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scene.size(); ++i) out.push_back(scene.name(i));
  return out;
}

TEST(StoredPlacement, LinksComeBeforeObstaclesAndEachIsMovedByItsFrame) {
  const EllipseRegistry registry(
      {circle("zeta_link", "base", 0.5, 0.0, 0.1), circle("alpha_link", "arm", 0.0, 0.0, 0.2)},
      {circle("a_rock", "map", 3.0, 1.0, 0.3), circle("m_rock", "cart", 0.0, 0.0, 0.4)});
  FramePlacer placer(ShiftTable{{{"base", 1.0}, {"arm", 2.0}, {"map", 0.0}, {"cart", -4.0}}, {}},
                     0.0);
  const StoredPlacement placed = placeStoredEllipses(registry, placer, 0.0, nullptr);
  EXPECT_EQ(names(placed.scene),
            (std::vector<std::string>{"alpha_link", "zeta_link", "a_rock", "m_rock"}));
  EXPECT_EQ(placed.scene.role(1), core::EllipseRole::Link);
  EXPECT_EQ(placed.scene.role(2), core::EllipseRole::Obstacle);
  EXPECT_EQ(placed.scene.ellipse(0).center, Eigen::Vector2d(2.0, 0.0));
  EXPECT_EQ(placed.scene.ellipse(1).center, Eigen::Vector2d(1.5, 0.0));
  EXPECT_EQ(placed.scene.ellipse(2).center, Eigen::Vector2d(3.0, 1.0));
  EXPECT_EQ(placed.scene.ellipse(3).center, Eigen::Vector2d(-4.0, 0.0));
  EXPECT_EQ(placed.obstacles, 2u);
  EXPECT_EQ(placed.reused_obstacles, 0u);
  EXPECT_TRUE(placed.skipped.empty());
  EXPECT_TRUE(placed.unavailable_frames.empty());
}

TEST(StoredPlacement, SkippedEllipsesAreSaidWhyAndTheirFramesListedOnceSorted) {
  Eigen::Isometry3d edge_on = Eigen::Isometry3d::Identity();
  edge_on.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  const EllipseRegistry registry(
      {circle("hand", "wrist", 0.0, 0.0, 0.1), circle("body", "base", 0.0, 0.0, 0.5),
       circle("plate", "tilted", 0.0, 0.0, 0.2)},
      {circle("crate", "truck", 0.0, 0.0, 0.3), circle("box", "truck", 1.0, 0.0, 0.3),
       circle("cone", "cart", 0.0, 0.0, 0.3), circle("post", "map", 2.0, 0.0, 0.1)});
  const ShiftTable shifts{{{"base", 0.0}, {"map", 0.0}, {"wrist", 0.0}}, {{"wrist", 1.0}}};
  FramePlacer placer(
      [&shifts, &edge_on](const std::string& frame) {
        if (frame != "tilted") return shifts(frame);
        FrameTransform transform;
        transform.ok = true;
        transform.fixed_from_frame = edge_on;
        return transform;
      },
      0.0, Freshness{0.5, 3.0});
  const StoredPlacement placed = placeStoredEllipses(registry, placer, 0.0, nullptr);
  EXPECT_EQ(names(placed.scene), (std::vector<std::string>{"body", "post"}));
  EXPECT_EQ(placed.obstacles, 4u) << "stored obstacles, placed or not";
  EXPECT_EQ(placed.unavailable_frames, (std::vector<std::string>{"cart", "truck"}));
  EXPECT_EQ(placed.stale_frames, std::vector<std::string>{"wrist"});
  ASSERT_EQ(placed.skipped.size(), 5u);
  EXPECT_EQ(placed.skipped[0],
            "hand: frame 'wrist' stale (transform of frame 'wrist' is 2 s old, older than "
            "max_transform_age 0.5 s)");
  EXPECT_NE(placed.skipped[1].find("plate"), std::string::npos) << placed.skipped[1];
  EXPECT_EQ(placed.skipped[2], "box: frame 'truck' unavailable");
  EXPECT_EQ(placed.skipped[3], "cone: frame 'cart' unavailable");
  EXPECT_EQ(placed.skipped[4], "crate: frame 'truck' unavailable");
}

TEST(StoredPlacement, WithTheCacheObstaclesThatStoodStillAreReusedAndTheSceneIsTheSame) {
  EllipseRegistry registry({circle("hand", "arm", 0.0, 0.0, 0.1)},
                           {circle("a", "map", 1.0, 0.0, 0.2), circle("b", "cart", 2.0, 0.0, 0.2)});
  ShiftTable table{{{"arm", 0.0}, {"map", 0.0}, {"cart", 0.5}}, {}};
  PlacementCache cache;
  for (int check = 0; check < 4; ++check) {
    table.shifts["arm"] = 0.25 * check;  // the arm moves every check, the obstacles stand
    FramePlacer cached_placer(table, 0.01), fresh_placer(table, 0.01);
    StoredPlacement cached = placeStoredEllipses(registry, cached_placer, 0.01, &cache, 3);
    const StoredPlacement fresh = placeStoredEllipses(registry, fresh_placer, 0.01, nullptr);
    ASSERT_EQ(names(cached.scene), names(fresh.scene));
    for (std::size_t i = 0; i < fresh.scene.size(); ++i) {
      EXPECT_EQ(cached.scene.ellipse(i).center, fresh.scene.ellipse(i).center) << check;
      EXPECT_EQ(cached.scene.ellipse(i).radius_x, fresh.scene.ellipse(i).radius_x) << check;
    }
    EXPECT_EQ(cached.obstacles, 2u);
    EXPECT_EQ(cached.reused_obstacles, check == 0 ? 0u : 2u) << "check " << check;
    EXPECT_GE(cached.scene.ellipses().capacity(), fresh.scene.size() + 3) << "room for queries";
    cache.recycle(std::move(cached.scene));
  }
  // The cart moves: its obstacle is projected anew, the other reused.
  table.shifts["cart"] = 0.75;
  FramePlacer placer(table, 0.01);
  const StoredPlacement moved = placeStoredEllipses(registry, placer, 0.01, &cache);
  EXPECT_EQ(moved.reused_obstacles, 1u);
  EXPECT_EQ(moved.scene.ellipse(2).center.x(), 2.75);
}

}  // namespace
}  // namespace ellipse_collision::app

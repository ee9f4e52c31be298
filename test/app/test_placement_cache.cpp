// The projections kept from one check to the next (app/placement_cache.h): a check through the
// cache gives the bits of one made afresh while frames move, vanish and come back and obstacles
// are added and removed; standing obstacles are gridded once; each frame is looked up once.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/placement_cache.h"
#include "frame_table.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

using test::circle;

using test::FrameTable;
using test::yawedPose;

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

void expectSameOutcome(const CheckOutcome& cached, const CheckOutcome& fresh, int cycle) {
  ASSERT_EQ(cached.error, fresh.error) << "cycle " << cycle;
  ASSERT_EQ(cached.placed.size(), fresh.placed.size()) << "cycle " << cycle;
  for (std::size_t i = 0; i < fresh.placed.size(); ++i) {
    const core::NamedEllipse a = cached.placed.entry(i);
    const core::NamedEllipse b = fresh.placed.entry(i);
    EXPECT_EQ(a.name, b.name) << "cycle " << cycle;
    EXPECT_TRUE(sameBits(a.ellipse.center.x(), b.ellipse.center.x()) &&
                sameBits(a.ellipse.center.y(), b.ellipse.center.y()) &&
                sameBits(a.ellipse.radius_x, b.ellipse.radius_x) &&
                sameBits(a.ellipse.radius_y, b.ellipse.radius_y) &&
                sameBits(a.ellipse.angle, b.ellipse.angle))
        << "cycle " << cycle << " " << a.name;
  }
  EXPECT_EQ(cached.unavailable_frames, fresh.unavailable_frames) << "cycle " << cycle;
  EXPECT_EQ(cached.skipped, fresh.skipped) << "cycle " << cycle;
  ASSERT_EQ(cached.collisions.size(), fresh.collisions.size()) << "cycle " << cycle;
  for (std::size_t i = 0; i < fresh.collisions.size(); ++i) {
    EXPECT_EQ(cached.collisions[i].name_a, fresh.collisions[i].name_a);
    EXPECT_EQ(cached.collisions[i].name_b, fresh.collisions[i].name_b);
    EXPECT_TRUE(sameBits(cached.collisions[i].contact_scale, fresh.collisions[i].contact_scale));
  }
  ASSERT_EQ(cached.warnings.size(), fresh.warnings.size()) << "cycle " << cycle;
  for (std::size_t i = 0; i < fresh.warnings.size(); ++i) {
    const core::NearPair& a = cached.warnings[i];
    const core::NearPair& b = fresh.warnings[i];
    EXPECT_EQ(a.name_a, b.name_a) << "cycle " << cycle;
    EXPECT_EQ(a.name_b, b.name_b) << "cycle " << cycle;
    EXPECT_TRUE(sameBits(a.distance, b.distance) && sameBits(a.point_a.x(), b.point_a.x()) &&
                sameBits(a.point_a.y(), b.point_a.y()) && sameBits(a.point_b.x(), b.point_b.x()) &&
                sameBits(a.point_b.y(), b.point_b.y()))
        << "cycle " << cycle << " " << a.name_a << " / " << a.name_b;
  }
}

/// One full check as the node makes it (through `cache`, then handing the placement of the state
/// it replaces back to the cache) beside one made afresh without a cache: the same bits. Returns
/// the fresh one.
CheckOutcome checkAsTheNodeAndAfresh(const EllipseRegistry& registry, const CheckSettings& settings,
                                     const FrameTable& table, PlacementCache& cache,
                                     CheckOutcome& node_state, int cycle) {
  CheckOutcome cached =
      runCheck(CheckRequest{}, registry, settings, TransformLookup(table), 0.0, &cache);
  CheckOutcome fresh = runCheck(CheckRequest{}, registry, settings, TransformLookup(table), 0.0);
  expectSameOutcome(cached, fresh, cycle);
  cache.recycle(std::move(node_state.placed));
  node_state = std::move(cached);
  return fresh;
}

TEST(PlacementCache, SameAnswerBitForBitAsProjectingEveryCycleWhileFramesMoveAndVanish) {
  EllipseRegistry registry(
      {circle("body", "base_link", 0.0, 0.0, 0.5), circle("hand", "arm", 0.3, 0.0, 0.1)}, {});
  std::vector<EllipseSpec> obstacles;
  for (int i = 0; i < 40; ++i) {
    obstacles.push_back(circle("rock" + std::to_string(i), i % 4 == 0 ? "cart" : "map",
                               0.1 * i - 2.0, 0.05 * (i % 7) - 0.2, 0.15));
  }
  ASSERT_EQ(registry.addObstacles(obstacles, "obstacles"), "");
  CheckSettings settings;
  settings.fixed_frame = "map";
  settings.global_padding_m = 0.01;
  std::map<std::string, int> lookups;
  FrameTable table{{{"map", Eigen::Isometry3d::Identity()},
                    {"base_link", yawedPose(0, 0, 0)},
                    {"arm", yawedPose(0, 0, 0)},
                    {"cart", yawedPose(0.5, 0, 0)}},
                   {},
                   &lookups};
  PlacementCache cache;
  std::size_t collisions = 0;
  CheckOutcome previous;  // the node's state: handed back to the cache when replaced
  for (int cycle = 0; cycle < 60; ++cycle) {
    // The arm moves every cycle, the base every third, the cart vanishes for a while and comes
    // back at its old pose; obstacles are added and removed now and then.
    table.poses["arm"] = yawedPose(0.05 * cycle - 1.5, 0.01 * cycle, 0.1 * cycle);
    if (cycle % 3 == 0) table.poses["base_link"] = yawedPose(0.04 * cycle - 1.0, 0.0, 0.05 * cycle);
    if (cycle == 20) table.poses.erase("cart");
    if (cycle == 25) table.poses["cart"] = yawedPose(0.5, 0, 0);
    if (cycle == 30) {
      ASSERT_EQ(registry.addObstacles({circle("late", "map", 0.2, 0.0, 0.3)}, "obstacles"), "");
    }
    if (cycle == 40) {
      ASSERT_EQ(registry.removeObstacles({"rock3", "late"}, "names"), "");
    }
    if (cycle == 50) {  // as many stored ellipses as before, one name different
      ASSERT_EQ(registry.removeObstacles({"rock5"}, "names"), "");
      ASSERT_EQ(registry.addObstacles({circle("rock5b", "map", 0.3, 0.0, 0.15)}, "obstacles"), "");
    }
    const CheckOutcome fresh =
        checkAsTheNodeAndAfresh(registry, settings, table, cache, previous, cycle);
    if (HasFatalFailure()) return;
    collisions += fresh.collisions.size();
  }
  EXPECT_GT(collisions, 20u) << "the comparison must see collisions";
  // Both refills ran: frame by frame mostly, entry by entry when the cart had vanished.
  EXPECT_GT(cache.frameRefills(), 30u);
  EXPECT_LT(cache.frameRefills(), cache.refilledChecks());
}

TEST(PlacementCache, StandingObstaclesAreGriddedOnceAndGiveTheSameBits) {
  // A robot arm sweeping through 300 obstacles that stand still in the map, except for a cart
  // that moves at cycle 60 and an obstacle added at cycle 90: after kChecksBeforeIndexing still
  // checks the cache checks the links against its grid of the obstacles; every answer, warnings
  // included, is the one of projecting and streaming everything afresh.
  EllipseRegistry registry(
      {circle("body", "base_link", 0.0, 0.0, 0.5), circle("hand", "arm", 0.6, 0.0, 0.15)}, {});
  std::vector<EllipseSpec> obstacles;
  for (int i = 0; i < 300; ++i) {
    obstacles.push_back(circle("rock" + std::to_string(i), i % 50 == 0 ? "cart" : "map",
                               0.13 * (i % 30) - 2.0, 0.21 * (i / 30) - 1.0,
                               0.04 + 0.01 * (i % 5)));
  }
  ASSERT_EQ(registry.addObstacles(obstacles, "obstacles"), "");
  CheckSettings settings;
  settings.fixed_frame = "map";
  settings.rules.warning_distance = 0.05;
  std::map<std::string, int> lookups;
  FrameTable table{{{"map", Eigen::Isometry3d::Identity()},
                    {"base_link", yawedPose(0, 0, 0)},
                    {"arm", yawedPose(0, 0, 0)},
                    {"cart", yawedPose(0.1, 0, 0)}},
                   {},
                   &lookups};
  PlacementCache cache;
  std::size_t collisions = 0, warnings = 0, indexed_checks = 0;
  const std::size_t still = StandingObstacles::kChecksBeforeIndexing;
  // The node's state, handed back to the cache when a newer check replaces it: two buffers
  // alternate, refilled in place (names kept, geometry rewritten).
  CheckOutcome previous;
  for (int cycle = 0; cycle < 130; ++cycle) {
    table.poses["arm"] = yawedPose(0.03 * cycle - 1.5, 0.4 * std::sin(0.2 * cycle), 0.1 * cycle);
    if (cycle == 60) table.poses["cart"] = yawedPose(0.3, 0.05, 0.2);
    if (cycle == 90) {
      ASSERT_EQ(registry.addObstacles({circle("late", "map", 0.2, 0.0, 0.3)}, "obstacles"), "");
    }
    const CheckOutcome fresh =
        checkAsTheNodeAndAfresh(registry, settings, table, cache, previous, cycle);
    if (HasFatalFailure()) return;
    collisions += fresh.collisions.size();
    warnings += fresh.warnings.size();
    const bool indexed = cache.standingObstacles().indexed();
    indexed_checks += indexed;
    // Gridded exactly when the obstacles have stood still long enough: from cycle `still`
    // (cycle 0 projects everything), not right after the cart moved or the registry changed.
    const bool expected = (cycle >= static_cast<int>(still) && cycle < 60) ||
                          (cycle >= 60 + static_cast<int>(still) && cycle < 90) ||
                          cycle >= 90 + static_cast<int>(still);
    EXPECT_EQ(indexed, expected) << "cycle " << cycle;
  }
  EXPECT_GT(collisions, 50u) << "the comparison must see collisions";
  EXPECT_GT(warnings, 50u) << "the comparison must see warnings";
  EXPECT_GT(indexed_checks, 60u);
  // Every check refills the buffer of two checks before, except the first two and the two after
  // the registry changed (cycle 90); all of those frame by frame (every frame is usable).
  EXPECT_EQ(cache.refilledChecks(), 126u);
  EXPECT_EQ(cache.frameRefills(), 126u);
}

TEST(PlacementCache, ReusedProjectionsLookUpEachFrameOncePerCheck) {
  EllipseRegistry registry({circle("hand", "arm", 0.0, 0.0, 0.1)},
                           {circle("a", "map", 1.0, 0.0, 0.2), circle("b", "map", 2.0, 0.0, 0.2),
                            circle("c", "cart", 0.0, 0.0, 0.2)});
  CheckSettings settings;
  settings.fixed_frame = "map";
  std::map<std::string, int> lookups;
  FrameTable table{{{"map", Eigen::Isometry3d::Identity()},
                    {"arm", yawedPose(0, 0, 0)},
                    {"cart", yawedPose(3, 0, 0)}},
                   {},
                   &lookups};
  PlacementCache cache;
  for (int cycle = 0; cycle < 3; ++cycle) {
    runCheck(CheckRequest{}, registry, settings, TransformLookup(table), 0.0, &cache);
  }
  EXPECT_EQ(lookups["map"], 3);
  EXPECT_EQ(lookups["arm"], 3);
  EXPECT_EQ(lookups["cart"], 3);
}

TEST(PlacementCache, AProjectionIsReusedOnlyThroughTheVeryTransformItWasMadeWith) {
  EllipseRegistry registry({circle("hand", "arm", 0.0, 0.0, 0.1)},
                           {circle("rock", "map", 1.0, 0.0, 0.2)});
  std::map<std::string, int> lookups;
  FrameTable table{
      {{"map", Eigen::Isometry3d::Identity()}, {"arm", yawedPose(0.5, 0.0, 0.25)}}, {}, &lookups};
  PlacementCache cache;
  cache.begin(registry, 0.0);
  // Links before obstacles; indices in the registry's (name) order.
  ASSERT_EQ(cache.placingOrder().size(), 2u);
  EXPECT_EQ(cache.placingOrder()[0].entry->first, "hand");
  EXPECT_EQ(cache.placingOrder()[0].role, core::EllipseRole::Link);
  EXPECT_EQ(cache.placingOrder()[1].index, 1u);
  EXPECT_EQ(cache.obstacleCount(), 1u);
  FramePlacer first(TransformLookup(table), 0.0);
  EXPECT_EQ(cache.reuse(0, first), nullptr) << "nothing stored yet";
  const core::Ellipse kept{{7.0, 7.0}, 1.0, 1.0, 0.0};  // the cache keeps what it is given
  cache.store(0, "arm", first.lookup("arm").fixed_from_frame, kept);

  const auto reusedThrough = [&](double padding) {
    cache.begin(registry, padding);
    FramePlacer placer(TransformLookup(table), padding);
    return cache.reuse(0, placer);
  };
  const core::Ellipse* reused = reusedThrough(0.0);
  ASSERT_NE(reused, nullptr) << "the same transform, bit for bit";
  EXPECT_EQ(reused->center, kept.center);
  table.poses["arm"].translation().x() = std::nextafter(0.5, 1.0);
  EXPECT_EQ(reusedThrough(0.0), nullptr) << "moved by one ulp";
  table.poses["arm"] = yawedPose(0.5, 0.0, 0.25);
  EXPECT_NE(reusedThrough(0.0), nullptr) << "back where it was projected";
  EXPECT_EQ(reusedThrough(0.01), nullptr) << "another padding forgets every projection";
  EXPECT_EQ(reusedThrough(0.0), nullptr) << "and it stays forgotten";

  // A registry change forgets too.
  cache.begin(registry, 0.0);
  FramePlacer again(TransformLookup(table), 0.0);
  cache.store(0, "arm", again.lookup("arm").fixed_from_frame, kept);
  EXPECT_NE(reusedThrough(0.0), nullptr);
  ASSERT_EQ(registry.addObstacles({circle("late", "map", 3.0, 0.0, 0.2)}, "obstacles"), "");
  EXPECT_EQ(reusedThrough(0.0), nullptr);
}

TEST(PlacementCache, AFrameThatIsStaleNowIsNotReusedThroughItsOldTransform) {
  EllipseRegistry registry({circle("hand", "arm", 0.0, 0.0, 0.1)}, {});
  const auto stamped = [](double stamp) {
    return TransformLookup([stamp](const std::string&) {
      FrameTransform transform;
      transform.ok = true;
      transform.stamp_s = stamp;
      return transform;
    });
  };
  PlacementCache cache;
  cache.begin(registry, 0.0);
  FramePlacer fresh(stamped(10.0), 0.0, Freshness{0.5, 10.0});
  cache.store(0, "arm", fresh.lookup("arm").fixed_from_frame, core::Ellipse{});
  cache.begin(registry, 0.0);
  FramePlacer still_fresh(stamped(10.0), 0.0, Freshness{0.5, 10.25});
  EXPECT_NE(cache.reuse(0, still_fresh), nullptr);
  cache.begin(registry, 0.0);
  FramePlacer stale(stamped(10.0), 0.0, Freshness{0.5, 11.0});
  EXPECT_EQ(cache.reuse(0, stale), nullptr) << "the same pose, but too old now";
}

TEST(PlacementCache, OnlyACompletePlacementOfThisRegistryIsRecycled) {
  EllipseRegistry registry({circle("hand", "arm", 0.0, 0.0, 0.1)},
                           {circle("rock", "map", 1.0, 0.0, 0.2)});
  PlacementCache cache;
  cache.begin(registry, 0.0);
  core::Scene stranger;
  stranger.push_back("hand", core::EllipseRole::Link, core::Ellipse{});
  stranger.push_back("rock", core::EllipseRole::Obstacle, core::Ellipse{});
  cache.recycle(std::move(stranger));
  EXPECT_TRUE(cache.takeRecycled().empty()) << "the right size, but not seen produced";
  core::Scene placed;
  placed.push_back("hand", core::EllipseRole::Link, core::Ellipse{});
  placed.push_back("rock", core::EllipseRole::Obstacle, core::Ellipse{});
  cache.produced(placed);
  cache.recycle(std::move(placed));
  cache.begin(registry, 0.0);
  const core::Scene recycled = cache.takeRecycled();
  ASSERT_EQ(recycled.size(), 2u);
  EXPECT_EQ(recycled.name(1), "rock");
  EXPECT_TRUE(cache.takeRecycled().empty()) << "taken once";
}

}  // namespace
}  // namespace ellipse_collision::app

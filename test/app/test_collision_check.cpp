// The orchestration of one check without ROS (app/collision_check.h): requests are validated,
// ellipses are placed through the transform lookup (each frame once), the core checks the scene,
// and the answer lists what was skipped and why. Expected values are worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include <cstring>
#include <map>

#include "ellipse_collision/app/collision_check.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

using test::circle;

/// Frames translated in the plane; unknown frames are unavailable. Counts the lookups. A frame
/// without an entry in `stamps` is timeless (static).
struct TranslationTable {
  std::map<std::string, Eigen::Vector2d> offsets;
  std::map<std::string, double> stamps;  ///< [s]
  std::map<std::string, int>* lookups;
  FrameTransform operator()(const std::string& frame) const {
    ++(*lookups)[frame];
    FrameTransform transform;
    const auto found = offsets.find(frame);
    if (found == offsets.end()) {
      transform.error = "frame '" + frame + "' does not exist";
      return transform;
    }
    transform.ok = true;
    if (stamps.count(frame)) transform.stamp_s = stamps.at(frame);
    transform.fixed_from_frame.translation() << found->second, 0.0;
    return transform;
  }
};

class CollisionCheckTest : public ::testing::Test {
 protected:
  CollisionCheckTest()
      : registry_({circle("body", "base_link", 0.0, 0.0, 0.5), circle("hand", "arm", 0.0, 0.0, 0.1),
                   circle("spare", "arm", 1.0, 0.0, 0.1)},
                  {circle("wall", "map", 0.0, 2.0, 1.0)}) {
    settings_.fixed_frame = "map";
    table_.offsets = {{"map", {0, 0}}, {"base_link", {0.0, 0.0}}};
    table_.lookups = &lookups_;
  }

  CheckOutcome run(const CheckRequest& request, double now_s = 0.0) {
    return runCheck(request, registry_, settings_, TransformLookup(table_), now_s);
  }

  EllipseRegistry registry_;
  CheckSettings settings_;
  TranslationTable table_;
  std::map<std::string, int> lookups_;
};

TEST_F(CollisionCheckTest, StoredEllipseWithoutTransformIsSkippedAndItsFrameListed) {
  const CheckOutcome outcome = run({});
  ASSERT_EQ(outcome.error, "");
  EXPECT_EQ(outcome.unavailable_frames, std::vector<std::string>{"arm"});
  EXPECT_EQ(outcome.skipped,
            (std::vector<std::string>{"hand: frame 'arm' unavailable",
                                      "spare: frame 'arm' unavailable"}));
  EXPECT_EQ(outcome.placed.size(), 2u);  // body, wall
  EXPECT_TRUE(outcome.collisions.empty());  // body reaches y = 0.5, the wall starts at y = 1
  EXPECT_EQ(lookups_["arm"], 1) << "each frame is looked up once per check";
}

TEST_F(CollisionCheckTest, TransformsMoveLinksIntoCollision) {
  table_.offsets["arm"] = {0.0, 0.95};  // hand: circle 0.1 at (0, 0.95) meets the wall at y = 1
  const CheckOutcome outcome = run({});
  ASSERT_EQ(outcome.error, "");
  EXPECT_TRUE(outcome.unavailable_frames.empty());
  ASSERT_EQ(outcome.collisions.size(), 1u);
  EXPECT_EQ(outcome.collisions[0].name_a, "hand");
  EXPECT_EQ(outcome.collisions[0].name_b, "wall");
  // Centres 1.05 apart, radii 0.1 + 1.0: scaled by 1.05 / 1.1 they touch.
  EXPECT_NEAR(outcome.collisions[0].contact_scale, 1.05 / 1.1, 1e-12);
}

TEST_F(CollisionCheckTest, GlobalPaddingGrowsEveryEllipse) {
  settings_.global_padding_m = 0.25;  // body reaches 0.75, the wall 0.75 below y = 2 - 1
  const CheckOutcome outcome = run({});
  ASSERT_EQ(outcome.collisions.size(), 1u);
  EXPECT_EQ(outcome.collisions[0].name_a, "body");
  EXPECT_NEAR(outcome.collisions[0].contact_scale, 2.0 / 2.0, 1e-12);
}

TEST_F(CollisionCheckTest, QueryIsCheckedAndNearestPartnerMeasured) {
  CheckRequest request;
  request.query = {circle("probe", "base_link", 3.0, 0.0, 0.5)};
  request.names = {"probe"};
  request.min_distance_of = "probe";
  ASSERT_EQ(validateCheckRequest(request, registry_, 0.0), "");
  const CheckOutcome outcome = run(request);
  ASSERT_EQ(outcome.error, "");
  EXPECT_TRUE(outcome.collisions.empty());
  ASSERT_TRUE(outcome.nearest);
  // body: 3 - 0.5 - 0.5 = 2; wall: |(3, -2)| - 1.5 = 2.1055...: body is nearer.
  EXPECT_EQ(outcome.nearest->name_b, "body");
  EXPECT_NEAR(outcome.nearest->distance, 2.0, 1e-12);
}

TEST_F(CollisionCheckTest, NearestOfAnUnplacedEllipseIsANoteNotAnError) {
  CheckRequest request;
  request.min_distance_of = "hand";
  const CheckOutcome outcome = run(request);
  EXPECT_EQ(outcome.error, "");
  EXPECT_FALSE(outcome.nearest);
  EXPECT_EQ(outcome.nearest_problem,
            "min_distance_of = 'hand': not measured, the ellipse could not be placed");
}

TEST_F(CollisionCheckTest, QueryInUnavailableFrameFailsTheRequest) {
  CheckRequest request;
  request.query = {circle("probe", "nowhere", 0.0, 0.0, 0.1)};
  const CheckOutcome outcome = run(request);
  EXPECT_EQ(outcome.error,
            "query[0].frame_id = 'nowhere': expected a frame with a transform to 'map', got none "
            "(frame 'nowhere' does not exist)");
}

TEST_F(CollisionCheckTest, RequestRulesNameTheFieldAndValue) {
  CheckRequest request;
  request.names = {"body", "ghost"};
  EXPECT_EQ(validateCheckRequest(request, registry_, 0.0),
            "names[1] = 'ghost': expected the name of a link, obstacle or query, got an unknown name");
  request.names = {"body", "body"};
  EXPECT_EQ(validateCheckRequest(request, registry_, 0.0),
            "names[1] = 'body': expected each name once, got a duplicate");
  request.names = {""};
  EXPECT_EQ(validateCheckRequest(request, registry_, 0.0), "names[0] = '': expected a non-empty name");
  request.names = {};
  request.query = {circle("wall", "map", 0, 0, 1)};
  EXPECT_EQ(validateCheckRequest(request, registry_, 0.0),
            "query[0].name = 'wall': expected a name used by no link, obstacle or other query, got "
            "a duplicate");
  request.query = {circle("q", "map", 0, 0, -1)};
  EXPECT_EQ(validateCheckRequest(request, registry_, 0.0),
            "query[0].radius_x = -1: expected a finite number > 0");
  request.query = {};
  request.min_distance_of = "ghost";
  EXPECT_EQ(validateCheckRequest(request, registry_, 0.0),
            "min_distance_of = 'ghost': expected the name of a link, obstacle or query (or empty), "
            "got an unknown name");
}

TEST_F(CollisionCheckTest, AttachedEllipsesNeedValidFieldsThenAKnownFrame) {
  const TransformLookup lookup(table_);
  EXPECT_EQ(validateAttached({circle("a", "map", 0, 0, 1)}, "obstacles", settings_, lookup), "");
  EXPECT_EQ(validateAttached({circle("a", "nowhere", 0, 0, 1), circle("b", "map", 0, 0, 0)},
                             "obstacles", settings_, lookup),
            "obstacles[1].radius_x = 0: expected a finite number > 0");
  EXPECT_EQ(validateAttached({circle("a", "nowhere", 0, 0, 1)}, "obstacles", settings_, lookup),
            "obstacles[0].frame_id = 'nowhere': expected a known tf frame with a transform to "
            "'map', got none (frame 'nowhere' does not exist)");
}

TEST_F(CollisionCheckTest, AttachedEllipsesAskForEachDistinctFrameOnce) {
  const TransformLookup lookup(table_);
  // 1,000 obstacles in two frames, interleaved and in runs: two lookups.
  std::vector<EllipseSpec> specs;
  for (int i = 0; i < 1000; ++i) {
    const char* frame = (i % 7 == 0 || i > 900) ? "base_link" : "map";
    specs.push_back(circle("o" + std::to_string(i), frame, i, 0, 0.1));
  }
  EXPECT_EQ(validateAttached(specs, "ellipses", settings_, lookup), "");
  EXPECT_EQ(lookups_, (std::map<std::string, int>{{"base_link", 1}, {"map", 1}}));
  // A missing frame after many known ones is still found, and named where it first stands.
  lookups_.clear();
  specs[950].frame_id = "nowhere";
  specs[960].frame_id = "nowhere";
  EXPECT_EQ(validateAttached(specs, "ellipses", settings_, lookup),
            "ellipses[950].frame_id = 'nowhere': expected a known tf frame with a transform to "
            "'map', got none (frame 'nowhere' does not exist)");
  EXPECT_EQ(lookups_, (std::map<std::string, int>{{"base_link", 1}, {"map", 1}, {"nowhere", 1}}));
}

TEST(Freshness, OnlyStampedTransformsOlderThanTheMaximumAreStale) {
  FrameTransform transform;
  transform.ok = true;
  transform.stamp_s = 100.0;
  EXPECT_FALSE(isStale(transform, {0.5, 100.5})) << "exactly max_transform_age old is fresh";
  EXPECT_TRUE(isStale(transform, {0.5, 100.6}));
  EXPECT_NEAR(ageOf(transform, {0.5, 100.6}), 0.6, 1e-9);
  EXPECT_FALSE(isStale(transform, {0.0, 1e6})) << "max_transform_age 0 is off";
  EXPECT_FALSE(isStale(transform, {0.5, 99.0})) << "a transform from the future is not old";
  transform.stamp_s = 0.0;
  EXPECT_FALSE(isStale(transform, {0.5, 1e6})) << "static chains (stamp 0) never go stale";
  EXPECT_EQ(ageOf(transform, {0.5, 1e6}), 0.0);
  transform.ok = false;
  transform.stamp_s = 1.0;
  EXPECT_FALSE(isStale(transform, {0.5, 1e6})) << "unavailable is not stale";
}

TEST_F(CollisionCheckTest, EverythingPlacedFromFreshDataIsComplete) {
  table_.offsets["arm"] = {0.0, -3.0};
  table_.stamps["arm"] = 10.0;
  settings_.max_transform_age_s = 0.5;
  const CheckOutcome outcome = run({}, 10.4);
  ASSERT_EQ(outcome.error, "");
  EXPECT_TRUE(outcome.complete);
  EXPECT_TRUE(outcome.stale_frames.empty());
  EXPECT_EQ(outcome.placed.size(), 4u);
}

TEST_F(CollisionCheckTest, UnavailableFrameMakesTheAnswerIncomplete) {
  const CheckOutcome outcome = run({});
  ASSERT_EQ(outcome.error, "");
  EXPECT_FALSE(outcome.complete);
  EXPECT_TRUE(outcome.stale_frames.empty());
}

TEST_F(CollisionCheckTest, StaleFrameIsNotCheckedAtItsOldPoseAndListed) {
  table_.offsets["arm"] = {0.0, 0.95};  // at this old pose the hand would touch the wall
  table_.stamps["arm"] = 10.0;
  table_.stamps["base_link"] = 11.0;    // fresh
  settings_.max_transform_age_s = 0.5;
  const CheckOutcome outcome = run({}, 11.25);
  ASSERT_EQ(outcome.error, "");
  EXPECT_EQ(outcome.stale_frames, std::vector<std::string>{"arm"});
  EXPECT_TRUE(outcome.unavailable_frames.empty());
  EXPECT_TRUE(outcome.collisions.empty()) << "the hand was not placed at its old pose";
  EXPECT_EQ(outcome.placed.size(), 2u);  // body, wall
  EXPECT_FALSE(outcome.complete);
  ASSERT_EQ(outcome.skipped.size(), 2u);
  EXPECT_EQ(outcome.skipped[0],
            "hand: frame 'arm' stale (transform of frame 'arm' is 1.25 s old, older than "
            "max_transform_age 0.5 s)");

  // Published again: fresh at once.
  table_.stamps["arm"] = 11.2;
  const CheckOutcome again = run({}, 11.25);
  EXPECT_TRUE(again.complete);
  EXPECT_TRUE(again.stale_frames.empty());
  EXPECT_EQ(again.collisions.size(), 1u);
}

TEST_F(CollisionCheckTest, FreshnessOffKeepsTheLastPose) {
  table_.offsets["arm"] = {0.0, 0.95};
  table_.stamps["arm"] = 10.0;
  settings_.max_transform_age_s = 0.0;
  const CheckOutcome outcome = run({}, 1000.0);
  EXPECT_TRUE(outcome.complete);
  EXPECT_EQ(outcome.collisions.size(), 1u);
}

TEST_F(CollisionCheckTest, QueryInAStaleFrameFailsTheRequest) {
  table_.offsets["arm"] = {0.0, 0.0};
  table_.stamps["arm"] = 10.0;
  settings_.max_transform_age_s = 0.5;
  CheckRequest request;
  request.query = {circle("probe", "arm", 0.0, 0.0, 0.1)};
  const CheckOutcome outcome = run(request, 12.0);
  EXPECT_EQ(outcome.error,
            "query[0].frame_id = 'arm': expected a transform to 'map' within max_transform_age, "
            "got a stale one (transform of frame 'arm' is 2 s old, older than max_transform_age "
            "0.5 s)");
}

}  // namespace
}  // namespace ellipse_collision::app

namespace ellipse_collision::app {
namespace {

/// Frames with rotation and translation, changeable between checks; counts lookups.
struct PoseTable {
  std::map<std::string, Eigen::Isometry3d> poses;
  std::map<std::string, int>* lookups;
  FrameTransform operator()(const std::string& frame) const {
    ++(*lookups)[frame];
    FrameTransform transform;
    const auto found = poses.find(frame);
    if (found == poses.end()) {
      transform.error = "frame '" + frame + "' does not exist";
      return transform;
    }
    transform.ok = true;
    transform.fixed_from_frame = found->second;
    return transform;
  }
};

Eigen::Isometry3d pose(double x, double y, double yaw) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  p.translate(Eigen::Vector3d(x, y, 0.0));
  p.rotate(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return p;
}

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
                                     const PoseTable& table, PlacementCache& cache,
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
  EllipseRegistry registry({circle("body", "base_link", 0.0, 0.0, 0.5),
                            circle("hand", "arm", 0.3, 0.0, 0.1)},
                           {});
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
  PoseTable table{{{"map", Eigen::Isometry3d::Identity()}, {"base_link", pose(0, 0, 0)},
                   {"arm", pose(0, 0, 0)}, {"cart", pose(0.5, 0, 0)}},
                  &lookups};
  PlacementCache cache;
  std::size_t collisions = 0;
  CheckOutcome previous;  // the node's state: handed back to the cache when replaced
  for (int cycle = 0; cycle < 60; ++cycle) {
    // The arm moves every cycle, the base every third, the cart vanishes for a while and comes
    // back at its old pose; obstacles are added and removed now and then.
    table.poses["arm"] = pose(0.05 * cycle - 1.5, 0.01 * cycle, 0.1 * cycle);
    if (cycle % 3 == 0) table.poses["base_link"] = pose(0.04 * cycle - 1.0, 0.0, 0.05 * cycle);
    if (cycle == 20) table.poses.erase("cart");
    if (cycle == 25) table.poses["cart"] = pose(0.5, 0, 0);
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
  EllipseRegistry registry({circle("body", "base_link", 0.0, 0.0, 0.5),
                            circle("hand", "arm", 0.6, 0.0, 0.15)},
                           {});
  std::vector<EllipseSpec> obstacles;
  for (int i = 0; i < 300; ++i) {
    obstacles.push_back(circle("rock" + std::to_string(i), i % 50 == 0 ? "cart" : "map",
                               0.13 * (i % 30) - 2.0, 0.21 * (i / 30) - 1.0, 0.04 + 0.01 * (i % 5)));
  }
  ASSERT_EQ(registry.addObstacles(obstacles, "obstacles"), "");
  CheckSettings settings;
  settings.fixed_frame = "map";
  settings.rules.warning_distance = 0.05;
  std::map<std::string, int> lookups;
  PoseTable table{{{"map", Eigen::Isometry3d::Identity()}, {"base_link", pose(0, 0, 0)},
                   {"arm", pose(0, 0, 0)}, {"cart", pose(0.1, 0, 0)}},
                  &lookups};
  PlacementCache cache;
  std::size_t collisions = 0, warnings = 0, indexed_checks = 0;
  const std::size_t still = StandingObstacles::kChecksBeforeIndexing;
  // The node's state, handed back to the cache when a newer check replaces it: two buffers
  // alternate, refilled in place (names kept, geometry rewritten).
  CheckOutcome previous;
  for (int cycle = 0; cycle < 130; ++cycle) {
    table.poses["arm"] = pose(0.03 * cycle - 1.5, 0.4 * std::sin(0.2 * cycle), 0.1 * cycle);
    if (cycle == 60) table.poses["cart"] = pose(0.3, 0.05, 0.2);
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
  PoseTable table{{{"map", Eigen::Isometry3d::Identity()}, {"arm", pose(0, 0, 0)},
                   {"cart", pose(3, 0, 0)}},
                  &lookups};
  PlacementCache cache;
  for (int cycle = 0; cycle < 3; ++cycle) {
    runCheck(CheckRequest{}, registry, settings, TransformLookup(table), 0.0, &cache);
  }
  EXPECT_EQ(lookups["map"], 3);
  EXPECT_EQ(lookups["arm"], 3);
  EXPECT_EQ(lookups["cart"], 3);
}

}  // namespace
}  // namespace ellipse_collision::app

// The orchestration of one check without ROS (app/collision_check.h): requests are validated,
// ellipses are placed through the transform lookup (each frame once), the core checks the scene,
// and the answer lists what was skipped and why. Expected values are worked out by hand.
#include <gtest/gtest.h>

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

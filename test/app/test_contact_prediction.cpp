// The time-to-contact step of a check (src/app/contact_prediction.cpp, app::predictAfterCheck())
// with transforms from a table: frames' velocities by the finite difference, obstacles' own
// velocities, the lag to the check's stamp, notes for what cannot be estimated. Expected values by
// hand.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/contact_prediction.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

using test::circle;
using test::translated;

/// The frame "arm" moving along map's x at 2 m/s through the origin at t = 10 s: its latest
/// transform (stamped 10 s), and its pose at any time.
FrameTransform armLatest(const std::string& f) {
  FrameTransform t = translated({{"map", {0, 0}}, {"arm", {0, 0}}}, f);
  if (f == "arm") t.stamp_s = 10.0;
  return t;
}
FrameTransform armAt(const std::string& f, double time_s) {
  FrameTransform t = translated({{"map", {0, 0}}, {"arm", {2.0 * (time_s - 10.0), 0}}}, f);
  t.stamp_s = time_s;
  return t;
}

TEST(PredictAfterCheck, ALinkOnAMovingFrameIsPredictedToMeetAStandingObstacle) {
  // The arm frame moves at 2 m/s along x (its pose 0.1 s ago was 0.2 m behind); its hand
  // (0.1 m) and the post (0.1 m) are 1.2 m apart: 1.0 m of gap at 2 m/s, contact after 0.5 s.
  const EllipseRegistry registry(
      {circle("hand", "arm", 0.0, 0.0, 0.1)},
      {circle("post", "map", 1.2, 0.0, 0.1), circle("far", "map", 0.0, 5.0, 0.1)});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const TransformLookup latest = armLatest;
  const TransformAtLookup at = armAt;
  CheckOutcome outcome = runCheck({}, registry, settings, latest, 10.0);
  ASSERT_EQ(outcome.error, "");
  predictAfterCheck(outcome, {}, registry, settings, at, 2.0, 10.0);
  ASSERT_EQ(outcome.predicted.size(), 1u);
  EXPECT_EQ(outcome.predicted[0].name_a, "hand");
  EXPECT_EQ(outcome.predicted[0].name_b, "post");
  EXPECT_NEAR(outcome.predicted[0].time, 0.5, 1e-9);
  EXPECT_TRUE(outcome.prediction_notes.empty());
  // Beyond the horizon: nothing. Off: nothing.
  CheckOutcome short_horizon = runCheck({}, registry, settings, latest, 10.0);
  predictAfterCheck(short_horizon, {}, registry, settings, at, 0.4, 10.0);
  EXPECT_TRUE(short_horizon.predicted.empty());
  // Checked 0.1 s after the arm's latest transform: the hand has moved on 0.2 m since, so the
  // contact is 0.1 s sooner from the check's stamp.
  CheckOutcome later = runCheck({}, registry, settings, latest, 10.1);
  predictAfterCheck(later, {}, registry, settings, at, 2.0, 10.1);
  ASSERT_EQ(later.predicted.size(), 1u);
  EXPECT_NEAR(later.predicted[0].time, 0.4, 1e-9);
  // 0.6 s after it: the hand has reached the post since (apart at the check's poses): time 0.
  CheckOutcome touched = runCheck({}, registry, settings, latest, 10.6);
  predictAfterCheck(touched, {}, registry, settings, at, 2.0, 10.6);
  ASSERT_EQ(touched.predicted.size(), 1u);
  EXPECT_EQ(touched.predicted[0].time, 0.0);
}

TEST(PredictAfterCheck, AnObstacleOwnVelocityIsTurnedIntoTheFixedFrame) {
  // The obstacle's frame is map turned by +90 deg: its vx = 1 m/s moves it along map's +y,
  // towards the link 1 m above it (gap 0.8 m): 0.8 s. Static frames: no tf motion.
  EllipseSpec mover = circle("mover", "turned", 0.0, 0.0, 0.1);
  mover.vx = 1.0;
  const EllipseRegistry registry({circle("link", "map", 0.0, 1.0, 0.1)}, {mover});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const auto latest = [](const std::string& f) {
    FrameTransform t = translated({{"map", {0, 0}}, {"turned", {0, 0}}}, f);
    if (f == "turned")
      t.fixed_from_frame.linear() =
          Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return t;
  };
  const TransformAtLookup at = [&](const std::string& f, double) { return latest(f); };
  CheckOutcome outcome = runCheck({}, registry, settings, latest, 0.0);
  predictAfterCheck(outcome, {}, registry, settings, at, 5.0, 0.0);
  ASSERT_EQ(outcome.predicted.size(), 1u);
  EXPECT_NEAR(outcome.predicted[0].time, 0.8, 1e-9);
}

TEST(PredictAfterCheck, AFrameWithoutAnEarlierPoseMovesByItsOwnVelocityOnlyAndIsNoted) {
  // tf has the arm at 10 s only: its velocity is unknown, so the hand stands, and the obstacle
  // moving towards it at 1 m/s (gap 1.0 m) is predicted at 1 s all the same.
  EllipseSpec cart = circle("cart", "map", 1.2, 0.0, 0.1);
  cart.vx = -1.0;
  const EllipseRegistry registry({circle("hand", "arm", 0.0, 0.0, 0.1)}, {cart});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const auto latest = [](const std::string& f) {
    FrameTransform t = translated({{"map", {0, 0}}, {"arm", {0, 0}}}, f);
    if (f == "arm") t.stamp_s = 10.0;
    return t;
  };
  const TransformAtLookup at = [](const std::string& f, double time_s) {
    FrameTransform t;
    t.error = "no transform of '" + f + "' at " + std::to_string(time_s);
    return t;
  };
  CheckOutcome outcome = runCheck({}, registry, settings, latest, 10.0);
  ASSERT_EQ(outcome.error, "");
  predictAfterCheck(outcome, {}, registry, settings, at, 2.0, 10.0);
  ASSERT_EQ(outcome.predicted.size(), 1u);
  EXPECT_NEAR(outcome.predicted[0].time, 1.0, 1e-9);
  ASSERT_EQ(outcome.prediction_notes.size(), 1u);
  EXPECT_EQ(outcome.prediction_notes[0].rfind("hand: velocity of frame 'arm' unknown (no "
                                              "transform of 'arm' at 9.9",
                                              0),
            0u)
      << outcome.prediction_notes[0];
}

TEST(PredictAfterCheck, PairsAlreadyTouchingAreNotRepeatedAndTheNamesFilterHolds) {
  // Static frames: link "a" and obstacle "b" overlap now; "c" approaches "a" along x at 1 m/s
  // from 1.2 m (gap 1.0 m), "d" along y from 3 m.
  EllipseSpec c = circle("c", "map", -1.2, 0.0, 0.1);
  c.vx = 1.0;
  EllipseSpec d = circle("d", "map", 0.0, 3.0, 0.1);
  d.vy = -1.0;
  const EllipseRegistry registry({circle("a", "map", 0.0, 0.0, 0.1)},
                                 {circle("b", "map", 0.05, 0.0, 0.1), c, d});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const auto latest = [](const std::string& f) { return translated({{"map", {0, 0}}}, f); };
  const TransformAtLookup at = [&](const std::string& f, double) { return latest(f); };
  const auto has = [](const core::PredictedContact& pair, const std::string& name) {
    return pair.name_a == name || pair.name_b == name;
  };
  CheckOutcome all = runCheck({}, registry, settings, latest, 0.0);
  ASSERT_EQ(all.collisions.size(), 1u);
  predictAfterCheck(all, {}, registry, settings, at, 5.0, 0.0);
  bool a_c = false;
  bool d_without_c = false;
  for (const auto& pair : all.predicted) {
    EXPECT_FALSE(has(pair, "a") && has(pair, "b")) << "touching now: not predicted";
    if (has(pair, "a") && has(pair, "c")) {
      a_c = true;
      EXPECT_NEAR(pair.time, 1.0, 1e-9) << "1.0 m of gap at 1 m/s";
    }
    d_without_c = d_without_c || (has(pair, "d") && !has(pair, "c"));
  }
  EXPECT_TRUE(a_c);
  EXPECT_TRUE(d_without_c);
  CheckRequest only_c;
  only_c.names = {"c"};
  CheckOutcome filtered = runCheck(only_c, registry, settings, latest, 0.0);
  predictAfterCheck(filtered, only_c, registry, settings, at, 5.0, 0.0);
  ASSERT_FALSE(filtered.predicted.empty());
  for (const auto& pair : filtered.predicted) EXPECT_TRUE(has(pair, "c"));
  CheckOutcome off = runCheck({}, registry, settings, latest, 0.0);
  predictAfterCheck(off, {}, registry, settings, at, 0.0, 0.0);
  EXPECT_TRUE(off.predicted.empty()) << "horizon 0: prediction off";
}

TEST(PredictAfterCheck, ALatestTransformOlderThanTheLagLimitMovesOnByTheLimitOnly) {
  // The arm at 2 m/s, its latest transform 5 s before the check: moved on kMaxPredictionLagS
  // (2 m), not 10 m. Post 4.2 m ahead of it (gap 4.0 m): 2.0 m left, 1 s at 2 m/s.
  const EllipseRegistry registry({circle("hand", "arm", 0.0, 0.0, 0.1)},
                                 {circle("post", "map", 4.2, 0.0, 0.1)});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const TransformLookup latest = armLatest;
  const TransformAtLookup at = armAt;
  CheckOutcome outcome = runCheck({}, registry, settings, latest, 15.0);
  ASSERT_EQ(outcome.error, "");
  predictAfterCheck(outcome, {}, registry, settings, at, 3.0, 15.0);
  ASSERT_EQ(outcome.predicted.size(), 1u);
  EXPECT_NEAR(outcome.predicted[0].time, (4.0 - 2.0 * kMaxPredictionLagS) / 2.0, 1e-9);
}

}  // namespace
}  // namespace ellipse_collision::app

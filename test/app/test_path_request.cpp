// ~check_path's rules and orchestration without ROS (app/path_request.h), and the time-to-contact
// step of a check (app::predictAfterCheck()) with transforms from a table. Expected values by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/contact_prediction.h"
#include "spec_builders.h"
#include "ellipse_collision/app/path_request.h"

namespace ellipse_collision::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using test::circle;

PathPoseInput pose(double x, double y, double yaw = 0.0, double stamp = 0.0) {
  PathPoseInput p;
  p.x = x;
  p.y = y;
  p.qz = std::sin(0.5 * yaw);
  p.qw = std::cos(0.5 * yaw);
  p.stamp_s = stamp;
  return p;
}

PathCheckRequest request(std::vector<PathPoseInput> poses) {
  PathCheckRequest r;
  r.path_frame = "map";
  r.moving_frame = "base_link";
  r.poses = std::move(poses);
  return r;
}

TEST(PathRequest, AValidPathPasses) {
  EXPECT_EQ(validatePathRequest(request({pose(0, 0), pose(1, 0, 0.5)})), "");
  EXPECT_EQ(validatePathRequest(request({pose(0, 0, 0, 10), pose(1, 0, 0, 10.5)})), "");
}

TEST(PathRequest, EachBadFieldIsNamedWithItsValue) {
  PathPoseInput long_q = pose(0, 0);
  long_q.qw = 1.01;
  PathPoseInput tilted = pose(0, 0);
  tilted.qx = 0.01;
  PathPoseInput nan_q = pose(0, 0);
  nan_q.qz = kNaN;
  PathPoseInput other_frame = pose(0, 0);
  other_frame.frame_id = "odom";
  const std::pair<PathCheckRequest, std::string> cases[] = {
      {request({}), "path.poses: expected at least one pose, got an empty path"},
      {request({pose(0, 0), pose(kNaN, 0)}), "path.poses[1].pose.position.x = nan"},
      {request({pose(0, 2e9)}), "path.poses[0].pose.position.y = 2e+09"},
      {request({nan_q}), "path.poses[0].pose.orientation.z = nan"},
      {request({long_q}), "got |q| = 1.01"},
      {request({pose(0, 0), tilted}), "path.poses[1].pose.orientation = (0.01, 0, 0, 1)"},
      {request({other_frame}), "path.poses[0].header.frame_id = 'odom'"},
      {request({pose(0, 0, 0, 2), pose(1, 0, 0, 1)}),
       "path.poses[1].header.stamp = 1: expected strictly increasing stamps"},
      {request({pose(0, 0, 0, 2), pose(1, 0, 0, 2)}), "path.poses[1].header.stamp = 2"},
      {request({pose(0, 0, 0, 0), pose(1, 0, 0, 1)}), "path.poses[1].header.stamp = 1: expected 0"},
      {request({pose(0, 0, 0, 1), pose(1, 0, 0, 0)}), "path.poses[1].header.stamp = 0"},
  };
  for (const auto& [bad, expected] : cases) {
    const std::string message = validatePathRequest(bad);
    EXPECT_NE(message.find(expected), std::string::npos)
        << "expected '" << expected << "' in '" << message << "'";
  }
}

TEST(PathRequest, PoseCountIsLimitedAtTheDocumentedLimit) {
  EXPECT_EQ(validatePathRequest(request(std::vector<PathPoseInput>(kMaxPathPoses, pose(0, 0)))),
            "");
  EXPECT_EQ(validatePathRequest(request(std::vector<PathPoseInput>(kMaxPathPoses + 1, pose(0, 0)))),
            "path.poses: expected at most 100000 poses, got 100001");
}

TEST(PathRequest, QuaternionToleranceIsTheDocumentedOne) {
  PathPoseInput within = pose(0, 0);
  within.qw = 1.0 + 0.9 * kQuaternionTolerance;
  EXPECT_EQ(validatePathRequest(request({within})), "");
  PathPoseInput beyond = pose(0, 0);
  beyond.qw = 1.0 + 1.1 * kQuaternionTolerance;
  EXPECT_NE(validatePathRequest(request({beyond})), "");
}

TEST(PathRequest, PosesBecomeHeadingsAndTimesFromTheFirstStamp) {
  bool timed = false;
  const auto poses =
      toPathPoses(request({pose(1, 2, 0.5, 100.0), pose(3, 4, -3.0, 101.5)}), &timed);
  EXPECT_TRUE(timed);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_NEAR(poses[0].yaw, 0.5, 1e-15);
  EXPECT_NEAR(poses[1].yaw, -3.0, 1e-15);
  EXPECT_EQ(poses[0].time, 0.0);
  EXPECT_EQ(poses[1].time, 1.5);
  toPathPoses(request({pose(0, 0), pose(1, 0)}), &timed);
  EXPECT_FALSE(timed);
}

/// Frames translated in the plane; unknown frames are unavailable.
FrameTransform translated(const std::map<std::string, Eigen::Vector2d>& table,
                          const std::string& frame) {
  FrameTransform t;
  const auto found = table.find(frame);
  if (found == table.end()) {
    t.error = "frame '" + frame + "' does not exist";
    return t;
  }
  t.ok = true;
  t.fixed_from_frame.translation() << found->second, 0.0;
  return t;
}

TEST(RunPathCheck, LinksMoveWithTheMovingFrameAndUnavailableFramesAreListed) {
  // The robot's frame is at (1, 0) in map now; its link 0.5 m ahead of it. Going 4 m along x
  // from map's origin, the link (0.2 m) meets the post (0.1 m) at x = 3: link centre at 2.7,
  // i.e. the frame at 2.2 of 4 m: fraction 0.55.
  const EllipseRegistry registry(
      {circle("nose", "base_link", 0.5, 0.0, 0.2), circle("lost", "camera", 0, 0, 0.1)},
      {circle("post", "map", 3.0, 0.0, 0.1)});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const TransformLookup to_moving = [](const std::string& f) {
    return translated({{"base_link", {0, 0}}}, f);
  };
  const TransformLookup to_map = [](const std::string& f) {
    return translated({{"map", {0, 0}}, {"base_link", {1, 0}}}, f);
  };
  const PathCheckOutcome outcome =
      runPathCheck(request({pose(0, 0), pose(4, 0)}), registry, settings, to_moving, to_map, 0.0);
  ASSERT_EQ(outcome.error, "");
  EXPECT_FALSE(outcome.result.collision_free);
  EXPECT_NEAR(outcome.result.fraction, 0.55, 1e-12);
  EXPECT_EQ(outcome.result.link, "nose");
  EXPECT_EQ(outcome.result.obstacle, "post");
  EXPECT_EQ(outcome.unavailable_frames, std::vector<std::string>{"camera"});
  EXPECT_NEAR(outcome.result.min_clearance, 3.0 - 0.1 - 0.7, 1e-12);

  PathCheckRequest unknown = request({pose(0, 0)});
  unknown.moving_frame = "nowhere";
  EXPECT_NE(runPathCheck(unknown, registry, settings, to_moving, to_map, 0.0)
                .error.find("moving_frame = 'nowhere'"),
            std::string::npos);
}

TEST(PredictAfterCheck, ALinkOnAMovingFrameIsPredictedToMeetAStandingObstacle) {
  // The arm frame moves at 2 m/s along x (its pose 0.1 s ago was 0.2 m behind); its hand
  // (0.1 m) and the post (0.1 m) are 1.2 m apart: 1.0 m of gap at 2 m/s, contact after 0.5 s.
  const EllipseRegistry registry(
      {circle("hand", "arm", 0.0, 0.0, 0.1)},
      {circle("post", "map", 1.2, 0.0, 0.1), circle("far", "map", 0.0, 5.0, 0.1)});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const auto latest = [](const std::string& f) {
    FrameTransform t = translated({{"map", {0, 0}}, {"arm", {0, 0}}}, f);
    if (f == "arm") t.stamp_s = 10.0;
    return t;
  };
  const TransformAtLookup at = [](const std::string& f, double time_s) {
    FrameTransform t = translated({{"map", {0, 0}}, {"arm", {2.0 * (time_s - 10.0), 0}}}, f);
    t.stamp_s = time_s;
    return t;
  };
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

}  // namespace
}  // namespace ellipse_collision::app

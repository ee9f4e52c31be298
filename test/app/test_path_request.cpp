// ~check_path's rules and orchestration without ROS (app/path_request.h) with transforms from a
// table. Expected values by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/path_request.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using test::circle;
using test::translated;

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

}  // namespace
}  // namespace ellipse_collision::app

#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/transform_lookup.h"
#include "ellipse_collision/core/path_check.h"

namespace ellipse_collision::app {

/// Most poses one ~check_path request may carry: 100,000 poses (a 10 km path at 10 cm spacing)
/// answer in well under a second; a longer path is refused, naming the count.
constexpr std::size_t kMaxPathPoses = 100000;
/// How far a pose's quaternion may be from unit length, | |q| - 1 | [-], and how far it may tilt
/// the moving frame out of the path frame's plane, sqrt(qx^2 + qy^2) / |q| (the sine of half the
/// tilt angle: 1e-3 is a tilt of about 0.11 deg). Beyond either, the pose is refused.
constexpr double kQuaternionTolerance = 1e-3;

/// One pose of a nav_msgs/Path as the application layer takes it.
struct PathPoseInput {
  std::string frame_id;  ///< the PoseStamped's own header.frame_id ("" or the path's frame)
  double stamp_s{0.0};   ///< header.stamp [s]; 0 = none
  double x{0.0}, y{0.0}, z{0.0};              ///< position [m]; z is ignored
  double qx{0.0}, qy{0.0}, qz{0.0}, qw{1.0};  ///< orientation
};

/// One ~check_path request.
struct PathCheckRequest {
  std::string path_frame;    ///< path.header.frame_id ("" = the fixed frame)
  std::string moving_frame;  ///< "" = the robot frame
  std::vector<PathPoseInput> poses;
};

/// The request's own rules, before any frame is looked up: 1 to kMaxPathPoses poses; every
/// position finite within core::kMaxCoordinate (z finite); every quaternion finite, within
/// kQuaternionTolerance of unit length and of a rotation about z; each pose's frame empty or the
/// path's; stamps all zero (a geometric path) or all non-zero and strictly increasing (a timed
/// path). Returns the first violation naming the field and value
/// ("path.poses[2].header.stamp = 1.5: expected ... after poses[1]'s 2"), or "".
std::string validatePathRequest(const PathCheckRequest& request);

/// The poses as the core takes them (heading from the quaternion, times from the first stamp).
/// Expects a request that passed validatePathRequest(); `timed` tells which kind it is.
std::vector<core::PathPose> toPathPoses(const PathCheckRequest& request, bool* timed);

/// The answer of one path check.
struct PathCheckOutcome {
  core::PathCheckResult result;
  std::vector<std::string> unavailable_frames;  ///< sorted; their ellipses were left out
  std::vector<std::string> skipped;             ///< why each left-out ellipse was left out
  /// Obstacle sources whose data is gone at the check ("source 'rear_scan' silent for 0.8 s
  /// (timeout 0.5 s)"): the path was checked without what they would have seen.
  std::vector<std::string> silent_sources;
  /// Every stored ellipse placed (none unavailable or skipped) and no source silent: an answer
  /// that leaves nothing out.
  bool complete() const {
    return unavailable_frames.empty() && skipped.empty() && silent_sources.empty();
  }
  std::string error;                            ///< a refused request: nothing checked
  ErrorKind error_kind{ErrorKind::None};        ///< what kind of failure `error` is
};

/// Places the links in the moving frame's plane through `to_moving` (each link rigidly by its
/// current transform to the moving frame) and the obstacles in the path frame's plane through
/// `to_path`, both padded as in runCheck(), then checks the path with core::checkPath(). On a
/// timed path the obstacles move by their own velocity (vx, vy, angular_velocity, turned into the
/// path frame), from where they are at `now_s` (same clock as the stamps): at path time t an
/// obstacle is displaced by its velocity times (first stamp - now_s + t). A moving frame or path
/// frame without a transform fails the request; a link or obstacle frame without one is left out
/// and listed. Expects a request that passed validatePathRequest(), with path_frame and
/// moving_frame filled in.
PathCheckOutcome runPathCheck(const PathCheckRequest& request, const EllipseRegistry& registry,
                              const CheckSettings& settings, const TransformLookup& to_moving,
                              const TransformLookup& to_path, double now_s);

}  // namespace ellipse_collision::app

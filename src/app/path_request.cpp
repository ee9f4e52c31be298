#include "ellipse_collision/app/path_request.h"

#include <cmath>
#include <set>

#include "ellipse_collision/app/frame_placer.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

using core::formatNumber;

std::string validatePathRequest(const PathCheckRequest& request) {
  const std::size_t n = request.poses.size();
  if (n == 0) return "path.poses: expected at least one pose, got an empty path";
  if (n > kMaxPathPoses) {
    return "path.poses: expected at most " + std::to_string(kMaxPathPoses) + " poses, got " +
           std::to_string(n);
  }
  const bool timed = request.poses.front().stamp_s != 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const PathPoseInput& p = request.poses[i];
    const std::string at = "path.poses[" + std::to_string(i) + "]";
    if (!p.frame_id.empty() && p.frame_id != request.path_frame) {
      return at + ".header.frame_id = '" + p.frame_id + "': expected '' or the path's frame '" +
             request.path_frame + "'";
    }
    const std::pair<const char*, double> position[] = {{"x", p.x}, {"y", p.y}};
    for (const auto& [key, value] : position) {
      if (!core::coordinateOk(value)) {
        return at + ".pose.position." + key + " = " + formatNumber(value) +
               ": expected a finite number within [" + formatNumber(-core::kMaxCoordinate) + ", " +
               formatNumber(core::kMaxCoordinate) + "]";
      }
    }
    if (!std::isfinite(p.z))
      return at + ".pose.position.z = " + formatNumber(p.z) + ": expected a finite number";
    const std::pair<const char*, double> quaternion[] = {
        {"x", p.qx}, {"y", p.qy}, {"z", p.qz}, {"w", p.qw}};
    for (const auto& [key, value] : quaternion) {
      if (!std::isfinite(value)) {
        return at + ".pose.orientation." + key + " = " + formatNumber(value) +
               ": expected a finite number";
      }
    }
    const double norm = std::sqrt(p.qx * p.qx + p.qy * p.qy + p.qz * p.qz + p.qw * p.qw);
    const std::string q = "(" + formatNumber(p.qx) + ", " + formatNumber(p.qy) + ", " +
                          formatNumber(p.qz) + ", " + formatNumber(p.qw) + ")";
    if (!(std::fabs(norm - 1.0) <= kQuaternionTolerance)) {
      return at + ".pose.orientation = " + q +
             ": expected a unit quaternion (| |q| - 1 | <= " + formatNumber(kQuaternionTolerance) +
             "), got |q| = " + formatNumber(norm);
    }
    const double tilt = std::hypot(p.qx, p.qy) / norm;
    if (!(tilt <= kQuaternionTolerance)) {
      return at + ".pose.orientation = " + q +
             ": expected a rotation about z only (sqrt(x^2 + y^2) / |q| <= " +
             formatNumber(kQuaternionTolerance) + "), got one that tilts out of the plane (" +
             formatNumber(tilt) + ")";
    }
    const std::string stamp = at + ".header.stamp = " + formatNumber(p.stamp_s);
    if (!timed && p.stamp_s != 0.0) {
      return stamp + ": expected 0 like poses[0]'s (all stamps zero: a geometric path)";
    }
    if (timed && i > 0 && !(p.stamp_s > request.poses[i - 1].stamp_s)) {
      return stamp + ": expected strictly increasing stamps (a timed path), after poses[" +
             std::to_string(i - 1) + "]'s " + formatNumber(request.poses[i - 1].stamp_s);
    }
  }
  return {};
}

std::vector<core::PathPose> toPathPoses(const PathCheckRequest& request, bool* timed) {
  std::vector<core::PathPose> poses;
  poses.reserve(request.poses.size());
  *timed = !request.poses.empty() && request.poses.front().stamp_s != 0.0;
  const double start = request.poses.empty() ? 0.0 : request.poses.front().stamp_s;
  for (const PathPoseInput& p : request.poses) {
    // The heading of a rotation about z (the tilt is within the tolerance): 2 atan2(qz, qw).
    poses.push_back({p.x, p.y, 2.0 * std::atan2(p.qz, p.qw), *timed ? p.stamp_s - start : 0.0});
  }
  return poses;
}

PathCheckOutcome runPathCheck(const PathCheckRequest& request, const EllipseRegistry& registry,
                              const CheckSettings& settings, const TransformLookup& to_moving,
                              const TransformLookup& to_path, double now_s) {
  PathCheckOutcome outcome;
  const FrameTransform moving = to_path(request.moving_frame);
  if (!moving.ok) {
    outcome.error_kind = ErrorKind::FrameUnavailable;
    outcome.error = "moving_frame = '" + request.moving_frame + "', path.header.frame_id = '" +
                    request.path_frame +
                    "': expected two frames with a transform between them, got none (" +
                    moving.error + ")";
    return outcome;
  }
  bool timed = false;
  const std::vector<core::PathPose> poses = toPathPoses(request, &timed);
  const Freshness freshness{settings.max_transform_age_s, now_s};
  FramePlacer links(to_moving, settings.global_padding_m, freshness);
  FramePlacer obstacles(to_path, settings.global_padding_m, freshness);
  core::PathScene scene;
  scene.allowed = settings.rules.allowed;
  std::set<std::string> unavailable;
  // On a timed path, obstacles are moved from now to the first pose's time.
  const double lead_s = timed ? request.poses.front().stamp_s - now_s : 0.0;
  for (const auto& [name, stored] : registry.entries()) {
    const bool is_link = stored.role() == core::EllipseRole::Link;
    FramePlacer& placement = is_link ? links : obstacles;
    const FramePlacer::Placement placed = placement.place(stored.spec, stored.role());
    if (placed.status != FramePlacer::Status::Placed) {
      // As runCheck() words it: the frame, not tf's message about the target frame.
      if (placed.status == FramePlacer::Status::FrameUnavailable) {
        unavailable.insert(stored.spec.frame_id);
        outcome.skipped.push_back(name + ": frame '" + stored.spec.frame_id + "' unavailable");
      } else {
        outcome.skipped.push_back(name + ": " + placed.error);
      }
      continue;
    }
    if (is_link) {
      scene.links.push_back(placed.ellipse);
      continue;
    }
    const core::Motion motion =
        ownMotion(stored.spec, placement.lookup(stored.spec.frame_id).fixed_from_frame);
    core::NamedEllipse obstacle = placed.ellipse;
    if (timed) {
      const std::string invalid =
          core::invalidSegmentReason(obstacle.ellipse, motion, std::fabs(lead_s));
      if (!invalid.empty()) {
        outcome.error_kind = ErrorKind::InvalidRequest;
        outcome.error = "obstacle '" + name + "' moved to the first pose's time: " + invalid;
        return outcome;
      }
      obstacle.ellipse = core::movedBy(obstacle.ellipse, motion, lead_s);
    }
    scene.obstacles.push_back(obstacle);
    scene.obstacle_motions.push_back(motion);
  }
  outcome.unavailable_frames.assign(unavailable.begin(), unavailable.end());
  outcome.result = core::checkPath(scene, poses, timed);
  if (!outcome.result.ok()) {
    // The core refuses a path whose obstacles' motion breaks its limits over a segment: the
    // request's times, not a bug.
    outcome.error_kind = ErrorKind::InvalidRequest;
    outcome.error = outcome.result.error;
  }
  return outcome;
}

}  // namespace ellipse_collision::app

#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core {

/// What a path check is given: links in the moving frame's plane, obstacles in the path frame's
/// plane where they are at the first pose, with their motion (used on timed paths only).
struct PathScene {
  std::vector<NamedEllipse> links;       ///< in the moving frame
  std::vector<NamedEllipse> obstacles;   ///< in the path frame, at the first pose's time
  std::vector<Motion> obstacle_motions;  ///< one per obstacle, in the path frame [m/s, rad/s]
  AllowedPairs allowed;                  ///< link-obstacle pairs never reported
};

/// The answer of checkPath().
struct PathCheckResult {
  bool collision_free{true};
  std::size_t segment{0};  ///< first contact between poses[segment] and poses[segment + 1]
  double fraction{0.0};    ///< of that segment, in [0, 1] (by time on timed paths)
  double time{0.0};        ///< [s] from the first pose (timed paths; 0 otherwise)
  std::string link;        ///< the first pair to touch (ties: smallest link, then obstacle name)
  std::string obstacle;
  /// The smallest distance() between a link and an obstacle at the poses up to the first
  /// contact (all poses when collision-free); has_clearance false when there is no pair.
  bool has_clearance{false};
  double min_clearance{0.0};  ///< [m]
  std::size_t min_clearance_pose{0};
  std::string clearance_link;
  std::string clearance_obstacle;
  std::string error;  ///< why the path could not be checked; nothing else is set then
  /// Pair tests done (segmentContact() and distance() calls): a statistic for tests and
  /// benchmarks, not part of the answer.
  std::size_t pair_tests{0};
  bool ok() const { return error.empty(); }
};

/// Checks a path of the moving frame continuously: every segment between consecutive poses
/// (segmentMotion(): straight line, shortest turn) against every link-obstacle pair not allowed,
/// with segmentContact(), never by sampling. `timed`: poses carry strictly increasing times from
/// 0 and obstacles move by their motion (an obstacle at time t is movedBy(obstacle, motion, t));
/// otherwise the path is geometric, obstacles stand still and each segment's tau is its fraction.
/// Link-link pairs are not checked: the links move rigidly together, so they do not change along
/// the path (~check_collisions reports them).
/// Broadphase: a BoxGrid over the standing obstacles' bounding-circle boxes, queried with each
/// link's swept box per segment (sweptLinkBox()); moving obstacles are tested by their own swept
/// box (sweptBox()) per segment. Only pairs whose swept boxes meet are given to segmentContact().
/// The minimum clearance is measured with distance() at the poses up to the segment of first
/// contact (poses[0 .. segment]); pairs whose bounding circles are farther apart than the best
/// distance so far are ruled out without a distance() call.
/// Preconditions: at least one pose; valid ellipses; finite poses within kMaxCoordinate; on timed
/// paths strictly increasing times starting at 0. A pair whose obstacle motion breaks
/// firstContact()'s limits over a segment (invalidSegmentReason()) makes the result an error.
PathCheckResult checkPath(const PathScene& scene, const std::vector<PathPose>& poses, bool timed);

}  // namespace ellipse_collision::core

#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <string>

namespace ellipse_collision::app {

/// The pose of one frame in the fixed frame, or why there is none.
struct FrameTransform {
  bool ok{false};
  Eigen::Isometry3d fixed_from_frame{Eigen::Isometry3d::Identity()};
  std::string error;  ///< why not, when !ok (the tf error)
  /// When the pose was measured [s, the caller's clock]; 0 = timeless (a chain of static
  /// transforms, or the frame itself), which never goes stale (isStale()).
  double stamp_s{0.0};
};

/// The freshness rule of one check: a transform measured more than `max_age_s` before
/// `reference_s` (now for latest-transform checks, the requested stamp otherwise) is stale.
struct Freshness {
  double max_age_s{0.0};    ///< [s]; 0 = off (nothing is ever stale)
  double reference_s{0.0};  ///< [s], on the same clock as FrameTransform::stamp_s
};

/// True iff `transform` was found but is older than the rule allows. Timeless transforms
/// (stamp 0) and a rule that is off are never stale.
bool isStale(const FrameTransform& transform, const Freshness& freshness);

/// How old `transform` is at the rule's reference time [s] (0 for a timeless one).
double ageOf(const FrameTransform& transform, const Freshness& freshness);

/// How the application layer asks for transforms. The ROS layer binds tf, the fixed frame, the
/// time and the timeout into one of these; tests and fuzzers pass a table of poses. A frame is its
/// own identity transform, so ellipses given in the fixed frame need no lookup at all.
using TransformLookup = std::function<FrameTransform(const std::string& frame)>;

/// A frame's pose in the fixed frame at a given time [s, same clock as FrameTransform::stamp_s].
using TransformAtLookup = std::function<FrameTransform(const std::string& frame, double time_s)>;

}  // namespace ellipse_collision::app

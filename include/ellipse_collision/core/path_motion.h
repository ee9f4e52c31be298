#pragma once

#include <Eigen/Core>

#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"

namespace ellipse_collision::core {

/// One pose of a planar path of a moving frame: position [m] and heading [rad] in the path's
/// frame, and its time [s] from the first pose (0 for every pose of a geometric path).
struct PathPose {
  double x{0.0};
  double y{0.0};
  double yaw{0.0};
  double time{0.0};
};

/// The rigid motion of the moving frame between two poses: its origin on the straight line, its
/// heading by the shortest rotation about z, both uniform in the segment's parameter
/// tau in [0, duration] (seconds on a timed path, the fraction of the segment on a geometric one).
struct SegmentMotion {
  Eigen::Vector2d start{0.0, 0.0};     ///< origin at tau = 0 [m]
  Eigen::Vector2d velocity{0.0, 0.0};  ///< of the origin [m per unit of tau]
  double start_yaw{0.0};               ///< [rad]
  double yaw_rate{0.0};                ///< [rad per unit of tau], |yaw_rate| * duration <= pi
  double duration{1.0};                ///< > 0
};

/// to_yaw - from_yaw wrapped into [-pi, pi] [rad]: the shortest rotation about z.
double shortestRotation(double from_yaw, double to_yaw);

/// The motion from `from` to `to` taking `duration` (> 0) units of tau.
SegmentMotion segmentMotion(const PathPose& from, const PathPose& to, double duration);

/// `in_moving` (an ellipse in the moving frame's plane) when the moving frame is at `position`
/// with heading `yaw`.
Ellipse placeAt(const Ellipse& in_moving, const Eigen::Vector2d& position, double yaw);

/// `e` after `tau` of `motion` (its centre on the line, its angle turned uniformly).
Ellipse movedBy(const Ellipse& e, const Motion& motion, double tau);

/// Swept bound of an ellipse moving by `motion` over [0, horizon]: the box around its bounding
/// circle at both ends (a turn about its own centre never leaves the bounding circle, so rotation
/// adds nothing), widened like boundingCircleBox(). It contains the ellipse at every time of the
/// interval.
BoundingBox sweptBox(const Ellipse& e, const Motion& motion, double horizon);

/// Swept bound of a link rigidly attached to the moving frame over one segment: the boxes of its
/// bounding circle at both ends, grown by the sagitta |c| (1 - cos(dyaw / 2)) of the arc its
/// centre c (in the moving frame) describes about the frame's origin. The centre's path is that
/// arc carried along the straight line, so it never leaves the chord's box grown by the sagitta.
BoundingBox sweptLinkBox(const Ellipse& link_in_moving, const SegmentMotion& motion);

/// First contact over one segment of a link rigidly attached to the moving frame (given in the
/// moving frame's plane) with an obstacle that is at `obstacle` at tau = 0 and moves by
/// `obstacle_motion` (per unit of tau). The time is in units of tau, within [0, duration].
///  - The link's centre on the frame's origin, or no turn: the link's motion is a core Motion and
///    firstContact() answers (exact for translation, certified for rotation).
///  - An offset link that turns (its centre on an arc carried along the line): firstContact()'s
///    rotating method on that motion, never late, within 2.5e-10 * duration of the first contact
///    (doc/core_methods.md).
/// Precondition: firstContact()'s (invalidMotionReason()) for the obstacle's motion over the
/// duration; see invalidSegmentReason().
FirstContact segmentContact(const Ellipse& link_in_moving, const SegmentMotion& motion,
                            const Ellipse& obstacle, const Motion& obstacle_motion);

/// Why segmentContact() cannot be called for this pair ("" when it can): the obstacle's motion
/// over the duration breaks firstContact()'s limits (invalidMotionReason()).
std::string invalidSegmentReason(const Ellipse& obstacle, const Motion& obstacle_motion,
                                 double duration);

}  // namespace ellipse_collision::core

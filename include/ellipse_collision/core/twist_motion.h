#pragma once

#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/path_motion.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core {

// A robot frame moving by a held planar twist, and its links' first contact with an obstacle
// (the velocity gate's kinematics; the method is described in doc/core_library.md, "Twists").

/// A planar velocity command in the robot frame, held constant: the robot frame then follows
/// exp(t * twist), an arc about the instantaneous centre of rotation (a line when wz = 0).
struct Twist {
  double vx{0.0};  ///< velocity of the frame's origin along its x axis [m/s]
  double vy{0.0};  ///< along its y axis [m/s]
  double wz{0.0};  ///< counter-clockwise turn rate [rad/s]
};

/// `twist` scaled by `k` (every component): the same arc, followed k times as fast.
Twist scaled(const Twist& twist, double k);

/// The robot frame's pose after `t` [s] of `twist`, in the frame at t = 0 (time = t); exact for a
/// tiny wz or a far instantaneous centre (no 1 - cos, no division by wz).
PathPose poseAfter(const Twist& twist, double t);

/// A link (in the robot frame at t = 0) after `t` [s] of `twist`.
Ellipse linkAfter(const Ellipse& link, const Twist& twist, double t);

/// Every link after `t` [s] of `twist`, names and roles kept: the robot drawn at a predicted
/// contact.
std::vector<NamedEllipse> linksAtTime(const std::vector<NamedEllipse>& links, const Twist& twist,
                                      double t);

/// Why `twist` cannot be held over `horizon` (finite, >= 0), naming the field and value
/// ("twist.vx = nan must be finite"), or "": firstContact()'s velocity limits.
std::string invalidTwistReason(const Twist& twist, double horizon);

/// Why twistContact() cannot be called with these arguments, naming the part, field and value
/// ("link: radius_x = 0 must be > 0", "obstacle: velocity.y = inf must be finite"), or "": an
/// ellipse, the horizon, the twist or the obstacle's motion invalid, or the link able to leave
/// kMaxCoordinate within the horizon.
std::string invalidTwistContactReason(const Ellipse& link, const Twist& twist,
                                      const Ellipse& obstacle, const Motion& obstacle_motion,
                                      double horizon);

/// The first time in [0, horizon] [s] at which `link`, rigidly attached to the robot frame moving
/// by `twist`, touches `obstacle` moving by `obstacle_motion` (containment and a shared boundary
/// point count); {true, 0} when they overlap now. Exact for wz = 0 and an obstacle that does not
/// turn, certified never late otherwise, within 2.5e-10 * horizon.
/// Precondition: invalidTwistContactReason() is empty (otherwise unspecified, but it returns).
FirstContact twistContact(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                          const Motion& obstacle_motion, double horizon);

}  // namespace ellipse_collision::core

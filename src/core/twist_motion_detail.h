#pragma once

#include <string>

#include "ellipse_collision/core/twist_motion.h"
#include "rotating_contact.h"

namespace ellipse_collision::core::detail {

/// The link as `a` of a rotating pair: its centre on the arc of the robot frame's twist, its
/// whole velocity v + wz z x c turning with the frame (the rotating method's `a_arc_velocity`).
RotatingPair twistPair(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                       const Motion& obstacle_motion);

/// twistContact() over `horizon` when its contact comes at or before `until` [s], no contact
/// otherwise: the same steps, stopped once the next one would pass `until`, so that a search for
/// the earliest of many pairs stops each at the earliest found so far with the horizon's time.
FirstContact twistContactUntil(const Ellipse& link, const Twist& twist, const Ellipse& obstacle,
                               const Motion& obstacle_motion, double horizon, double until);

/// Why `link` could leave kMaxCoordinate within `horizon` under `twist` (|centre| + R + |v| H:
/// an arc is no longer than the line), or "".
std::string linkReachReason(const Ellipse& link, const Twist& twist, double horizon);

}  // namespace ellipse_collision::core::detail

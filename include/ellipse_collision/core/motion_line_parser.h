#pragma once

#include <string>
#include <string_view>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/first_contact.h"

namespace ellipse_collision::core {

/// One line of `check_ellipses --motion` input:
/// `cx1 cy1 rx1 ry1 angle1 vx1 vy1 w1 cx2 cy2 rx2 ry2 angle2 vx2 vy2 w2 horizon`
/// (centres and radii in m, angles in rad, velocities in m/s, angular velocities in rad/s about
/// the centre, horizon in s).
struct MotionLine {
  enum class Kind { Motion, Skip, Error };
  Kind kind{Kind::Skip};  ///< Skip: blank line or `#` comment
  Ellipse first;
  Motion first_motion;
  Ellipse second;
  Motion second_motion;
  double horizon{0.0};  ///< [s]
  std::string error;    ///< why the line is bad, when kind == Error
};

/// Parses one line (without its newline; a trailing '\r' is ignored), like parsePairLine(): fields
/// separated by runs of spaces and tabs, '#' starts a comment line, numbers read with
/// std::from_chars (one optional leading '+'). Errors name the field and value: `expected 17
/// fields, got 9`, `field 6 (vx1) is not a number: "abc"`, `field 17 (horizon) is out of the range
/// of a double: "1e999"`, or invalidMotionReason() for values firstContact() refuses ("ellipse 1:
/// radius_x = -1 must be > 0", "horizon = -1 must be >= 0", "motion 2: angular_velocity = inf
/// must be finite"). The first problem found is reported.
MotionLine parseMotionLine(std::string_view line);

}  // namespace ellipse_collision::core

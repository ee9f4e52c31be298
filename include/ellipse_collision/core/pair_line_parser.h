#pragma once

#include <string>
#include <string_view>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// One line of check_ellipses input: `cx1 cy1 rx1 ry1 angle1 cx2 cy2 rx2 ry2 angle2`
/// (centres and radii in m, angles in rad; fields 1-5 are ellipse 1, fields 6-10 ellipse 2).
struct PairLine {
  enum class Kind { Pair, Skip, Error };
  Kind kind{Kind::Skip};  ///< Skip: blank line or `#` comment
  Ellipse first;
  Ellipse second;
  std::string error;  ///< why the line is bad, when kind == Error
};

/// Parses one line (without its newline; a trailing '\r' is ignored). Fields are separated by runs
/// of spaces and tabs; a line whose first non-blank character is '#' is a comment. Numbers are read
/// with std::from_chars (C syntax whatever the locale, one optional leading '+'). Errors name the
/// field: `expected 10 fields, got 9`, `field 3 (rx1) is not a number: "abc"`, `field 1 (cx1) is
/// out of the range of a double: "1e999"`, or `ellipse 1: ` / `ellipse 2: ` followed by
/// invalidReason() for a value the core rejects (not finite, radius <= 0, out of its range). The
/// first problem found is reported.
PairLine parsePairLine(std::string_view line);

}  // namespace ellipse_collision::core

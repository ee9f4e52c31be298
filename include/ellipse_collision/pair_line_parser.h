#pragma once

#include <string>
#include <string_view>

#include "ellipse_collision/ellipse.h"

namespace ellipse_collision {

/// One line of check_ellipses input: `cx1 cy1 rx1 ry1 angle1 cx2 cy2 rx2 ry2 angle2`.
struct PairLine {
  enum class Kind { Pair, Skip, Error };
  Kind kind{Kind::Skip};  ///< Skip: blank line or `#` comment
  Ellipse first;
  Ellipse second;
  std::string error;      ///< why the line is bad, when kind == Error
};

/// Parses one line (without its newline; a trailing '\r' is ignored). Numbers are read with the C
/// locale's syntax; non-finite values and radii <= 0 are errors naming the field.
PairLine parsePairLine(std::string_view line);

}  // namespace ellipse_collision

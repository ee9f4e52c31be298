#pragma once

// The last step of every certification in the core (enclosing_ellipse.cpp, ellipsoid.cpp,
// enclosing_ellipsoid.cpp): a length computed in long double, stored as a double that is no
// smaller. Internal to the core (src/core).

#include <cmath>
#include <limits>

namespace ellipse_collision::core::detail {

/// The smallest double >= `value`.
inline double roundedUp(long double value) {
  const double d = static_cast<double>(value);
  return d < value ? std::nextafter(d, std::numeric_limits<double>::infinity()) : d;
}

}  // namespace ellipse_collision::core::detail

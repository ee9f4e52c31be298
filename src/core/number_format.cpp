#include "ellipse_collision/core/number_format.h"

#include <array>
#include <charconv>
#include <cmath>

namespace ellipse_collision::core {

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";  // the sign of a NaN means nothing to a user
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  // to_chars without a precision is the shortest round-trip form, and ignores the locale.
  std::array<char, 64> buffer;
  const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
  return std::string(buffer.data(), end);
}

}  // namespace ellipse_collision::core

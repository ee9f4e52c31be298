#include "ellipse_collision/core/number_format.h"

#include <array>
#include <charconv>
#include <cmath>
#include <string>

namespace ellipse_collision::core {

std::string formatNumber(double value) {
  std::string text;
  appendNumber(text, value);
  return text;
}

void appendNumber(std::string& out, double value) {
  if (std::isnan(value)) {  // the sign of a NaN means nothing to a user
    out += "nan";
  } else if (std::isinf(value)) {
    out += value > 0 ? "inf" : "-inf";
  } else {
    // to_chars without a precision is the shortest round-trip form, and ignores the locale.
    std::array<char, 64> buffer;
    const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
    out.append(buffer.data(), end);
  }
}

}  // namespace ellipse_collision::core

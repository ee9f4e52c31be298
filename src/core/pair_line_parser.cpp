#include "ellipse_collision/core/pair_line_parser.h"

#include <array>
#include <string>
#include <utility>

#include "ellipse_collision/core/number_fields.h"

namespace ellipse_collision::core {
namespace {

constexpr std::size_t kFieldCount = 10;
constexpr std::array<const char*, kFieldCount> kFieldNames = {"cx1", "cy1", "rx1", "ry1", "angle1",
                                                              "cx2", "cy2", "rx2", "ry2", "angle2"};

PairLine errorLine(std::string message) {
  PairLine result;
  result.kind = PairLine::Kind::Error;
  result.error = std::move(message);
  return result;
}

}  // namespace

PairLine parsePairLine(std::string_view line) {
  std::array<double, kFieldCount> values{};
  std::string error;
  switch (parseNumberFields(line, kFieldNames.data(), kFieldCount, values.data(), error)) {
    case NumberFields::Skip:
      return PairLine{};
    case NumberFields::Error:
      return errorLine(std::move(error));
    case NumberFields::Numbers:
      break;
  }
  PairLine result;
  result.kind = PairLine::Kind::Pair;
  result.first = Ellipse{Eigen::Vector2d(values[0], values[1]), values[2], values[3], values[4]};
  result.second = Ellipse{Eigen::Vector2d(values[5], values[6]), values[7], values[8], values[9]};
  // Validity (finite fields, radii > 0) is the core's rule: reuse it rather than restate it.
  if (std::string reason = invalidReason(result.first); !reason.empty()) {
    return errorLine("ellipse 1: " + reason);
  }
  if (std::string reason = invalidReason(result.second); !reason.empty()) {
    return errorLine("ellipse 2: " + reason);
  }
  return result;
}

}  // namespace ellipse_collision::core

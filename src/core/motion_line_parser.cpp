#include "ellipse_collision/core/motion_line_parser.h"

#include <array>
#include <string>
#include <utility>

#include "ellipse_collision/core/number_fields.h"

namespace ellipse_collision::core {
namespace {

constexpr std::size_t kFieldCount = 17;
constexpr std::array<const char*, kFieldCount> kFieldNames = {
    "cx1", "cy1", "rx1", "ry1", "angle1", "vx1", "vy1", "w1", "cx2",
    "cy2", "rx2", "ry2", "angle2", "vx2", "vy2", "w2", "horizon"};

MotionLine failure(std::string message) {
  MotionLine result;
  result.kind = MotionLine::Kind::Error;
  result.error = std::move(message);
  return result;
}

}  // namespace

MotionLine parseMotionLine(std::string_view line) {
  std::array<double, kFieldCount> v{};
  std::string error;
  switch (parseNumberFields(line, kFieldNames.data(), kFieldCount, v.data(), error)) {
    case NumberFields::Skip:
      return {};
    case NumberFields::Error:
      return failure(std::move(error));
    case NumberFields::Numbers:
      break;
  }
  MotionLine result;
  result.kind = MotionLine::Kind::Motion;
  result.first = Ellipse{{v[0], v[1]}, v[2], v[3], v[4]};
  result.first_motion = Motion{{v[5], v[6]}, v[7]};
  result.second = Ellipse{{v[8], v[9]}, v[10], v[11], v[12]};
  result.second_motion = Motion{{v[13], v[14]}, v[15]};
  result.horizon = v[16];
  // The value rules are firstContact()'s own: reuse them rather than restate them.
  if (std::string reason = invalidMotionReason(result.first, result.first_motion, result.second,
                                               result.second_motion, result.horizon);
      !reason.empty()) {
    return failure(std::move(reason));
  }
  return result;
}

}  // namespace ellipse_collision::core

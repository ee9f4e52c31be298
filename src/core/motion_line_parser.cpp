#include "ellipse_collision/core/motion_line_parser.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <string>
#include <system_error>
#include <utility>

namespace ellipse_collision::core {
namespace {

constexpr std::size_t kFieldCount = 17;
constexpr std::array<const char*, kFieldCount> kFieldNames = {
    "cx1", "cy1", "rx1", "ry1", "angle1", "vx1", "vy1", "w1", "cx2",
    "cy2", "rx2", "ry2", "angle2", "vx2", "vy2", "w2", "horizon"};

// Quoted fields are cut so that a megabyte of garbage does not become a megabyte of message.
constexpr std::size_t kMaxQuotedChars = 40;

bool isBlank(char c) { return c == ' ' || c == '\t'; }

MotionLine failure(std::string message) {
  MotionLine result;
  result.kind = MotionLine::Kind::Error;
  result.error = std::move(message);
  return result;
}

// The field as written, shortened, with control bytes escaped so the message stays on one line.
std::string quoted(std::string_view field) {
  std::string text = "\"";
  const std::size_t shown = std::min(field.size(), kMaxQuotedChars);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto byte = static_cast<unsigned char>(field[i]);
    if (byte < 0x20 || byte == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      text += "\\x";
      text += kHex[byte >> 4];
      text += kHex[byte & 0xf];
    } else {
      if (byte == '"' || byte == '\\') text += '\\';
      text += field[i];
    }
  }
  if (shown < field.size()) text += "...";
  return text + '"';
}

std::string label(std::size_t index) {
  return "field " + std::to_string(index + 1) + " (" + kFieldNames[index] + ")";
}

// "" on success, else why the field is not a double.
std::string readNumber(std::string_view field, std::size_t index, double& value) {
  std::string_view digits = field;
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') {
    digits.remove_prefix(1);  // from_chars refuses the '+' people write
  }
  const char* const end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    return label(index) + " is out of the range of a double: " + quoted(field);
  }
  if (ec != std::errc() || ptr != end) return label(index) + " is not a number: " + quoted(field);
  return {};
}

}  // namespace

MotionLine parseMotionLine(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::array<std::string_view, kFieldCount> fields;
  std::size_t count = 0;
  for (std::size_t pos = 0; pos < line.size();) {
    while (pos < line.size() && isBlank(line[pos])) ++pos;
    if (pos == line.size()) break;
    std::size_t end = pos;
    while (end < line.size() && !isBlank(line[end])) ++end;
    if (count == 0 && line[pos] == '#') return {};  // comment, even if indented
    if (count < kFieldCount) fields[count] = line.substr(pos, end - pos);
    ++count;
    pos = end;
  }
  if (count == 0) return {};
  if (count != kFieldCount) {
    return failure("expected " + std::to_string(kFieldCount) + " fields, got " +
                   std::to_string(count));
  }
  std::array<double, kFieldCount> v{};
  for (std::size_t i = 0; i < kFieldCount; ++i) {
    if (std::string reason = readNumber(fields[i], i, v[i]); !reason.empty()) {
      return failure(std::move(reason));
    }
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

#include "ellipse_collision/core/pair_line_parser.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <string>
#include <system_error>
#include <utility>

namespace ellipse_collision::core {
namespace {

constexpr std::size_t kFieldCount = 10;
constexpr std::array<const char*, kFieldCount> kFieldNames = {"cx1", "cy1", "rx1", "ry1", "angle1",
                                                              "cx2", "cy2", "rx2", "ry2", "angle2"};

// Quoted fields are cut so that a megabyte of garbage does not become a megabyte of message.
constexpr std::size_t kMaxQuotedChars = 40;

bool isSeparator(char c) { return c == ' ' || c == '\t'; }

PairLine errorLine(std::string message) {
  PairLine result;
  result.kind = PairLine::Kind::Error;
  result.error = std::move(message);
  return result;
}

// The field as written, cut to kMaxQuotedChars, with control bytes escaped so that the
// message stays on one line.
std::string quote(std::string_view field) {
  std::string quoted = "\"";
  const std::size_t shown = std::min(field.size(), kMaxQuotedChars);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto byte = static_cast<unsigned char>(field[i]);
    if (byte < 0x20 || byte == 0x7f) {
      static constexpr char kHex[] = "0123456789abcdef";
      quoted += "\\x";
      quoted += kHex[byte >> 4];
      quoted += kHex[byte & 0xf];
    } else if (byte == '"' || byte == '\\') {
      quoted += '\\';
      quoted += field[i];
    } else {
      quoted += field[i];
    }
  }
  if (shown < field.size()) quoted += "...";
  quoted += '"';
  return quoted;
}

std::string fieldLabel(std::size_t index) {
  return "field " + std::to_string(index + 1) + " (" + kFieldNames[index] + ")";
}

// Parses one field into `value`; returns an empty string on success, else why it failed.
// from_chars rejects a leading '+', which people do write, so one is skipped here; "nan" and
// "inf" parse and are rejected later by invalidReason() as non-finite.
std::string parseField(std::string_view field, std::size_t index, double& value) {
  std::string_view digits = field;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') {
    digits.remove_prefix(1);
  }
  const char* const end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    return fieldLabel(index) + " is out of the range of a double: " + quote(field);
  }
  if (ec != std::errc() || ptr != end) {
    return fieldLabel(index) + " is not a number: " + quote(field);
  }
  return {};
}

}  // namespace

PairLine parsePairLine(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);

  // Split on runs of spaces/tabs. Fields beyond the tenth are only counted, for the message.
  std::array<std::string_view, kFieldCount> fields;
  std::size_t count = 0;
  std::size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && isSeparator(line[pos])) ++pos;
    if (pos == line.size()) break;
    std::size_t end = pos;
    while (end < line.size() && !isSeparator(line[end])) ++end;
    if (count == 0 && line[pos] == '#') return PairLine{};  // comment, even if indented
    if (count < kFieldCount) fields[count] = line.substr(pos, end - pos);
    ++count;
    pos = end;
  }
  if (count == 0) return PairLine{};  // blank line
  if (count != kFieldCount) {
    return errorLine("expected " + std::to_string(kFieldCount) + " fields, got " +
                     std::to_string(count));
  }

  std::array<double, kFieldCount> values{};
  for (std::size_t i = 0; i < kFieldCount; ++i) {
    std::string reason = parseField(fields[i], i, values[i]);
    if (!reason.empty()) return errorLine(std::move(reason));
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

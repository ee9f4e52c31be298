#include "ellipse_collision/core/number_fields.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <system_error>
#include <utility>

namespace ellipse_collision::core {
namespace {

// Quoted fields are cut so that a megabyte of garbage does not become a megabyte of message.
constexpr std::size_t kMaxQuotedChars = 40;

bool isSeparator(char c) { return c == ' ' || c == '\t'; }

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

std::string fieldLabel(const char* const* names, std::size_t index) {
  return "field " + std::to_string(index + 1) + " (" + names[index] + ")";
}

// Parses one field into `value`; returns an empty string on success, else why it failed.
// from_chars rejects a leading '+', which people do write, so one is skipped here; "nan" and
// "inf" parse and are refused later by the caller's value rules as non-finite.
std::string parseField(std::string_view field, const char* const* names, std::size_t index,
                       double& value) {
  std::string_view digits = field;
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') {
    digits.remove_prefix(1);
  }
  const char* const end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) {
    return fieldLabel(names, index) + " is out of the range of a double: " + quote(field);
  }
  if (ec != std::errc() || ptr != end) {
    return fieldLabel(names, index) + " is not a number: " + quote(field);
  }
  return {};
}

}  // namespace

NumberFields parseNumberFields(std::string_view line, const char* const* names, std::size_t count,
                               double* values, std::string& error) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  // Split on runs of spaces/tabs; each field is parsed as it is found, fields beyond `count` are
  // only counted, for the message.
  std::size_t found = 0;
  std::string first_bad;
  std::size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && isSeparator(line[pos])) ++pos;
    if (pos == line.size()) break;
    std::size_t end = pos;
    while (end < line.size() && !isSeparator(line[end])) ++end;
    if (found == 0 && line[pos] == '#') return NumberFields::Skip;  // comment, even if indented
    if (found < count && first_bad.empty()) {
      first_bad = parseField(line.substr(pos, end - pos), names, found, values[found]);
    }
    ++found;
    pos = end;
  }
  if (found == 0) return NumberFields::Skip;  // blank line
  if (found != count) {
    error = "expected " + std::to_string(count) + " fields, got " + std::to_string(found);
    return NumberFields::Error;
  }
  if (!first_bad.empty()) {
    error = std::move(first_bad);
    return NumberFields::Error;
  }
  return NumberFields::Numbers;
}

}  // namespace ellipse_collision::core

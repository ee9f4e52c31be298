// Fuzz target: parsePairLine(), the line parser of check_ellipses, fed arbitrary bytes.
//
// Invariants:
//  - Skip only for blank lines and '#' comments; a wrong field count is an error that gives the
//    count found by an independent split;
//  - an error is one printable line of bounded length that starts with a documented prefix;
//  - a parsed pair holds two valid ellipses whose fields equal strtod() of the tokens (an
//    independent, correctly rounded reader), and printing them back parses to the same bits;
//  - the accepted pair then goes through overlap()/contactScale() as the tool does.

#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "ellipse_collision/ellipse_collision.h"
#include "fuzz_input.h"

namespace ellipse_collision::fuzz {
namespace {

// Longest error: a field label plus a quoted field of at most 40 escaped bytes (4 chars each).
constexpr std::size_t kMaxErrorLength = 300;

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> found;
  std::size_t pos = 0;
  while (pos < line.size()) {
    if (line[pos] == ' ' || line[pos] == '\t') {
      ++pos;
      continue;
    }
    const std::size_t start = pos;
    while (pos < line.size() && line[pos] != ' ' && line[pos] != '\t') ++pos;
    found.push_back(line.substr(start, pos - start));
  }
  return found;
}

std::string shown(std::string_view line) {
  std::string text;
  for (unsigned char c : line.substr(0, 200)) {
    if (c >= 0x20 && c < 0x7f) {
      text += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      text += hex;
    }
  }
  return "\"" + text + "\"";
}

bool startsWith(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

void checkError(const core::PairLine& parsed, std::string_view line, std::size_t token_count) {
  const std::string& error = parsed.error;
  FUZZ_REQUIRE(!error.empty() && error.size() <= kMaxErrorLength,
               "error empty or too long (" + std::to_string(error.size()) + ") for " + shown(line));
  for (unsigned char c : error) {
    FUZZ_REQUIRE(c >= 0x20 && c != 0x7f, "error holds a control byte: " + shown(error));
  }
  FUZZ_REQUIRE(startsWith(error, "expected 10 fields, got ") || startsWith(error, "field ") ||
                   startsWith(error, "ellipse 1: ") || startsWith(error, "ellipse 2: "),
               "undocumented error form: " + shown(error));
  if (token_count != 10) {
    FUZZ_REQUIRE(error == "expected 10 fields, got " + std::to_string(token_count),
                 "wrong field count in " + shown(error) + " for " + shown(line));
  }
}

void checkPair(const core::PairLine& parsed, const std::vector<std::string_view>& fields,
               std::string_view line) {
  FUZZ_REQUIRE(fields.size() == 10, "pair from " + std::to_string(fields.size()) + " fields");
  FUZZ_REQUIRE(parsed.error.empty(), "pair with an error: " + parsed.error);
  FUZZ_REQUIRE(documentedValid(parsed.first) && documentedValid(parsed.second),
               "invalid ellipse accepted from " + shown(line));

  const double values[10] = {parsed.first.center.x(),  parsed.first.center.y(),
                             parsed.first.radius_x,    parsed.first.radius_y,
                             parsed.first.angle,       parsed.second.center.x(),
                             parsed.second.center.y(), parsed.second.radius_x,
                             parsed.second.radius_y,   parsed.second.angle};
  std::string reprinted;
  for (std::size_t i = 0; i < 10; ++i) {
    // strtod accepts more syntax (hex, leading blanks) but on the decimal forms from_chars takes
    // it must read the same correctly rounded value.
    const std::string token(fields[i]);
    char* end = nullptr;
    const double expected = std::strtod(token.c_str(), &end);
    FUZZ_REQUIRE(end == token.c_str() + token.size(),
                 "strtod does not read all of field " + std::to_string(i + 1) + " " + shown(token));
    FUZZ_REQUIRE(expected == values[i], "field " + std::to_string(i + 1) + " " + shown(token) +
                                            " parsed differently from strtod");
    char number[64];
    const auto result = std::to_chars(number, number + sizeof number, values[i]);
    reprinted.append(number, result.ptr);
    reprinted += i % 2 ? '\t' : ' ';
  }
  const core::PairLine again = core::parsePairLine(reprinted);
  FUZZ_REQUIRE(again.kind == core::PairLine::Kind::Pair && again.first.center == parsed.first.center &&
                   again.first.radius_x == parsed.first.radius_x &&
                   again.first.radius_y == parsed.first.radius_y &&
                   again.first.angle == parsed.first.angle &&
                   again.second.center == parsed.second.center &&
                   again.second.radius_x == parsed.second.radius_x &&
                   again.second.radius_y == parsed.second.radius_y &&
                   again.second.angle == parsed.second.angle,
               "printing the pair back does not parse to the same values: " + shown(reprinted));

  const bool overlapping = core::overlap(parsed.first, parsed.second);
  const double t = core::contactScale(parsed.first, parsed.second);
  FUZZ_REQUIRE(std::isfinite(t) && t >= 0.0 && overlapping == core::overlap(parsed.second, parsed.first),
               "core misbehaves on the parsed pair from " + shown(line));
}

}  // namespace
}  // namespace ellipse_collision::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  std::setlocale(LC_ALL, "C");  // strtod must read '.' as the decimal point, like from_chars
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ellipse_collision;
  using namespace ellipse_collision::fuzz;
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  const core::PairLine parsed = core::parsePairLine(line);

  std::string_view content = line;
  if (!content.empty() && content.back() == '\r') content.remove_suffix(1);
  const std::vector<std::string_view> fields = tokens(content);
  const bool comment = !fields.empty() && fields.front().front() == '#';

  switch (parsed.kind) {
    case core::PairLine::Kind::Skip:
      FUZZ_REQUIRE(fields.empty() || comment,
                   "skipped a line that is not blank or a comment: " + shown(line));
      break;
    case core::PairLine::Kind::Error:
      FUZZ_REQUIRE(!fields.empty() && !comment, "error for a blank or comment line " + shown(line));
      checkError(parsed, line, fields.size());
      break;
    case core::PairLine::Kind::Pair:
      FUZZ_REQUIRE(!comment, "pair from a comment line " + shown(line));
      checkPair(parsed, fields, line);
      break;
  }
  return 0;
}

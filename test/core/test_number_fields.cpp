// The line format of check_ellipses read once (core/number_fields.h): fields split on blanks,
// comments and blank lines skipped, every refusal naming the field by number and name with its
// text quoted, cut and escaped.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ellipse_collision/core/number_fields.h"

namespace ellipse_collision::core {
namespace {

constexpr const char* kNames[] = {"x", "y", "r"};

struct Parsed {
  NumberFields kind;
  double values[3];
  std::string error;
};

Parsed parse(std::string_view line) {
  Parsed p{NumberFields::Skip, {-7.0, -7.0, -7.0}, ""};
  p.kind = parseNumberFields(line, kNames, 3, p.values, p.error);
  return p;
}

TEST(NumberFields, ThreeFieldsAreReadInOrderWhateverTheBlanks) {
  const Parsed p = parse(" \t1.5\t\t-2e-3   +0.25 \r");
  ASSERT_EQ(p.kind, NumberFields::Numbers) << p.error;
  EXPECT_EQ(p.values[0], 1.5);
  EXPECT_EQ(p.values[1], -2e-3);
  EXPECT_EQ(p.values[2], 0.25);
  EXPECT_EQ(p.error, "");
}

TEST(NumberFields, BlankAndCommentLinesAreSkipped) {
  for (const char* line : {"", "   ", "\t", "\r", "# x y r", "   #1 2 3", "\t#", "#\r"}) {
    const Parsed p = parse(line);
    EXPECT_EQ(p.kind, NumberFields::Skip) << "'" << line << "'";
    EXPECT_EQ(p.values[0], -7.0) << "nothing written";
  }
  EXPECT_EQ(parse("1 # 2").kind, NumberFields::Error) << "'#' only starts a comment first";
}

TEST(NumberFields, TheCountIsCheckedBeforeAnyField) {
  EXPECT_EQ(parse("1 2").error, "expected 3 fields, got 2");
  EXPECT_EQ(parse("1 2 3 4").error, "expected 3 fields, got 4");
  EXPECT_EQ(parse("abc 2 3 4 5").error, "expected 3 fields, got 5");
}

TEST(NumberFields, TheFirstBadFieldIsNamedByNumberAndName) {
  EXPECT_EQ(parse("1 2 abc").error, "field 3 (r) is not a number: \"abc\"");
  EXPECT_EQ(parse("1 x2 ?").error, "field 2 (y) is not a number: \"x2\"");
  EXPECT_EQ(parse("1e999 2 3").error, "field 1 (x) is out of the range of a double: \"1e999\"");
  EXPECT_EQ(parse("1 -1e-400 3").error, "field 2 (y) is out of the range of a double: \"-1e-400\"");
  EXPECT_EQ(parse("1 2 3").kind, NumberFields::Numbers);
}

TEST(NumberFields, OnlyOneLeadingPlusIsAllowed) {
  EXPECT_EQ(parse("+1 2 3").values[0], 1.0);
  EXPECT_EQ(parse("++1 2 3").error, "field 1 (x) is not a number: \"++1\"");
  EXPECT_EQ(parse("+-1 2 3").error, "field 1 (x) is not a number: \"+-1\"");
  EXPECT_EQ(parse("+ 2 3").error, "field 1 (x) is not a number: \"+\"");
  EXPECT_EQ(parse("1+ 2 3").error, "field 1 (x) is not a number: \"1+\"");
}

TEST(NumberFields, CSyntaxOnlyWithNanAndInfinityLeftToTheValueRules) {
  const Parsed special = parse("nan inf -infinity");
  ASSERT_EQ(special.kind, NumberFields::Numbers) << special.error;
  EXPECT_TRUE(std::isnan(special.values[0]));
  EXPECT_EQ(special.values[1], INFINITY);
  EXPECT_EQ(special.values[2], -INFINITY);
  EXPECT_EQ(parse("0x10 2 3").error, "field 1 (x) is not a number: \"0x10\"");
  EXPECT_EQ(parse("1,5 2 3").error, "field 1 (x) is not a number: \"1,5\"");
  EXPECT_EQ(parse(".5 5. 3").values[1], 5.0);
}

TEST(NumberFields, QuotedTextIsEscapedAndCutToFortyCharacters) {
  EXPECT_EQ(parse("1 2 a\"b\\c").error, "field 3 (r) is not a number: \"a\\\"b\\\\c\"");
  EXPECT_EQ(parse(std::string_view("1 2 a\x01\x7f", 7)).error,
            "field 3 (r) is not a number: \"a\\x01\\x7f\"");
  EXPECT_EQ(parse(std::string_view("1 2 a\0b", 7)).error,
            "field 3 (r) is not a number: \"a\\x00b\"");
  const std::string long_field(50, 'z');
  EXPECT_EQ(parse("1 2 " + long_field).error,
            "field 3 (r) is not a number: \"" + std::string(40, 'z') + "...\"");
  EXPECT_EQ(parse("1 2 " + std::string(40, 'z')).error,
            "field 3 (r) is not a number: \"" + std::string(40, 'z') + "\"")
      << "exactly forty: not cut";
  EXPECT_EQ(parse("1 2 3\r4").error, "field 3 (r) is not a number: \"3\\x0d4\"")
      << "a carriage return inside the line is a byte of a field";
}

}  // namespace
}  // namespace ellipse_collision::core

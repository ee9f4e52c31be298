#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <string>

#include "ellipse_collision/core/pair_line_parser.h"

namespace ellipse_collision::core {
namespace {

constexpr std::array<const char*, 10> kFieldNames = {"cx1", "cy1", "rx1", "ry1", "angle1",
                                                     "cx2", "cy2", "rx2", "ry2", "angle2"};

// A good line whose ten fields are all different, so that a value in the wrong slot shows.
constexpr const char* kGoodLine = "1.5 -2 3 0.25 0.5 -4e-1 7 8.125 9 -1.25";

// kGoodLine with field `index` (0-based) replaced by `value`.
std::string lineWithField(std::size_t index, const std::string& value) {
  std::array<std::string, 10> fields = {"1.5",   "-2", "3",     "0.25", "0.5",
                                        "-4e-1", "7",  "8.125", "9",    "-1.25"};
  fields[index] = value;
  std::string line;
  for (const std::string& field : fields) line += field + " ";
  return line;
}

void expectGoodLineValues(const PairLine& parsed) {
  ASSERT_EQ(parsed.kind, PairLine::Kind::Pair) << parsed.error;
  EXPECT_TRUE(parsed.error.empty());
  EXPECT_EQ(parsed.first.center.x(), 1.5);
  EXPECT_EQ(parsed.first.center.y(), -2.0);
  EXPECT_EQ(parsed.first.radius_x, 3.0);
  EXPECT_EQ(parsed.first.radius_y, 0.25);
  EXPECT_EQ(parsed.first.angle, 0.5);
  EXPECT_EQ(parsed.second.center.x(), -0.4);
  EXPECT_EQ(parsed.second.center.y(), 7.0);
  EXPECT_EQ(parsed.second.radius_x, 8.125);
  EXPECT_EQ(parsed.second.radius_y, 9.0);
  EXPECT_EQ(parsed.second.angle, -1.25);
}

PairLine expectError(const std::string& line) {
  PairLine parsed = parsePairLine(line);
  EXPECT_EQ(parsed.kind, PairLine::Kind::Error) << "line: " << line;
  EXPECT_FALSE(parsed.error.empty()) << "line: " << line;
  return parsed;
}

// ------------------------------------------------------------------------------ good lines

TEST(PairLineParser, TenNumbersFillBothEllipsesInFieldOrder) {
  expectGoodLineValues(parsePairLine(kGoodLine));
}

TEST(PairLineParser, TabsRunsOfBlanksAndLeadingOrTrailingBlanksSeparateFields) {
  expectGoodLineValues(parsePairLine(" \t 1.5\t-2  3 \t0.25 0.5\t\t-4e-1 7 8.125 9 -1.25 \t "));
}

TEST(PairLineParser, TrailingCarriageReturnIsIgnored) {
  expectGoodLineValues(parsePairLine(std::string(kGoodLine) + "\r"));
}

TEST(PairLineParser, ScientificNotationLeadingPlusAndBareDecimalPointsParse) {
  const PairLine parsed = parsePairLine("+1e-3 -.5 2E1 1. 1e+0 0 -0 +.25 3.5e-2 -3.14159");
  ASSERT_EQ(parsed.kind, PairLine::Kind::Pair) << parsed.error;
  EXPECT_EQ(parsed.first.center.x(), 1e-3);
  EXPECT_EQ(parsed.first.center.y(), -0.5);
  EXPECT_EQ(parsed.first.radius_x, 20.0);
  EXPECT_EQ(parsed.first.radius_y, 1.0);
  EXPECT_EQ(parsed.first.angle, 1.0);
  EXPECT_EQ(parsed.second.radius_x, 0.25);
  EXPECT_EQ(parsed.second.radius_y, 3.5e-2);
  EXPECT_EQ(parsed.second.angle, -3.14159);
}

TEST(PairLineParser, SeventeenDigitValuesRoundTripExactly) {
  const double awkward = 0.1 + 0.2;  // 0.30000000000000004
  const PairLine parsed = parsePairLine(lineWithField(3, "0.30000000000000004"));
  ASSERT_EQ(parsed.kind, PairLine::Kind::Pair) << parsed.error;
  EXPECT_EQ(parsed.first.radius_y, awkward);
}

TEST(PairLineParser, AngleIsNotRestrictedToOneTurn) {
  const PairLine parsed = parsePairLine(lineWithField(4, "-100.5"));
  ASSERT_EQ(parsed.kind, PairLine::Kind::Pair) << parsed.error;
  EXPECT_EQ(parsed.first.angle, -100.5);
}

// ------------------------------------------------------------------------------ skipped lines

TEST(PairLineParser, EmptyAndBlankLinesAreSkipped) {
  for (const char* line : {"", " ", "\t", " \t  \t", "\r", "  \r"}) {
    const PairLine parsed = parsePairLine(line);
    EXPECT_EQ(parsed.kind, PairLine::Kind::Skip) << '"' << line << '"';
    EXPECT_TRUE(parsed.error.empty());
  }
}

TEST(PairLineParser, CommentLinesAreSkippedEvenWhenIndentedOrHoldingNumbers) {
  for (const char* line : {"#", "# a comment", "  # indented", "\t#tab-indented\r",
                           "#1 2 3 4 5 6 7 8 9 10", "## twice", "# not a number: abc"}) {
    EXPECT_EQ(parsePairLine(line).kind, PairLine::Kind::Skip) << '"' << line << '"';
  }
}

// ------------------------------------------------------------------------------ bad lines

TEST(PairLineParser, TooFewFieldsAreReportedWithTheCount) {
  EXPECT_EQ(expectError("1 2 3 4 5 6 7 8 9").error, "expected 10 fields, got 9");
  EXPECT_EQ(expectError("1").error, "expected 10 fields, got 1");
}

TEST(PairLineParser, TooManyFieldsAreReportedWithTheCount) {
  EXPECT_EQ(expectError(std::string(kGoodLine) + " 11").error, "expected 10 fields, got 11");
  std::string many;
  for (int i = 0; i < 1000; ++i) many += "1 ";
  EXPECT_EQ(expectError(many).error, "expected 10 fields, got 1000");
}

TEST(PairLineParser, TrailingCommentAfterNumbersIsNotAComment) {
  EXPECT_EQ(expectError(std::string(kGoodLine) + " # note").error, "expected 10 fields, got 12");
}

TEST(PairLineParser, NonNumberNamesFieldNumberNameAndValue) {
  EXPECT_EQ(expectError(lineWithField(2, "abc")).error, "field 3 (rx1) is not a number: \"abc\"");
  for (std::size_t i = 0; i < kFieldNames.size(); ++i) {
    const std::string expected =
        "field " + std::to_string(i + 1) + " (" + kFieldNames[i] + ") is not a number: \"x\"";
    EXPECT_EQ(expectError(lineWithField(i, "x")).error, expected);
  }
}

TEST(PairLineParser, NumbersWithTrailingOrForeignSyntaxAreRejectedNotTruncated) {
  // from_chars would stop early on each of these; the whole field must be a number.
  for (const char* field :
       {"1.5m", "1,5", "0x10", "1e", "1e5.0", "--1", "+-1", "++1", "+", "-", ".", "1..2", "1_000",
        "\xc2\xa0"
        "1"}) {
    const std::string expected = std::string("field 6 (cx2) is not a number: \"") + field + "\"";
    EXPECT_EQ(expectError(lineWithField(5, field)).error, expected) << field;
  }
}

TEST(PairLineParser, OverflowAndUnderflowAreRejectedNotClamped) {
  EXPECT_EQ(expectError(lineWithField(0, "1e999")).error,
            "field 1 (cx1) is out of the range of a double: \"1e999\"");
  EXPECT_EQ(expectError(lineWithField(9, "-1e-999")).error,
            "field 10 (angle2) is out of the range of a double: \"-1e-999\"");
}

TEST(PairLineParser, FirstBadFieldIsTheOneReported) {
  std::string line = lineWithField(1, "first");
  line.replace(line.find("0.5"), 3, "second");
  EXPECT_EQ(expectError(line).error, "field 2 (cy1) is not a number: \"first\"");
}

TEST(PairLineParser, NonPositiveRadiusIsReportedByInvalidReasonForTheRightEllipse) {
  const PairLine negative = expectError(lineWithField(2, "-1"));
  Ellipse first{Eigen::Vector2d(1.5, -2.0), -1.0, 0.25, 0.5};
  ASSERT_FALSE(invalidReason(first).empty());
  EXPECT_EQ(negative.error, "ellipse 1: " + invalidReason(first));
  EXPECT_NE(negative.error.find("-1"), std::string::npos) << negative.error;

  const PairLine zero = expectError(lineWithField(8, "0"));
  Ellipse second{Eigen::Vector2d(-0.4, 7.0), 8.125, 0.0, -1.25};
  ASSERT_FALSE(invalidReason(second).empty());
  EXPECT_EQ(zero.error, "ellipse 2: " + invalidReason(second));
}

TEST(PairLineParser, NonFiniteValuesAreReportedByInvalidReasonForTheRightEllipse) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  Ellipse first{Eigen::Vector2d(nan, -2.0), 3.0, 0.25, 0.5};
  EXPECT_EQ(expectError(lineWithField(0, "nan")).error, "ellipse 1: " + invalidReason(first));

  Ellipse second{Eigen::Vector2d(-0.4, 7.0), 8.125, 9.0, -inf};
  EXPECT_EQ(expectError(lineWithField(9, "-inf")).error, "ellipse 2: " + invalidReason(second));

  Ellipse infinite_radius{Eigen::Vector2d(1.5, -2.0), 3.0, inf, 0.5};
  EXPECT_EQ(expectError(lineWithField(3, "infinity")).error,
            "ellipse 1: " + invalidReason(infinite_radius));
}

TEST(PairLineParser, ValuesOutsideTheCoreRangesAreReportedByInvalidReason) {
  // The core bounds radii and coordinates so that its arithmetic cannot overflow.
  Ellipse huge_radius{Eigen::Vector2d(1.5, -2.0), 1e300, 0.25, 0.5};
  ASSERT_FALSE(invalidReason(huge_radius).empty());
  EXPECT_EQ(expectError(lineWithField(2, "1e300")).error,
            "ellipse 1: " + invalidReason(huge_radius));

  Ellipse far_centre{Eigen::Vector2d(-0.4, 1e300), 8.125, 9.0, -1.25};
  ASSERT_FALSE(invalidReason(far_centre).empty());
  EXPECT_EQ(expectError(lineWithField(6, "1e300")).error,
            "ellipse 2: " + invalidReason(far_centre));
}

TEST(PairLineParser, FirstEllipseIsCheckedBeforeTheSecond) {
  std::string line = lineWithField(3, "-2");
  line.replace(line.find("8.125"), 5, "-3");
  const PairLine parsed = expectError(line);
  EXPECT_EQ(parsed.error.rfind("ellipse 1: ", 0), 0u) << parsed.error;
}

TEST(PairLineParser, CarriageReturnOtherThanTheLastCharacterIsAnError) {
  EXPECT_EQ(expectError(lineWithField(9, "-1.25\r") + "\r").error.rfind("field 10", 0), 0u);
}

TEST(PairLineParser, LongGarbageFieldIsQuotedShortened) {
  const std::string garbage(100000, 'g');
  const PairLine parsed = expectError(lineWithField(4, garbage));
  EXPECT_EQ(parsed.error.rfind("field 5 (angle1) is not a number: \"gggg", 0), 0u);
  EXPECT_LT(parsed.error.size(), 100u);
  EXPECT_EQ(parsed.error.substr(parsed.error.size() - 4), "...\"");
}

TEST(PairLineParser, ControlCharactersInAQuotedFieldAreEscaped) {
  const PairLine parsed = expectError(lineWithField(0, std::string("a\x01\x7f\"\\", 5)));
  EXPECT_EQ(parsed.error, "field 1 (cx1) is not a number: \"a\\x01\\x7f\\\"\\\\\"");
}

TEST(PairLineParser, EmbeddedNulByteIsAnErrorNotATerminator) {
  std::string line = kGoodLine;
  line.insert(line.find(' '), 1, '\0');  // "1.5\0 -2 ..."
  EXPECT_EQ(expectError(line).error, "field 1 (cx1) is not a number: \"1.5\\x00\"");
}

}  // namespace
}  // namespace ellipse_collision::core

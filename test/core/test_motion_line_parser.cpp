// parseMotionLine(): the `check_ellipses --motion` line format and its error messages.

#include <gtest/gtest.h>

#include <string>

#include "ellipse_collision/core/motion_line_parser.h"

namespace ellipse_collision::core {
namespace {

constexpr const char* kGood = "0 0 1 0.5 0.1  1 0 0.2  5 0 1 1 0  -1 0 0  10";

TEST(MotionLineParser, ReadsAllSeventeenFields) {
  const MotionLine m = parseMotionLine(kGood);
  ASSERT_EQ(m.kind, MotionLine::Kind::Motion) << m.error;
  EXPECT_EQ(m.first.radius_y, 0.5);
  EXPECT_EQ(m.first.angle, 0.1);
  EXPECT_EQ(m.first_motion.velocity.x(), 1.0);
  EXPECT_EQ(m.first_motion.angular_velocity, 0.2);
  EXPECT_EQ(m.second.center.x(), 5.0);
  EXPECT_EQ(m.second_motion.velocity.x(), -1.0);
  EXPECT_EQ(m.horizon, 10.0);
}

TEST(MotionLineParser, SkipsBlankAndCommentLinesAndTolerantOfCrAndPlus) {
  EXPECT_EQ(parseMotionLine("").kind, MotionLine::Kind::Skip);
  EXPECT_EQ(parseMotionLine(" \t ").kind, MotionLine::Kind::Skip);
  EXPECT_EQ(parseMotionLine("  # 1 2 3").kind, MotionLine::Kind::Skip);
  EXPECT_EQ(parseMotionLine(std::string(kGood) + "\r").kind, MotionLine::Kind::Motion);
  EXPECT_EQ(parseMotionLine("+0 0 1 1 0 0 0 0 5 0 1 1 0 0 0 0 +1").kind, MotionLine::Kind::Motion);
}

TEST(MotionLineParser, ErrorsNameTheFieldAndValue) {
  EXPECT_EQ(parseMotionLine("1 2 3").error, "expected 17 fields, got 3");
  EXPECT_EQ(parseMotionLine(std::string(kGood) + " 1").error, "expected 17 fields, got 18");
  EXPECT_EQ(parseMotionLine("0 0 1 1 0 abc 0 0 5 0 1 1 0 0 0 0 1").error,
            "field 6 (vx1) is not a number: \"abc\"");
  EXPECT_EQ(parseMotionLine("0 0 1 1 0 0 0 0 5 0 1 1 0 0 0 0 1e999").error,
            "field 17 (horizon) is out of the range of a double: \"1e999\"");
  EXPECT_EQ(parseMotionLine("0 0 -1 1 0 0 0 0 5 0 1 1 0 0 0 0 1").error,
            "ellipse 1: radius_x = -1 must be > 0");
  EXPECT_EQ(parseMotionLine("0 0 1 1 0 0 0 0 5 0 1 1 0 0 0 0 -1").error,
            "horizon = -1 must be >= 0");
  EXPECT_EQ(parseMotionLine("0 0 1 1 0 0 0 0 5 0 1 1 0 0 0 inf 1").error,
            "motion 2: angular_velocity = inf must be finite");
  EXPECT_EQ(parseMotionLine("0 0 1 1 0 0 nan 0 5 0 1 1 0 0 0 0 1").error,
            "motion 1: velocity.y = nan must be finite");
  EXPECT_EQ(parseMotionLine("0 0 1 1 0 0 0 0 5 0 1 1 0 0 0 50 10").kind, MotionLine::Kind::Error);
}

}  // namespace
}  // namespace ellipse_collision::core

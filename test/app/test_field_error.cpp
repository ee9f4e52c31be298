// How a refused field is rendered (app/field_error.h): the entry's name, the key, the value as
// given and what was expected; the range rule of settings.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ellipse_collision/app/field_error.h"

namespace ellipse_collision::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(FieldError, CoreViolationsAreRenderedInRequestWords) {
  EXPECT_EQ(describeFieldError("query[0]", fieldError("x", *core::coordinateViolation(kNaN))),
            "query[0].x = nan: expected a finite number");
  EXPECT_EQ(describeFieldError("query[0]", fieldError("radius_x", *core::radiusViolation(-kInf))),
            "query[0].radius_x = -inf: expected a finite number > 0");
  EXPECT_EQ(describeFieldError("q[1]", fieldError("radius_y", *core::radiusViolation(0.0))),
            "q[1].radius_y = 0: expected a finite number > 0");
  EXPECT_EQ(describeFieldError("q[1]", fieldError("y", *core::coordinateViolation(-2e9))),
            "q[1].y = -2e+09: expected a number within [-1e+09, 1e+09]");
  EXPECT_FALSE(core::coordinateViolation(1e9));
  EXPECT_FALSE(core::radiusViolation(1e-9));
  EXPECT_EQ(entryName("obstacles", 12), "obstacles[12]");
}

TEST(FieldError, RangeViolationsOfTheCoreQuoteBothEnds) {
  const FieldError error = fieldError("angle", *core::angleViolation(kInf));
  EXPECT_EQ(error.key, "angle");
  EXPECT_EQ(error.actual, "inf");
  EXPECT_FALSE(error.expected.empty());
  EXPECT_EQ(describeFieldError("links[0]", fieldError("x", *core::coordinateViolation(1.5e9))),
            "links[0].x = 1.5e+09: expected a number within [-1e+09, 1e+09]");
  EXPECT_EQ(describeFieldError("links[0]", fieldError("radius_x", *core::radiusViolation(2e9))),
            "links[0].radius_x = 2e+09: expected a number within [1e-09, 1e+09]");
}

TEST(FindOutsideRange, ClosedRangeAcceptsItsEndsAndRefusesTheNextDouble) {
  EXPECT_FALSE(findOutsideRange("k", 0.0, 0.0, 2.5));
  EXPECT_FALSE(findOutsideRange("k", 2.5, 0.0, 2.5));
  EXPECT_FALSE(findOutsideRange("k", -0.0, 0.0, 2.5));
  const auto above = findOutsideRange("gate/margin", std::nextafter(2.5, 3.0), 0.0, 2.5);
  ASSERT_TRUE(above);
  EXPECT_EQ(above->key, "gate/margin");
  EXPECT_EQ(above->expected, "a number within [0, 2.5]");
  EXPECT_EQ(above->actual, "2.5000000000000004");
  const auto below = findOutsideRange("gate/margin", -1e-300, 0.0, 2.5);
  ASSERT_TRUE(below);
  EXPECT_EQ(below->actual, "-1e-300");
}

TEST(FindOutsideRange, ExcludedMinimumRefusesItAndSaysSo) {
  const auto at_min = findOutsideRange("horizon", 0.0, 0.0, 60.0, true);
  ASSERT_TRUE(at_min);
  EXPECT_EQ(describeFieldError("gate", *at_min),
            "gate.horizon = 0: expected a number within (0, 60]");
  EXPECT_FALSE(findOutsideRange("horizon", 5e-324, 0.0, 60.0, true)) << "the least double above";
}

TEST(FindOutsideRange, NanIsWithinNoRangeAndInfinitiesOnlyInInfiniteOnes) {
  for (const bool min_excluded : {false, true}) {
    const auto nan = findOutsideRange("k", kNaN, -kInf, kInf, min_excluded);
    ASSERT_TRUE(nan);
    EXPECT_EQ(nan->actual, "nan");
    EXPECT_EQ(nan->expected,
              std::string("a number within ") + (min_excluded ? "(" : "[") + "-inf, inf]");
  }
  EXPECT_TRUE(findOutsideRange("k", kInf, 0.0, 1e308));
  EXPECT_TRUE(findOutsideRange("k", -kInf, -1e308, 0.0));
  EXPECT_FALSE(findOutsideRange("k", kInf, 0.0, kInf));
  EXPECT_TRUE(findOutsideRange("k", -kInf, -kInf, 0.0, true));
}

TEST(FieldError, EntryNamesCountFromZeroAndKeepTheFieldAsGiven) {
  EXPECT_EQ(entryName("links", 0), "links[0]");
  EXPECT_EQ(entryName("gate/obstacles", 18446744073709551615ull),
            "gate/obstacles[18446744073709551615]");
  EXPECT_EQ(describeFieldError(entryName("q", 3), FieldError{"name", "a non-empty string", "''"}),
            "q[3].name = '': expected a non-empty string");
}

}  // namespace
}  // namespace ellipse_collision::app

// The field rules of ellipses in requests, messages and configuration (app/ellipse_spec.h,
// app/field_error.h), and the one number formatter; no ROS.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

EllipseSpec sampleSpec() {
  EllipseSpec spec;
  spec.name = "forearm";
  spec.frame_id = "forearm_link";
  spec.x = 0.125;
  spec.y = -3.5;
  spec.angle = 0.1;
  spec.radius_x = 0.3;
  spec.radius_y = 0.07;
  spec.padding = 0.01;
  return spec;
}

TEST(EllipseSpec, PaddingOfEntryAndNodeIsAddedToBothRadii) {
  const core::Ellipse e = paddedEllipse(sampleSpec(), 0.02);
  EXPECT_DOUBLE_EQ(e.radius_x, 0.3 + 0.01 + 0.02);
  EXPECT_DOUBLE_EQ(e.radius_y, 0.07 + 0.01 + 0.02);
  EXPECT_EQ(e.center, Eigen::Vector2d(0.125, -3.5));
  EXPECT_EQ(e.angle, 0.1);
}

TEST(EllipseSpec, ValidSpecHasNoInvalidField) { EXPECT_FALSE(findInvalidField(sampleSpec())); }

struct InvalidCase {
  const char* what;
  void (*spoil)(EllipseSpec&);
  const char* key;
  const char* actual;
};

TEST(EllipseSpec, EachInvalidFieldIsNamedWithItsValue) {
  const InvalidCase cases[] = {
      {"empty name", [](EllipseSpec& s) { s.name = ""; }, "name", "''"},
      {"empty frame", [](EllipseSpec& s) { s.frame_id = ""; }, "frame_id", "''"},
      {"leading slash", [](EllipseSpec& s) { s.frame_id = "/odom"; }, "frame_id", "'/odom'"},
      {"nan x", [](EllipseSpec& s) { s.x = kNaN; }, "x", "nan"},
      {"inf y", [](EllipseSpec& s) { s.y = kInf; }, "y", "inf"},
      {"nan angle", [](EllipseSpec& s) { s.angle = kNaN; }, "angle", "nan"},
      {"zero radius_x", [](EllipseSpec& s) { s.radius_x = 0.0; }, "radius_x", "0"},
      {"negative radius_y", [](EllipseSpec& s) { s.radius_y = -0.5; }, "radius_y", "-0.5"},
      {"infinite radius_x", [](EllipseSpec& s) { s.radius_x = kInf; }, "radius_x", "inf"},
      {"nan radius_y", [](EllipseSpec& s) { s.radius_y = kNaN; }, "radius_y", "nan"},
      {"negative padding", [](EllipseSpec& s) { s.padding = -0.01; }, "padding", "-0.01"},
      {"nan padding", [](EllipseSpec& s) { s.padding = kNaN; }, "padding", "nan"},
      {"radius beyond the core's range", [](EllipseSpec& s) { s.radius_x = 2e9; }, "radius_x",
       "2e+09"},
      {"radius below the core's range", [](EllipseSpec& s) { s.radius_y = 1e-10; }, "radius_y",
       "1e-10"},
      {"centre beyond the core's range", [](EllipseSpec& s) { s.y = -3e9; }, "y", "-3e+09"},
      {"padding beyond the core's range", [](EllipseSpec& s) { s.padding = 1e10; }, "padding",
       "1e+10"},
      {"nan vx", [](EllipseSpec& s) { s.vx = kNaN; }, "vx", "nan"},
      {"infinite vy", [](EllipseSpec& s) { s.vy = -kInf; }, "vy", "-inf"},
      {"vx beyond the core's speed", [](EllipseSpec& s) { s.vx = 2e9; }, "vx", "2e+09"},
      {"nan angular_velocity", [](EllipseSpec& s) { s.angular_velocity = kNaN; },
       "angular_velocity", "nan"},
      {"angular_velocity beyond the core's range",
       [](EllipseSpec& s) { s.angular_velocity = -3e9; }, "angular_velocity", "-3e+09"},
  };
  for (const InvalidCase& c : cases) {
    EllipseSpec spec = sampleSpec();
    c.spoil(spec);
    const auto invalid = findInvalidField(spec);
    ASSERT_TRUE(invalid) << c.what;
    EXPECT_EQ(invalid->key, c.key) << c.what;
    EXPECT_EQ(invalid->actual, c.actual) << c.what;
    EXPECT_FALSE(invalid->expected.empty()) << c.what;
  }
}

TEST(EllipseSpec, FrameKeyIsSpelledAsTheCallerAsks) {
  EllipseSpec spec = sampleSpec();
  spec.frame_id = "";
  EXPECT_EQ(findInvalidField(spec, "frame")->key, "frame");
}

TEST(EllipseSpec, RequestErrorNamesEntryFieldValueAndExpectation) {
  EllipseSpec spec = sampleSpec();
  spec.radius_x = -1;
  EXPECT_EQ(describeFieldError("obstacles[2]", *findInvalidField(spec)),
            "obstacles[2].radius_x = -1: expected a finite number > 0");
}

TEST(EllipseSpec, PaddedRadiiMustStayWithinTheCoreRange) {
  // Each field within range, but radius + entry padding + global padding beyond kMaxRadius.
  EllipseSpec spec = sampleSpec();
  EXPECT_FALSE(findInvalidPaddedField(spec, 0.02));
  spec.radius_x = core::kMaxRadius;
  EXPECT_FALSE(findInvalidField(spec));  // alone it is fine; the entry padding 0.01 is not
  auto invalid = findInvalidPaddedField(spec, 0.0);
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->key, "radius_x");
  EXPECT_EQ(invalid->actual, "1e+09");
  EXPECT_EQ(describeFieldError("query[0]", *invalid),
            "query[0].radius_x = 1e+09: expected a number whose padded radius (radius_x + padding "
            "0.01 + global padding 0 = 1000000000.01) lies within [1e-09, 1e+09]");

  spec = sampleSpec();
  spec.padding = 0.0;
  spec.radius_y = core::kMaxRadius;
  EXPECT_FALSE(findInvalidPaddedField(spec, 0.0));  // exactly at the limit
  invalid = findInvalidPaddedField(spec, 0.02);     // the global padding pushes it over
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->key, "radius_y");
  EXPECT_EQ(
      describeFieldError("obstacles[3]", *invalid).rfind("obstacles[3].radius_y = 1e+09: ", 0),
      0u);

  spec = sampleSpec();
  spec.radius_x = 6e8;
  spec.padding = 5e8;
  invalid = findInvalidPaddedField(spec, 0.0, "frame");
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->key, "radius_x");
  EXPECT_EQ(invalid->actual, "6e+08");
}

TEST(EllipseSpec, PaddedCheckReportsPlainFieldErrorsFirst) {
  EllipseSpec spec = sampleSpec();
  spec.frame_id = "";
  EXPECT_EQ(findInvalidPaddedField(spec, 0.0, "frame")->key, "frame");
  spec = sampleSpec();
  spec.padding = 2e9;
  EXPECT_EQ(findInvalidPaddedField(spec, 0.0)->key, "padding");
}

TEST(EllipseSpec, AcceptedPaddedSpecIsValidForTheCore) {
  for (double radius : {core::kMinRadius, 1.0, core::kMaxRadius - 1.0, core::kMaxRadius}) {
    for (double padding : {0.0, 0.5, 1.0}) {
      for (double global : {0.0, 0.02, 0.5}) {
        EllipseSpec spec = sampleSpec();
        spec.radius_x = radius;
        spec.padding = padding;
        const bool accepted = !findInvalidPaddedField(spec, global);
        EXPECT_EQ(accepted, core::invalidReason(paddedEllipse(spec, global)).empty())
            << radius << " + " << padding << " + " << global;
      }
    }
  }
}

TEST(EllipseSpec, NumbersAreFormattedShortestAndReadBackExactly) {
  EXPECT_EQ(core::formatNumber(0.1), "0.1");
  EXPECT_EQ(core::formatNumber(-2), "-2");
  EXPECT_EQ(core::formatNumber(20), "20");
  EXPECT_EQ(core::formatNumber(1234.5), "1234.5");
  EXPECT_EQ(core::formatNumber(kNaN), "nan");
  EXPECT_EQ(core::formatNumber(-kInf), "-inf");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::stod(core::formatNumber(third)), third);
}

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

}  // namespace
}  // namespace ellipse_collision::app

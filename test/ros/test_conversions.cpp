// Message <-> core conversions and ellipse field validation; no ROS master needed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "ellipse_collision/ros/conversions.h"

namespace ellipse_collision {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

EllipseSpec sampleSpec() {
  EllipseSpec spec;
  spec.name = "forearm";
  spec.frame_id = "forearm_link";
  spec.x = 0.125;
  spec.y = -3.5;
  spec.angle = 0.1;  // not exactly representable: the round trip must keep every bit anyway
  spec.radius_x = 0.3;
  spec.radius_y = 0.07;
  spec.padding = 0.01;
  return spec;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

void expectSameSpec(const EllipseSpec& a, const EllipseSpec& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.frame_id, b.frame_id);
  EXPECT_TRUE(sameBits(a.x, b.x));
  EXPECT_TRUE(sameBits(a.y, b.y));
  EXPECT_TRUE(sameBits(a.angle, b.angle));
  EXPECT_TRUE(sameBits(a.radius_x, b.radius_x));
  EXPECT_TRUE(sameBits(a.radius_y, b.radius_y));
  EXPECT_TRUE(sameBits(a.padding, b.padding));
}

TEST(Conversions, EllipseSpecSurvivesTheRoundTripThroughTheMessage) {
  expectSameSpec(fromMsg(toMsg(sampleSpec())), sampleSpec());
}

TEST(Conversions, EveryMessageFieldLandsInTheMatchingSpecField) {
  Ellipse msg;
  msg.name = "n";
  msg.frame_id = "f";
  msg.x = 1;
  msg.y = 2;
  msg.angle = 3;
  msg.radius_x = 4;
  msg.radius_y = 5;
  msg.padding = 6;
  const EllipseSpec spec = fromMsg(msg);
  EXPECT_EQ(spec.name, "n");
  EXPECT_EQ(spec.frame_id, "f");
  EXPECT_EQ(spec.x, 1);
  EXPECT_EQ(spec.y, 2);
  EXPECT_EQ(spec.angle, 3);
  EXPECT_EQ(spec.radius_x, 4);
  EXPECT_EQ(spec.radius_y, 5);
  EXPECT_EQ(spec.padding, 6);
  EXPECT_EQ(toMsg(spec), msg);
}

TEST(Conversions, NonFiniteValuesPassThroughUnchangedForTheValidatorToSee) {
  EllipseSpec spec = sampleSpec();
  spec.x = kNaN;
  spec.radius_y = -kInf;
  expectSameSpec(fromMsg(toMsg(spec)), spec);
}

TEST(Conversions, EllipseArrayEntryWithoutFrameTakesTheHeaderFrame) {
  EllipseArray array;
  array.header.frame_id = "odom";
  array.ellipses.push_back(toMsg(sampleSpec()));
  array.ellipses.push_back(toMsg(sampleSpec()));
  array.ellipses[1].frame_id = "";
  array.ellipses[1].name = "rock";
  const std::vector<EllipseSpec> specs = fromMsg(array);
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[0].frame_id, "forearm_link");
  EXPECT_EQ(specs[1].frame_id, "odom");
  EXPECT_EQ(specs[1].name, "rock");
}

TEST(Conversions, CollidingPairSurvivesTheRoundTripThroughTheMessage) {
  const core::CollidingPair pair{"arm", "crate", 0.8333333333333334};
  const core::CollidingPair back = fromMsg(toMsg(pair));
  EXPECT_EQ(back.name_a, "arm");
  EXPECT_EQ(back.name_b, "crate");
  EXPECT_TRUE(sameBits(back.contact_scale, pair.contact_scale));
  const std::vector<CollisionPair> msgs = toMsg(std::vector<core::CollidingPair>{pair, {"b", "c", 0.5}});
  ASSERT_EQ(msgs.size(), 2u);
  EXPECT_EQ(msgs[1].name_a, "b");
  EXPECT_EQ(msgs[1].contact_scale, 0.5);
}

TEST(Conversions, NearPairSurvivesTheRoundTripThroughTheClearanceMessage) {
  const core::NearPair pair{"arm", "crate", 0.1, {0.3, -1.0 / 3.0}, {0.35, -0.4}};
  const ClearancePair msg = toMsg(pair);
  EXPECT_EQ(msg.name_a, "arm");
  EXPECT_EQ(msg.name_b, "crate");
  EXPECT_TRUE(sameBits(msg.distance, 0.1));
  EXPECT_TRUE(sameBits(msg.point_a.x, 0.3));
  EXPECT_TRUE(sameBits(msg.point_a.y, -1.0 / 3.0));
  EXPECT_TRUE(sameBits(msg.point_b.x, 0.35));
  EXPECT_TRUE(sameBits(msg.point_b.y, -0.4));
  EXPECT_EQ(msg.point_a.z, 0.0);  // points lie in the fixed frame's plane
  EXPECT_EQ(msg.point_b.z, 0.0);
  const core::NearPair back = fromMsg(msg);
  EXPECT_EQ(back.name_a, pair.name_a);
  EXPECT_EQ(back.name_b, pair.name_b);
  EXPECT_TRUE(sameBits(back.distance, pair.distance));
  EXPECT_EQ(back.point_a, pair.point_a);
  EXPECT_EQ(back.point_b, pair.point_b);

  const std::vector<ClearancePair> msgs =
      toMsg(std::vector<core::NearPair>{pair, {"b", "c", 2.0, {1, 2}, {3, 4}}});
  ASSERT_EQ(msgs.size(), 2u);
  EXPECT_EQ(msgs[1].name_a, "b");
  EXPECT_EQ(msgs[1].point_b.y, 4.0);
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
  EXPECT_EQ(describeRequestError("obstacles[2]", *findInvalidField(spec)),
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
  EXPECT_EQ(describeRequestError("query[0]", *invalid),
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
      describeRequestError("obstacles[3]", *invalid).rfind("obstacles[3].radius_y = 1e+09: ", 0),
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
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(-2), "-2");
  EXPECT_EQ(formatNumber(20), "20");
  EXPECT_EQ(formatNumber(1234.5), "1234.5");
  EXPECT_EQ(formatNumber(kNaN), "nan");
  EXPECT_EQ(formatNumber(-kInf), "-inf");
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::stod(formatNumber(third)), third);
}

}  // namespace
}  // namespace ellipse_collision

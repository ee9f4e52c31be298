// The ellipses of requests, messages and configuration (app/ellipse_spec.h): each field rule
// naming the field and its value, the padded radii, the padded ellipsoid, the placement in the
// fixed frame's plane and the own velocity in another frame, against closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

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
      describeFieldError("obstacles[3]", *invalid).rfind("obstacles[3].radius_y = 1e+09: ", 0), 0u);

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

EllipseSpec sampleEllipsoid() {
  EllipseSpec spec = sampleSpec();
  spec.ellipsoid = EllipsoidPart{0.5, 0.25, -0.125, 0.2};
  return spec;
}

TEST(EllipseSpec, EllipsoidDepthFieldsAreNamedWithTheirValue) {
  EXPECT_FALSE(findInvalidField(sampleEllipsoid()));
  const InvalidCase cases[] = {
      {"nan z", [](EllipseSpec& s) { s.ellipsoid->z = kNaN; }, "z", "nan"},
      {"z beyond the core's range", [](EllipseSpec& s) { s.ellipsoid->z = 2e9; }, "z", "2e+09"},
      {"inf roll", [](EllipseSpec& s) { s.ellipsoid->roll = kInf; }, "roll", "inf"},
      {"nan pitch", [](EllipseSpec& s) { s.ellipsoid->pitch = kNaN; }, "pitch", "nan"},
      {"negative radius_z", [](EllipseSpec& s) { s.ellipsoid->radius_z = -0.5; }, "radius_z",
       "-0.5"},
      {"nan radius_z", [](EllipseSpec& s) { s.ellipsoid->radius_z = kNaN; }, "radius_z", "nan"},
      {"radius_z below the core's range", [](EllipseSpec& s) { s.ellipsoid->radius_z = 1e-10; },
       "radius_z", "1e-10"},
  };
  for (const InvalidCase& c : cases) {
    EllipseSpec spec = sampleEllipsoid();
    c.spoil(spec);
    const auto invalid = findInvalidField(spec);
    ASSERT_TRUE(invalid) << c.what;
    EXPECT_EQ(invalid->key, c.key) << c.what;
    EXPECT_EQ(invalid->actual, c.actual) << c.what;
  }
}

TEST(EllipseSpec, ForgottenRadiusZWithATiltNamesTheFirstTiltField) {
  EllipseSpec spec = sampleEllipsoid();
  spec.ellipsoid->radius_z = 0.0;  // z 0.5, roll 0.25, pitch -0.125: z is named first
  EXPECT_EQ(describeFieldError("obstacles[0]", *findInvalidField(spec)),
            "obstacles[0].z = 0.5: expected 0 when radius_z = 0 (a planar ellipse); z, roll and "
            "pitch describe an ellipsoid, which needs radius_z > 0");
  spec.ellipsoid->z = 0.0;
  EXPECT_EQ(findInvalidField(spec)->key, "roll");
  spec.ellipsoid->roll = 0.0;
  EXPECT_EQ(findInvalidField(spec)->key, "pitch");
  EXPECT_EQ(findInvalidField(spec)->actual, "-0.125");
  spec.ellipsoid->pitch = 0.0;  // no tilt: then it is radius_z's own rule
  EXPECT_EQ(describeFieldError("obstacles[0]", *findInvalidField(spec)),
            "obstacles[0].radius_z = 0: expected a finite number > 0");
}

TEST(EllipseSpec, VelocityLimitsAreInclusiveAndNamedWithTheirUnit) {
  EllipseSpec spec = sampleSpec();
  spec.vx = -core::kMaxSpeed;
  spec.vy = core::kMaxSpeed;
  spec.angular_velocity = core::kMaxAngularVelocity;
  EXPECT_FALSE(findInvalidField(spec));
  spec.vy = std::nextafter(core::kMaxSpeed, kInf);
  auto invalid = findInvalidField(spec);
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->expected, "a finite number within [" + core::formatNumber(-core::kMaxSpeed) +
                                   ", " + core::formatNumber(core::kMaxSpeed) + "] m/s");
  spec.vy = 0.0;
  spec.angular_velocity = -std::nextafter(core::kMaxAngularVelocity, kInf);
  invalid = findInvalidField(spec);
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->key, "angular_velocity");
  EXPECT_EQ(invalid->expected.substr(invalid->expected.size() - 6), " rad/s");
}

TEST(EllipseSpec, PaddedRadiusZIsCheckedLikeTheOthers) {
  EllipseSpec spec = sampleEllipsoid();
  spec.padding = 0.0;
  spec.ellipsoid->radius_z = core::kMaxRadius;
  EXPECT_FALSE(findInvalidPaddedField(spec, 0.0));
  const auto invalid = findInvalidPaddedField(spec, 1.0);
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->key, "radius_z");
  EXPECT_EQ(invalid->actual, "1e+09");
}

TEST(EllipseSpec, PaddedEllipsoidIsYawPitchRollOfThePaddedRadii) {
  const EllipseSpec spec = sampleEllipsoid();
  const core::Ellipsoid e = paddedEllipsoid(spec, 0.02);
  EXPECT_EQ(e.center, Eigen::Vector3d(0.125, -3.5, 0.5));
  EXPECT_EQ(e.radii, Eigen::Vector3d(0.3 + 0.01 + 0.02, 0.07 + 0.01 + 0.02, 0.2 + 0.01 + 0.02));
  // R = Rz(yaw) Ry(pitch) Rx(roll) written out element by element in long double.
  const long double yaw = 0.1L, pitch = -0.125L, roll = 0.25L;
  const long double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch),
                    sp = std::sin(pitch), cr = std::cos(roll), sr = std::sin(roll);
  const long double expected[3][3] = {{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
                                      {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
                                      {-sp, cp * sr, cp * cr}};
  const Eigen::Matrix3d r = e.orientation.toRotationMatrix();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(r(i, j), static_cast<double>(expected[i][j]), 1e-15) << i << "," << j;
    }
  }
}

/// A pose: yaw about z after roll about x, then a translation.
Eigen::Isometry3d framePose(double x, double y, double z, double yaw, double roll = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(Eigen::Vector3d(x, y, z));
  pose.rotate(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
              Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
  return pose;
}

TEST(EllipseSpec, PlanarSpecInAYawedFrameIsMovedAndTurnedRigidly) {
  EllipseSpec spec = sampleSpec();
  spec.angle = 0.3;
  const double yaw = 0.5;
  const core::ProjectionResult placed = placeInPlane(spec, 0.02, framePose(1.0, -2.0, 7.0, yaw));
  ASSERT_TRUE(placed.ok()) << placed.error;
  const long double c = std::cos(static_cast<long double>(yaw));
  const long double s = std::sin(static_cast<long double>(yaw));
  EXPECT_NEAR(placed.ellipse.center.x(), static_cast<double>(1.0L + c * 0.125L - s * -3.5L), 1e-14);
  EXPECT_NEAR(placed.ellipse.center.y(), static_cast<double>(-2.0L + s * 0.125L + c * -3.5L),
              1e-14);
  EXPECT_NEAR(placed.ellipse.radius_x, 0.33, 1e-15);
  EXPECT_NEAR(placed.ellipse.radius_y, 0.1, 1e-15);
  EXPECT_NEAR(placed.ellipse.angle, 0.8, 1e-14);
}

TEST(EllipseSpec, PlanarSpecInARolledFrameIsFlattenedByTheCosine) {
  // Rolled about x by 60 degrees: the frame's y axis shortens by cos 60 = 1/2 in the plane.
  EllipseSpec spec = sampleSpec();
  spec.angle = 0.0;
  spec.x = 0.0;
  spec.y = 0.4;
  spec.padding = 0.0;
  spec.radius_x = 0.3;
  spec.radius_y = 0.2;
  const core::ProjectionResult placed =
      placeInPlane(spec, 0.0, framePose(0.0, 0.0, 0.0, 0.0, std::acos(0.5L)));
  ASSERT_TRUE(placed.ok()) << placed.error;
  EXPECT_NEAR(placed.ellipse.center.y(), 0.2, 1e-15);
  EXPECT_NEAR(placed.ellipse.radius_x, 0.3, 1e-15);
  EXPECT_NEAR(placed.ellipse.radius_y, 0.1, 1e-15);
}

TEST(EllipseSpec, EdgeOnPlanarSpecIsRefusedButAnEllipsoidCastsItsShadow) {
  const Eigen::Isometry3d edge_on = framePose(0.0, 0.0, 0.0, 0.0, M_PI / 2);
  const core::ProjectionResult planar = placeInPlane(sampleSpec(), 0.0, edge_on);
  EXPECT_FALSE(planar.ok());
  EXPECT_NE(planar.error.find("forearm"), std::string::npos) << planar.error;
  // Rolled 90 degrees the ellipsoid's shadow has its y extent from radius_z: 0.2 + 0.01.
  EllipseSpec spec = sampleEllipsoid();
  spec.angle = 0.0;
  spec.ellipsoid->roll = 0.0;
  spec.ellipsoid->pitch = 0.0;
  const core::ProjectionResult shadow = placeInPlane(spec, 0.0, edge_on);
  ASSERT_TRUE(shadow.ok()) << shadow.error;
  const double major = std::max(shadow.ellipse.radius_x, shadow.ellipse.radius_y);
  const double minor = std::min(shadow.ellipse.radius_x, shadow.ellipse.radius_y);
  EXPECT_NEAR(major, 0.31, 1e-9);
  EXPECT_NEAR(minor, 0.21, 1e-9);
  // The centre (0.125, -3.5, 0.5) rolled: y' = -z = -0.5, z' = y.
  EXPECT_NEAR(shadow.ellipse.center.x(), 0.125, 1e-12);
  EXPECT_NEAR(shadow.ellipse.center.y(), -0.5, 1e-12);
}

TEST(EllipseSpec, OwnMotionTurnsWithTheFrameAndFlipsWithIt) {
  EllipseSpec spec = sampleSpec();
  spec.vx = 0.5;
  spec.vy = -0.25;
  spec.angular_velocity = 0.75;
  const core::Motion same = ownMotion(spec, Eigen::Isometry3d::Identity());
  EXPECT_EQ(same.velocity, Eigen::Vector2d(0.5, -0.25));
  EXPECT_EQ(same.angular_velocity, 0.75);
  // Yawed by 90 degrees and moved: (vx, vy) -> (-vy, vx); the translation does not count.
  const core::Motion yawed = ownMotion(spec, framePose(3.0, 4.0, 5.0, M_PI / 2));
  EXPECT_NEAR(yawed.velocity.x(), 0.25, 1e-15);
  EXPECT_NEAR(yawed.velocity.y(), 0.5, 1e-15);
  EXPECT_NEAR(yawed.angular_velocity, 0.75, 1e-15);
  // Upside down (rolled by pi): y and the turning sense flip.
  const core::Motion flipped = ownMotion(spec, framePose(0.0, 0.0, 0.0, 0.0, M_PI));
  EXPECT_NEAR(flipped.velocity.x(), 0.5, 1e-15);
  EXPECT_NEAR(flipped.velocity.y(), 0.25, 1e-15);
  EXPECT_NEAR(flipped.angular_velocity, -0.75, 1e-15);
  // Rolled by 60 degrees: the turn rate counts by cos 60 = 1/2, vy shortens likewise.
  const core::Motion rolled = ownMotion(spec, framePose(0.0, 0.0, 0.0, 0.0, M_PI / 3));
  EXPECT_NEAR(rolled.velocity.y(), -0.125, 1e-15);
  EXPECT_NEAR(rolled.angular_velocity, 0.375, 1e-15);
}

}  // namespace
}  // namespace ellipse_collision::app

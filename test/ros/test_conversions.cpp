// Message <-> application/core conversions, field by field; no ROS master needed. (The field
// rules themselves are tested in test/app/test_ellipse_spec.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "ellipse_collision/ros/conversions.h"

namespace ellipse_collision {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

app::EllipseSpec sampleSpec() {
  app::EllipseSpec spec;
  spec.name = "forearm";
  spec.frame_id = "forearm_link";
  spec.x = 0.125;
  spec.y = -3.5;
  spec.angle = 0.1;  // not exactly representable: the round trip must keep every bit anyway
  spec.radius_x = 0.3;
  spec.radius_y = 0.07;
  spec.padding = 0.01;
  spec.vx = 0.3;
  spec.vy = -1.7;
  spec.angular_velocity = 0.7;
  return spec;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

void expectSameSpec(const app::EllipseSpec& a, const app::EllipseSpec& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.frame_id, b.frame_id);
  EXPECT_TRUE(sameBits(a.x, b.x));
  EXPECT_TRUE(sameBits(a.y, b.y));
  EXPECT_TRUE(sameBits(a.angle, b.angle));
  EXPECT_TRUE(sameBits(a.radius_x, b.radius_x));
  EXPECT_TRUE(sameBits(a.radius_y, b.radius_y));
  EXPECT_TRUE(sameBits(a.padding, b.padding));
  EXPECT_TRUE(sameBits(a.vx, b.vx));
  EXPECT_TRUE(sameBits(a.vy, b.vy));
  EXPECT_TRUE(sameBits(a.angular_velocity, b.angular_velocity));
  ASSERT_EQ(a.ellipsoid.has_value(), b.ellipsoid.has_value());
  if (a.ellipsoid) {
    EXPECT_TRUE(sameBits(a.ellipsoid->z, b.ellipsoid->z));
    EXPECT_TRUE(sameBits(a.ellipsoid->roll, b.ellipsoid->roll));
    EXPECT_TRUE(sameBits(a.ellipsoid->pitch, b.ellipsoid->pitch));
    EXPECT_TRUE(sameBits(a.ellipsoid->radius_z, b.ellipsoid->radius_z));
  }
}

/// sampleSpec() as an ellipsoid, every field of the part a number that is not exactly a double.
app::EllipseSpec sampleEllipsoid() {
  app::EllipseSpec spec = sampleSpec();
  spec.ellipsoid = app::EllipsoidPart{0.3, 1.1, -0.7, 0.45};
  return spec;
}

TEST(Conversions, EllipseSpecSurvivesTheRoundTripThroughTheMessage) {
  expectSameSpec(fromMsg(toMsg(sampleSpec())), sampleSpec());
  expectSameSpec(fromMsg(toMsg(sampleEllipsoid())), sampleEllipsoid());
}

TEST(Conversions, APlanarEllipseHasZeroDepthAndAnyOtherDepthIsAnEllipsoid) {
  // A message built without the ellipsoid fields is planar, and a planar spec writes them as 0.
  Ellipse msg = toMsg(sampleSpec());
  EXPECT_EQ(msg.z, 0.0);
  EXPECT_EQ(msg.roll, 0.0);
  EXPECT_EQ(msg.pitch, 0.0);
  EXPECT_EQ(msg.radius_z, 0.0);
  EXPECT_FALSE(fromMsg(msg).ellipsoid);
  msg.z = -0.0;  // still zero
  EXPECT_FALSE(fromMsg(msg).ellipsoid);
  // Any one of the four not 0 (NaN included) makes the ellipsoid part, for the field rules to
  // judge: a tilt without radius_z is refused there, not read as planar here.
  for (double Ellipse::*field : {&Ellipse::z, &Ellipse::roll, &Ellipse::pitch, &Ellipse::radius_z}) {
    for (const double value : {0.25, -1.0, kNaN}) {
      Ellipse tilted = toMsg(sampleSpec());
      tilted.*field = value;
      const app::EllipseSpec spec = fromMsg(tilted);
      ASSERT_TRUE(spec.ellipsoid);
      const Ellipse back = toMsg(spec);
      EXPECT_TRUE(sameBits(back.*field, value));
    }
  }
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
  msg.vx = 7;
  msg.vy = 8;
  msg.angular_velocity = 9;
  msg.z = 10;
  msg.roll = 11;
  msg.pitch = 12;
  msg.radius_z = 13;
  const app::EllipseSpec spec = fromMsg(msg);
  EXPECT_EQ(spec.name, "n");
  EXPECT_EQ(spec.frame_id, "f");
  EXPECT_EQ(spec.x, 1);
  EXPECT_EQ(spec.y, 2);
  EXPECT_EQ(spec.angle, 3);
  EXPECT_EQ(spec.radius_x, 4);
  EXPECT_EQ(spec.radius_y, 5);
  EXPECT_EQ(spec.padding, 6);
  EXPECT_EQ(spec.vx, 7);
  EXPECT_EQ(spec.vy, 8);
  EXPECT_EQ(spec.angular_velocity, 9);
  ASSERT_TRUE(spec.ellipsoid);
  EXPECT_EQ(spec.ellipsoid->z, 10);
  EXPECT_EQ(spec.ellipsoid->roll, 11);
  EXPECT_EQ(spec.ellipsoid->pitch, 12);
  EXPECT_EQ(spec.ellipsoid->radius_z, 13);
  EXPECT_EQ(toMsg(spec), msg);
}

TEST(Conversions, NonFiniteValuesPassThroughUnchangedForTheValidatorToSee) {
  app::EllipseSpec spec = sampleSpec();
  spec.x = kNaN;
  spec.radius_y = -kInf;
  expectSameSpec(fromMsg(toMsg(spec)), spec);
  spec = sampleEllipsoid();
  spec.ellipsoid->radius_z = kNaN;
  spec.ellipsoid->pitch = kInf;
  expectSameSpec(fromMsg(toMsg(spec)), spec);
}

TEST(Conversions, EllipseArrayEntryWithoutFrameTakesTheHeaderFrame) {
  EllipseArray array;
  array.header.frame_id = "odom";
  array.ellipses.push_back(toMsg(sampleSpec()));
  array.ellipses.push_back(toMsg(sampleEllipsoid()));
  array.ellipses[1].frame_id = "";
  array.ellipses[1].name = "rock";
  const std::vector<app::EllipseSpec> specs = fromMsg(array);
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[0].frame_id, "forearm_link");
  EXPECT_EQ(specs[1].frame_id, "odom");
  EXPECT_EQ(specs[1].name, "rock");
  EXPECT_FALSE(specs[0].ellipsoid);
  ASSERT_TRUE(specs[1].ellipsoid);
  EXPECT_EQ(specs[1].ellipsoid->radius_z, 0.45);
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

// The incident replay reads decisions back from ~gate_state's message: every field returns as it
// was written, and an action the gate does not have is refused.
TEST(Conversions, AGateDecisionSurvivesTheRoundTripThroughGateState) {
  app::GateDecision decision;
  decision.action = core::GateAction::Slow;
  decision.scale = 0.4375;
  decision.input.linear = Eigen::Vector3d(1.5, -0.25, 0.0);
  decision.input.angular = Eigen::Vector3d(0.0, 0.0, 0.75);
  decision.output.linear = decision.input.linear * decision.scale;
  decision.output.angular = decision.input.angular * decision.scale;
  decision.contact_predicted = true;
  decision.time_to_contact_s = 1.125;
  decision.link = "base_link";
  decision.obstacle = "front/scan_3";
  decision.contact_point = Eigen::Vector2d(2.5, -0.125);
  decision.braking_distance_m = 0.9;
  decision.free_distance_m = 1.7;
  decision.unavoidable = false;
  decision.impact_speed = 0.0;
  decision.reason = "slows for 'front/scan_3'";
  app::GateDecision back;
  ASSERT_TRUE(fromMsg(toMsg(decision), &back));
  EXPECT_EQ(back.action, decision.action);
  EXPECT_EQ(back.scale, decision.scale);
  EXPECT_EQ(back.input.linear, decision.input.linear);
  EXPECT_EQ(back.input.angular, decision.input.angular);
  EXPECT_EQ(back.output.linear, decision.output.linear);
  EXPECT_EQ(back.output.angular, decision.output.angular);
  EXPECT_EQ(back.contact_predicted, decision.contact_predicted);
  EXPECT_EQ(back.time_to_contact_s, decision.time_to_contact_s);
  EXPECT_EQ(back.link, decision.link);
  EXPECT_EQ(back.obstacle, decision.obstacle);
  EXPECT_EQ(back.contact_point, decision.contact_point);
  EXPECT_EQ(back.braking_distance_m, decision.braking_distance_m);
  EXPECT_EQ(back.free_distance_m, decision.free_distance_m);
  EXPECT_EQ(back.unavoidable, decision.unavoidable);
  EXPECT_EQ(back.reason, decision.reason);

  GateState unknown = toMsg(decision);
  unknown.action = "BRAKE";
  app::GateDecision untouched;
  EXPECT_FALSE(fromMsg(unknown, &untouched));
  EXPECT_EQ(untouched.scale, app::GateDecision().scale);
}

TEST(Conversions, ARangeMessageKeepsEveryFieldNonFiniteOnesIncluded) {
  sensor_msgs::Range msg;
  msg.header.frame_id = "sonar_left";
  msg.range = 1.25f;
  msg.min_range = 0.02f;
  msg.max_range = 4.0f;
  msg.field_of_view = 0.5f;
  app::RangeReading reading = fromMsg(msg);
  EXPECT_EQ(reading.frame_id, "sonar_left");
  EXPECT_EQ(reading.range, 1.25);
  EXPECT_EQ(reading.min_range, static_cast<double>(0.02f));
  EXPECT_EQ(reading.max_range, 4.0);
  EXPECT_EQ(reading.field_of_view, 0.5);
  msg.range = -std::numeric_limits<float>::infinity();
  msg.field_of_view = std::numeric_limits<float>::quiet_NaN();
  reading = fromMsg(msg);
  EXPECT_EQ(reading.range, -kInf);
  EXPECT_TRUE(std::isnan(reading.field_of_view));
}

}  // namespace
}  // namespace ellipse_collision

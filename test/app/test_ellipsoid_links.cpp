// Ellipsoid links (EllipseSpec::ellipsoid) in the application layer: validated by the field
// rules, placed by their shadow wherever a link is placed (checks, path checks, the gate's scene),
// where a planar ellipse in a tilted frame is refused edge-on. Values worked out by hand: an upper
// arm of radii (0.2, 0.06, 0.06) rolled 90 degrees about its own x axis still shadows 0.2 x 0.06.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/frame_placer.h"
#include "ellipse_collision/app/link_fitting.h"
#include "ellipse_collision/app/path_request.h"
#include "shadow_oracle.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

constexpr double kPi = 3.14159265358979323846;

EllipseSpec upperArm(const std::string& frame) {
  EllipseSpec spec = test::circle("upper_arm", frame, 0.0, 0.0, 0.2);
  spec.radius_y = 0.06;
  spec.ellipsoid = EllipsoidPart{0.0, 0.0, 0.0, 0.06};
  return spec;
}

/// "map" is the fixed frame; "arm" is rolled by `roll` about x at the origin.
TransformLookup rolledArm(double roll) {
  return [roll](const std::string& frame) {
    FrameTransform transform;
    transform.ok = frame == "map" || frame == "arm";
    if (!transform.ok) transform.error = "frame '" + frame + "' does not exist";
    if (frame == "arm") {
      transform.fixed_from_frame.linear() =
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()).toRotationMatrix();
    }
    return transform;
  };
}

TEST(EllipsoidLinks, FieldsKeepTheCoreRules) {
  EllipseSpec spec = upperArm("arm");
  EXPECT_FALSE(findInvalidField(spec));
  spec.ellipsoid->radius_z = 0.0;
  auto error = findInvalidField(spec);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->key, "radius_z");
  spec.ellipsoid->radius_z = 0.06;
  spec.ellipsoid->roll = std::nan("");
  error = findInvalidField(spec);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->key, "roll");
  spec.ellipsoid->roll = 0.0;
  spec.ellipsoid->z = 2e9;
  error = findInvalidField(spec);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->key, "z");
  spec.ellipsoid->z = 0.0;
  spec.padding = 1e9;  // padded radius_x = 1e9 + 0.2 is beyond kMaxRadius
  error = findInvalidPaddedField(spec, 0.0);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->key, "radius_x");
}

TEST(EllipsoidLinks, PaddingGrowsAllThreeRadii) {
  EllipseSpec spec = upperArm("arm");
  spec.padding = 0.01;
  const core::Ellipsoid padded = paddedEllipsoid(spec, 0.02);
  EXPECT_DOUBLE_EQ(padded.radii.x(), 0.23);
  EXPECT_DOUBLE_EQ(padded.radii.y(), 0.09);
  EXPECT_DOUBLE_EQ(padded.radii.z(), 0.09);
}

TEST(EllipsoidLinks, RolledLinkIsPlacedByItsShadowWherePlanarOneIsLost) {
  for (const double degrees : {0.0, 80.0, 90.0, 170.0}) {
    FramePlacer placement(rolledArm(degrees * kPi / 180.0), 0.0);
    const auto placed = placement.place(upperArm("arm"), core::EllipseRole::Query);
    ASSERT_EQ(placed.status, FramePlacer::Status::Placed) << degrees << ": " << placed.error;
    EXPECT_NEAR(placed.ellipse.ellipse.radius_x, 0.2, 1e-12) << degrees;
    EXPECT_NEAR(placed.ellipse.ellipse.radius_y, 0.06, 1e-12) << degrees;
  }
  EllipseSpec planar = upperArm("arm");
  planar.ellipsoid.reset();
  FramePlacer placement(rolledArm(kPi / 2), 0.0);
  EXPECT_EQ(placement.place(planar, core::EllipseRole::Query).status,
            FramePlacer::Status::Degenerate);
}

TEST(EllipsoidLinks, CheckReportsThePostTheRolledArmShadows) {
  // The post at (0, 0.1), radius 0.05, reaches down to y = 0.05; the rolled arm's shadow up to
  // y = 0.06. The planar arm seen edge-on would be skipped and the post missed.
  EllipseRegistry registry({upperArm("arm")}, {test::circle("post", "map", 0.0, 0.1, 0.05)});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const CheckOutcome outcome = runCheck({}, registry, settings, rolledArm(kPi / 2), 0.0);
  ASSERT_EQ(outcome.error, "");
  EXPECT_TRUE(outcome.skipped.empty());
  ASSERT_EQ(outcome.collisions.size(), 1u);
  EXPECT_EQ(outcome.collisions[0].name_a, "upper_arm");
  EXPECT_EQ(outcome.collisions[0].name_b, "post");
}

TEST(EllipsoidLinks, PathCheckMovesTheRolledArmsShadow) {
  // The arm frame is base_link rolled 90 degrees: its shadow reaches 0.2 m ahead of the frame.
  // Going 2 m along x from map's origin, it meets the post (0.05 m at x = 1) when the frame is
  // at 1 - 0.05 - 0.2 = 0.75: fraction 0.375. The planar arm is seen edge-on and left out.
  const EllipseRegistry registry({upperArm("arm")}, {test::circle("post", "map", 1.0, 0.0, 0.05)});
  CheckSettings settings;
  settings.fixed_frame = "map";
  const TransformLookup to_moving = [](const std::string& frame) {
    return rolledArm(kPi / 2)(frame == "base_link" ? "map" : frame);  // base_link is the origin
  };
  const TransformLookup to_map = [](const std::string& frame) {
    FrameTransform t;
    t.ok = frame == "map" || frame == "base_link";
    return t;
  };
  PathCheckRequest request;
  request.path_frame = "map";
  request.moving_frame = "base_link";
  request.poses.resize(2);
  request.poses[1].x = 2.0;
  const PathCheckOutcome outcome = runPathCheck(request, registry, settings, to_moving, to_map, 0.0);
  ASSERT_EQ(outcome.error, "");
  EXPECT_TRUE(outcome.skipped.empty());
  EXPECT_FALSE(outcome.result.collision_free);
  EXPECT_EQ(outcome.result.link, "upper_arm");
  EXPECT_NEAR(outcome.result.fraction, 0.375, 1e-9);

  EllipseSpec planar = upperArm("arm");
  planar.ellipsoid.reset();
  const EllipseRegistry planar_registry({planar}, {test::circle("post", "map", 1.0, 0.0, 0.05)});
  const PathCheckOutcome lost =
      runPathCheck(request, planar_registry, settings, to_moving, to_map, 0.0);
  EXPECT_TRUE(lost.result.collision_free);
  EXPECT_EQ(lost.skipped.size(), 1u);
}

TEST(EllipsoidLinks, FittedArmFootprintContainsItsCylinderAtEveryRollAndPitch) {
  // Upper arm: cylinder of radius 6 cm and length 40 cm along the link's x, from 0 to 0.4 m.
  core::CollisionShape cylinder;
  cylinder.type = core::CollisionShape::Cylinder;
  cylinder.radius = 0.06;
  cylinder.length = 0.4;
  cylinder.link_from_shape.linear() =
      Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  cylinder.link_from_shape.translation() = Eigen::Vector3d(0.2, 0.0, 0.0);
  const LinkFitResult fitted =
      fitLinkEllipses({LinkGeometry{"upper_arm", {cylinder}}}, 0.0, LinkShape::Ellipsoid);
  ASSERT_TRUE(fitted.ok()) << fitted.error;
  ASSERT_EQ(fitted.links.size(), 1u);
  const EllipseSpec& arm = fitted.links[0];
  ASSERT_TRUE(arm.ellipsoid);
  EXPECT_NE(linksYaml(fitted.links).find("radius_z: "), std::string::npos);

  // Surface samples of the cylinder (wall and end discs), placed through the link's pose and
  // projected, against the footprint the check places for that pose.
  double worst = -1.0;
  for (int roll_step = 0; roll_step <= 18; ++roll_step) {
    for (int pitch_step = 0; pitch_step <= 18; ++pitch_step) {
      const double roll = roll_step * kPi / 18, pitch = pitch_step * kPi / 18;
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.linear() = (Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                          .toRotationMatrix();
      pose.translation() = Eigen::Vector3d(1.0, -0.5, 0.3);
      FramePlacer placement(
          [&pose](const std::string&) {
            FrameTransform t;
            t.ok = true;
            t.fixed_from_frame = pose;
            return t;
          },
          0.0);
      const auto placed = placement.place(arm, core::EllipseRole::Query);
      ASSERT_EQ(placed.status, FramePlacer::Status::Placed) << placed.error;
      for (int k = 0; k < 720; ++k) {
        const double t = 2 * kPi * (k % 72) / 72, along = (k / 72) / 9.0;
        for (const Eigen::Vector3d& local :
             {Eigen::Vector3d(0.06 * std::cos(t), 0.06 * std::sin(t), 0.4 * (along - 0.5)),
              Eigen::Vector3d(0.06 * along * std::cos(t), 0.06 * along * std::sin(t), -0.2),
              Eigen::Vector3d(0.06 * along * std::cos(t), 0.06 * along * std::sin(t), 0.2)}) {
          const Eigen::Vector3d p = pose * (cylinder.link_from_shape * local);
          const double form =
              static_cast<double>(test::shadowForm(placed.ellipse.ellipse, p.x(), p.y()));
          worst = std::max(worst, form - 1.0);
          ASSERT_LE(form, 1.0) << "roll " << roll << " pitch " << pitch;
        }
      }
    }
  }
  std::printf("[ record   ] fitted arm over 361 roll/pitch poses: worst projected-cylinder "
              "form - 1 = %.3g\n", worst);
}

}  // namespace
}  // namespace ellipse_collision::app

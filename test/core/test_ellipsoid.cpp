// shadowOnPlane() against an independent reference in quad precision: the shadow against the
// projections of surface points of the placed ellipsoid (every one inside, the support point in
// each direction on the boundary to 1e-9). Each family prints a "[ record   ]" line with its
// worst figures. (minimumVolumeEllipsoid(): test_enclosing_ellipsoid.cpp.)

#include <gtest/gtest.h>
#include <quadmath.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipsoid.h"
#include "ellipse_collision/core/frame_projection.h"
#include "random_source.h"
#include "shadow_oracle.h"

namespace ellipse_collision::core {
namespace test {
namespace {

using Vec3 = Eigen::Vector3d;
using ellipse_collision::test::ellipsoidForm;
using ellipse_collision::test::QMat3;
using ellipse_collision::test::quad;
using ellipse_collision::test::QVec3;
using ellipse_collision::test::randomOrientation;
using ellipse_collision::test::RandomSource;

constexpr double kPi = 3.14159265358979323846;

Eigen::Isometry3d randomPose(RandomSource& random, double reach) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = randomOrientation(random).toRotationMatrix();
  pose.translation() = Vec3(random.uniform(-reach, reach), random.uniform(-reach, reach),
                            random.uniform(-reach, reach));
  return pose;
}

struct ShadowRecord {
  int shadows{0};
  double worst_outside{-1.0};  // largest (form - 1) of a projected surface point, > 0 would fail
  double worst_slack{0.0};    // largest 1 - form of the support points: how far from touching
  double worst_own_slack{0.0};  // ... less what the rounding of the centre to a double costs
  ~ShadowRecord() {
    std::printf("[ record   ] shadows: %d, worst surface-sample form - 1 = %.3g, worst support "
                "slack = %.3g (%.3g beyond the centre's rounding)\n",
                shadows, worst_outside, worst_slack, worst_own_slack);
  }
};

/// Every projected surface sample inside the shadow; the support point of each of 256 directions
/// inside and on the boundary to 1e-9 in the quadratic form, plus what the rounding of the centre
/// to a double costs (4 ulp(|centre|) / radius_y, as for the 2D fit): test::compareShadow().
void expectExactShadow(const Ellipsoid& e, const Eigen::Isometry3d& pose, RandomSource& random,
                       ShadowRecord& record) {
  const ProjectionResult shadow = shadowOnPlane(e, pose, "e");
  ASSERT_TRUE(shadow.ok()) << shadow.error;
  ++record.shadows;
  const ellipse_collision::test::ShadowAgreement agreement =
      ellipse_collision::test::compareShadow(shadow.ellipse,
                                             ellipse_collision::test::placeInQuad(e, pose), random);
  record.worst_outside = std::max(record.worst_outside, agreement.worst_outside);
  record.worst_slack = std::max(record.worst_slack, agreement.worst_slack);
  record.worst_own_slack = std::max(record.worst_own_slack,
                                    agreement.worst_slack - (agreement.allowed_slack - 1e-9));
  ASSERT_LE(agreement.worst_outside, 0.0) << "a surface sample outside the shadow";
  ASSERT_LE(agreement.worst_support_outside, 0.0) << "a support point outside the shadow";
  ASSERT_LE(agreement.worst_slack, agreement.allowed_slack)
      << "the shadow does not touch the support point in some direction";
}

TEST(EllipsoidShadow, RolledCylinderKeepsItsStrip) {
  // An upper arm along x: 40 cm long, 6 cm radius; its frame rolled about x. A planar ellipse in
  // the frame's xy-plane is lost edge-on at 90 degrees; the ellipsoid's shadow keeps its width.
  Ellipsoid arm;
  arm.radii = Vec3(0.2, 0.06, 0.06);
  for (const double degrees : {0.0, 45.0, 80.0, 90.0, 135.0, 180.0}) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::AngleAxisd(degrees * kPi / 180.0, Vec3::UnitX()).toRotationMatrix();
    const ProjectionResult shadow = shadowOnPlane(arm, pose, "upper_arm");
    ASSERT_TRUE(shadow.ok()) << shadow.error;
    EXPECT_NEAR(shadow.ellipse.radius_x, 0.2, 1e-15) << degrees;
    EXPECT_NEAR(shadow.ellipse.radius_y, 0.06, 1e-15) << degrees;
    EXPECT_GE(shadow.ellipse.radius_y, 0.06) << degrees;  // rounded up, never thinner
  }
  Ellipse planar;
  planar.radius_x = 0.2, planar.radius_y = 0.06;
  Eigen::Isometry3d rolled = Eigen::Isometry3d::Identity();
  rolled.linear() = Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()).toRotationMatrix();
  EXPECT_FALSE(projectToPlane(planar, rolled, "upper_arm").ok());
}

TEST(EllipsoidShadow, PitchedArmShadowShortens) {
  // Pitched by 60 degrees about y, the 0.2 m semi-axis along x shadows as 0.2 cos 60 = 0.1, and
  // the 0.06 one along z adds in quadrature: the shadow's x radius is sqrt(0.1^2 + 0.06^2 sin^2).
  Ellipsoid arm;
  arm.radii = Vec3(0.2, 0.06, 0.06);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(kPi / 3, Vec3::UnitY()).toRotationMatrix();
  const ProjectionResult shadow = shadowOnPlane(arm, pose, "upper_arm");
  ASSERT_TRUE(shadow.ok()) << shadow.error;
  const double along = std::hypot(0.2 * 0.5, 0.06 * std::sin(kPi / 3));
  EXPECT_NEAR(std::max(shadow.ellipse.radius_x, shadow.ellipse.radius_y), std::max(along, 0.06),
              1e-15);
  EXPECT_NEAR(std::min(shadow.ellipse.radius_x, shadow.ellipse.radius_y), std::min(along, 0.06),
              1e-15);
}

TEST(EllipsoidShadow, MatchesProjectedSurfaceOfRandomPlacements) {
  RandomSource random(20261126);
  ShadowRecord record;
  for (int trial = 0; trial < 300; ++trial) {
    Ellipsoid e;
    const double size = random.logUniform(1e-3, 1e2);
    // Up to 1e3 between the radii: needles and pancakes seen from every side.
    e.radii = Vec3(size * random.logUniform(1e-3, 1.0), size * random.logUniform(1e-3, 1.0), size);
    e.center = Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)) * size;
    e.orientation = randomOrientation(random);
    expectExactShadow(e, randomPose(random, trial % 3 == 0 ? 1e3 : 1.0), random, record);
    if (HasFatalFailure()) return;
  }
}

TEST(EllipsoidShadow, FlatEllipsoidSeenEdgeOnKeepsItsThickness) {
  Ellipsoid disk;
  disk.radii = Vec3(0.3, 0.2, 1e-6);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()).toRotationMatrix();
  const ProjectionResult shadow = shadowOnPlane(disk, pose, "disk");
  ASSERT_TRUE(shadow.ok()) << shadow.error;
  EXPECT_NEAR(shadow.ellipse.radius_y, 1e-6, 1e-15);
  EXPECT_GE(shadow.ellipse.radius_y, 1e-6);
  RandomSource random(7);
  ShadowRecord record;
  expectExactShadow(disk, pose, random, record);
}

TEST(EllipsoidShadow, NeedleTooThinToCertifyIsRefusedAndOneJustBelowContainsItsSamples) {
  // A needle 1e9 m long and 1e-9 m thin (axis ratio 1e18): the certification's error bound is
  // larger than its width, and the shadow is refused by name instead of coming out NaN.
  Ellipsoid needle;
  needle.radii = Vec3(1e9, 1e-9, 1e-9);
  const ProjectionResult refused = shadowOnPlane(needle, Eigen::Isometry3d::Identity(), "needle");
  EXPECT_EQ(refused.error.rfind("ellipsoid 'needle': its shadow is too thin to certify (axis ratio ",
                                0),
            0u)
      << refused.error;
  // At an axis ratio of 1e16 it is certified, grown by at most a few percent, and still holds
  // every projected surface sample (the support slack is the growth, not 1e-9).
  needle.radii = Vec3(1e7, 1e-9, 1e-9);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.5, Vec3::UnitY()).toRotationMatrix();
  const ProjectionResult shadow = shadowOnPlane(needle, pose, "needle");
  ASSERT_TRUE(shadow.ok()) << shadow.error;
  RandomSource random(11);
  const ellipse_collision::test::ShadowAgreement agreement = ellipse_collision::test::compareShadow(
      shadow.ellipse, ellipse_collision::test::placeInQuad(needle, pose), random);
  EXPECT_LE(agreement.worst_outside, 0.0);
  EXPECT_LE(agreement.worst_support_outside, 0.0);
  EXPECT_LE(agreement.worst_slack, 0.1);
}

TEST(EllipsoidShadow, RefusesInvalidInputNamingTheField) {
  Ellipsoid e;
  e.radii.z() = 0.0;
  ProjectionResult shadow = shadowOnPlane(e, Eigen::Isometry3d::Identity(), "forearm");
  EXPECT_EQ(shadow.error, "ellipsoid 'forearm': radii.z = 0 must be > 0");
  e.radii.z() = 1.0;
  e.orientation = Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0);
  shadow = shadowOnPlane(e, Eigen::Isometry3d::Identity(), "forearm");
  EXPECT_EQ(shadow.error, "ellipsoid 'forearm': orientation is not a unit quaternion (norm 2)");
  e.orientation = Eigen::Quaterniond::Identity();
  e.center.y() = std::nan("");
  shadow = shadowOnPlane(e, Eigen::Isometry3d::Identity(), "forearm");
  EXPECT_EQ(shadow.error, "ellipsoid 'forearm': center.y = nan is not finite");
  e.center.y() = 0.0;
  Eigen::Isometry3d broken = Eigen::Isometry3d::Identity();
  broken.translation().x() = std::numeric_limits<double>::infinity();
  shadow = shadowOnPlane(e, broken, "forearm");
  EXPECT_EQ(shadow.error, "ellipsoid 'forearm': the transform of its frame is not finite");
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

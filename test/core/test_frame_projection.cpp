// Frame projection: hand-computed tilted frames and an independent check that samples the rim in
// 3D, projects the points by dropping z, and finds the preimages of the returned extreme points.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "ellipse_collision/core/frame_projection.h"
#include "scene_test_helpers.h"

namespace ellipse_collision::core {
namespace {

using scene_test::ellipse;

Eigen::Isometry3d pose(const Eigen::Vector3d& translation, const Eigen::Matrix3d& rotation) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = rotation;
  t.translation() = translation;
  return t;
}

Eigen::Matrix3d aboutX(double rad) {
  return Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitX()).matrix();
}
Eigen::Matrix3d aboutZ(double rad) {
  return Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitZ()).matrix();
}

/// Angles of an ellipse are equivalent modulo pi; the difference folded into (-pi/2, pi/2].
double angleDifferenceModPi(double a, double b) { return std::remainder(a - b, M_PI); }

/// The point of the in-frame ellipse at parameter s, in 3D frame coordinates (z = 0).
Eigen::Vector3d rimPoint(const Ellipse& e, double s) {
  const Eigen::Vector2d local(e.radius_x * std::cos(s), e.radius_y * std::sin(s));
  const Eigen::Vector2d p = e.center + Eigen::Rotation2Dd(e.angle) * local;
  return Eigen::Vector3d(p.x(), p.y(), 0.0);
}

/// Implicit-equation value (x'/rx)^2 + (y'/ry)^2 of point q for ellipse e: 1 on the rim.
double implicitValue(const Ellipse& e, const Eigen::Vector2d& q) {
  const Eigen::Vector2d local = Eigen::Rotation2Dd(-e.angle) * (q - e.center);
  return std::pow(local.x() / e.radius_x, 2) + std::pow(local.y() / e.radius_y, 2);
}

/// Point p of the frame's xy-plane whose projection is q: solves the 3D map restricted to z = 0
/// with a QR factorisation (independent of the closed-form SVD under test).
Eigen::Vector2d preimage(const Eigen::Isometry3d& fixed_from_frame, const Eigen::Vector2d& q) {
  Eigen::Matrix<double, 2, 2> m;
  m.col(0) =
      (fixed_from_frame * Eigen::Vector3d::UnitX() - fixed_from_frame.translation()).head<2>();
  m.col(1) =
      (fixed_from_frame * Eigen::Vector3d::UnitY() - fixed_from_frame.translation()).head<2>();
  return m.colPivHouseholderQr().solve(q - fixed_from_frame.translation().head<2>());
}

TEST(FrameProjection, IdentityTransformKeepsTheEllipse) {
  const Ellipse in = ellipse(1.5, -2.0, 0.7, 0.3, 0.4);
  const ProjectionResult out = projectToPlane(in, Eigen::Isometry3d::Identity(), "plate");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NEAR(out.ellipse.center.x(), 1.5, 1e-15);
  EXPECT_NEAR(out.ellipse.center.y(), -2.0, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_x, 0.7, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_y, 0.3, 1e-15);
  EXPECT_NEAR(out.ellipse.angle, 0.4, 1e-15);
}

TEST(FrameProjection, CircleInFrameTiltedSixtyDegreesAboutXBecomesHalfAsTall) {
  // Frame at (3, -1, 0.7) rotated 60 deg about x: its y axis becomes (0, cos 60, sin 60).
  // Centre (1, 2, 0) -> (1, 2 cos 60, 2 sin 60) + t = (4, 0, ...). Radius along y: 0.4 cos 60.
  const Ellipse circle = ellipse(1.0, 2.0, 0.4, 0.4, 0.0);
  const ProjectionResult out =
      projectToPlane(circle, pose({3.0, -1.0, 0.7}, aboutX(M_PI / 3)), "disc");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NEAR(out.ellipse.center.x(), 4.0, 1e-15);
  EXPECT_NEAR(out.ellipse.center.y(), 0.0, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_x, 0.4, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_y, 0.2, 1e-15);
  EXPECT_NEAR(angleDifferenceModPi(out.ellipse.angle, 0.0), 0.0, 1e-15);
}

TEST(FrameProjection, EllipseInYawedAndTiltedFrameTurnsWithTheYaw) {
  // R = Rz(90 deg) Rx(60 deg): the tilt halves the ellipse's y radius (0.3 -> 0.15), the yaw
  // then turns its x axis (radius 0.5) onto the fixed y axis, so the angle is pi/2.
  const Ellipse in = ellipse(0.0, 0.0, 0.5, 0.3, 0.0);
  const ProjectionResult out =
      projectToPlane(in, pose({0.2, 0.1, 0.0}, aboutZ(M_PI / 2) * aboutX(M_PI / 3)), "gripper");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NEAR(out.ellipse.center.x(), 0.2, 1e-15);
  EXPECT_NEAR(out.ellipse.center.y(), 0.1, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_x, 0.5, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_y, 0.15, 1e-15);
  EXPECT_NEAR(angleDifferenceModPi(out.ellipse.angle, M_PI / 2), 0.0, 1e-15);
}

TEST(FrameProjection, TiltThatMakesTheMinorAxisMajorSwapsTheAxes) {
  // Ellipse 0.5 x 0.3 in a frame rotated 60 deg about y: the frame's x axis projects to length
  // cos 60, so the x radius shrinks to 0.25, below the untouched y radius 0.3. The projection is
  // 0.3 along fixed y (major) and 0.25 along fixed x (minor): angle pi/2.
  const Ellipse in = ellipse(0.0, 0.0, 0.5, 0.3, 0.0);
  const Eigen::Matrix3d about_y = Eigen::AngleAxisd(M_PI / 3, Eigen::Vector3d::UnitY()).matrix();
  const ProjectionResult out = projectToPlane(in, pose({0.0, 0.0, 0.0}, about_y), "forearm");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NEAR(out.ellipse.radius_x, 0.3, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_y, 0.25, 1e-15);
  EXPECT_NEAR(angleDifferenceModPi(out.ellipse.angle, M_PI / 2), 0.0, 1e-15);
}

TEST(FrameProjection, UpsideDownFrameMirrorsTheAngle) {
  // Half turn about x maps (x, y) to (x, -y): the centre's y and the angle change sign.
  const Ellipse in = ellipse(1.0, 0.5, 0.6, 0.2, M_PI / 6);
  const ProjectionResult out = projectToPlane(in, pose({0.0, 0.0, 2.0}, aboutX(M_PI)), "flipped");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NEAR(out.ellipse.center.x(), 1.0, 1e-15);
  EXPECT_NEAR(out.ellipse.center.y(), -0.5, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_x, 0.6, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_y, 0.2, 1e-15);
  EXPECT_NEAR(angleDifferenceModPi(out.ellipse.angle, -M_PI / 6), 0.0, 1e-15);
}

TEST(FrameProjection, HeightOfTheFrameDoesNotMatter) {
  const Ellipse in = ellipse(0.3, 0.1, 0.6, 0.2, 1.0);
  const Eigen::Matrix3d r = aboutZ(0.3) * aboutX(0.5);
  const ProjectionResult low = projectToPlane(in, pose({1.0, 2.0, -5.0}, r), "a");
  const ProjectionResult high = projectToPlane(in, pose({1.0, 2.0, 7.5}, r), "a");
  ASSERT_TRUE(low.ok() && high.ok());
  EXPECT_EQ(low.ellipse.center, high.ellipse.center);
  EXPECT_EQ(low.ellipse.radius_x, high.ellipse.radius_x);
  EXPECT_EQ(low.ellipse.radius_y, high.ellipse.radius_y);
  EXPECT_EQ(low.ellipse.angle, high.ellipse.angle);
}

TEST(FrameProjection, RandomPosesProjectRimPointsOntoTheReturnedEllipse) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> radius(0.05, 3.0);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Quaterniond q =
        Eigen::Quaterniond(unit(rng), unit(rng), unit(rng), unit(rng)).normalized();
    const Eigen::Matrix3d rotation = q.toRotationMatrix();
    // Keep away from edge-on frames, whose conditioning is tested separately.
    if (std::abs(rotation(2, 2)) < 0.05) continue;
    const Eigen::Isometry3d t =
        pose(3.0 * Eigen::Vector3d(unit(rng), unit(rng), unit(rng)), rotation);
    const Ellipse in =
        ellipse(2 * unit(rng), 2 * unit(rng), radius(rng), radius(rng), 4 * unit(rng));
    const ProjectionResult out = projectToPlane(in, t, "random");
    ASSERT_TRUE(out.ok()) << out.error;
    ++checked;

    for (int k = 0; k < 32; ++k) {
      const Eigen::Vector3d rim = t * rimPoint(in, 2 * M_PI * k / 32);
      ASSERT_NEAR(implicitValue(out.ellipse, rim.head<2>()), 1.0, 1e-12) << "trial " << trial;
    }
    // Each extreme point of the returned ellipse is the image of a rim point of the original.
    const Eigen::Vector2d major_axis =
        Eigen::Rotation2Dd(out.ellipse.angle) * Eigen::Vector2d::UnitX();
    const Eigen::Vector2d minor_axis =
        Eigen::Rotation2Dd(out.ellipse.angle) * Eigen::Vector2d::UnitY();
    for (const Eigen::Vector2d& extreme :
         {Eigen::Vector2d(out.ellipse.center + out.ellipse.radius_x * major_axis),
          Eigen::Vector2d(out.ellipse.center - out.ellipse.radius_x * major_axis),
          Eigen::Vector2d(out.ellipse.center + out.ellipse.radius_y * minor_axis),
          Eigen::Vector2d(out.ellipse.center - out.ellipse.radius_y * minor_axis)}) {
      ASSERT_NEAR(implicitValue(in, preimage(t, extreme)), 1.0, 1e-12) << "trial " << trial;
    }
    EXPECT_GE(out.ellipse.radius_x, out.ellipse.radius_y * (1 - 1e-15));
    EXPECT_GT(out.ellipse.angle, -M_PI / 2);
    EXPECT_LE(out.ellipse.angle, M_PI / 2);
  }
  EXPECT_GT(checked, 1500);
}

TEST(FrameProjection, RadiiMatchEigenSingularValues) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const Eigen::Matrix3d rotation = Eigen::Quaterniond(unit(rng), unit(rng), unit(rng), unit(rng))
                                         .normalized()
                                         .toRotationMatrix();
    if (std::abs(rotation(2, 2)) < 0.05) continue;
    const Ellipse in =
        ellipse(0.0, 0.0, 0.1 + std::abs(unit(rng)), 0.1 + std::abs(unit(rng)), 3 * unit(rng));
    const ProjectionResult out = projectToPlane(in, pose(Eigen::Vector3d::Zero(), rotation), "svd");
    ASSERT_TRUE(out.ok()) << out.error;
    const Eigen::Matrix2d a = rotation.topLeftCorner<2, 2>() *
                              Eigen::Rotation2Dd(in.angle).matrix() *
                              Eigen::Vector2d(in.radius_x, in.radius_y).asDiagonal();
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(a, Eigen::ComputeFullU);
    EXPECT_NEAR(out.ellipse.radius_x, svd.singularValues()(0), 1e-14);
    EXPECT_NEAR(out.ellipse.radius_y, svd.singularValues()(1), 1e-14);
    if (svd.singularValues()(0) - svd.singularValues()(1) > 1e-3) {
      const Eigen::Vector2d u = svd.matrixU().col(0);
      EXPECT_NEAR(angleDifferenceModPi(out.ellipse.angle, std::atan2(u.y(), u.x())), 0.0, 1e-10);
    }
  }
}

TEST(FrameProjection, NearlyEdgeOnFrameStillGivesAnAccurateThinEllipse) {
  // Tilt with cos = 1e-5, well above the edge-on threshold: radius_y = 0.4 * 1e-5.
  const double tilt = std::acos(1e-5);
  const ProjectionResult out =
      projectToPlane(ellipse(0.0, 0.0, 0.4, 0.4, 0.0), pose({0, 0, 0}, aboutX(tilt)), "thin");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NEAR(out.ellipse.radius_x, 0.4, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_y / (0.4 * std::cos(tilt)), 1.0, 1e-9);
}

TEST(FrameProjection, EdgeOnFrameIsAnErrorNamingTheEllipse) {
  const ProjectionResult out = projectToPlane(ellipse(0.0, 0.0, 0.4, 0.2, 0.3),
                                              pose({0, 0, 0}, aboutX(M_PI / 2)), "wing");
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.error.find("'wing'"), std::string::npos) << out.error;
  EXPECT_NE(out.error.find("edge-on"), std::string::npos) << out.error;
}

TEST(FrameProjection, TiltJustPastTheThresholdIsRefused) {
  // A circle thinned to 1e-7 of its radius is below kMinProjectedThinning = 1e-6.
  const ProjectionResult out = projectToPlane(ellipse(0.0, 0.0, 0.4, 0.4, 0.0),
                                              pose({0, 0, 0}, aboutX(std::acos(1e-7))), "sliver");
  EXPECT_FALSE(out.ok());
  EXPECT_NE(out.error.find("'sliver'"), std::string::npos) << out.error;
}

TEST(FrameProjection, InvalidEllipseIsAnErrorNamingEllipseAndField) {
  const ProjectionResult out =
      projectToPlane(ellipse(0.0, 0.0, -1.0, 0.2, 0.0), Eigen::Isometry3d::Identity(), "bad");
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.error.find("'bad'"), std::string::npos) << out.error;
  EXPECT_NE(out.error.find("radius_x"), std::string::npos) << out.error;
}

TEST(FrameProjection, ProjectionThinnedBelowTheSmallestRadiusIsAnError) {
  // 2e-9 m tilted 70 deg: 2e-9 cos 70 = 6.8e-10 m < kMinRadius, though far from edge-on.
  const ProjectionResult out = projectToPlane(ellipse(0.0, 0.0, 0.5, 2e-9, 0.0),
                                              pose({0, 0, 0}, aboutX(70 * M_PI / 180)), "hair");
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.error.find("'hair'"), std::string::npos) << out.error;
  EXPECT_NE(out.error.find("out of range"), std::string::npos) << out.error;
}

TEST(FrameProjection, ProjectionMovedBeyondTheLargestCoordinateIsAnError) {
  const ProjectionResult out =
      projectToPlane(ellipse(0.9e9, 0.0, 1.0, 1.0, 0.0),
                     pose({0.2e9, 0, 0}, Eigen::Matrix3d::Identity()), "far");
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.error.find("center.x"), std::string::npos) << out.error;
}

TEST(FrameProjection, LargestRadiiProjectWithoutOverflow) {
  const ProjectionResult out =
      projectToPlane(ellipse(0.0, 0.0, kMaxRadius, 0.8 * kMaxRadius, 0.0),
                     pose({0, 0, 0}, aboutX(M_PI / 3)), "large");
  ASSERT_TRUE(out.ok()) << out.error;
  EXPECT_NEAR(out.ellipse.radius_x / kMaxRadius, 1.0, 1e-15);
  EXPECT_NEAR(out.ellipse.radius_y / (0.4 * kMaxRadius), 1.0, 1e-15);
}

TEST(FrameProjection, NonFiniteTransformIsAnError) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation().x() = std::numeric_limits<double>::quiet_NaN();
  const ProjectionResult out = projectToPlane(ellipse(0.0, 0.0, 1.0, 1.0, 0.0), t, "lost");
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.error.find("'lost'"), std::string::npos) << out.error;
}


// Fuzzer finding: planar frames must not round the radii, or an ellipse at the edge of the valid
// range would be refused after a mere yaw.
TEST(FrameProjection, RotationAboutZKeepsRadiiExactlyAtTheRangeEdges) {
  for (double yaw : {0.0, 0.3, -2.0, 3.1}) {
    Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
    transform.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    transform.translation() = Eigen::Vector3d(1.0, -2.0, 0.5);
    for (double angle : {0.0, 0.7, 1.9}) {
      const Ellipse e{{0.25, 0.5}, kMinRadius, kMaxRadius, angle};
      const ProjectionResult placed = projectToPlane(e, transform, "edge");
      ASSERT_TRUE(placed.ok()) << placed.error;
      // Reported as major radius first, the angle turned by a quarter turn to match.
      EXPECT_EQ(placed.ellipse.radius_x, kMaxRadius);
      EXPECT_EQ(placed.ellipse.radius_y, kMinRadius);
      EXPECT_GT(placed.ellipse.angle, -M_PI / 2);
      EXPECT_LE(placed.ellipse.angle, M_PI / 2);
      EXPECT_NEAR(std::remainder(placed.ellipse.angle - angle - yaw - M_PI / 2, M_PI), 0.0, 1e-15);
      EXPECT_TRUE(placed.ellipse.center.isApprox(
          (transform * Eigen::Vector3d(0.25, 0.5, 0.0)).head<2>(), 1e-15));
    }
  }
}

}  // namespace
}  // namespace ellipse_collision::core

// shadowOnPlane() and minimumVolumeEllipsoid() against independent references in quad precision:
// the shadow against the projections of surface points of the placed ellipsoid (every one inside,
// the support point in each direction on the boundary to 1e-9); the fit against closed-form
// minimum-volume ellipsoids (a box's corners, an octahedron, a regular simplex, a regular prism)
// and their random affine images, whose minimum is the affine image. Each family prints a
// "[ record   ]" line with its worst figures.

#include <gtest/gtest.h>
#include <quadmath.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipsoid.h"
#include "ellipse_collision/core/enclosing_ellipsoid.h"
#include "ellipse_collision/core/frame_projection.h"
#include "random_source.h"
#include "shadow_oracle.h"

namespace ellipse_collision::core {
namespace test {
namespace {

using Vec3 = Eigen::Vector3d;
using ellipse_collision::test::QMat3;
using ellipse_collision::test::quad;
using ellipse_collision::test::QVec3;
using ellipse_collision::test::RandomSource;

constexpr double kPi = 3.14159265358979323846;

/// |diag(r)^-1 R^T (p - c)|^2 in quad: <= 1 inside the ellipsoid.
quad ellipsoidForm(const Ellipsoid& e, const Vec3& p) {
  const QMat3 r = ellipse_collision::test::quadRotation(e.orientation);
  QVec3 d;
  for (int i = 0; i < 3; ++i) d[i] = static_cast<quad>(p[i]) - e.center[i];
  const QVec3 y = r.transpose() * d;
  quad sum = 0;
  for (int i = 0; i < 3; ++i) sum += (y[i] / e.radii[i]) * (y[i] / e.radii[i]);
  return sum;
}

quad volumeOf(const Ellipsoid& e) {
  return static_cast<quad>(e.radii.x()) * e.radii.y() * e.radii.z();  // / (4 pi / 3)
}

Eigen::Quaterniond randomOrientation(RandomSource& random) {
  Eigen::Quaterniond q(random.normal(), random.normal(), random.normal(), random.normal());
  return q.normalized();
}

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

// ---- minimumVolumeEllipsoid() -------------------------------------------------------------------

struct FitRecord {
  explicit FitRecord(const char* name) : name(name) {}
  ~FitRecord() {
    std::printf("[ record   ] %s: %d sets, worst |volume / reference - 1| = %.3g, worst point "
                "form - 1 = %.3g, median fit time = %.3g us\n",
                name, sets, worst, worst_form, medianMicroseconds());
  }
  double medianMicroseconds() {
    if (times.empty()) return 0.0;
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    return times[times.size() / 2];
  }
  const char* name;
  int sets{0};
  double worst{0.0};
  double worst_form{-1.0};
  std::vector<double> times;
};

/// Fits, checks containment of every point in quad, and compares the volume with `reference`
/// (the product of the reference radii): never below (to rounding), at most 1e-6 above.
void expectMinimumVolume(const std::vector<Vec3>& points, quad reference, FitRecord& record) {
  const auto start = std::chrono::steady_clock::now();
  const EnclosingEllipsoid fit = minimumVolumeEllipsoid(points);
  record.times.push_back(
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  ASSERT_TRUE(fit.ok) << fit.error;
  ++record.sets;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const quad form = ellipsoidForm(fit.ellipsoid, points[i]);
    record.worst_form = std::max(record.worst_form, static_cast<double>(form - 1));
    ASSERT_LE(static_cast<double>(form), 1.0) << "point " << i << " outside";
  }
  const double excess = static_cast<double>(volumeOf(fit.ellipsoid) / reference - 1);
  record.worst = std::max(record.worst, std::abs(excess));
  EXPECT_LE(excess, 1e-6);
  // The reference is the minimum for the exact points; the points as doubles differ from them by
  // rounding (offsets up to 10 sizes, axes down to 1e-4 sizes: 1e-11 relative), and the
  // certification adds a few ulps to the radii.
  EXPECT_GE(excess, -1e-9);
  EXPECT_LE(excess, fit.volume_excess_bound + 1e-9);
}

std::vector<Vec3> boxCorners(const Vec3& half) {
  std::vector<Vec3> corners;
  for (int k = 0; k < 8; ++k) {
    corners.emplace_back((k & 1 ? 1 : -1) * half.x(), (k & 2 ? 1 : -1) * half.y(),
                         (k & 4 ? 1 : -1) * half.z());
  }
  return corners;
}

std::vector<Vec3> octahedron() {
  std::vector<Vec3> points;
  for (int i = 0; i < 3; ++i) points.push_back(Vec3::Unit(i)), points.push_back(-Vec3::Unit(i));
  return points;
}

/// A regular tetrahedron inscribed in the unit sphere, which is its minimum-volume ellipsoid.
std::vector<Vec3> regularTetrahedron() {
  const double s = 1.0 / std::sqrt(3.0);
  return {Vec3(s, s, s), Vec3(s, -s, -s), Vec3(-s, s, -s), Vec3(-s, -s, s)};
}

/// Two regular n-gons of radius rho at z = +-h: by symmetry the minimum is the spheroid of radii
/// (sqrt(3/2) rho, sqrt(3/2) rho, sqrt(3) h), minimising a^2 c subject to rho^2/a^2 + h^2/c^2 = 1.
std::vector<Vec3> regularPrism(int n, double rho, double h, double phase) {
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k) {
    const double angle = phase + 2.0 * kPi * k / n;
    for (const double z : {-h, h}) points.emplace_back(rho * std::cos(angle), rho * std::sin(angle), z);
  }
  return points;
}

/// Random points strictly inside the unit ball's image under the set's own minimum: they do not
/// change it. `radius` < 1 of the reference sphere.
void addInteriorPoints(std::vector<Vec3>& points, RandomSource& random, int count, double radius) {
  for (int k = 0; k < count; ++k) {
    Vec3 u(random.normal(), random.normal(), random.normal());
    points.push_back(u.normalized() * radius * std::cbrt(random.uniform(0.0, 1.0)));
  }
}

TEST(MinimumVolumeEllipsoid, ClosedFormSets) {
  FitRecord record("closed forms");
  const Vec3 half(0.2, 0.06, 0.03);
  // Box: radii sqrt(3) times the half-extents.
  expectMinimumVolume(boxCorners(half), static_cast<quad>(3.0) * sqrtq(3.0) * half.prod(), record);
  expectMinimumVolume(octahedron(), 1, record);
  expectMinimumVolume(regularTetrahedron(), 1, record);
  // The co-circular case where Khachiyan's weights are not unique.
  for (const int n : {3, 8, 64}) {
    expectMinimumVolume(regularPrism(n, 0.06, 0.2, 0.3), 1.5 * 0.06 * 0.06 * sqrtq(3.0) * 0.2,
                        record);
  }
}

TEST(MinimumVolumeEllipsoid, AffineImagesOfClosedForms) {
  RandomSource random(34);
  FitRecord record("affine images");
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec3> base;
    quad reference = 1;  // product of the base set's minimum radii
    switch (trial % 4) {
      case 0: base = boxCorners(Vec3(1, 1, 1)), reference = 3 * sqrtq(3.0); break;
      case 1: base = octahedron(); break;
      case 2: base = regularTetrahedron(); break;
      default:
        base = regularPrism(4 + random.index(60), 1.0, 1.0, random.uniform(0, 1));
        reference = 1.5 * sqrtq(3.0);
    }
    // Interior points inside the sphere inscribed in the base's hull do not move the minimum.
    addInteriorPoints(base, random, random.index(40), trial % 4 == 2 ? 1.0 / 3.0 : 0.5);
    Eigen::Matrix3d linear;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) linear(i, j) = random.normal();
    }
    // Up to 1e4 between the axes (on top of the random matrix's own), sizes from 1 mm to 10 m,
    // offsets up to 10 sizes.
    const double size = random.logUniform(1e-3, 10.0);
    linear = randomOrientation(random).toRotationMatrix() *
             Eigen::Vector3d(random.logUniform(1e-2, 1.0), random.logUniform(1e-2, 1.0), 1.0)
                 .asDiagonal() *
             linear * size;
    const Vec3 offset =
        10.0 * size * Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    std::vector<Vec3> points;
    for (const Vec3& p : base) points.push_back(linear * p + offset);
    quad det = 0;
    {
      QMat3 q;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) q(i, j) = linear(i, j);
      }
      det = q(0, 0) * (q(1, 1) * q(2, 2) - q(1, 2) * q(2, 1)) -
            q(0, 1) * (q(1, 0) * q(2, 2) - q(1, 2) * q(2, 0)) +
            q(0, 2) * (q(1, 0) * q(2, 1) - q(1, 1) * q(2, 0));
    }
    expectMinimumVolume(points, fabsq(det) * reference, record);
    if (HasFatalFailure()) return;
  }
}

TEST(MinimumVolumeEllipsoid, ContainsLargeClouds) {
  RandomSource random(5);
  FitRecord record("clouds of 2000 points (containment only)");
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Vec3> points;
    for (int k = 0; k < 2000; ++k) {
      points.emplace_back(random.normal() * 0.3, random.normal() * 0.05, random.normal() * 0.02);
    }
    const auto start = std::chrono::steady_clock::now();
    const EnclosingEllipsoid fit = minimumVolumeEllipsoid(points);
    record.times.push_back(std::chrono::duration<double, std::micro>(
                               std::chrono::steady_clock::now() - start)
                               .count());
    ASSERT_TRUE(fit.ok) << fit.error;
    ++record.sets;
    EXPECT_LE(fit.volume_excess_bound, 2e-9);
    for (const Vec3& p : points) {
      const quad form = ellipsoidForm(fit.ellipsoid, p);
      record.worst_form = std::max(record.worst_form, static_cast<double>(form - 1));
      ASSERT_LE(static_cast<double>(form), 1.0);
    }
  }
}

TEST(MinimumVolumeEllipsoid, RefusesBadInputNamingIt) {
  EXPECT_EQ(minimumVolumeEllipsoid({}).error, "points is empty");
  EXPECT_EQ(minimumVolumeEllipsoid({Vec3(0, 0, 0), Vec3(1, std::nan(""), 0)}).error,
            "points[1].y = nan is not finite");
  const EnclosingEllipsoid flat =
      minimumVolumeEllipsoid({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)});
  EXPECT_FALSE(flat.ok);
  EXPECT_NE(flat.error.find("span no volume"), std::string::npos) << flat.error;
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

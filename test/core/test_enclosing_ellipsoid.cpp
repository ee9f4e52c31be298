// minimumVolumeEllipsoid() (core/enclosing_ellipsoid.h) against closed-form minimum-volume
// ellipsoids (a box's corners, an octahedron, a regular simplex, a regular prism) and their random
// affine images, whose minimum is the affine image, every point inside in quad precision
// (test/support/shadow_oracle.h's form); growToContain() against the same form; refusals named.
// Each family prints a "[ record   ]" line with its worst figures.

#include <gtest/gtest.h>
#include <quadmath.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ellipse_collision/core/enclosing_ellipsoid.h"
#include "random_source.h"
#include "shadow_oracle.h"

namespace ellipse_collision::core {
namespace test {
namespace {

using Vec3 = Eigen::Vector3d;
using ellipse_collision::test::ellipsoidForm;
using ellipse_collision::test::QMat3;
using ellipse_collision::test::quad;
using ellipse_collision::test::randomOrientation;
using ellipse_collision::test::RandomSource;

constexpr double kPi = 3.14159265358979323846;

quad volumeOf(const Ellipsoid& e) {
  return static_cast<quad>(e.radii.x()) * e.radii.y() * e.radii.z();  // / (4 pi / 3)
}

struct FitRecord {
  explicit FitRecord(const char* name) : name(name) {}
  ~FitRecord() {
    std::printf(
        "[ record   ] %s: %d sets, worst |volume / reference - 1| = %.3g, worst point "
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
    for (const double z : {-h, h})
      points.emplace_back(rho * std::cos(angle), rho * std::sin(angle), z);
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
      case 0:
        base = boxCorners(Vec3(1, 1, 1)), reference = 3 * sqrtq(3.0);
        break;
      case 1:
        base = octahedron();
        break;
      case 2:
        base = regularTetrahedron();
        break;
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
    record.times.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
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

TEST(GrowToContain, AnEllipsoidTurnedSlightlyIsGrownByOneFactorUntilEveryPointIsInside) {
  RandomSource random(6);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Vec3> points;
    for (int k = 0; k < 200; ++k) {
      points.emplace_back(random.normal() * 0.4, random.normal() * 0.1, random.normal() * 0.05);
    }
    const EnclosingEllipsoid fit = minimumVolumeEllipsoid(points);
    ASSERT_TRUE(fit.ok) << fit.error;
    Ellipsoid turned = fit.ellipsoid;
    turned.orientation = turned.orientation *
                         Eigen::Quaterniond(Eigen::AngleAxisd(1e-3, Vec3(1, 2, 3).normalized()));
    quad worst = 0;
    for (const Vec3& p : points) worst = std::max(worst, ellipsoidForm(turned, p));
    ASSERT_GT(static_cast<double>(worst), 1.0) << "the turn must push points out";
    const Vec3 before = turned.radii;
    ASSERT_TRUE(growToContain(turned, points));
    for (const Vec3& p : points) ASSERT_LE(static_cast<double>(ellipsoidForm(turned, p)), 1.0);
    const double factor = turned.radii.x() / before.x();
    EXPECT_GT(factor, 1.0);
    EXPECT_NEAR(turned.radii.y() / before.y(), factor, 1e-12) << "one common factor";
    EXPECT_NEAR(turned.radii.z() / before.z(), factor, 1e-12);
    // The least factor: sqrt of the worst form, up to a few ulps.
    EXPECT_NEAR(factor, std::sqrt(static_cast<double>(worst)), 1e-12);
    EXPECT_EQ(turned.center, fit.ellipsoid.center);
  }
}

TEST(GrowToContain, AnEllipsoidHoldingEveryPointIsLeftAsItIs) {
  Ellipsoid e;
  e.center = Vec3(1, 2, 3);
  e.radii = Vec3(2, 1, 0.5);
  const std::vector<Vec3> points = {Vec3(1, 2, 3), Vec3(2, 2, 3), Vec3(1, 2.5, 3.25)};
  ASSERT_TRUE(growToContain(e, points));
  EXPECT_EQ(e.radii, Vec3(2, 1, 0.5));
  EXPECT_EQ(e.center, Vec3(1, 2, 3));
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

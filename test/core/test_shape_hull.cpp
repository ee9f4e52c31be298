// fitLinkEllipsoid(): the link ellipsoid of URDF collision shapes contains every part of them,
// curved surfaces included (dense surface samples, checked in quad precision), and is close to
// the closed-form minimum: a box's corners give radii sqrt(3) times its half-extents, a cylinder
// (the hull of two circles) the spheroid of radii (sqrt(3/2) r, sqrt(3/2) r, sqrt(3) l / 2), a
// sphere itself.
#include <gtest/gtest.h>
#include <quadmath.h>

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "ellipse_collision/core/shape_hull.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace test {
namespace {

using quad = __float128;
using Vec3 = Eigen::Vector3d;
using ellipse_collision::test::RandomSource;

constexpr double kPi = 3.14159265358979323846;

/// |diag(r)^-1 R^T (p - c)|^2 in quad, R from the quaternion normalised in quad.
quad form(const Ellipsoid& e, const Eigen::Matrix<quad, 3, 1>& p) {
  quad w = e.orientation.w(), x = e.orientation.x(), y = e.orientation.y(), z = e.orientation.z();
  const quad n = sqrtq(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  Eigen::Matrix<quad, 3, 3> r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 2 * (x * y + w * z),
      1 - 2 * (x * x + z * z), 2 * (y * z - w * x), 2 * (x * z - w * y), 2 * (y * z + w * x),
      1 - 2 * (x * x + y * y);
  Eigen::Matrix<quad, 3, 1> d;
  for (int i = 0; i < 3; ++i) d[i] = p[i] - static_cast<quad>(e.center[i]);
  const Eigen::Matrix<quad, 3, 1> local = r.transpose() * d;
  quad sum = 0;
  for (int i = 0; i < 3; ++i) sum += (local[i] / e.radii[i]) * (local[i] / e.radii[i]);
  return sum;
}

/// A point of the shape's surface in the link frame, in quad: `a`, `b` in [0, 1) pick it.
Eigen::Matrix<quad, 3, 1> surfacePoint(const CollisionShape& s, double a, double b, int face) {
  quad local[3];
  const quad t = 2 * acosq(-1) * a;
  switch (s.type) {
    case CollisionShape::Cylinder:  // side wall or one of the end discs (face 0, 1, 2)
      if (face == 0) {
        local[0] = s.radius * cosq(t), local[1] = s.radius * sinq(t), local[2] = s.length * (b - 0.5);
      } else {
        local[0] = s.radius * sqrtq(b) * cosq(t), local[1] = s.radius * sqrtq(b) * sinq(t);
        local[2] = (face == 1 ? -0.5 : 0.5) * s.length;
      }
      break;
    case CollisionShape::Sphere: {
      const quad z = 2 * static_cast<quad>(b) - 1, ring = sqrtq(1 - z * z);
      local[0] = s.radius * ring * cosq(t), local[1] = s.radius * ring * sinq(t), local[2] = s.radius * z;
      break;
    }
    default: {  // box: a point on the face `face` (0..5)
      const int axis = face / 2;
      local[axis] = (face % 2 ? 0.5 : -0.5) * s.box_size[axis];
      local[(axis + 1) % 3] = (a - 0.5) * s.box_size[(axis + 1) % 3];
      local[(axis + 2) % 3] = (b - 0.5) * s.box_size[(axis + 2) % 3];
    }
  }
  Eigen::Matrix<quad, 3, 1> p;
  for (int i = 0; i < 3; ++i) {
    p[i] = s.link_from_shape.translation()[i];
    for (int j = 0; j < 3; ++j) p[i] += static_cast<quad>(s.link_from_shape.linear()(i, j)) * local[j];
  }
  return p;
}

void expectContainsShapes(const Ellipsoid& e, const std::vector<CollisionShape>& shapes,
                          RandomSource& random, double& worst) {
  for (const CollisionShape& s : shapes) {
    for (int k = 0; k < 20000; ++k) {
      const int face = k % (s.type == CollisionShape::Box ? 6 : 3);
      const quad f = form(e, surfacePoint(s, random.uniform(0, 1), random.uniform(0, 1), face));
      worst = std::max(worst, static_cast<double>(f - 1));
      ASSERT_LE(static_cast<double>(f), 1.0) << "surface sample " << k << " of a shape outside";
    }
  }
}

CollisionShape cylinderAlongX(double radius, double length, const Vec3& at) {
  CollisionShape s;
  s.type = CollisionShape::Cylinder;
  s.radius = radius;
  s.length = length;
  s.link_from_shape.linear() = Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()).toRotationMatrix();
  s.link_from_shape.translation() = at;
  return s;
}

TEST(LinkEllipsoid, CylinderBoxAndSphereAgainstClosedForms) {
  RandomSource random(11);
  double worst = -1.0;
  // Upper arm: cylinder r = 6 cm, 40 cm along x, centred 20 cm out.
  const std::vector<CollisionShape> arm = {cylinderAlongX(0.06, 0.4, Vec3(0.2, 0, 0))};
  auto start = std::chrono::steady_clock::now();
  const EnclosingEllipsoid fit = fitLinkEllipsoid(arm);
  const double cylinder_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(fit.ok) << fit.error;
  const double volume = fit.ellipsoid.radii.prod();
  const double reference = 1.5 * 0.06 * 0.06 * std::sqrt(3.0) * 0.2;
  // The circumscribed polygons reach 1 / cos(pi / 8192) - 1 = 7.4e-8 beyond the circles.
  EXPECT_GE(volume / reference - 1, -1e-9);
  EXPECT_LE(volume / reference - 1, 3e-7);
  EXPECT_NEAR(fit.ellipsoid.center.x(), 0.2, 1e-9);
  expectContainsShapes(fit.ellipsoid, arm, random, worst);

  CollisionShape box;
  box.type = CollisionShape::Box;
  box.box_size = Vec3(0.3, 0.1, 0.05);
  box.link_from_shape.linear() = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const EnclosingEllipsoid box_fit = fitLinkEllipsoid({box});
  ASSERT_TRUE(box_fit.ok) << box_fit.error;
  EXPECT_NEAR(box_fit.ellipsoid.radii.prod() / (3 * std::sqrt(3.0) * 0.15 * 0.05 * 0.025), 1.0, 1e-8);
  expectContainsShapes(box_fit.ellipsoid, {box}, random, worst);

  CollisionShape ball;
  ball.type = CollisionShape::Sphere;
  ball.radius = 0.05;
  ball.link_from_shape.translation() = Vec3(0.1, -0.2, 0.3);
  start = std::chrono::steady_clock::now();
  const EnclosingEllipsoid ball_fit = fitLinkEllipsoid({ball});
  const double sphere_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(ball_fit.ok) << ball_fit.error;
  for (int i = 0; i < 3; ++i) {
    EXPECT_GE(ball_fit.ellipsoid.radii[i], 0.05);
    EXPECT_LE(ball_fit.ellipsoid.radii[i], 0.05 * (1 + 8e-5));  // 1 / cos(pi / 256) - 1 = 7.5e-5
  }
  expectContainsShapes(ball_fit.ellipsoid, {ball}, random, worst);

  // A forearm of a cylinder and a box gripper together.
  const std::vector<CollisionShape> forearm = {cylinderAlongX(0.04, 0.3, Vec3(0.15, 0, 0)), box};
  const EnclosingEllipsoid forearm_fit = fitLinkEllipsoid(forearm);
  ASSERT_TRUE(forearm_fit.ok) << forearm_fit.error;
  expectContainsShapes(forearm_fit.ellipsoid, forearm, random, worst);
  std::printf("[ record   ] link ellipsoids: worst surface-sample form - 1 = %.3g; fit time: "
              "cylinder (16384 points) %.3g ms, sphere (%d points) %.3g ms\n",
              worst, cylinder_ms, 2 + (kSphereGridLatitudes - 1) * 2 * kSphereGridLatitudes,
              sphere_ms);
}

TEST(LinkEllipsoid, RefusesBadShapesAndFlatGeometry) {
  CollisionShape bad;
  bad.type = CollisionShape::Cylinder;
  bad.radius = -1;
  bad.length = 1;
  EXPECT_EQ(fitLinkEllipsoid({bad}).error, "shapes[0]: radius = -1 must be > 0");
  EXPECT_EQ(fitLinkEllipsoid({}).error, "shapes is empty");
  CollisionShape plate;
  plate.type = CollisionShape::Mesh;
  plate.mesh_vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_FALSE(fitLinkEllipsoid({plate}).ok);
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

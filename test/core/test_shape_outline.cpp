// outlinePoints() / fitLinkEllipse(): the fitted link ellipse contains sampled points of the true
// 3D shapes (projected), and its area is within 1e-6 of the minimum: against closed forms
// (sphere and standing cylinder: the circle; lying cylinder: the rectangle's ellipse) or against
// the barrier oracle on points sampled ON the true silhouette, whose minimum ellipse is a lower
// bound of the true one (so passing against it is the stricter test).

#include <gtest/gtest.h>
#include <quadmath.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "ellipse_collision/core/shape_outline.h"
#include "enclosing_ellipse_oracle.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace test {
namespace {

using quad = __float128;
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Points = std::vector<Vec2>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kAreaTolerance = 1e-6;
// Box and mesh outlines are the projected vertices, exact up to the rounding of the transform:
// an independently transformed surface point may sit this far (relative) outside.
constexpr double kTransformRounding = 1e-12;
// Points per circle for the silhouette samples the oracle sees: the samples' minimum ellipse is
// then within 1 / cos^2(pi / n) - 1 = 1.5e-7 of the true one.
constexpr int kSilhouetteSamples = 8192;

class Generator : public ellipse_collision::test::RandomSource {
 public:
  using RandomSource::RandomSource;
  Vec3 unitVector() {
    std::normal_distribution<double> n(0.0, 1.0);
    Vec3 v(n(engine()), n(engine()), n(engine()));
    return v.normalized();
  }
  Eigen::Isometry3d pose(double max_offset) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = Eigen::AngleAxisd(uniform(0.0, kPi), unitVector()).toRotationMatrix();
    t.translation() = Vec3(uniform(-max_offset, max_offset), uniform(-max_offset, max_offset),
                           uniform(-max_offset, max_offset));
    return t;
  }

};

Vec2 project(const Eigen::Isometry3d& t, const Vec3& local) {
  // Written out rather than t * local, so that rounding differs from the implementation's.
  const Eigen::Matrix3d& r = t.linear();
  return {r(0, 0) * local.x() + r(0, 1) * local.y() + r(0, 2) * local.z() + t.translation().x(),
          r(1, 0) * local.x() + r(1, 1) * local.y() + r(1, 2) * local.z() + t.translation().y()};
}

/// Surface points of the true shape, projected.
Points surfaceSamples(const CollisionShape& s, Generator& gen, int count) {
  Points out;
  const Eigen::Isometry3d& t = s.link_from_shape;
  for (int k = 0; k < count; ++k) {
    switch (s.type) {
      case CollisionShape::Box: {
        Vec3 local(gen.uniform(-0.5, 0.5) * s.box_size.x(), gen.uniform(-0.5, 0.5) * s.box_size.y(),
                   gen.uniform(-0.5, 0.5) * s.box_size.z());
        const int axis = k % 3;
        local[axis] = (k % 2 ? 0.5 : -0.5) * s.box_size[axis];
        out.push_back(project(t, local));
        break;
      }
      case CollisionShape::Sphere: {
        // Half on the silhouette (the link-plane great circle), half anywhere.
        if (k % 2) {
          const double phi = gen.uniform(-kPi, kPi);
          const Vec3 c = t.translation();
          out.emplace_back(c.x() + s.radius * std::cos(phi), c.y() + s.radius * std::sin(phi));
        } else {
          out.push_back(project(t, s.radius * gen.unitVector()));
        }
        break;
      }
      case CollisionShape::Cylinder: {
        const double phi = gen.uniform(-kPi, kPi);
        const double rho = k % 3 == 2 ? s.radius * std::sqrt(gen.uniform(0.0, 1.0)) : s.radius;
        const double z = k % 3 == 1 ? gen.uniform(-0.5, 0.5) * s.length
                                    : (k % 2 ? 0.5 : -0.5) * s.length;
        out.push_back(project(t, Vec3(rho * std::cos(phi), rho * std::sin(phi), z)));
        break;
      }
      case CollisionShape::Mesh:
        out.push_back(project(t, s.mesh_vertices[k % s.mesh_vertices.size()]));
        break;
    }
  }
  return out;
}

/// Points ON the true projection's boundary-defining set (vertices, dense circle points): their
/// minimum ellipse is at most the true one.
Points silhouetteSamples(const CollisionShape& s) {
  Points out;
  const Eigen::Isometry3d& t = s.link_from_shape;
  const auto circle = [&](const Vec3& centre, const Vec3& u, const Vec3& v, double r) {
    for (int k = 0; k < kSilhouetteSamples; ++k) {
      const double phi = 2.0 * kPi * k / kSilhouetteSamples;
      out.push_back(project(t, centre + r * (std::cos(phi) * u + std::sin(phi) * v)));
    }
  };
  switch (s.type) {
    case CollisionShape::Box:
      for (int c = 0; c < 8; ++c) {
        out.push_back(project(t, Vec3((c & 1 ? 0.5 : -0.5) * s.box_size.x(),
                                      (c & 2 ? 0.5 : -0.5) * s.box_size.y(),
                                      (c & 4 ? 0.5 : -0.5) * s.box_size.z())));
      }
      break;
    case CollisionShape::Sphere: {
      // The link-plane great circle, in link coordinates.
      for (int k = 0; k < kSilhouetteSamples; ++k) {
        const double phi = 2.0 * kPi * k / kSilhouetteSamples;
        out.emplace_back(t.translation().x() + s.radius * std::cos(phi),
                         t.translation().y() + s.radius * std::sin(phi));
      }
      break;
    }
    case CollisionShape::Cylinder:
      for (const double side : {-0.5, 0.5}) {
        circle(Vec3(0, 0, side * s.length), Vec3::UnitX(), Vec3::UnitY(), s.radius);
      }
      break;
    case CollisionShape::Mesh:
      for (const Vec3& v : s.mesh_vertices) out.push_back(project(t, v));
      break;
  }
  return out;
}

struct Record {
  explicit Record(const char* name) : name(name) {}
  ~Record() {
    std::printf("[ record   ] %s: %d links, worst |area / reference - 1| = %.3g, containment "
                "violations = %d (of %d sampled surface points)\n",
                name, links, worst, violations, samples);
  }
  const char* name;
  int links{0}, violations{0}, samples{0};
  double worst{0.0};
};

/// Fits, checks containment of surface samples and the area against `reference` [m^2], which is
/// the minimum or a lower bound of it.
void expectFit(const std::vector<CollisionShape>& shapes, double reference, Record& record,
               Generator& gen, bool exact_outline) {
  const EnclosingEllipse fit = fitLinkEllipse(shapes);
  ++record.links;
  ASSERT_EQ(fit.status, EnclosingStatus::Ok) << fit.error;
  ASSERT_EQ(invalidReason(fit.ellipse), "");
  const quad limit = exact_outline ? 1 + static_cast<quad>(kTransformRounding) : 1;
  for (const CollisionShape& s : shapes) {
    const quad shape_limit = s.type == CollisionShape::Box || s.type == CollisionShape::Mesh ? limit : 1;
    for (const Vec2& p : surfaceSamples(s, gen, 3000)) {
      ++record.samples;
      const quad q = quadQuadraticForm(fit.ellipse, p);
      if (q > shape_limit) {
        ++record.violations;
        ADD_FAILURE() << "sample (" << p.x() << ", " << p.y() << ") outside, q - 1 = "
                      << static_cast<double>(q - 1) << ", ellipse " << describeEllipse(fit.ellipse);
      }
    }
  }
  const double ratio = static_cast<double>(quadArea(fit.ellipse) / reference) - 1.0;
  record.worst = std::max(record.worst, std::abs(ratio));
  EXPECT_LE(ratio, kAreaTolerance) << describeEllipse(fit.ellipse);
  EXPECT_GE(ratio, -1e-9) << describeEllipse(fit.ellipse);
}

/// The oracle's minimum area over the silhouette samples of `shapes` [m^2]: a lower bound of the
/// true minimum, by the oracle's cutting planes (dense circle samples).
double oracleArea(const std::vector<CollisionShape>& shapes) {
  Points all;
  for (const CollisionShape& s : shapes) {
    const Points some = silhouetteSamples(s);
    all.insert(all.end(), some.begin(), some.end());
  }
  const OracleEllipse o = oracleMinimumAreaEllipseByCuttingPlanes(all);
  EXPECT_TRUE(o.converged);
  return static_cast<double>(o.area);
}

/// expectFit() against the oracle on the silhouette samples.
void expectFitNearOracle(const std::vector<CollisionShape>& shapes, Record& record,
                         Generator& gen, bool exact_outline) {
  const EnclosingEllipse fit = fitLinkEllipse(shapes);
  ASSERT_TRUE(fit.ok()) << fit.error;
  expectFit(shapes, oracleArea(shapes), record, gen, exact_outline);
}

CollisionShape sphere(double r, const Eigen::Isometry3d& pose) {
  CollisionShape s;
  s.type = CollisionShape::Sphere;
  s.radius = r;
  s.link_from_shape = pose;
  return s;
}

CollisionShape cylinder(double r, double length, const Eigen::Isometry3d& pose) {
  CollisionShape s;
  s.type = CollisionShape::Cylinder;
  s.radius = r;
  s.length = length;
  s.link_from_shape = pose;
  return s;
}

CollisionShape box(const Vec3& size, const Eigen::Isometry3d& pose) {
  CollisionShape s;
  s.type = CollisionShape::Box;
  s.box_size = size;
  s.link_from_shape = pose;
  return s;
}

TEST(FitLinkEllipse, SphereGivesCircleOfItsRadius) {
  Record record("spheres (pi r^2)");
  Generator gen(51);
  for (int k = 0; k < 20; ++k) {
    const double r = gen.logUniform(1e-3, 10.0);
    const CollisionShape s = sphere(r, gen.pose(5.0));
    expectFit({s}, kPi * r * r, record, gen, false);
    const EnclosingEllipse fit = fitLinkEllipse({s});
    EXPECT_NEAR(fit.ellipse.center.x(), s.link_from_shape.translation().x(), 1e-9 * (1 + r));
    EXPECT_NEAR(fit.ellipse.center.y(), s.link_from_shape.translation().y(), 1e-9 * (1 + r));
  }
}

TEST(FitLinkEllipse, StandingCylinderGivesCircle) {
  Record record("standing cylinders (pi r^2)");
  Generator gen(52);
  for (int k = 0; k < 20; ++k) {
    const double r = gen.logUniform(1e-2, 2.0), length = gen.logUniform(1e-2, 5.0);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = Eigen::AngleAxisd(gen.uniform(-kPi, kPi), Vec3::UnitZ()).toRotationMatrix();
    pose.translation() = Vec3(gen.uniform(-3, 3), gen.uniform(-3, 3), gen.uniform(-3, 3));
    expectFit({cylinder(r, length, pose)}, kPi * r * r, record, gen, false);
  }
}

TEST(FitLinkEllipse, LyingCylinderGivesEllipseOfItsRectangle) {
  Record record("lying cylinders (pi (2r) L / 2)");
  Generator gen(53);
  for (int k = 0; k < 20; ++k) {
    const double r = gen.logUniform(1e-2, 2.0), length = gen.logUniform(1e-2, 5.0);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    // Axis horizontal: pitch by 90 degrees, then any yaw.
    pose.linear() = (Eigen::AngleAxisd(gen.uniform(-kPi, kPi), Vec3::UnitZ()) *
                     Eigen::AngleAxisd(kPi / 2, Vec3::UnitY()))
                        .toRotationMatrix();
    pose.translation() = Vec3(gen.uniform(-3, 3), gen.uniform(-3, 3), gen.uniform(-3, 3));
    expectFit({cylinder(r, length, pose)}, kPi * r * length, record, gen, false);
  }
}

TEST(FitLinkEllipse, TiltedCylinderIsNearTheSilhouetteMinimum) {
  Record record("tilted cylinders (oracle on the rims)");
  Generator gen(54);
  for (int k = 0; k < 10; ++k) {
    const CollisionShape s = cylinder(gen.logUniform(1e-2, 1.0), gen.logUniform(1e-2, 2.0), gen.pose(2.0));
    expectFitNearOracle({s}, record, gen, false);
  }
}

TEST(FitLinkEllipse, BoxWithOffsetAndRotationMatchesOracleOnCorners) {
  Record record("boxes (oracle on the corners)");
  Generator gen(55);
  for (int k = 0; k < 30; ++k) {
    const Vec3 size(gen.logUniform(1e-2, 2.0), gen.logUniform(1e-2, 2.0), gen.logUniform(1e-2, 2.0));
    const CollisionShape s = box(size, gen.pose(5.0));
    expectFitNearOracle({s}, record, gen, true);
  }
  // Axis-aligned: the rectangle's ellipse, pi w h / 2.
  const CollisionShape aligned = box(Vec3(2.0, 0.5, 3.0), Eigen::Isometry3d(Eigen::Translation3d(1.0, -2.0, 0.7)));
  expectFit({aligned}, kPi * 2.0 * 0.5 / 2.0, record, gen, true);
}

TEST(FitLinkEllipse, MeshVerticesMatchOracle) {
  Record record("meshes (oracle on the vertices)");
  Generator gen(56);
  for (int k = 0; k < 20; ++k) {
    CollisionShape s;
    s.type = CollisionShape::Mesh;
    s.link_from_shape = gen.pose(2.0);
    for (int i = 0, n = 4 + k; i < n; ++i) {
      s.mesh_vertices.emplace_back(gen.uniform(-1, 1), gen.uniform(-0.5, 0.5), gen.uniform(-0.2, 0.2));
    }
    expectFitNearOracle({s}, record, gen, true);
  }
}

TEST(FitLinkEllipse, LinkOfSeveralShapesContainsThemAll) {
  Record record("links of box + sphere + cylinder (oracle on silhouettes)");
  Generator gen(57);
  for (int k = 0; k < 10; ++k) {
    const std::vector<CollisionShape> shapes = {
        box(Vec3(0.6, 0.3, 0.2), gen.pose(0.5)), sphere(0.15, gen.pose(0.8)),
        cylinder(0.08, 0.5, gen.pose(0.6))};
    expectFitNearOracle(shapes, record, gen, true);
  }
}

TEST(FitLinkEllipse, VerticalPlateIsDegenerate) {
  CollisionShape s;
  s.type = CollisionShape::Mesh;
  s.mesh_vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, 0, 2}};
  const EnclosingEllipse fit = fitLinkEllipse({s});
  EXPECT_EQ(fit.status, EnclosingStatus::Degenerate);
  EXPECT_NEAR((fit.segment_end - fit.segment_start).norm(), 1.0, 1e-15);
  const OutlineResult outline = linkOutline({s});
  ASSERT_TRUE(outline.ok());
  const EnclosingEllipse grown = enclosingEllipseWithMinRadius(outline.points, 0.01);
  EXPECT_TRUE(grown.ok()) << grown.error;
}

TEST(OutlinePoints, SphereOutlineIsACircumscribedPolygon) {
  const OutlineResult o = outlinePoints(sphere(2.0, Eigen::Isometry3d(Eigen::Translation3d(1, 1, 1))));
  ASSERT_TRUE(o.ok());
  ASSERT_EQ(o.points.size(), static_cast<std::size_t>(kCirclePolygonVertices));
  for (const Vec2& p : o.points) {
    EXPECT_NEAR((p - Vec2(1, 1)).norm(), 2.0 / std::cos(kPi / kCirclePolygonVertices), 1e-11);
  }
}

TEST(OutlinePoints, ErrorsNameTheFieldAndValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Eigen::Isometry3d id = Eigen::Isometry3d::Identity();
  EXPECT_EQ(outlinePoints(box(Vec3(1, -2, 1), id)).error, "box_size.y = -2 must be > 0");
  EXPECT_EQ(outlinePoints(box(Vec3(1, 1, nan), id)).error, "box_size.z = nan is not finite");
  EXPECT_EQ(outlinePoints(sphere(0.0, id)).error, "radius = 0 must be > 0");
  EXPECT_EQ(outlinePoints(cylinder(1.0, -0.5, id)).error, "length = -0.5 must be > 0");
  EXPECT_EQ(outlinePoints(cylinder(inf, 1.0, id)).error, "radius = inf is not finite");
  CollisionShape mesh;
  mesh.type = CollisionShape::Mesh;
  EXPECT_EQ(outlinePoints(mesh).error, "mesh_vertices is empty");
  mesh.mesh_vertices = {{0, 0, 0}, {1, 2, nan}};
  EXPECT_EQ(outlinePoints(mesh).error, "mesh_vertices[1].z = nan is not finite");
  Eigen::Isometry3d bad = id;
  bad.translation().x() = inf;
  EXPECT_EQ(outlinePoints(sphere(1.0, bad)).error, "link_from_shape(0, 3) = inf is not finite");
  bad = id;
  bad.linear()(0, 0) = 2.0;
  EXPECT_EQ(outlinePoints(sphere(1.0, bad)).error.rfind("link_from_shape: rotation is not orthonormal", 0), 0u);
  EXPECT_EQ(linkOutline({}).error, "shapes is empty");
  EXPECT_EQ(fitLinkEllipse({sphere(1.0, id), sphere(-1.0, id)}).error, "shapes[1]: radius = -1 must be > 0");
  EXPECT_EQ(fitLinkEllipse({sphere(-1.0, id)}).status, EnclosingStatus::Error);
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

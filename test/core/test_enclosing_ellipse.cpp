// minimumAreaEllipse() and enclosingEllipseWithMinRadius() against closed forms and the
// independent barrier oracle (enclosing_ellipse_oracle.h). Every family uses a fixed seed so that
// a failure repeats; each prints "family: N sets, worst |area / reference - 1| = X, containment
// violations = V" for the record.

#include <gtest/gtest.h>
#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "ellipse_collision/core/enclosing_ellipse.h"
#include "enclosing_ellipse_oracle.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace test {
namespace {

using quad = __float128;
using Vec2 = Eigen::Vector2d;
using Points = std::vector<Vec2>;

constexpr double kPi = 3.14159265358979323846;

// The promise: area within this of the true minimum (relative).
constexpr double kAreaTolerance = 1e-6;
// Sets up to this size use the quad-precision oracle, larger ones the long double one.
constexpr std::size_t kQuadOracleMaxPoints = 12;
// ... and sets above this size its cutting-plane form.
constexpr std::size_t kCuttingPlaneMinPoints = 500;

/// Per-family record, printed when the test ends.
struct Family {
  explicit Family(const char* name) : name(name) {}
  ~Family() {
    std::printf("[ record   ] %s: %d sets, worst |area / reference - 1| = %.3g, containment "
                "violations = %d\n",
                name, sets, worst, violations);
  }
  const char* name;
  int sets{0};
  double worst{0.0};
  int violations{0};
};

std::string describe(const Points& points) {
  std::string out = "points (" + std::to_string(points.size()) + "):";
  char buffer[80];
  for (std::size_t i = 0; i < points.size() && i < 12; ++i) {
    std::snprintf(buffer, sizeof buffer, " (%.17g, %.17g)", points[i].x(), points[i].y());
    out += buffer;
  }
  return out + (points.size() > 12 ? " ..." : "");
}

/// Every point inside `e`, evaluated in quad from the double fields.
int countOutside(const Ellipse& e, const Points& points) {
  int outside = 0;
  for (const Vec2& p : points) outside += quadQuadraticForm(e, p) > 1 ? 1 : 0;
  return outside;
}

/// Checks an Ok result: valid, every point inside, area within kAreaTolerance of `reference`
/// (from below: the reference is the minimum or a lower bound of it, up to `reference_gap`).
void expectMinimal(const Points& points, double reference, double reference_gap, Family& family) {
  const EnclosingEllipse result = minimumAreaEllipse(points);
  ++family.sets;
  ASSERT_EQ(result.status, EnclosingStatus::Ok) << result.error << "\n" << describe(points);
  ASSERT_EQ(invalidReason(result.ellipse), "") << describe(points);
  const int outside = countOutside(result.ellipse, points);
  family.violations += outside;
  EXPECT_EQ(outside, 0) << describeEllipse(result.ellipse) << "\n" << describe(points);
  const double ratio = static_cast<double>(quadArea(result.ellipse) / reference) - 1.0;
  family.worst = std::max(family.worst, std::abs(ratio));
  EXPECT_LE(ratio, kAreaTolerance) << describeEllipse(result.ellipse) << "\n" << describe(points);
  EXPECT_GE(ratio, -reference_gap - 1e-12)
      << describeEllipse(result.ellipse) << "\n" << describe(points);
  EXPECT_LE(result.area_excess_bound, 1e-9);
}

void expectMatchesOracle(const Points& points, Family& family) {
  const OracleEllipse oracle =
      points.size() > kCuttingPlaneMinPoints
          ? oracleMinimumAreaEllipseByCuttingPlanes(points)
          : oracleMinimumAreaEllipse(points, points.size() <= kQuadOracleMaxPoints
                                                 ? OraclePrecision::Quad
                                                 : OraclePrecision::LongDouble);
  ASSERT_TRUE(oracle.converged) << describe(points);
  expectMinimal(points, static_cast<double>(oracle.area), static_cast<double>(oracle.gap), family);
}

class Generator : public ellipse_collision::test::RandomSource {
 public:
  using RandomSource::RandomSource;

  /// n points of a random shape: uniform in a rotated rectangle of axis ratio up to `max_ratio`,
  /// Gaussian, or on a rotated ellipse's rim, scaled by `size` [m] about `center` [m].
  Points set(int n, const Vec2& center, double size, double max_ratio) {
    const double ratio = logUniform(1.0, max_ratio);
    const double angle = uniform(-kPi, kPi);
    const double c = std::cos(angle), s = std::sin(angle);
    const int kind = integer(0, 2);
    Points points;
    for (int i = 0; i < n; ++i) {
      double x, y;
      if (kind == 0) {
        x = uniform(-1.0, 1.0), y = uniform(-1.0, 1.0);
      } else if (kind == 1) {
        x = normal(), y = normal();
      } else {
        const double phi = uniform(-kPi, kPi);
        x = std::cos(phi), y = std::sin(phi);
      }
      y /= ratio;
      points.emplace_back(center.x() + size * (c * x - s * y), center.y() + size * (s * x + c * y));
    }
    return points;
  }

};

// ------------------------------------------------------------------ closed forms

TEST(MinimumAreaEllipse, TriangleGivesSteinerCircumellipse) {
  Family family("triangles (Steiner circumellipse)");
  Generator gen(11);
  for (int k = 0; k < 200; ++k) {
    Points t;
    for (int i = 0; i < 3; ++i) t.emplace_back(gen.uniform(-5.0, 5.0), gen.uniform(-5.0, 5.0));
    const quad ax = static_cast<quad>(t[1].x()) - t[0].x(), ay = static_cast<quad>(t[1].y()) - t[0].y();
    const quad bx = static_cast<quad>(t[2].x()) - t[0].x(), by = static_cast<quad>(t[2].y()) - t[0].y();
    const quad triangle = fabsq(ax * by - ay * bx) / 2;
    if (triangle < 1e-3) continue;  // thin triangles are covered by the oracle families
    const quad steiner = 4 * acosq(-1) / (3 * sqrtq(3)) * triangle;
    expectMinimal(t, static_cast<double>(steiner), 0.0, family);
  }
}

TEST(MinimumAreaEllipse, ParallelogramGivesEllipseThroughItsVertices) {
  Family family("parallelograms (2 pi |det(u, v)|)");
  Generator gen(12);
  for (int k = 0; k < 200; ++k) {
    const Vec2 c(gen.uniform(-10.0, 10.0), gen.uniform(-10.0, 10.0));
    const Vec2 u(gen.uniform(-2.0, 2.0), gen.uniform(-2.0, 2.0));
    const Vec2 v(gen.uniform(-2.0, 2.0), gen.uniform(-2.0, 2.0));
    const Points p = {c + u + v, c + u - v, c - u + v, c - u - v};
    // The vertices are rounded; the reference uses the rounded vertices' own u and v only when
    // they still form a parallelogram, so use the exact formula on the rounded corners instead.
    const quad ux = (static_cast<quad>(p[0].x()) - p[3].x()) / 2, uy = (static_cast<quad>(p[0].y()) - p[3].y()) / 2;
    const quad vx = (static_cast<quad>(p[0].x()) - p[1].x()) / 2, vy = (static_cast<quad>(p[0].y()) - p[1].y()) / 2;
    const quad det = fabsq(ux * vy - uy * vx);
    if (det < 1e-2) continue;
    // Rounded corners are a parallelogram to ~1e-16: compare with the oracle-free formula with
    // the rounding's 1e-12 slack below the 1e-6 tolerance.
    expectMinimal(p, static_cast<double>(2 * acosq(-1) * det), 1e-12, family);
  }
}

TEST(MinimumAreaEllipse, RectangleGivesHalfPiWidthHeight) {
  Family family("rectangles (pi w h / 2)");
  Generator gen(13);
  for (int k = 0; k < 100; ++k) {
    const double w = gen.logUniform(1e-3, 1e3), h = gen.logUniform(1e-3, 1e3);
    const double x0 = gen.uniform(-100.0, 100.0), y0 = gen.uniform(-100.0, 100.0);
    Points p = {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
    // Interior and edge points must not change anything.
    for (int i = 0; i < 20; ++i) p.emplace_back(x0 + gen.uniform(0.0, w), y0 + gen.uniform(0.0, h));
    const quad wq = static_cast<quad>(p[1].x()) - p[0].x(), hq = static_cast<quad>(p[3].y()) - p[0].y();
    expectMinimal(p, static_cast<double>(acosq(-1) * wq * hq / 2), 0.0, family);
  }
}

TEST(MinimumAreaEllipse, RegularPolygonGivesCircumcircle) {
  Family family("regular n-gons (circumcircle)");
  Generator gen(14);
  for (const int n : {3, 4, 5, 6, 7, 8, 12, 17, 64, 360, 4096}) {
    for (int k = 0; k < 5; ++k) {
      const double r = gen.logUniform(1e-3, 1e3), phase = gen.uniform(0.0, 2.0 * kPi);
      const Vec2 c(gen.uniform(-1e3, 1e3), gen.uniform(-1e3, 1e3));
      Points p;
      quad smallest = 1e300, largest = 0;  // the rounded vertices' distances from the centre
      for (int i = 0; i < n; ++i) {
        const double phi = phase + 2.0 * kPi * i / n;
        p.emplace_back(c.x() + r * std::cos(phi), c.y() + r * std::sin(phi));
        const quad dx = static_cast<quad>(p.back().x()) - c.x(), dy = static_cast<quad>(p.back().y()) - c.y();
        const quad d = sqrtq(dx * dx + dy * dy);
        smallest = std::min(smallest, d), largest = std::max(largest, d);
      }
      // The rounded vertices are on a circle to (largest - smallest) / r ~ 1e-13.
      const quad circle = acosq(-1) * largest * largest;
      const double slack = static_cast<double>(1 - smallest * smallest / (largest * largest));
      expectMinimal(p, static_cast<double>(circle), slack, family);
    }
  }
}

// ------------------------------------------------------------------ oracle families

TEST(MinimumAreaEllipse, EveryPointInsideOnRandomSets) {
  Family small("random sets, 3-12 points (quad oracle)");
  Family medium("random sets, 13-200 points (long double oracle)");
  Generator gen(21);
  for (int k = 0; k < 150; ++k) {
    const int n = gen.integer(3, 12);
    expectMatchesOracle(gen.set(n, {gen.uniform(-10, 10), gen.uniform(-10, 10)}, gen.logUniform(0.1, 10), 20.0), small);
  }
  for (int k = 0; k < 100; ++k) {
    const int n = gen.integer(13, 200);
    expectMatchesOracle(gen.set(n, {gen.uniform(-10, 10), gen.uniform(-10, 10)}, gen.logUniform(0.1, 10), 20.0), medium);
  }
}

TEST(MinimumAreaEllipse, CoCircularPointsMatchOracle) {
  Family family("co-circular sets");
  Generator gen(22);
  for (int k = 0; k < 60; ++k) {
    const int n = gen.integer(4, 40);
    const double r = gen.logUniform(0.01, 100.0);
    const Vec2 c(gen.uniform(-50, 50), gen.uniform(-50, 50));
    // Angles in an arc of random width: from a balanced set (the circle is the answer) to a
    // half-circle (it is not).
    const double arc = gen.uniform(kPi, 2.0 * kPi);
    Points p;
    for (int i = 0; i < n; ++i) {
      const double phi = gen.uniform(0.0, arc);
      p.emplace_back(c.x() + r * std::cos(phi), c.y() + r * std::sin(phi));
    }
    expectMatchesOracle(p, family);
  }
}

TEST(MinimumAreaEllipse, MillionScaleOffsetsMatchOracle) {
  Family family("unit-size sets 1e6 from the origin");
  Generator gen(23);
  for (int k = 0; k < 80; ++k) {
    const double phi = gen.uniform(-kPi, kPi);
    const double distance = gen.uniform(1e6, 3e6);
    const Vec2 c(distance * std::cos(phi), distance * std::sin(phi));
    expectMatchesOracle(gen.set(gen.integer(3, 60), c, gen.uniform(0.5, 2.0), 10.0), family);
  }
}

TEST(MinimumAreaEllipse, TinySetsMatchOracle) {
  Family family("1e-4-size sets");
  Generator gen(24);
  for (int k = 0; k < 80; ++k) {
    const Vec2 c(gen.uniform(-1.0, 1.0), gen.uniform(-1.0, 1.0));
    expectMatchesOracle(gen.set(gen.integer(3, 60), c, 1e-4, 10.0), family);
  }
}

TEST(MinimumAreaEllipse, ThinSetsMatchOracle) {
  Family family("thin sets, axis ratio 1e2-1e4");
  Generator gen(25);
  for (int k = 0; k < 60; ++k) {
    Points p = gen.set(gen.integer(3, 12), {gen.uniform(-5, 5), gen.uniform(-5, 5)}, 1.0, 1.0);
    // Squash along a random direction by a large ratio.
    const double ratio = gen.logUniform(1e2, 1e4), angle = gen.uniform(-kPi, kPi);
    const Vec2 u(std::cos(angle), std::sin(angle)), v(-u.y(), u.x());
    for (Vec2& q : p) q = q.dot(u) * u + (q.dot(v) / ratio) * v;
    expectMatchesOracle(p, family);
  }
}

TEST(MinimumAreaEllipse, ThousandsOfPointsMatchOracle) {
  Family family("1000-3000 points");
  Generator gen(26);
  for (int k = 0; k < 6; ++k) {
    expectMatchesOracle(gen.set(gen.integer(1000, 3000), {gen.uniform(-5, 5), gen.uniform(-5, 5)}, 2.0, 5.0), family);
  }
}

TEST(MinimumAreaEllipse, DuplicatesDoNotChangeTheResult) {
  Family family("sets with duplicates");
  Generator gen(27);
  for (int k = 0; k < 40; ++k) {
    Points p = gen.set(gen.integer(3, 10), {0.0, 0.0}, 1.0, 5.0);
    const std::size_t distinct = p.size();
    for (std::size_t i = 0; i < 3 * distinct; ++i) p.push_back(p[gen.integer(0, static_cast<int>(distinct) - 1)]);
    expectMatchesOracle(p, family);
  }
}

// ------------------------------------------------------------------ degenerate sets

/// Every point within the segment description (in quad, with the documented rounding).
void expectWithinSegment(const EnclosingEllipse& r, const Points& points) {
  const quad ax = r.segment_start.x(), ay = r.segment_start.y();
  const quad bx = r.segment_end.x(), by = r.segment_end.y();
  const quad lx = bx - ax, ly = by - ay, length2 = lx * lx + ly * ly;
  quad extent = 0;
  for (const Vec2& p : points) extent = std::max(extent, fabsq(static_cast<quad>(p.x()) - ax) + fabsq(static_cast<quad>(p.y()) - ay));
  for (const Vec2& p : points) {
    const quad px = static_cast<quad>(p.x()) - ax, py = static_cast<quad>(p.y()) - ay;
    quad t = length2 > 0 ? (px * lx + py * ly) / length2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    const quad dx = px - t * lx, dy = py - t * ly;
    EXPECT_LE(static_cast<double>(sqrtq(dx * dx + dy * dy)), r.half_width + 1e-15 * static_cast<double>(extent))
        << describe(points);
  }
}

TEST(MinimumAreaEllipse, CollinearPointsAreDegenerateWithTheirSegment) {
  Generator gen(31);
  int sets = 0;
  for (int k = 0; k < 100; ++k) {
    const double angle = k % 4 == 0 ? 0.0 : (k % 4 == 1 ? kPi / 2 : gen.uniform(-kPi, kPi));
    const Vec2 u(std::cos(angle), std::sin(angle));
    const Vec2 c = k % 2 ? Vec2(gen.uniform(-1e6, 1e6), gen.uniform(-1e6, 1e6)) : Vec2(0.0, 0.0);
    const double length = gen.logUniform(1e-2, 1e2);
    Points p;
    double lo = 1e300, hi = -1e300;
    for (int i = 0, n = gen.integer(2, 50); i < n; ++i) {
      const double s = gen.uniform(-length, length);
      lo = std::min(lo, s), hi = std::max(hi, s);
      p.push_back(c + s * u);
    }
    const EnclosingEllipse r = minimumAreaEllipse(p);
    ++sets;
    ASSERT_EQ(r.status, EnclosingStatus::Degenerate) << describe(p);
    expectWithinSegment(r, p);
    // The segment is the points' extent, not more.
    EXPECT_NEAR((r.segment_end - r.segment_start).norm(), hi - lo, 1e-9 * (1.0 + c.norm()));
  }
  std::printf("[ record   ] collinear: %d sets, all Degenerate\n", sets);
}

TEST(MinimumAreaEllipse, OnePointAndRepeatedPointsAreDegenerate) {
  for (const Points& p : {Points{{3.0, -4.0}}, Points(7, Vec2(1e6, -2e6)), Points{{1.0, 1.0}, {2.0, 3.0}},
                          Points{{1.0, 1.0}, {2.0, 3.0}, {1.0, 1.0}, {2.0, 3.0}}}) {
    const EnclosingEllipse r = minimumAreaEllipse(p);
    ASSERT_EQ(r.status, EnclosingStatus::Degenerate) << describe(p);
    expectWithinSegment(r, p);
    // Only the documented rounding pad (a few ulps of the extent).
    EXPECT_LE(r.half_width, 1e-14 * (1.0 + p.front().norm())) << describe(p);
  }
}

TEST(MinimumAreaEllipse, SetsBelowTheMinimumRadiusAreDegenerate) {
  // A triangle 1e-12 m across could only be enclosed by radii below kMinRadius.
  const Points p = {{5.0, 5.0}, {5.0 + 1e-12, 5.0}, {5.0, 5.0 + 1e-12}};
  const EnclosingEllipse r = minimumAreaEllipse(p);
  EXPECT_EQ(r.status, EnclosingStatus::Degenerate);
  expectWithinSegment(r, p);
}

TEST(MinimumAreaEllipse, ErrorsNameThePointAndValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(minimumAreaEllipse({}).error, "points is empty");
  EXPECT_EQ(minimumAreaEllipse({{0, 0}, {1, 0}, {0, 1}, {nan, 0}}).error, "points[3].x = nan is not finite");
  EXPECT_EQ(minimumAreaEllipse({{0, -inf}}).error, "points[0].y = -inf is not finite");
  EXPECT_EQ(minimumAreaEllipse({{0, 0}, {2e9, 0}}).error, "points[1].x = 2e+09 is outside [-1e+09, 1e+09] m");
  EXPECT_EQ(minimumAreaEllipse({}).status, EnclosingStatus::Error);
  // Points inside the coordinate range whose ellipse would exceed kMaxRadius.
  const EnclosingEllipse huge = minimumAreaEllipse({{-1e9, -1e9}, {1e9, -1e9}, {0, 1e9}});
  EXPECT_EQ(huge.status, EnclosingStatus::Error);
  EXPECT_NE(huge.error.find("out of range: radius_x"), std::string::npos) << huge.error;
}

// ------------------------------------------------------------------ enclosingEllipseWithMinRadius

void expectEnclosingWithMinRadius(const Points& p, double min_radius) {
  const EnclosingEllipse r = enclosingEllipseWithMinRadius(p, min_radius);
  ASSERT_EQ(r.status, EnclosingStatus::Ok) << r.error << "\n" << describe(p);
  EXPECT_EQ(invalidReason(r.ellipse), "");
  EXPECT_GE(r.ellipse.radius_x, min_radius);
  EXPECT_GE(r.ellipse.radius_y, min_radius);
  EXPECT_GE(r.ellipse.radius_x, r.ellipse.radius_y);
  EXPECT_EQ(countOutside(r.ellipse, p), 0) << describeEllipse(r.ellipse) << "\n" << describe(p);
}

TEST(EnclosingEllipseWithMinRadius, OnePointGivesCircleOfMinRadius) {
  const EnclosingEllipse r = enclosingEllipseWithMinRadius({{1.5, -2.5}}, 0.05);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.ellipse.center, Vec2(1.5, -2.5));
  EXPECT_DOUBLE_EQ(r.ellipse.radius_x, 0.05);
  EXPECT_DOUBLE_EQ(r.ellipse.radius_y, 0.05);
}

TEST(EnclosingEllipseWithMinRadius, TwoPointsGiveThinEllipseAlongThem) {
  const EnclosingEllipse r = enclosingEllipseWithMinRadius({{0.0, 0.0}, {0.0, 2.0}}, 0.01);
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_NEAR(r.ellipse.center.x(), 0.0, 1e-15);
  EXPECT_NEAR(r.ellipse.center.y(), 1.0, 1e-15);
  EXPECT_NEAR(r.ellipse.radius_x, 1.0, 1e-12);
  // The ends lie on the boundary, so the certification adds a few ulps.
  EXPECT_GE(r.ellipse.radius_y, 0.01);
  EXPECT_NEAR(r.ellipse.radius_y, 0.01, 1e-15);
  EXPECT_NEAR(std::abs(r.ellipse.angle), kPi / 2, 1e-15);
  expectEnclosingWithMinRadius({{0.0, 0.0}, {0.0, 2.0}}, 0.01);
}

TEST(EnclosingEllipseWithMinRadius, EveryPointInsideForLinesClustersAndThinSets) {
  Generator gen(41);
  int sets = 0;
  for (int k = 0; k < 300; ++k) {
    const double min_radius = gen.logUniform(1e-4, 1.0);
    const Vec2 c(gen.uniform(-1e6, 1e6), gen.uniform(-1e6, 1e6));
    Points p;
    switch (k % 5) {
      case 0:  // collinear
      case 1: {  // nearly collinear
        const double angle = gen.uniform(-kPi, kPi);
        const Vec2 u(std::cos(angle), std::sin(angle)), v(-u.y(), u.x());
        const double length = gen.logUniform(1e-3, 10.0);
        const double noise = k % 5 == 1 ? gen.logUniform(1e-9, 1e-2) : 0.0;
        for (int i = 0, n = gen.integer(1, 40); i < n; ++i) {
          p.push_back(c + gen.uniform(-length, length) * u + gen.uniform(-noise, noise) * v);
        }
        break;
      }
      case 2:  // duplicates of one or two points
        for (int i = 0, n = gen.integer(1, 6); i < n; ++i) p.push_back(i % 2 ? c : Vec2(c + Vec2(gen.uniform(-1, 1), 0.0)));
        break;
      default:  // general clusters, sometimes smaller than min_radius
        p = gen.set(gen.integer(3, 40), c, gen.logUniform(1e-4, 2.0), 100.0);
    }
    expectEnclosingWithMinRadius(p, min_radius);
    ++sets;
  }
  std::printf("[ record   ] enclosingEllipseWithMinRadius: %d sets, containment violations = 0\n", sets);
}

TEST(EnclosingEllipseWithMinRadius, RejectsInvalidMinRadius) {
  const Points p = {{0.0, 0.0}};
  EXPECT_EQ(enclosingEllipseWithMinRadius(p, 0.0).error, "min_radius = 0 must be > 0");
  EXPECT_EQ(enclosingEllipseWithMinRadius(p, std::nan("")).error, "min_radius = nan is not finite");
  EXPECT_EQ(enclosingEllipseWithMinRadius(p, 1e-12).error, "min_radius = 1e-12 is outside [1e-09, 1e+09] m");
  EXPECT_EQ(enclosingEllipseWithMinRadius({}, 0.1).error, "points is empty");
}

TEST(EnclosingEllipseWithMinRadius, KeepsTheMinimumEllipseWhenItIsLargeEnough) {
  const Points p = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {0.0, 1.0}};
  const EnclosingEllipse a = minimumAreaEllipse(p);
  const EnclosingEllipse b = enclosingEllipseWithMinRadius(p, 0.1);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a.ellipse.radius_x, b.ellipse.radius_x);
  EXPECT_EQ(a.ellipse.radius_y, b.ellipse.radius_y);
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

// The drawn polygon of an ellipse (rviz markers): vertices on the rim, its gap to the true rim
// measured by dense sampling against the documented bound, the segment count rule, and the
// triangle fan's orientation and area against the closed form of an affine regular n-gon.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "ellipse_collision/core/ellipse_polygon.h"
#include "scene_test_helpers.h"

namespace ellipse_collision::core {
namespace {

using scene_test::ellipse;

/// The ellipse's implicit form at p: 1 on the rim (computed through the inverse rotation, not the
/// parameterisation the code uses).
double implicitForm(const Ellipse& e, const Eigen::Vector2d& p) {
  const Eigen::Vector2d d = p - e.center;
  const double u = std::cos(e.angle) * d.x() + std::sin(e.angle) * d.y();
  const double v = -std::sin(e.angle) * d.x() + std::cos(e.angle) * d.y();
  return (u / e.radius_x) * (u / e.radius_x) + (v / e.radius_y) * (v / e.radius_y);
}

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

/// Largest distance from densely sampled rim points (by arc, 20,000 samples) to the polygon's
/// edges.
double largestGap(const Ellipse& e, const std::vector<Eigen::Vector2d>& polygon) {
  double largest = 0.0;
  const int samples = 20000;
  for (int k = 0; k < samples; ++k) {
    const double t = 2.0 * M_PI * (k + 0.5) / samples;
    const Eigen::Vector2d local(e.radius_x * std::cos(t), e.radius_y * std::sin(t));
    const Eigen::Vector2d p =
        e.center + Eigen::Vector2d(std::cos(e.angle) * local.x() - std::sin(e.angle) * local.y(),
                                   std::sin(e.angle) * local.x() + std::cos(e.angle) * local.y());
    double nearest = INFINITY;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      nearest =
          std::min(nearest, distanceToSegment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
    }
    largest = std::max(largest, nearest);
  }
  return largest;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

TEST(EllipsePolygon, VerticesLieOnTheRimCounterClockwiseFromTheEllipsesOwnXAxis) {
  const Ellipse e = ellipse(3.0, -2.0, 0.7, 0.2, 0.9);
  const std::vector<Eigen::Vector2d> polygon = ellipsePolygon(e, 20);
  ASSERT_EQ(polygon.size(), 20u);
  for (const Eigen::Vector2d& p : polygon) EXPECT_NEAR(implicitForm(e, p), 1.0, 1e-12);
  EXPECT_NEAR(polygon[0].x(), 3.0 + 0.7 * std::cos(0.9), 1e-15);
  EXPECT_NEAR(polygon[0].y(), -2.0 + 0.7 * std::sin(0.9), 1e-15);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    EXPECT_GT(cross(a - e.center, b - e.center), 0.0) << "edge " << i << " turns clockwise";
  }
}

TEST(EllipsePolygon, EveryCountGivesTheSameBitsAsEvaluatingTheRimDirectly) {
  // The counts the markers use come from tables computed once; any other count is evaluated.
  const Ellipse e = ellipse(-1.5, 4.25, 0.31, 0.07, -2.2);
  const double c = std::cos(e.angle), s = std::sin(e.angle);
  for (const int n : {3, 4, 16, 37, 50, 64, 65, 200}) {
    const std::vector<Eigen::Vector2d> polygon = ellipsePolygon(e, n);
    ASSERT_EQ(polygon.size(), static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const double t = 2.0 * M_PI * i / n;
      const double x = e.radius_x * std::cos(t), y = e.radius_y * std::sin(t);
      ASSERT_EQ(polygon[i].x(), e.center.x() + c * x - s * y) << "n = " << n << ", i = " << i;
      ASSERT_EQ(polygon[i].y(), e.center.y() + s * x + c * y) << "n = " << n << ", i = " << i;
    }
  }
}

TEST(EllipsePolygon, SegmentCountIsTheSmallestWithinTheGapBetweenItsBounds) {
  // Circles: the closed form n = ceil(pi / acos(1 - gap / r)), clamped to [16, 64].
  for (const double r : {0.01, 0.1, 0.2, 0.5, 1.0, 1.5, 3.0, 100.0}) {
    const int closed_form = static_cast<int>(std::ceil(M_PI / std::acos(1.0 - kMaxDrawGap / r)));
    const int expected = std::clamp(closed_form, kMinDrawSegments, kMaxDrawSegments);
    EXPECT_EQ(drawSegments(ellipse(0, 0, r, r, 0)), expected) << "r = " << r;
  }
  EXPECT_EQ(drawSegments(ellipse(0, 0, 0.1, 0.1, 0)), 16);
  EXPECT_EQ(drawSegments(ellipse(0, 0, 1.0, 1.0, 0)), 50);
  EXPECT_EQ(drawSegments(ellipse(0, 0, 100.0, 100.0, 0)), 64);
  // The larger radius decides, whichever axis it is on.
  EXPECT_EQ(drawSegments(ellipse(0, 0, 1.0, 0.01, 0)), drawSegments(ellipse(0, 0, 0.01, 1.0, 2)));
}

TEST(EllipsePolygon, DrawnRimStaysWithinTheDocumentedGapOfTheTrueRim) {
  for (const Ellipse& e : {ellipse(0, 0, 0.1, 0.1, 0), ellipse(1, 2, 0.3, 0.2, M_PI / 2),
                           ellipse(-4, 7, 1.0, 0.05, 0.3), ellipse(0, 0, 2.5, 2.0, -1.0),
                           ellipse(10, 10, 50.0, 1.0, 0.1)}) {
    const int n = drawSegments(e);
    const double bound = std::max(e.radius_x, e.radius_y) * (1.0 - std::cos(M_PI / n));
    const double gap = largestGap(e, ellipsePolygon(e, n));
    EXPECT_LE(gap, bound * (1 + 1e-9)) << "radii " << e.radius_x << " x " << e.radius_y;
    if (n < kMaxDrawSegments) {
      EXPECT_LE(gap, kMaxDrawGap);
    }
  }
  // For a circle the bound is attained at the middle of each chord.
  const Ellipse circle = ellipse(0, 0, 1.0, 1.0, 0);
  const int n = drawSegments(circle);
  EXPECT_NEAR(largestGap(circle, ellipsePolygon(circle, n)), 1.0 - std::cos(M_PI / n), 1e-7);
}

TEST(EllipsePolygon, TriangleFanCoversTheAffineRegularPolygonCounterClockwise) {
  const Ellipse e = ellipse(1.0, 2.0, 0.3, 0.2, M_PI / 2);
  std::vector<Eigen::Vector2d> triangles;
  forEachTrianglePoint(e, [&triangles](const Eigen::Vector2d& p) { triangles.push_back(p); });
  const int n = drawSegments(e);
  ASSERT_EQ(triangles.size(), static_cast<std::size_t>(3 * (n - 2)));
  ASSERT_EQ(triangles.size(), ellipseTrianglePoints(e));
  double area = 0.0;
  for (std::size_t i = 0; i < triangles.size(); i += 3) {
    const double twice = cross(triangles[i + 1] - triangles[i], triangles[i + 2] - triangles[i]);
    EXPECT_GT(twice, 0.0) << "triangle " << i / 3 << " is clockwise or degenerate";
    area += twice / 2;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(implicitForm(e, triangles[i + k]), 1.0, 1e-12);
  }
  // An affine image of the regular n-gon inscribed in the unit circle: (n / 2) sin(2 pi / n) a b.
  EXPECT_NEAR(area, n / 2.0 * std::sin(2 * M_PI / n) * 0.3 * 0.2, 1e-14);
  EXPECT_GT(area, 0.97 * M_PI * 0.3 * 0.2);
}

TEST(EllipsePolygon, TheMarkersAllocationFreePathGivesTheSameBitsAsThePolygon) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    // Radii from 1e-4 to 1e3 m: every segment count from 16 to 64 is met.
    const double a = std::pow(10.0, -4.0 + 7.0 * unit(rng));
    const Ellipse e = ellipse(1e3 * (unit(rng) - 0.5), 1e3 * (unit(rng) - 0.5), a,
                              a * (0.01 + unit(rng)), 2 * M_PI * unit(rng));
    const int n = drawSegments(e);
    std::array<Eigen::Vector2d, kMaxDrawSegments> into;
    ASSERT_EQ(drawnPolygonInto(e, into.data()), n);
    const std::vector<Eigen::Vector2d> polygon = ellipsePolygon(e, n);
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(into[static_cast<std::size_t>(i)], polygon[static_cast<std::size_t>(i)])
          << "trial " << trial << " vertex " << i;
    }
    std::vector<Eigen::Vector2d> fan;
    forEachTrianglePoint(e, [&fan](const Eigen::Vector2d& p) { fan.push_back(p); });
    ASSERT_EQ(fan.size(), ellipseTrianglePoints(e));
    ASSERT_EQ(fan.size(), static_cast<std::size_t>(3 * (n - 2)));
    for (std::size_t t = 0; t < fan.size() / 3; ++t) {
      ASSERT_EQ(fan[3 * t], polygon[0]);
      ASSERT_EQ(fan[3 * t + 1], polygon[t + 1]);
      ASSERT_EQ(fan[3 * t + 2], polygon[t + 2]);
    }
  }
}

}  // namespace
}  // namespace ellipse_collision::core

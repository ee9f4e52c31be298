#include "ellipse_collision/polygonal_test.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "polygonal_test_detail.h"

namespace ellipse_collision {
namespace {

using Eigen::Vector2d;

// Deeper levels than this cannot be resolved in double precision anyway.
constexpr int kMaxLevels = 30;

// Decisions closer than this (relative to the scale of the picture) to the rim of the circle are
// left undecided: rounding in the frame change must never turn into a wrong answer.
constexpr double kRelativeMargin = 1e-10;

// For an arc of angular width w = (pi/2) / 2^level on the ellipse's parameter circle:
//  - the rim point at its middle is (a + b) * mid[level] (a, b: rim points at its ends),
//  - the tangents at its ends cross at (a + b) * corner[level].
// Both are affine images of the same facts about the unit circle, hence valid on the ellipse.
struct ArcCoefficients {
  std::array<double, kMaxLevels + 1> mid;
  std::array<double, kMaxLevels + 1> corner;

  ArcCoefficients() {
    for (int level = 0; level <= kMaxLevels; ++level) {
      const double width = (M_PI / 2.0) / std::ldexp(1.0, level);
      mid[level] = 0.5 / std::cos(0.5 * width);
      corner[level] = 1.0 / (1.0 + std::cos(width));
    }
  }
};

const ArcCoefficients& arcCoefficients() {
  static const ArcCoefficients coefficients;
  return coefficients;
}

double cross(const Vector2d& u, const Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

double segmentDistanceSquared(const Vector2d& point, const Vector2d& start, const Vector2d& end) {
  const Vector2d along = end - start;
  const Vector2d to_point = point - start;
  const double projection = to_point.dot(along);
  if (projection <= 0.0) return to_point.squaredNorm();
  const double length_sq = along.squaredNorm();
  if (projection >= length_sq) return (point - end).squaredNorm();
  const double perpendicular = cross(along, to_point);
  return perpendicular * perpendicular / length_sq;
}

bool insideTriangle(const Vector2d& point, const Vector2d& a, const Vector2d& b, const Vector2d& c) {
  const double ab = cross(b - a, point - a);
  const double bc = cross(c - b, point - b);
  const double ca = cross(a - c, point - c);
  return (ab >= 0.0 && bc >= 0.0 && ca >= 0.0) || (ab <= 0.0 && bc <= 0.0 && ca <= 0.0);
}

struct Arc {
  Vector2d start;  ///< rim point, relative to the ellipse centre
  Vector2d end;
  int level;
};

}  // namespace

const char* toString(PolygonalResult result) {
  switch (result) {
    case PolygonalResult::Overlap:
      return "overlap";
    case PolygonalResult::Separate:
      return "separate";
    case PolygonalResult::Unknown:
      return "unknown";
  }
  return "invalid";
}

namespace detail {

PolygonalResult polygonalTestRelative(const RelativeShape& shape, int max_iterations) {
  max_iterations = std::clamp(max_iterations, 0, kMaxLevels);
  const Vector2d p = shape.axes.col(0);
  const Vector2d q = shape.axes.col(1);
  const double scale = 1.0 + shape.center.lpNorm<Eigen::Infinity>() +
                       p.lpNorm<Eigen::Infinity>() + q.lpNorm<Eigen::Infinity>();
  const double margin = kRelativeMargin * scale;
  const double hit_sq = (1.0 - margin) * (1.0 - margin);  // certainly inside the unit disk
  const double miss_sq = (1.0 + margin) * (1.0 + margin);  // certainly outside it

  // Either centre inside the other ellipse proves overlap (this also covers containment).
  if (shape.center.squaredNorm() <= hit_sq) return PolygonalResult::Overlap;
  if ((shape.inverse_axes * shape.center).squaredNorm() <= 1.0 - 2.0 * kRelativeMargin) {
    return PolygonalResult::Overlap;
  }

  // Work relative to the ellipse centre; the disk centre is then at -center.
  const Vector2d disk = -shape.center;
  const ArcCoefficients& coefficients = arcCoefficients();

  // Depth-first over the arcs of the rim; the ellipse is the inscribed polygon plus the
  // segments between each chord and its arc, and each segment lies inside its tangent triangle.
  std::array<Arc, 4 + 2 * kMaxLevels + 2> stack;
  int size = 0;
  stack[size++] = {p, q, 0};
  stack[size++] = {q, -p, 0};
  stack[size++] = {-p, -q, 0};
  stack[size++] = {-q, p, 0};

  // Bounds the work when the rims run close together over a long stretch.
  int budget = 16 * (max_iterations + 1);
  bool undecided = false;
  while (size > 0) {
    const Arc arc = stack[--size];
    const double chord_sq = segmentDistanceSquared(disk, arc.start, arc.end);
    if (chord_sq <= hit_sq) return PolygonalResult::Overlap;  // the chord lies in the ellipse

    const Vector2d corner = (arc.start + arc.end) * coefficients.corner[arc.level];
    const bool misses_triangle = chord_sq > miss_sq &&
                                 segmentDistanceSquared(disk, arc.start, corner) > miss_sq &&
                                 segmentDistanceSquared(disk, corner, arc.end) > miss_sq &&
                                 !insideTriangle(disk, arc.start, arc.end, corner);
    if (misses_triangle) continue;

    if (arc.level >= max_iterations || --budget < 0) {
      undecided = true;  // out of iterations: unknown, never "no collision"
      continue;
    }
    const Vector2d middle = (arc.start + arc.end) * coefficients.mid[arc.level];
    stack[size++] = {middle, arc.end, arc.level + 1};
    stack[size++] = {arc.start, middle, arc.level + 1};
  }
  return undecided ? PolygonalResult::Unknown : PolygonalResult::Separate;
}

}  // namespace detail

PolygonalResult polygonalTest(const Ellipse& a, const Ellipse& b, int max_iterations) {
  const auto shape = detail::canonicalRelativeShape(a, b);
  return detail::polygonalTestRelative(shape, max_iterations);
}

}  // namespace ellipse_collision

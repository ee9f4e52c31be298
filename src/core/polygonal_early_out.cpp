#include "ellipse_collision/core/polygonal_early_out.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "polygonal_early_out_detail.h"

namespace ellipse_collision::core {
namespace detail {
namespace {

// Deeper levels than this cannot be resolved in double precision anyway.
constexpr int kMaxLevels = 30;

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

/// Whether `point` lies right of the directed line start -> end by more than sqrt(radius_sq): a
/// cheap certificate that a disk of that radius misses everything left of the line.
bool farRightOf(const Point& point, const Point& start, const Point& end, double radius_sq) {
  const Point along = end - start;
  const double left = cross(along, point - start);
  return left < 0.0 && left * left > radius_sq * squaredNorm(along);
}

bool insideTriangle(const Point& point, const Point& a, const Point& b, const Point& c) {
  const double ab = cross(b - a, point - a);
  const double bc = cross(c - b, point - b);
  const double ca = cross(a - c, point - c);
  return (ab >= 0.0 && bc >= 0.0 && ca >= 0.0) || (ab <= 0.0 && bc <= 0.0 && ca <= 0.0);
}

/// Whether the disk of radius sqrt(radius_sq) about `point` misses the triangle (start, corner,
/// end), which is counter-clockwise: det(p, q) > 0 keeps the rim's orientation.
bool diskMissesTriangle(const Point& point, const Point& start, const Point& corner,
                        const Point& end, double radius_sq) {
  // Separated by one of the triangle's edges: decides most triangles with one cross product.
  if (farRightOf(point, end, start, radius_sq) || farRightOf(point, start, corner, radius_sq) ||
      farRightOf(point, corner, end, radius_sq)) {
    return true;
  }
  return !segmentWithin(point, start, end, radius_sq) &&
         !segmentWithin(point, start, corner, radius_sq) &&
         !segmentWithin(point, corner, end, radius_sq) &&
         !insideTriangle(point, start, end, corner);
}

struct Arc {
  Point start;  ///< rim point, relative to the ellipse centre
  Point end;
  int level;
};

}  // namespace

PolygonalResult polygonalRefinement(const RelativeShape& shape, const PolygonalMargins& margins,
                                    int max_iterations) {
  max_iterations = std::clamp(max_iterations, 0, kMaxLevels);
  const Point p{shape.p_x, shape.p_y}, q{shape.q_x, shape.q_y};
  const Point disk{-shape.center_x, -shape.center_y};  // relative to the ellipse's centre
  const ArcCoefficients& coefficients = arcCoefficients();

  // Depth-first over the arcs of the rim; the ellipse is the inscribed polygon plus the segments
  // between each chord and its arc, and each segment lies inside its tangent triangle.
  std::array<Arc, 4 + 2 * kMaxLevels + 2> stack;
  int size = 0;
  stack[size++] = {p, q, 0};
  stack[size++] = {q, p * -1.0, 0};
  stack[size++] = {p * -1.0, q * -1.0, 0};
  stack[size++] = {q * -1.0, p, 0};

  // Bounds the work when the rims run close together over a long stretch.
  int budget = 16 * (max_iterations + 1);
  bool undecided = false;
  while (size > 0) {
    const Arc arc = stack[--size];
    const Point corner = (arc.start + arc.end) * coefficients.corner[arc.level];
    // The chord is an edge of the triangle, so a miss of the triangle is a miss of the chord.
    if (diskMissesTriangle(disk, arc.start, corner, arc.end, margins.miss_sq)) continue;
    // The chord lies in the ellipse: touching it proves overlap.
    if (segmentWithin(disk, arc.start, arc.end, margins.hit_sq)) return PolygonalResult::Overlap;

    if (arc.level >= max_iterations || --budget < 0) {
      undecided = true;  // out of iterations: unknown, never "no collision"
      continue;
    }
    const Point middle = (arc.start + arc.end) * coefficients.mid[arc.level];
    stack[size++] = {middle, arc.end, arc.level + 1};
    stack[size++] = {arc.start, middle, arc.level + 1};
  }
  return undecided ? PolygonalResult::Unknown : PolygonalResult::Separate;
}

}  // namespace detail

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

PolygonalResult polygonalTest(const Ellipse& a, const Ellipse& b, int max_iterations) {
  return detail::polygonalTestRelative(detail::canonicalRelativeShape(a, b), max_iterations);
}

}  // namespace ellipse_collision::core

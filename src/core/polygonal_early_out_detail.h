#pragma once

#include <algorithm>
#include <cmath>

#include "ellipse_collision/core/polygonal_early_out.h"
#include "relative_shape.h"

namespace ellipse_collision::core::detail {

/// A point or vector of the relative frame, in plain doubles (see RelativeShape).
struct Point {
  double x;
  double y;
};

inline Point operator+(const Point& u, const Point& v) { return {u.x + v.x, u.y + v.y}; }
inline Point operator-(const Point& u, const Point& v) { return {u.x - v.x, u.y - v.y}; }
inline Point operator*(const Point& u, double k) { return {u.x * k, u.y * k}; }
inline double dot(const Point& u, const Point& v) { return u.x * v.x + u.y * v.y; }
inline double squaredNorm(const Point& u) { return dot(u, u); }
inline double cross(const Point& u, const Point& v) { return u.x * v.y - u.y * v.x; }

/// Whether the segment [start, end] comes within sqrt(radius_sq) of `point`, without the division
/// of the distance itself. All three cases are evaluated and combined without branches: which
/// one applies is as unpredictable as the pairs, and a mispredicted branch costs more than the
/// arithmetic.
inline bool segmentWithin(const Point& point, const Point& start, const Point& end,
                          double radius_sq) {
  const Point along = end - start;
  const Point to_point = point - start;
  const double projection = dot(to_point, along);
  const double length_sq = squaredNorm(along);
  const double perpendicular = cross(along, to_point);
  const double start_sq = squaredNorm(to_point);
  const double end_sq = squaredNorm(point - end);
  const bool before = projection <= 0.0;
  const bool after = projection >= length_sq;
  return (before & (start_sq <= radius_sq)) | (after & (end_sq <= radius_sq)) |
         (!before & !after & (perpendicular * perpendicular <= radius_sq * length_sq));
}

/// Decisions closer than this (relative to the scale of the picture) to the rim of the circle are
/// left undecided: rounding in the frame change must never turn into a wrong answer.
inline constexpr double kPolygonalRelativeMargin = 1e-10;

/// Squared distances from the disk's centre that are certainly inside (hit) and certainly
/// outside (miss) the unit disk, for this picture's scale.
struct PolygonalMargins {
  double hit_sq;
  double miss_sq;
};

inline PolygonalMargins polygonalMargins(const RelativeShape& shape) {
  const double scale = 1.0 + std::max(std::abs(shape.center_x), std::abs(shape.center_y)) +
                       std::max(std::abs(shape.p_x), std::abs(shape.p_y)) +
                       std::max(std::abs(shape.q_x), std::abs(shape.q_y));
  const double margin = kPolygonalRelativeMargin * scale;
  return {(1.0 - margin) * (1.0 - margin), (1.0 + margin) * (1.0 + margin)};
}

/// Whether the picture can be judged with polygons in double precision: the rounding margin must
/// stay small against the unit circle, and the ellipse's thickness far above the rounding of its
/// coordinates (a needle thinner than that has triangles whose orientation tests are noise).
/// Otherwise the answer is Unknown and the eigenvalue test decides.
inline bool polygonalResolvable(const RelativeShape& shape) {
  constexpr double kMaxScale = 1e7;          // margin <= 1e-3 of the unit circle
  constexpr double kMinThickness = 1e-6;     // minor semi-axis / scale, >> the margin
  const double extent = std::max(std::abs(shape.p_x), std::abs(shape.p_y)) +
                        std::max(std::abs(shape.q_x), std::abs(shape.q_y));
  const double scale = 1.0 + std::max(std::abs(shape.center_x), std::abs(shape.center_y)) + extent;
  // det / extent bounds the minor semi-axis from below (up to a factor 2).
  return scale <= kMaxScale && shape.determinant >= kMinThickness * scale * extent;
}

/// Level 0 of the polygonal test, on the inscribed parallelogram (+-p, +-q) and the
/// circumscribed one (+-p +-q), without branches as in segmentWithin(). It decides most pairs
/// that the circle tests leave, and inline it stays in registers.
inline PolygonalResult polygonalLevelZero(const RelativeShape& shape,
                                          const PolygonalMargins& margins) {
  const Point p{shape.p_x, shape.p_y}, q{shape.q_x, shape.q_y};
  const Point disk{-shape.center_x, -shape.center_y};  // relative to the ellipse's centre
  // w = adj([p q]) * disk = det * (the disk's centre in the ellipse's parameter coordinates):
  // no division needed.
  const double det = shape.determinant;
  const double w0 = q.y * disk.x - q.x * disk.y;
  const double w1 = p.x * disk.y - p.y * disk.x;
  const Point side_p = p * std::copysign(1.0, w0);  // the vertices on the disk's side
  const Point side_q = q * std::copysign(1.0, w1);
  // Overlap: either centre inside the other ellipse (this covers containment), or the disk
  // touching the chord between the vertices on its side, which lies in the ellipse.
  const bool ellipse_centre_in_disk = squaredNorm(disk) <= margins.hit_sq;
  const bool disk_centre_in_ellipse =
      w0 * w0 + w1 * w1 <= (1.0 - 2.0 * kPolygonalRelativeMargin) * det * det;
  const bool touches_chord = segmentWithin(disk, side_p, side_q, margins.hit_sq);
  if (ellipse_centre_in_disk | disk_centre_in_ellipse | touches_chord) {
    return PolygonalResult::Overlap;
  }
  // Separate: the disk misses the circumscribed parallelogram. Its nearest point lies on an edge
  // the centre is beyond, and only the edges on the disk's side can be.
  const bool beyond_p = std::abs(w0) > det, beyond_q = std::abs(w1) > det;
  const bool near_p_edge = segmentWithin(disk, side_p - q, side_p + q, margins.miss_sq);
  const bool near_q_edge = segmentWithin(disk, side_q - p, side_q + p, margins.miss_sq);
  if ((beyond_p | beyond_q) & (!beyond_p | !near_p_edge) & (!beyond_q | !near_q_edge)) {
    return PolygonalResult::Separate;
  }
  return PolygonalResult::Unknown;
}

/// The bisection of the rim's arcs down to level `max_iterations`.
PolygonalResult polygonalRefinement(const RelativeShape& shape, const PolygonalMargins& margins,
                                    int max_iterations);

/// The polygonal test against the unit circle at the origin for `shape` (see relativeShape()).
inline PolygonalResult polygonalTestRelative(const RelativeShape& shape, int max_iterations) {
  if (!polygonalResolvable(shape)) return PolygonalResult::Unknown;
  const PolygonalMargins margins = polygonalMargins(shape);
  const PolygonalResult level_zero = polygonalLevelZero(shape, margins);
  if (level_zero != PolygonalResult::Unknown || max_iterations <= 0) return level_zero;
  return polygonalRefinement(shape, margins, max_iterations);
}

}  // namespace ellipse_collision::core::detail

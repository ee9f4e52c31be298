#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// How a drawn ellipse is approximated: an inscribed polygon whose vertices lie on the rim at
/// equal steps of the parameter t (point(t) = centre + R(angle) (radius_x cos t, radius_y sin t)).
/// A chord of the unit circle over a step of 2 pi / n lies at most 1 - cos(pi / n) inside it; the
/// affine map to the ellipse stretches that gap by at most the larger radius, so the polygon is
/// within max(radius_x, radius_y) (1 - cos(pi / n)) of the true rim everywhere.
///
/// The segment count keeps that gap below kMaxDrawGap (2 mm, below a pixel at any view that shows
/// a robot whole) with at least kMinDrawSegments (a 0.1 m obstacle is a 16-gon: round to the eye)
/// and at most kMaxDrawSegments (a 1 m link is a 64-gon, 0.12 % of its radius).
constexpr double kMaxDrawGap = 0.002;  ///< [m]
constexpr int kMinDrawSegments = 16;
constexpr int kMaxDrawSegments = 64;

/// The smallest n in [kMinDrawSegments, kMaxDrawSegments] with
/// max(radius_x, radius_y) (1 - cos(pi / n)) <= max_gap (kMaxDrawSegments when none is).
int drawSegments(const Ellipse& ellipse, double max_gap = kMaxDrawGap);

/// The n vertices of the inscribed polygon, counter-clockwise, the first at t = 0 (the end of the
/// ellipse's own x axis). n >= 3.
std::vector<Eigen::Vector2d> ellipsePolygon(const Ellipse& ellipse, int segments);

/// The vertices of ellipsePolygon(ellipse, drawSegments(ellipse)), the same bits, written to
/// `vertices` (room for kMaxDrawSegments); returns their count. Without an allocation: the
/// markers draw thousands of ellipses per cycle, and a vector per polygon was a tenth of that.
int drawnPolygonInto(const Ellipse& ellipse, Eigen::Vector2d* vertices);

/// The number of points the fan of `ellipse` has: 3 (drawSegments(ellipse) - 2).
std::size_t ellipseTrianglePoints(const Ellipse& ellipse);

/// Calls visit(point) for each point of the filled polygon of drawSegments(ellipse) vertices as a
/// fan from its first vertex: n - 2 triangles, three consecutive points each, counter-clockwise
/// (what rviz's TRIANGLE_LIST marker draws).
template <class Visit>
void forEachTrianglePoint(const Ellipse& ellipse, Visit&& visit) {
  std::array<Eigen::Vector2d, kMaxDrawSegments> vertices;
  const int n = drawnPolygonInto(ellipse, vertices.data());
  for (int i = 1; i + 1 < n; ++i) {
    visit(vertices[0]);
    visit(vertices[i]);
    visit(vertices[i + 1]);
  }
}

}  // namespace ellipse_collision::core

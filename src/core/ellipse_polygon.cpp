#include "ellipse_collision/core/ellipse_polygon.h"

#include <cmath>

namespace ellipse_collision::core {

int drawSegments(const Ellipse& ellipse, double max_gap) {
  const double radius = boundingRadius(ellipse);
  for (int n = kMinDrawSegments; n < kMaxDrawSegments; ++n) {
    if (radius * (1.0 - std::cos(M_PI / n)) <= max_gap) return n;
  }
  return kMaxDrawSegments;
}

std::vector<Eigen::Vector2d> ellipsePolygon(const Ellipse& ellipse, int segments) {
  const double c = std::cos(ellipse.angle);
  const double s = std::sin(ellipse.angle);
  std::vector<Eigen::Vector2d> vertices;
  vertices.reserve(static_cast<std::size_t>(segments));
  for (int i = 0; i < segments; ++i) {
    const double t = 2.0 * M_PI * i / segments;
    const double x = ellipse.radius_x * std::cos(t);
    const double y = ellipse.radius_y * std::sin(t);
    vertices.emplace_back(ellipse.center.x() + c * x - s * y, ellipse.center.y() + s * x + c * y);
  }
  return vertices;
}

std::size_t appendEllipseTriangles(const Ellipse& ellipse,
                                   std::vector<Eigen::Vector2d>& triangles) {
  const std::vector<Eigen::Vector2d> vertices = ellipsePolygon(ellipse, drawSegments(ellipse));
  const std::size_t before = triangles.size();
  for (std::size_t i = 1; i + 1 < vertices.size(); ++i) {
    triangles.push_back(vertices[0]);
    triangles.push_back(vertices[i]);
    triangles.push_back(vertices[i + 1]);
  }
  return triangles.size() - before;
}

}  // namespace ellipse_collision::core

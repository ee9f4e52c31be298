#include "ellipse_collision/core/ellipse_polygon.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ellipse_collision::core {

namespace {

/// The trigonometry of every polygon the markers draw, computed once (the same expressions, so the
/// same bits): a stream of changing obstacles redraws thousands of them per second, and their
/// sines and cosines were a tenth of the node's time.
struct DrawTables {
  /// sagitta[n] = 1 - cos(pi / n): the gap of an n-gon inscribed in the unit circle.
  std::array<double, kMaxDrawSegments + 1> sagitta{};
  /// unit[n][i] = (cos t, sin t), t = 2 pi i / n.
  std::array<std::vector<Eigen::Vector2d>, kMaxDrawSegments + 1> unit;

  DrawTables() {
    for (int n = 3; n <= kMaxDrawSegments; ++n) {
      sagitta[n] = 1.0 - std::cos(M_PI / n);
      unit[n].reserve(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) {
        const double t = 2.0 * M_PI * i / n;
        unit[n].emplace_back(std::cos(t), std::sin(t));
      }
    }
  }
};

const DrawTables& drawTables() {
  static const DrawTables tables;
  return tables;
}

/// Vertex i of the n-gon: centre + R(angle) (radius_x cos t, radius_y sin t), t = 2 pi i / n, the
/// one expression of ellipsePolygon() and drawnPolygonInto() (so the two give the same bits).
template <class Emit>
void polygonVertices(const Ellipse& ellipse, int segments, Emit&& emit) {
  const double c = std::cos(ellipse.angle);
  const double s = std::sin(ellipse.angle);
  const auto add = [&](double cos_t, double sin_t) {
    const double x = ellipse.radius_x * cos_t;
    const double y = ellipse.radius_y * sin_t;
    emit(Eigen::Vector2d(ellipse.center.x() + c * x - s * y, ellipse.center.y() + s * x + c * y));
  };
  if (segments >= 3 && segments <= kMaxDrawSegments) {
    for (const Eigen::Vector2d& direction : drawTables().unit[segments]) {
      add(direction.x(), direction.y());
    }
  } else {
    for (int i = 0; i < segments; ++i) {
      const double t = 2.0 * M_PI * i / segments;
      add(std::cos(t), std::sin(t));
    }
  }
}

}  // namespace

int drawSegments(const Ellipse& ellipse, double max_gap) {
  const double radius = boundingRadius(ellipse);
  const DrawTables& tables = drawTables();
  for (int n = kMinDrawSegments; n < kMaxDrawSegments; ++n) {
    if (radius * tables.sagitta[n] <= max_gap) return n;
  }
  return kMaxDrawSegments;
}

std::vector<Eigen::Vector2d> ellipsePolygon(const Ellipse& ellipse, int segments) {
  std::vector<Eigen::Vector2d> vertices;
  vertices.reserve(static_cast<std::size_t>(std::max(segments, 0)));
  polygonVertices(ellipse, segments, [&](const Eigen::Vector2d& v) { vertices.push_back(v); });
  return vertices;
}

int drawnPolygonInto(const Ellipse& ellipse, Eigen::Vector2d* vertices) {
  const int segments = drawSegments(ellipse);  // within [kMinDrawSegments, kMaxDrawSegments]
  polygonVertices(ellipse, segments, [&](const Eigen::Vector2d& v) { *vertices++ = v; });
  return segments;
}

std::size_t ellipseTrianglePoints(const Ellipse& ellipse) {
  return 3 * static_cast<std::size_t>(drawSegments(ellipse) - 2);
}

}  // namespace ellipse_collision::core

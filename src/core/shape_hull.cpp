#include "ellipse_collision/core/shape_hull.h"

#include <cmath>
#include <cstddef>

#include "link_points.h"

namespace ellipse_collision::core {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

/// Appends the circumscribed polygon of the disc {centre + radius (cos t u + sin t v)}.
void appendDisc(const Vec3& centre, const Vec3& u, const Vec3& v, double radius,
                std::vector<Vec3>& out) {
  const int n = kCirclePolygonVertices;
  const double reach = radius * (1.0 + kOutlineRoundingMargin) / std::cos(kPi / n);
  for (int k = 0; k < n; ++k) {
    const double phi = 2.0 * kPi * k / n;
    out.push_back(centre + reach * (std::cos(phi) * u + std::sin(phi) * v));
  }
}

/// Appends the sphere's grid (see kSphereGridLatitudes).
void appendSphere(const Vec3& centre, double radius, std::vector<Vec3>& out) {
  const int rings = kSphereGridLatitudes, longitudes = 2 * kSphereGridLatitudes;
  const double reach = radius * (1.0 + kOutlineRoundingMargin) / std::cos(kPi / rings);
  out.push_back(centre + reach * Vec3::UnitZ());
  out.push_back(centre - reach * Vec3::UnitZ());
  for (int k = 1; k < rings; ++k) {
    const double latitude = -0.5 * kPi + kPi * k / rings;
    for (int j = 0; j < longitudes; ++j) {
      const double longitude = 2.0 * kPi * j / longitudes;
      out.push_back(centre + reach * Vec3(std::cos(latitude) * std::cos(longitude),
                                          std::cos(latitude) * std::sin(longitude),
                                          std::sin(latitude)));
    }
  }
}

}  // namespace

HullPointsResult hullPoints(const CollisionShape& shape) {
  HullPointsResult result;
  result.error = invalidReason(shape);
  if (!result.ok()) return result;
  std::vector<Vec3>& out = result.points;
  detail::appendShapePoints(
      shape, [](const Vec3& p) { return p; },
      [&out](const Vec3& centre, const Vec3& u, const Vec3& v, double radius) {
        appendDisc(centre, u, v, radius, out);
      },
      [&out](const Vec3& centre, double radius) { appendSphere(centre, radius, out); }, out);
  return result;
}

HullPointsResult linkHullPoints(const std::vector<CollisionShape>& shapes) {
  return detail::linkPoints<HullPointsResult>(shapes, hullPoints);
}

EnclosingEllipsoid fitLinkEllipsoid(const std::vector<CollisionShape>& shapes) {
  const HullPointsResult hull = linkHullPoints(shapes);
  if (!hull.ok()) {
    EnclosingEllipsoid result;
    result.error = hull.error;
    return result;
  }
  return minimumVolumeEllipsoid(hull.points);
}

}  // namespace ellipse_collision::core

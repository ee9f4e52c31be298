#include "ellipse_collision/core/shape_outline.h"

#include <cmath>
#include <cstddef>
#include <optional>

#include "ellipse_collision/core/number_format.h"

#include "link_points.h"

namespace ellipse_collision::core {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

// A rotation whose columns are orthonormal to this tolerance is accepted; URDF origins are built
// from roll-pitch-yaw in double, so their error is ~1e-16, while anything else is a wrong input.
constexpr double kOrthonormalityTolerance = 1e-9;

/// "key = value must be > 0" / "... is not finite" for a length, or nothing.
std::optional<std::string> lengthError(const std::string& key, double value) {
  if (!std::isfinite(value)) return key + " = " + formatNumber(value) + " is not finite";
  if (!(value > 0.0)) return key + " = " + formatNumber(value) + " must be > 0";
  return std::nullopt;
}

std::optional<std::string> finiteError(const std::string& key, double value) {
  if (!std::isfinite(value)) return key + " = " + formatNumber(value) + " is not finite";
  return std::nullopt;
}

const char* const kAxes[] = {"x", "y", "z"};

std::string transformError(const Eigen::Isometry3d& t) {
  const Eigen::Matrix4d& m = t.matrix();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      if (!std::isfinite(m(r, c))) {
        return "link_from_shape(" + std::to_string(r) + ", " + std::to_string(c) +
               ") = " + formatNumber(m(r, c)) + " is not finite";
      }
    }
  }
  const double error = (t.linear().transpose() * t.linear() - Eigen::Matrix3d::Identity())
                           .cwiseAbs()
                           .maxCoeff();
  if (error > kOrthonormalityTolerance || t.linear().determinant() < 0.0) {
    return "link_from_shape: rotation is not orthonormal (deviation " + formatNumber(error) +
           ") or is a reflection";
  }
  return {};
}

/// The regular n-gon circumscribed about the unit circle, pushed out by the rounding margin, in
/// the disc's own coordinates.
const std::vector<Vec2>& unitPolygon() {
  static const std::vector<Vec2> polygon = [] {
    const int n = kCirclePolygonVertices;
    const double reach = (1.0 + kOutlineRoundingMargin) / std::cos(kPi / n);
    std::vector<Vec2> out;
    out.reserve(n);
    for (int k = 0; k < n; ++k) {
      const double phi = 2.0 * kPi * k / n;
      out.emplace_back(reach * std::cos(phi), reach * std::sin(phi));
    }
    return out;
  }();
  return polygon;
}

/// Appends the outline of the projected disc {centre + radius (cos t u + sin t v)}, u and v the
/// disc's orthonormal in-plane axes in the link frame: the affine image of the circumscribed
/// polygon, xy kept.
void appendDisc(const Vec3& centre, const Vec3& u, const Vec3& v, double radius,
                std::vector<Vec2>& out) {
  const Vec2 c = centre.head<2>();
  const Vec2 a = radius * u.head<2>(), b = radius * v.head<2>();
  for (const Vec2& p : unitPolygon()) out.push_back(c + p.x() * a + p.y() * b);
}

}  // namespace

std::string invalidReason(const CollisionShape& shape) {
  if (std::string error = transformError(shape.link_from_shape); !error.empty()) return error;
  std::optional<std::string> error;
  switch (shape.type) {
    case CollisionShape::Box:
      for (int i = 0; i < 3 && !error; ++i) {
        error = lengthError(std::string("box_size.") + kAxes[i], shape.box_size[i]);
      }
      break;
    case CollisionShape::Sphere:
      error = lengthError("radius", shape.radius);
      break;
    case CollisionShape::Cylinder:
      error = lengthError("radius", shape.radius);
      if (!error) error = lengthError("length", shape.length);
      break;
    case CollisionShape::Mesh:
      if (shape.mesh_vertices.empty()) return "mesh_vertices is empty";
      for (std::size_t k = 0; k < shape.mesh_vertices.size() && !error; ++k) {
        for (int i = 0; i < 3 && !error; ++i) {
          error = finiteError("mesh_vertices[" + std::to_string(k) + "]." + kAxes[i],
                              shape.mesh_vertices[k][i]);
        }
      }
      break;
    default:
      return "type = " + std::to_string(static_cast<int>(shape.type)) + " is not a shape type";
  }
  return error.value_or(std::string());
}

OutlineResult outlinePoints(const CollisionShape& shape) {
  OutlineResult result;
  result.error = invalidReason(shape);
  if (!result.ok()) return result;
  std::vector<Vec2>& out = result.points;
  detail::appendShapePoints(
      shape, [](const Vec3& p) -> Vec2 { return p.head<2>(); },
      [&out](const Vec3& centre, const Vec3& u, const Vec3& v, double radius) {
        appendDisc(centre, u, v, radius, out);
      },
      // The projection of a sphere is the disc of its radius in any orientation.
      [&out](const Vec3& centre, double radius) {
        appendDisc(centre, Vec3::UnitX(), Vec3::UnitY(), radius, out);
      },
      out);
  return result;
}

OutlineResult linkOutline(const std::vector<CollisionShape>& shapes) {
  return detail::linkPoints<OutlineResult>(shapes, outlinePoints);
}

EnclosingEllipse fitLinkEllipse(const std::vector<CollisionShape>& shapes) {
  const OutlineResult outline = linkOutline(shapes);
  if (!outline.ok()) {
    EnclosingEllipse result;
    result.status = EnclosingStatus::Error;
    result.error = outline.error;
    return result;
  }
  return minimumAreaEllipse(outline.points);
}

}  // namespace ellipse_collision::core

#pragma once

// The points of a link's collision shapes: the per-shape dispatch and the loop over a link's
// shapes, shared by the planar outline (shape_outline.cpp) and the 3D hull (shape_hull.cpp).
// Internal to the core (src/core).

#include <string>
#include <vector>

#include "ellipse_collision/core/shape_outline.h"

namespace ellipse_collision::core::detail {

/// The points of one valid `shape` appended to `out`: a box's 8 corners and a mesh's vertices
/// through `point(p)` (p in the link's frame), a cylinder's two end discs through
/// `disc(centre, u, v, radius)`, a sphere through `sphere(centre, radius)`. The outline and the
/// hull differ only in these: a point is projected or kept, a disc is a polygon of 2D or 3D
/// points, a sphere is a disc seen from above or a grid in 3D.
template <class Point, class PointOf, class DiscOf, class SphereOf>
void appendShapePoints(const CollisionShape& shape, const PointOf& point, const DiscOf& disc,
                       const SphereOf& sphere, std::vector<Point>& out) {
  using Vec3 = Eigen::Vector3d;
  const Eigen::Isometry3d& t = shape.link_from_shape;
  switch (shape.type) {
    case CollisionShape::Box: {
      const Vec3 half = 0.5 * shape.box_size;
      for (int corner = 0; corner < 8; ++corner) {
        out.push_back(point(t * Vec3((corner & 1) ? half.x() : -half.x(),
                                     (corner & 2) ? half.y() : -half.y(),
                                     (corner & 4) ? half.z() : -half.z())));
      }
      break;
    }
    case CollisionShape::Mesh:
      out.reserve(out.size() + shape.mesh_vertices.size());
      for (const Vec3& v : shape.mesh_vertices) out.push_back(point(t * v));
      break;
    case CollisionShape::Sphere:
      sphere(t.translation(), shape.radius);
      break;
    case CollisionShape::Cylinder: {
      const Vec3 u = t.linear().col(0), v = t.linear().col(1), axis = t.linear().col(2);
      for (const double side : {-0.5, 0.5}) {
        disc(t.translation() + side * shape.length * axis, u, v, shape.radius);
      }
      break;
    }
  }
}

/// `points_of(shape)` for every shape, concatenated; on the first refused shape nothing but its
/// error, as "shapes[i]: <error>". `Result` has `points`, `error` and ok().
template <class Result, class PointsOf>
Result linkPoints(const std::vector<CollisionShape>& shapes, PointsOf points_of) {
  Result result;
  if (shapes.empty()) {
    result.error = "shapes is empty";
    return result;
  }
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    Result one = points_of(shapes[i]);
    if (!one.ok()) {
      result.points.clear();
      result.error = "shapes[" + std::to_string(i) + "]: " + one.error;
      return result;
    }
    result.points.insert(result.points.end(), one.points.begin(), one.points.end());
  }
  return result;
}

}  // namespace ellipse_collision::core::detail

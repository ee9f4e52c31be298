#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "ellipse_collision/core/enclosing_ellipse.h"

namespace ellipse_collision::core {

/// One piece of a link's collision geometry, as a URDF <collision> element describes it, without
/// ROS types. Only the fields of its type are read.
struct CollisionShape {
  enum Type { Box, Cylinder, Sphere, Mesh };
  Type type{Box};
  /// Pose of the shape in the link frame (the URDF <origin>): rotation and translation [m].
  Eigen::Isometry3d link_from_shape{Eigen::Isometry3d::Identity()};
  /// Box: full edge lengths along the shape's x, y, z [m], each > 0.
  Eigen::Vector3d box_size{0.0, 0.0, 0.0};
  /// Sphere, Cylinder: radius [m], > 0.
  double radius{0.0};
  /// Cylinder: full length along the shape's z axis [m], > 0.
  double length{0.0};
  /// Mesh: vertices in the shape frame, already scaled [m]; at least one.
  std::vector<Eigen::Vector3d> mesh_vertices;
};

/// Vertices of the circumscribed polygons used for spheres and cylinder ends. The polygon's
/// vertices lie at 1 / cos(pi / n) of the radius, so each outline lies within its shape scaled by
/// 1 + eta, eta = 1 / cos(pi / n) - 1 = 7.4e-8, about its centre; the fitted ellipse's area then
/// exceeds the true minimum by at most (1 + 2 eta)^2 - 1 = 2.9e-7 (a point of the scaled shape is
/// s + eta (s - c) with s, c in the minimum ellipse E, and E - E = 2 (E - centre)).
constexpr int kCirclePolygonVertices = 8192;

/// Relative outward push of the polygon vertices beyond the tangent construction, so that the
/// rounding of their coordinates (a few ulps) cannot bring an edge inside the disc.
constexpr double kOutlineRoundingMargin = 1e-12;

/// Either the outline points or why there are none.
struct OutlineResult {
  std::vector<Eigen::Vector2d> points;  ///< [m], in the link frame's xy-plane
  std::string error;                    ///< names the field and its value; empty on success
  bool ok() const { return error.empty(); }
};

/// Why `shape` cannot be outlined ("radius = -1 must be > 0", "mesh_vertices[2].z = nan is not
/// finite", "link_from_shape: rotation is not orthonormal"), or an empty string.
std::string invalidReason(const CollisionShape& shape);

/// 2D points whose convex hull contains the orthographic projection of `shape` along the link
/// frame's z axis onto its xy-plane (link_from_shape applied, z dropped).
/// - Box: the 8 projected corners; Mesh: the projected vertices (both exact).
/// - Sphere: the regular kCirclePolygonVertices-gon circumscribed about the projected disc.
/// - Cylinder (axis along the shape's z, tilted by the rotation): the projection is the convex
///   hull of the two projected end discs, each an ellipse (a segment when the axis is
///   horizontal); each is outlined by the affine image of the circumscribed polygon of its disc,
///   which contains it (affine maps keep containment).
/// Rounding: box and mesh points are the vertices transformed in double (exact up to ~1e-16
/// relative); polygon vertices are pushed out by kOutlineRoundingMargin, so that their rounding
/// cannot bring an edge inside a disc whose projection is not thinner than ~1e-4 of its size.
OutlineResult outlinePoints(const CollisionShape& shape);

/// The outline points of every shape, concatenated; the error names the shape
/// ("shapes[1]: radius = -1 must be > 0"), or says that there is none.
OutlineResult linkOutline(const std::vector<CollisionShape>& shapes);

/// The link ellipse: minimumAreaEllipse() of linkOutline(). Error on an invalid shape or an empty
/// list; Degenerate when the projection spans no area (a vertical plate seen edge-on), in which
/// case enclosingEllipseWithMinRadius(linkOutline(shapes).points, r) gives a usable ellipse.
EnclosingEllipse fitLinkEllipse(const std::vector<CollisionShape>& shapes);

}  // namespace ellipse_collision::core

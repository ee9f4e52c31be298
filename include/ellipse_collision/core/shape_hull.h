#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ellipse_collision/core/enclosing_ellipsoid.h"
#include "ellipse_collision/core/shape_outline.h"

namespace ellipse_collision::core {

/// Spheres are enclosed by the points R v on a latitude-longitude grid of directions v with this
/// many latitude steps from pole to pole (and twice as many longitudes). Every direction lies
/// within theta = pi / kSphereGridLatitudes of a grid direction (half a step in latitude plus
/// half a step along the ring), so the hull of the points at R = r / cos(theta) contains the
/// ball: each supporting plane of the hull lies at >= R cos(theta) = r. The ellipsoid's radii
/// then exceed the sphere's minimum by at most 1 / cos(theta) - 1 = 7.5e-5.
constexpr int kSphereGridLatitudes = 256;

/// Either the 3D points or why there are none.
struct HullPointsResult {
  std::vector<Eigen::Vector3d> points;  ///< [m], in the link frame
  std::string error;                    ///< names the field and its value; empty on success
  bool ok() const { return error.empty(); }
};

/// 3D points whose convex hull contains `shape` in the link frame (link_from_shape applied):
/// - Box: the 8 corners; Mesh: the vertices (both exact).
/// - Cylinder: the two end discs' circumscribed regular kCirclePolygonVertices-gons (as the 2D
///   outline's, pushed out by kOutlineRoundingMargin): the prism between them contains the
///   cylinder, the convex hull of its end discs.
/// - Sphere: the grid of kSphereGridLatitudes described there.
HullPointsResult hullPoints(const CollisionShape& shape);

/// The hull points of every shape, concatenated; the error names the shape ("shapes[1]: radius =
/// -1 must be > 0"), or says that there is none.
HullPointsResult linkHullPoints(const std::vector<CollisionShape>& shapes);

/// The link ellipsoid: minimumVolumeEllipsoid() of linkHullPoints(): certified to contain every
/// vertex and every curved part. Error on an invalid shape, an empty list, or geometry spanning
/// no volume (a flat plate mesh: then fit the planar ellipse, fitLinkEllipse()).
EnclosingEllipsoid fitLinkEllipsoid(const std::vector<CollisionShape>& shapes);

}  // namespace ellipse_collision::core

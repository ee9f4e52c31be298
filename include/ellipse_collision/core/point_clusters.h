#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// The points of a planar laser scan (a sensor_msgs/LaserScan's fields) in the scanner's frame
/// [m], in beam order: beam i at angle angle_min + i angle_increment [rad] and range ranges[i]
/// [m] gives (r cos a, r sin a). A beam is skipped, never an error, when its range is NaN or
/// infinite, below max(range_min, 0) or above range_max [m] (a NaN limit skips every beam), above
/// kMaxCoordinate, or its angle is not finite.
std::vector<Eigen::Vector2d> scanPoints(const std::vector<float>& ranges, double angle_min,
                                        double angle_increment, double range_min,
                                        double range_max);

/// Splits points given in scan order into clusters: consecutive points closer than
/// `cluster_distance` [m] (strictly) belong to the same cluster, so a skipped beam inside an
/// object does not split it. No wrap-around: on a full 360° scan an object across the scan's
/// start is two clusters. Clusters with fewer than `min_cluster_points` points are dropped
/// (0 counts as 1). Non-finite points end a cluster and are dropped; a `cluster_distance` that is
/// not > 0 (or NaN) makes every point its own cluster. Each cluster keeps the scan order.
std::vector<std::vector<Eigen::Vector2d>> clusterPoints(
    const std::vector<Eigen::Vector2d>& ordered_points, double cluster_distance,
    std::size_t min_cluster_points);

/// Splits unordered points (a point cloud's, projected) into clusters by single linkage: two
/// points closer than `cluster_distance` [m] (strictly) are in the same cluster, and so are
/// chains of such points. Clusters come in the order of their first point, each keeping the
/// input order. Points not finite or beyond kMaxCoordinate are dropped; a `cluster_distance` that
/// is not > 0 and finite makes every point its own cluster (so do points more than 2^52 cluster
/// distances from the origin). Clusters with fewer than `min_cluster_points` points are dropped
/// (0 counts as 1). Cost: O(n) expected through a grid of cells of side `cluster_distance`, plus
/// the pairs of points in neighbouring cells.
std::vector<std::vector<Eigen::Vector2d>> clusterUnorderedPoints(
    const std::vector<Eigen::Vector2d>& points, double cluster_distance,
    std::size_t min_cluster_points);

/// One ellipse per cluster, each from enclosingEllipseWithMinRadius().
struct ClusterEllipses {
  std::vector<Ellipse> ellipses;  ///< in the points' frame, in cluster order
  /// Clusters that got no ellipse and why ("cluster 3: the enclosing ellipse is out of range:
  /// ..."), e.g. points beyond kMaxCoordinate; other clusters still get theirs.
  std::vector<std::string> skipped;
  /// Set, with no ellipses, when `min_radius` is invalid.
  std::string error;
};

/// clusterPoints(), then per cluster the enclosing ellipse with both radii >= `min_radius` [m]
/// (within [kMinRadius, kMaxRadius]): a cluster of one point is a circle of `min_radius`, two
/// points or a straight wall a thin ellipse along them.
ClusterEllipses clusterEllipses(const std::vector<Eigen::Vector2d>& ordered_points,
                                double cluster_distance, std::size_t min_cluster_points,
                                double min_radius);

/// The second half of clusterEllipses() for clusters formed otherwise (clusterUnorderedPoints()):
/// per cluster the enclosing ellipse with both radii >= `min_radius` [m].
ClusterEllipses fitClusters(const std::vector<std::vector<Eigen::Vector2d>>& clusters,
                            double min_radius);

}  // namespace ellipse_collision::core

#include "ellipse_collision/core/point_clusters.h"

#include <algorithm>
#include <cmath>

#include "ellipse_collision/core/enclosing_ellipse.h"

namespace ellipse_collision::core {

std::vector<Eigen::Vector2d> scanPoints(const std::vector<float>& ranges, double angle_min,
                                        double angle_increment, double range_min,
                                        double range_max) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(ranges.size());
  const double lowest = std::max(range_min, 0.0);
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double r = ranges[i];
    // Written so that NaN ranges and NaN limits fail the test.
    if (!(std::isfinite(r) && r >= lowest && r <= range_max && r <= kMaxCoordinate)) continue;
    const double angle = angle_min + static_cast<double>(i) * angle_increment;
    if (!std::isfinite(angle)) continue;
    points.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return points;
}

std::vector<std::vector<Eigen::Vector2d>> clusterPoints(
    const std::vector<Eigen::Vector2d>& ordered_points, double cluster_distance,
    std::size_t min_cluster_points) {
  const std::size_t minimum = std::max<std::size_t>(min_cluster_points, 1);
  std::vector<std::vector<Eigen::Vector2d>> clusters;
  std::vector<Eigen::Vector2d> current;
  const auto close = [&] {
    if (current.size() >= minimum) clusters.push_back(std::move(current));
    current.clear();
  };
  for (const Eigen::Vector2d& p : ordered_points) {
    if (!p.allFinite()) {
      close();
      continue;
    }
    // Squared distances: no square root per point; NaN distance never joins.
    if (!current.empty() &&
        !((p - current.back()).squaredNorm() < cluster_distance * cluster_distance &&
          cluster_distance > 0.0)) {
      close();
    }
    current.push_back(p);
  }
  close();
  return clusters;
}

ClusterEllipses clusterEllipses(const std::vector<Eigen::Vector2d>& ordered_points,
                                double cluster_distance, std::size_t min_cluster_points,
                                double min_radius) {
  ClusterEllipses result;
  if (radiusViolation(min_radius)) {
    // The same words as enclosingEllipseWithMinRadius(), which checks it the same way.
    result.error = enclosingEllipseWithMinRadius({Eigen::Vector2d::Zero()}, min_radius).error;
    return result;
  }
  const auto clusters = clusterPoints(ordered_points, cluster_distance, min_cluster_points);
  result.ellipses.reserve(clusters.size());
  for (std::size_t i = 0; i < clusters.size(); ++i) {
    const EnclosingEllipse fit = enclosingEllipseWithMinRadius(clusters[i], min_radius);
    if (fit.ok()) {
      result.ellipses.push_back(fit.ellipse);
    } else {
      result.skipped.push_back("cluster " + std::to_string(i) + ": " + fit.error);
    }
  }
  return result;
}

}  // namespace ellipse_collision::core

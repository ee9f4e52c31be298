#include "ellipse_collision/core/point_clusters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "ellipse_collision/core/enclosing_ellipse.h"
#include "ellipse_collision/core/scan_contours.h"

namespace ellipse_collision::core {

std::vector<Eigen::Vector2d> scanPoints(const std::vector<float>& ranges, double angle_min,
                                        double angle_increment, double range_min,
                                        double range_max) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(ranges.size());
  for (const SensorReturn& r :
       scanView(ranges, angle_min, angle_increment, range_min, range_max, 0.0).returns) {
    points.push_back(r.point);
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

std::vector<std::vector<Eigen::Vector2d>> clusterUnorderedPoints(
    const std::vector<Eigen::Vector2d>& points, double cluster_distance,
    std::size_t min_cluster_points) {
  const std::size_t minimum = std::max<std::size_t>(min_cluster_points, 1);
  std::vector<Eigen::Vector2d> kept;
  kept.reserve(points.size());
  for (const Eigen::Vector2d& p : points) {
    if (p.allFinite() && coordinateOk(p.x()) && coordinateOk(p.y())) kept.push_back(p);
  }
  const bool joins = cluster_distance > 0.0 && std::isfinite(cluster_distance);
  // Grid of cells of side cluster_distance: points closer than that lie in the same or adjacent
  // cells, so each point is compared with the points of 9 cells only. Cell indices beyond
  // +-2^52 (coordinates over 2^52 cluster distances) are not representable: such points stay
  // alone.
  constexpr double kMaxCell = 4503599627370496.0;  // 2^52
  const auto cellOf = [&](const Eigen::Vector2d& p, std::int64_t& cx, std::int64_t& cy) {
    const double fx = std::floor(p.x() / cluster_distance), fy = std::floor(p.y() / cluster_distance);
    if (!(std::abs(fx) < kMaxCell && std::abs(fy) < kMaxCell)) return false;
    cx = static_cast<std::int64_t>(fx);
    cy = static_cast<std::int64_t>(fy);
    return true;
  };
  const auto key = [](std::int64_t cx, std::int64_t cy) {
    return static_cast<std::uint64_t>(cx) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(cy);
  };
  std::vector<std::size_t> parent(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) parent[i] = i;
  const auto root = [&parent](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  if (joins) {
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
    std::vector<std::array<std::int64_t, 2>> cell_of(kept.size());
    std::vector<bool> gridded(kept.size(), false);
    for (std::size_t i = 0; i < kept.size(); ++i) {
      std::int64_t cx = 0, cy = 0;
      if (!cellOf(kept[i], cx, cy)) continue;
      gridded[i] = true;
      cell_of[i] = {cx, cy};
      cells[key(cx, cy)].push_back(i);
    }
    const double limit = cluster_distance * cluster_distance;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (!gridded[i]) continue;
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          const auto cell = cells.find(key(cell_of[i][0] + dx, cell_of[i][1] + dy));
          if (cell == cells.end()) continue;
          for (const std::size_t j : cell->second) {
            // Different cells may share a hash key: the distance test decides anyway.
            if (j <= i || (kept[i] - kept[j]).squaredNorm() >= limit) continue;
            const std::size_t a = root(i), b = root(j);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
          }
        }
      }
    }
  }
  // Clusters in the order of their first point, points in input order.
  std::vector<std::vector<Eigen::Vector2d>> clusters;
  std::unordered_map<std::size_t, std::size_t> cluster_of_root;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const auto [it, added] = cluster_of_root.emplace(root(i), clusters.size());
    if (added) clusters.emplace_back();
    clusters[it->second].push_back(kept[i]);
  }
  clusters.erase(std::remove_if(clusters.begin(), clusters.end(),
                                [&](const auto& c) { return c.size() < minimum; }),
                 clusters.end());
  return clusters;
}

ClusterEllipses clusterEllipses(const std::vector<Eigen::Vector2d>& ordered_points,
                                double cluster_distance, std::size_t min_cluster_points,
                                double min_radius) {
  return fitClusters(clusterPoints(ordered_points, cluster_distance, min_cluster_points),
                     min_radius);
}

ClusterEllipses fitClusters(const std::vector<std::vector<Eigen::Vector2d>>& clusters,
                            double min_radius) {
  ClusterEllipses result;
  if (radiusViolation(min_radius)) {
    // The same words as enclosingEllipseWithMinRadius(), which checks it the same way.
    result.error = enclosingEllipseWithMinRadius({Eigen::Vector2d::Zero()}, min_radius).error;
    return result;
  }
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

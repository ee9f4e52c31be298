#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/field_error.h"

namespace ellipse_collision::app {

/// scan_obstacles' parameters (README: scan_obstacles; config in launch/scan_obstacles.launch).
struct ScanObstacleSettings {
  double cluster_distance{0.1};  ///< points closer than this join one cluster [m]
  int min_cluster_points{3};     ///< smaller clusters are dropped (noise)
  double min_radius{0.05};       ///< both radii of every ellipse at least this [m]
  /// Cloud points are used when z_min <= z <= z_max, z in the cloud's frame [m] (costmap_2d's
  /// obstacle layer defaults: from the ground to 2 m).
  double z_min{0.0};
  double z_max{2.0};
  std::string name_prefix{"scan_"};  ///< ellipse i is named name_prefix + i
};

/// Accepted ranges (refused, never clamped): cluster_distance within [kMinClusterDistance,
/// kMaxClusterDistance]; min_cluster_points within [1, kMaxClusterPoints]; min_radius within
/// [core::kMinRadius, core::kMaxRadius]; z_min, z_max finite with z_min <= z_max; name_prefix
/// non-empty.
constexpr double kMinClusterDistance = 1e-6;  ///< [m]
constexpr double kMaxClusterDistance = 1e3;   ///< [m]
constexpr int kMaxClusterPoints = 1000000;

/// The first setting outside its range, naming its key, or nothing.
std::optional<FieldError> findInvalidSetting(const ScanObstacleSettings& settings);

/// Obstacle ellipses of one sensor message, in the sensor's frame.
struct SensorObstacles {
  std::vector<EllipseSpec> ellipses;  ///< names name_prefix + index, frame_id = the sensor frame
  std::vector<std::string> skipped;   ///< clusters that got no ellipse, and why
};

/// A laser scan (sensor_msgs/LaserScan's fields, angles [rad], ranges [m]): its points
/// (core::scanPoints(): NaN, inf and out-of-range beams skipped) clustered in beam order
/// (core::clusterPoints()), each cluster enclosed by the minimum-area ellipse with both radii >=
/// min_radius (core::fitClusters()). `settings` must pass findInvalidSetting().
SensorObstacles scanObstacles(const std::vector<float>& ranges, double angle_min,
                              double angle_increment, double range_min, double range_max,
                              const std::string& frame_id, const ScanObstacleSettings& settings);

/// A point cloud's points [m] (x, y, z in the cloud's frame, any order): those with z within
/// [z_min, z_max] projected onto the xy-plane, clustered by single linkage
/// (core::clusterUnorderedPoints()) and enclosed like scanObstacles().
SensorObstacles cloudObstacles(const std::vector<Eigen::Vector3f>& points,
                               const std::string& frame_id, const ScanObstacleSettings& settings);

}  // namespace ellipse_collision::app

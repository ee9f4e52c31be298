#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_spec.h"
#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/core/scan_contours.h"

namespace ellipse_collision::app {

/// scan_obstacles' parameters (README: scan_obstacles; config in launch/scan_obstacles.launch).
struct ScanObstacleSettings {
  /// Scans: consecutive returns closer than this always join one contour (beside the adaptive
  /// breakpoint rule, core::sameContour()); clouds: the single-linkage distance [m].
  double cluster_distance{0.1};
  /// The noise rule: contours (scans) or clusters (clouds) of fewer returns are dropped. 1 keeps
  /// every return (a thin pole seen by one beam is an obstacle).
  int min_cluster_points{1};
  /// Both radii of every ellipse at least this [m], except a single return whose circle of
  /// min_radius would enter the free space (core::contourEllipses()).
  double min_radius{0.05};
  /// The sensor's range noise, one standard deviation [m]: the breakpoint rule allows 3 sigma.
  double range_noise_sigma{0.01};
  /// No ellipse enters a beam's free part, from range_min to the return minus this [m] (or to
  /// range_max for a beam without return).
  double free_space_tolerance{0.1};
  /// Cloud points are used when z_min <= z <= z_max, z in the cloud's frame [m] (costmap_2d's
  /// obstacle layer defaults: from the ground to 2 m).
  double z_min{0.0};
  double z_max{2.0};
  std::string name_prefix{"scan_"};  ///< ellipse i is named name_prefix + i
};

/// Accepted ranges (refused, never clamped): cluster_distance within [kMinClusterDistance,
/// kMaxClusterDistance]; min_cluster_points within [1, kMaxClusterPoints]; min_radius within
/// [core::kMinRadius, core::kMaxRadius]; range_noise_sigma within [0, kMaxRangeNoiseSigma];
/// free_space_tolerance within [kMinFreeSpaceTolerance, kMaxFreeSpaceTolerance] (> 0: a return's
/// own beam must leave room for an ellipse around it); z_min, z_max finite with z_min <= z_max;
/// name_prefix non-empty.
constexpr double kMinClusterDistance = 1e-6;  ///< [m]
constexpr double kMaxClusterDistance = 1e3;   ///< [m]
constexpr int kMaxClusterPoints = 1000000;
constexpr double kMaxRangeNoiseSigma = 1.0;        ///< [m]
constexpr double kMinFreeSpaceTolerance = 1e-3;    ///< [m]
constexpr double kMaxFreeSpaceTolerance = 10.0;    ///< [m]

/// The first setting outside its range, naming its key, or nothing.
std::optional<FieldError> findInvalidSetting(const ScanObstacleSettings& settings);

/// The keys from `first` to `last` (the returns' keys: beams or angular bins) of one ellipse,
/// going round a ring of keys: last < first when the run crosses the scan's start.
struct KeySpan {
  std::size_t first{0};
  std::size_t last{0};
};

/// One contour (scans) or cluster (clouds) the ellipses were cut from: one thing the sensor sees,
/// what ObstacleTracker follows from message to message.
struct SensorObject {
  Eigen::Vector2d centroid{0.0, 0.0};  ///< mean of its returns, sensor frame [m]
  double extent{0.0};                  ///< farthest return from the centroid [m]
  std::vector<std::size_t> ellipses;   ///< indices into SensorObstacles::ellipses
  /// Scans: a beam beside either end returns nearer (by more than cluster_distance) or unknown
  /// (NaN): something in front may hide part of it, so its centroid moves as the view does.
  bool occluded{false};
};

/// Obstacle ellipses of one sensor message, in the sensor's frame.
struct SensorObstacles {
  /// Names: name_prefix + the key of the ellipse's first return (scans: its beam index, so a
  /// name stays while the scene does; clouds: its angular bin, + "_" + n for the n-th further
  /// ellipse starting in the same bin); frame_id = the sensor frame.
  std::vector<EllipseSpec> ellipses;
  std::vector<std::string> skipped;   ///< clusters that got no ellipse, and why
  /// The keys each ellipse covers (same order as `ellipses`), on a ring of `key_ring` keys (a
  /// full turn's scan may start a run near its last beam and end it near its first): what
  /// ScanNameKeeper matches from one message to the next.
  std::vector<KeySpan> spans;
  std::size_t key_ring{1};  ///< scans: the number of beams; clouds: core::kCloudBins
  /// The split hints this message did not need (core::ContourEllipses::unneeded_hints).
  std::vector<std::size_t> unneeded_hints;
  /// The contours or clusters, each with the ellipses cut from it (every ellipse in one).
  std::vector<SensorObject> objects;
};

/// A laser scan (sensor_msgs/LaserScan's fields, angles [rad], ranges [m]): its returns and
/// free beams (core::scanView()), cut into contours by the adaptive breakpoint rule
/// (core::breakContours()), each contour split into as few ellipses as keep every return inside
/// and the free space free (core::contourEllipses(), cut first where `split_hints` say:
/// ScanCutMemory). `settings` must pass findInvalidSetting().
SensorObstacles scanObstacles(const std::vector<float>& ranges, double angle_min,
                              double angle_increment, double range_min, double range_max,
                              const std::string& frame_id, const ScanObstacleSettings& settings,
                              const std::vector<std::size_t>& split_hints = {});

/// What scanObstacles() keeps from one scan of a sensor to the next: the beams' trigonometry
/// (core::ScanBeams) and the storage of the scan's view. The output is the same with fresh ones.
struct ScanBuffers {
  core::ScanBeams beams;
  core::SensorView view;
};

/// scanObstacles() reusing `buffers` (SensorObstacleSeries keeps one per sensor).
SensorObstacles scanObstacles(const std::vector<float>& ranges, double angle_min,
                              double angle_increment, double range_min, double range_max,
                              const std::string& frame_id, const ScanObstacleSettings& settings,
                              const std::vector<std::size_t>& split_hints, ScanBuffers& buffers);

/// A point cloud's points [m] (x, y, z in the cloud's frame, any order): those with z within
/// [z_min, z_max] projected onto the xy-plane (core::cloudView(): the rays from the frame's
/// origin to each bin's nearest point are the free space), clustered by single linkage
/// (core::cloudContours()) and split into ellipses like scanObstacles().
SensorObstacles cloudObstacles(const std::vector<Eigen::Vector3f>& points,
                               const std::string& frame_id, const ScanObstacleSettings& settings,
                               const std::vector<std::size_t>& split_hints = {});

}  // namespace ellipse_collision::app

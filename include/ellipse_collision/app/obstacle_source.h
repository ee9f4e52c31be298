#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/app/obstacle_tracker.h"
#include "ellipse_collision/app/scan_obstacles.h"

namespace ellipse_collision::app {

/// What a source's messages are: ellipses as they are (ellipse_collision/EllipseArray); a laser
/// scan (sensor_msgs/LaserScan) or a point cloud (sensor_msgs/PointCloud2) turned into ellipses
/// by the scan_obstacles pipeline; a sonar or IR reading (sensor_msgs/Range, rangeObstacles());
/// the other robots of the fleet (ellipse_collision/EllipseArray footprints, FleetRoster).
enum class SourceType { Ellipses, Scan, Cloud, Range, Robots };

/// "ellipses", "scan", "cloud", "range" or "robots", as the `type` key spells them.
const char* toString(SourceType type);
/// The type `text` names, or a FieldError of key `key`.
std::optional<FieldError> parseSourceType(const std::string& text, const std::string& key,
                                          SourceType* type);

/// One entry of the node's `sources`: a stream of obstacles whose messages replace only its own
/// obstacles, with its own freshness watchdog.
struct SourceSpec {
  std::string name;  ///< [A-Za-z0-9_]+; its obstacles are named "<name>/<obstacle name>"
  SourceType type{SourceType::Ellipses};
  std::string topic;  ///< resolved in the node's namespace ("~x": private)
  /// Silent for longer than this [s] makes answers incomplete and the gate INCOMPLETE;
  /// 0 = no watchdog. Type robots: a robot silent for longer is dropped (> 0, default
  /// kDefaultRobotsTimeoutS), and the source is watched only when `required`.
  double timeout_s{0.0};
  /// Type robots only: no footprint from any robot for `timeout_s` makes answers incomplete
  /// (a fleet that must be there); otherwise robots come and go freely.
  bool required{false};
  /// Type robots only: [m] added to the padding of every other robot's link, within
  /// [0, kMaxRobotsPaddingM]. Their velocities are straight lines from their stamps; a robot that
  /// turns, brakes or swings an arm strays from that line, by about a t^2 / 2 after t [s] at an
  /// acceleration a: this is the room left for it.
  double padding_m{0.0};
  /// The pipeline's settings (types scan and cloud; range uses min_radius alone).
  ScanObstacleSettings scan;
  /// Types scan and cloud: the obstacles' velocities (ObstacleTracker); the node's fixed_frame
  /// unless the entry's `tracking/fixed_frame` says otherwise.
  TrackingSettings tracking;
};

/// The default source every node has: ~obstacles, no watchdog (obstacle_timeout drops its
/// obstacles instead), obstacle names as they come. Listed sources may not reuse its name or
/// topic.
inline constexpr const char* kDefaultSourceName = "obstacles";
inline constexpr double kMaxSourceTimeoutS = 3600.0;  ///< timeout within [0, kMaxSourceTimeoutS]
inline constexpr double kDefaultRobotsTimeoutS = 1.0;  ///< a robots source's timeout unless given
inline constexpr double kMaxRobotsPaddingM = 10.0;     ///< a robots source's padding within [0, it]

/// The first violation of the source list's rules, its key naming the entry ("sources[1].topic"):
/// name non-empty of [A-Za-z0-9_] and used once (kDefaultSourceName included); topic non-empty
/// and used once ("obstacles" and "~obstacles" are the default source's); timeout finite within
/// [0, kMaxSourceTimeoutS] (> 0 for type robots); `required` and `padding` (within
/// [0, kMaxRobotsPaddingM]) on type robots only; a scan, cloud
/// or range source's settings pass findInvalidSetting().
std::optional<FieldError> findInvalidSources(const std::vector<SourceSpec>& sources);

/// Whether the source's silence makes answers incomplete (SourceFreshness): every source but a
/// robots source that is not `required` (robots that leave are normal).
bool watchesSilence(const SourceSpec& source);

/// The name an obstacle of source `source` is stored under: "<source>/<obstacle>", so that two
/// sources (two scanners both naming their ellipses scan_0, ...) never claim the same name.
std::string sourceObstacleName(const std::string& source, const std::string& obstacle);

}  // namespace ellipse_collision::app

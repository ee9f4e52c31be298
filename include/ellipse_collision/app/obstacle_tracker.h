#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/app/scan_obstacles.h"
#include "ellipse_collision/core/path_motion.h"

namespace ellipse_collision::app {

/// How one sensor's obstacles are tracked from message to message (doc/tracking.md).
struct TrackingSettings {
  bool enabled{true};
  /// The tf frame the tracks live in: one that stands in the world (the sensor's own motion is
  /// taken out through tf).
  std::string fixed_frame{"odom"};
  /// The fastest obstacle followed [m/s]: a centre is associated with a track only within
  /// max_speed times the time since the track was seen, plus kAssociationSlack.
  double max_speed{3.0};
  /// Objects (a contour or cluster) whose returns reach farther than this from their centroid [m]
  /// are never tracked and stand: the centroid of a wall slides as the robot sees another part.
  double max_size{0.8};
  /// A track's velocity is used once it has been seen this many times.
  int confirm_count{8};
  /// A velocity below this [m/s] (or within 3 standard deviations of 0) is reported as 0.
  double min_speed{0.1};
  /// One standard deviation of a measured centre [m]: range noise and the fit's jitter.
  double position_sigma{0.03};
};

/// Accepted: fixed_frame a tf frame id (non-empty, no leading '/'), max_speed within
/// (0, core::kMaxSpeed], max_size within (0, core::kMaxRadius], confirm_count within [2, 1000],
/// min_speed within [0, max_speed], position_sigma within (0, 1]. The first key outside (as
/// "tracking/max_speed"), or nothing.
std::optional<FieldError> findInvalidSetting(const TrackingSettings& settings);

/// Every obstacle of `obstacles` stands (vx = vy = angular_velocity = 0): what a sensor's
/// obstacles say when tracking is off, or when its motion through the fixed frame is unknown.
void standStill(SensorObstacles& obstacles);

/// Velocities for one sensor's obstacles, tracked in the fixed frame so the sensor's own motion
/// is taken out. What is tracked is each object (SensorObject: the contour or cluster the
/// ellipses were cut from), measured by the centroid of its returns, which range noise and a
/// contour cut anew barely move: each message's centroids are placed in the fixed frame through
/// the sensor's pose, associated with the tracks (nearest predicted centroid first, within the
/// gate), and each track's velocity is the least-squares slope of its centroids over the last
/// kWindowS, with a standard deviation from their spread about that line (at least
/// position_sigma). Every ellipse of the object gets its velocity. The rule that keeps a weak
/// estimate from reporting motion: a velocity is used only when its track was seen
/// confirm_count times, and the speed is at least min_speed and 3 standard deviations;
/// otherwise the object stands (vx = vy = 0). While the sensor moves, the part of an object it
/// sees turns with the direction it is seen from, and so does the centroid of its returns, at up
/// to extent times that direction's rate of turn: a speed within that drift is not reported
/// either. Objects larger than max_size, and scan contours a nearer return may hide in part
/// (SensorObject::occluded), are not tracked and stand. A thing that moves is thus predicted
/// standing until its track is confirmed (0.2 s at 40 Hz), and what stands is not predicted moving
/// by noise.
class ObstacleTracker {
 public:
  /// [m] a centroid may jump this far beyond max_speed * dt (a contour that gains or loses an end).
  static constexpr double kAssociationSlack = 0.15;
  /// [s] the centroids a velocity is fitted to: long enough to average range noise, short enough
  /// that a cart starting to roll is seen within half a second.
  static constexpr double kWindowS = 0.4;
  /// [s] a track unseen this long is dropped.
  static constexpr double kMaxUnseenS = 0.5;

  /// `settings` must pass findInvalidSetting().
  explicit ObstacleTracker(TrackingSettings settings) : settings_(std::move(settings)) {}

  /// Sets vx, vy (in the axes of their frame, the sensor's) and angular_velocity 0 of each ellipse
  /// of `obstacles`, the message stamped `stamp_s` [s], seen from `sensor` (the sensor frame's
  /// pose in the fixed frame at that stamp; pose.time unused). A stamp not after the last one
  /// starts afresh (a bag looped, time jumped back). With tracking disabled every ellipse stands.
  void track(double stamp_s, const core::PathPose& sensor, SensorObstacles& obstacles);

  std::size_t trackCount() const { return tracks_.size(); }
  const TrackingSettings& settings() const { return settings_; }

 private:
  struct Sample {
    double t;
    Eigen::Vector2d centre;  ///< in the fixed frame [m]
  };
  struct Fit {
    Eigen::Vector2d velocity{0.0, 0.0};  ///< [m/s] fixed frame
    double sigma{0.0};                   ///< standard deviation of each component [m/s]
  };
  struct Track {
    std::vector<Sample> samples;  ///< within kWindowS of the last, oldest first
    int updates{0};               ///< measurements so far
  };
  /// Drops the samples older than kWindowS before `stamp_s` [s].
  static void keepWindow(std::vector<Sample>& samples, double stamp_s);
  /// The track's velocity, fitted to its samples (zero and infinite sigma with fewer than 2).
  Fit fit(const Track& track) const;
  /// Small enough, and not partly hidden (its centroid would move with the view): tracked.
  bool trackable(const SensorObject& object) const;
  /// The velocity to put on an obstacle of `track` (fixed frame), by the rule above; `drift` [m/s]
  /// is how fast the view alone may move its centroid.
  Eigen::Vector2d reportedVelocity(const Track& track, const Fit& fit, double drift) const;

  TrackingSettings settings_;
  std::vector<Track> tracks_;
  std::vector<Sample> sensor_;  ///< the sensor's positions within kWindowS (fixed frame)
  std::optional<double> last_stamp_s_;
};

}  // namespace ellipse_collision::app

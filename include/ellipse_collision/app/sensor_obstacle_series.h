#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "ellipse_collision/app/obstacle_tracker.h"
#include "ellipse_collision/app/scan_cut_memory.h"
#include "ellipse_collision/app/scan_name_keeper.h"
#include "ellipse_collision/app/scan_obstacles.h"

namespace ellipse_collision::app {

/// One sensor's messages in turn, as scan_obstacles handles them: each scan is cut first where
/// the last scans cut it (ScanCutMemory), and names are carried over from message to message
/// (ScanNameKeeper), so that a scene that stays keeps its ellipses and names under range noise.
/// Clouds keep their names; their cuts are not carried over (a cloud's bins and clusters are not
/// ordered beams). track() then puts each object's velocity on its ellipses (ObstacleTracker).
class SensorObstacleSeries {
 public:
  /// `settings` and `tracking` must pass findInvalidSetting().
  explicit SensorObstacleSeries(ScanObstacleSettings settings, TrackingSettings tracking = {})
      : settings_(std::move(settings)), scan_tracker_(tracking), cloud_tracker_(tracking) {}

  /// scanObstacles() of the next scan (sensor_msgs/LaserScan's fields).
  SensorObstacles scan(const std::vector<float>& ranges, double angle_min,
                       double angle_increment, double range_min, double range_max,
                       const std::string& frame_id);

  /// cloudObstacles() of the next cloud.
  SensorObstacles cloud(const std::vector<Eigen::Vector3f>& points, const std::string& frame_id);

  /// The velocities of `obstacles` (the last scan's or cloud's, stamped `stamp_s` [s], seen from
  /// the sensor's pose `sensor` in tracking().fixed_frame): ObstacleTracker::track(), scans and
  /// clouds each with their own tracks.
  void trackScan(double stamp_s, const core::PathPose& sensor, SensorObstacles& obstacles) {
    scan_tracker_.track(stamp_s, sensor, obstacles);
  }
  void trackCloud(double stamp_s, const core::PathPose& sensor, SensorObstacles& obstacles) {
    cloud_tracker_.track(stamp_s, sensor, obstacles);
  }

  const ScanObstacleSettings& settings() const { return settings_; }
  const TrackingSettings& tracking() const { return scan_tracker_.settings(); }

 private:
  ScanObstacleSettings settings_;
  ObstacleTracker scan_tracker_;
  ObstacleTracker cloud_tracker_;
  ScanCutMemory scan_splits_;
  ScanBuffers scan_buffers_;  ///< the beams' trigonometry and the view's storage, reused
  ScanNameKeeper scan_names_;
  ScanNameKeeper cloud_names_;
};

}  // namespace ellipse_collision::app

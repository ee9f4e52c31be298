#include "ellipse_collision/app/sensor_obstacle_series.h"

namespace ellipse_collision::app {

SensorObstacles SensorObstacleSeries::scan(const std::vector<float>& ranges, double angle_min,
                                           double angle_increment, double range_min,
                                           double range_max, const std::string& frame_id) {
  SensorObstacles obstacles = scanObstacles(
      ranges, angle_min, angle_increment, range_min, range_max, frame_id, settings_,
      scan_splits_.hints(ranges, frame_id, settings_.range_noise_sigma), scan_buffers_);
  scan_splits_.update(obstacles, ranges);
  scan_names_.rename(obstacles);
  return obstacles;
}

SensorObstacles SensorObstacleSeries::cloud(const std::vector<Eigen::Vector3f>& points,
                                            const std::string& frame_id) {
  SensorObstacles obstacles = cloudObstacles(points, frame_id, settings_);
  cloud_names_.rename(obstacles);
  return obstacles;
}

}  // namespace ellipse_collision::app

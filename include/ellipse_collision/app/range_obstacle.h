#pragma once

#include <optional>
#include <string>

#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/app/scan_obstacles.h"

namespace ellipse_collision::app {

/// One reading of a sonar or IR ranger (sensor_msgs/Range's fields) in its frame: the cone
/// points along the frame's x axis.
struct RangeReading {
  double range{0.0};          ///< [m]; +inf = nothing in range, -inf = something too close
  double min_range{0.0};      ///< [m]
  double max_range{0.0};      ///< [m]
  double field_of_view{0.0};  ///< the cone's full angle [rad]
  std::string frame_id;
};

/// The name of a range reading's one obstacle (a `range` source stores it as "<source>/range").
inline constexpr const char* kRangeObstacleName = "range";

/// The obstacle of one reading: none when the reading is free (+inf, or at or beyond max_range);
/// otherwise one ellipse, named kRangeObstacleName, covering the cone's arc at the measured range
/// (a reading below min_range, or -inf, at min_range): the smallest ellipse around the arc's
/// bounding box, each radius at least `min_radius` [m]. Refuses (nothing in `out`) a NaN range,
/// a field_of_view outside (0, pi], min_range not finite or negative, max_range not finite or
/// not above min_range, naming the field and value.
std::optional<FieldError> rangeObstacles(const RangeReading& reading, double min_radius,
                                         SensorObstacles* out);

}  // namespace ellipse_collision::app

#include "ellipse_collision/app/range_obstacle.h"

#include <algorithm>
#include <cmath>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

std::optional<FieldError> rangeObstacles(const RangeReading& reading, double min_radius,
                                         SensorObstacles* out) {
  *out = SensorObstacles();
  if (!(reading.field_of_view > 0.0 && reading.field_of_view <= M_PI)) {
    return FieldError{"field_of_view", "a number within (0, pi] [rad]",
                      core::formatNumber(reading.field_of_view)};
  }
  if (!(std::isfinite(reading.min_range) && reading.min_range >= 0.0)) {
    return FieldError{"min_range", "a finite number >= 0", core::formatNumber(reading.min_range)};
  }
  if (!(std::isfinite(reading.max_range) && reading.max_range > reading.min_range)) {
    return FieldError{"max_range",
                      "a finite number > min_range = " + core::formatNumber(reading.min_range),
                      core::formatNumber(reading.max_range)};
  }
  if (std::isnan(reading.range)) return FieldError{"range", "a number or +-inf", "nan"};
  // REP 117: +inf is nothing within max_range; a reading at max_range is the same.
  if (reading.range >= reading.max_range) return std::nullopt;
  // Too close (-inf, or below min_range): something is there, at least as near as min_range.
  const double r = std::max(reading.range, reading.min_range);
  // The arc {r (cos t, sin t) : |t| <= h} lies in the box x in [r cos h, r], |y| <= r sin h;
  // the smallest ellipse around a box of half-sizes (w, v) has semi-axes sqrt(2) (w, v).
  const double h = reading.field_of_view / 2.0;
  const double w = r * (1.0 - std::cos(h)) / 2.0;
  const double v = r * std::sin(h);
  EllipseSpec spec;
  spec.name = kRangeObstacleName;
  spec.frame_id = reading.frame_id;
  spec.x = r * (1.0 + std::cos(h)) / 2.0;
  spec.radius_x = std::max(std::sqrt(2.0) * w, min_radius);
  spec.radius_y = std::max(std::sqrt(2.0) * v, min_radius);
  out->ellipses.push_back(spec);
  out->spans.push_back({0, 0});
  return std::nullopt;
}

}  // namespace ellipse_collision::app

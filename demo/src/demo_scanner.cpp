#include "demo_scanner.h"

#include <cmath>
#include <limits>

namespace ellipse_collision {

double rayHit(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
              const core::Ellipse& ellipse) {
  constexpr double kMiss = std::numeric_limits<double>::infinity();
  // In the ellipse's axes scaled to the unit circle: |o + t d|^2 = 1.
  const double c = std::cos(ellipse.angle), s = std::sin(ellipse.angle);
  const Eigen::Vector2d rel = origin - ellipse.center;
  const Eigen::Vector2d o((c * rel.x() + s * rel.y()) / ellipse.radius_x,
                          (-s * rel.x() + c * rel.y()) / ellipse.radius_y);
  const Eigen::Vector2d d((c * direction.x() + s * direction.y()) / ellipse.radius_x,
                          (-s * direction.x() + c * direction.y()) / ellipse.radius_y);
  const double a = d.squaredNorm(), b = o.dot(d), k = o.squaredNorm() - 1.0;
  if (k <= 0.0) return kMiss;  // inside: a real scanner sees nothing useful there
  const double discriminant = b * b - a * k;
  if (discriminant < 0.0 || b >= 0.0) return kMiss;  // misses, or the ellipse is behind
  return (-b - std::sqrt(discriminant)) / a;
}

std::vector<float> rayCastScan(const Pose2D& sensor, const std::vector<core::Ellipse>& world,
                               const ScannerModel& model) {
  std::vector<float> ranges(static_cast<std::size_t>(model.beams));
  for (int i = 0; i < model.beams; ++i) {
    const double angle = sensor.yaw + model.angle_min + i * model.angle_increment;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    double nearest = std::numeric_limits<double>::infinity();
    for (const core::Ellipse& e : world) nearest = std::min(nearest, rayHit(sensor.position, direction, e));
    ranges[i] = nearest <= model.range_max ? static_cast<float>(nearest)
                                           : std::numeric_limits<float>::infinity();
  }
  return ranges;
}

}  // namespace ellipse_collision

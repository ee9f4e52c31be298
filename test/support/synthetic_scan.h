#pragma once

// Synthetic sensor data for the scan_obstacles tests and benchmarks: a 2D world of wall segments
// and round pillars (vertical surfaces), ray-cast from the sensor at the origin into the fields
// of a sensor_msgs/LaserScan or into a 3D point cloud with rings, with seeded range noise.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "random_source.h"

namespace ellipse_collision::test {

constexpr double kScanPi = 3.14159265358979323846;

struct WorldSegment {
  Eigen::Vector2d a, b;  ///< [m] in the sensor's frame
};
struct WorldCircle {
  Eigen::Vector2d centre;  ///< [m]
  double radius;           ///< [m]
};
struct World {
  std::vector<WorldSegment> walls;
  std::vector<WorldCircle> pillars;

  /// An axis-aligned box [m] as its four walls.
  void addBox(double x0, double y0, double x1, double y1) {
    walls.push_back({{x0, y0}, {x1, y0}});
    walls.push_back({{x1, y0}, {x1, y1}});
    walls.push_back({{x1, y1}, {x0, y1}});
    walls.push_back({{x0, y1}, {x0, y0}});
  }
};

/// Distance [m] along the ray from the origin at `angle` [rad] to the first surface, if any.
inline std::optional<double> rayCast(const World& world, double angle) {
  const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
  double best = std::numeric_limits<double>::infinity();
  for (const WorldSegment& w : world.walls) {
    // t d = a + s (b - a): two equations by Cramer's rule.
    const Eigen::Vector2d e = w.b - w.a;
    const double det = d.x() * (-e.y()) - d.y() * (-e.x());
    if (det == 0.0) continue;
    const double t = (w.a.x() * (-e.y()) - w.a.y() * (-e.x())) / det;
    const double s = (d.x() * w.a.y() - d.y() * w.a.x()) / det;
    if (t > 0.0 && s >= 0.0 && s <= 1.0 && t < best) best = t;
  }
  for (const WorldCircle& c : world.pillars) {
    const double b = d.dot(c.centre);
    const double disc = b * b - (c.centre.squaredNorm() - c.radius * c.radius);
    if (disc < 0.0) continue;
    const double t = b - std::sqrt(disc);
    if (t > 0.0 && t < best) best = t;
  }
  if (!std::isfinite(best)) return std::nullopt;
  return best;
}

/// A LaserScan's fields.
struct ScanFields {
  std::vector<float> ranges;
  double angle_min{-kScanPi};
  double angle_increment{2.0 * kScanPi / 720.0};
  double range_min{0.05};
  double range_max{10.0};

  double angle(std::size_t i) const { return angle_min + static_cast<double>(i) * angle_increment; }
};

/// A full turn of `beams` beams from -pi: the ray-cast range plus N(0, sigma^2) noise (seeded),
/// +inf where the ray meets nothing within range_max.
inline ScanFields castScan(const World& world, int beams = 720, double range_max = 10.0,
                           double sigma = 0.0, std::uint64_t seed = 1) {
  RandomSource random(seed);
  ScanFields scan;
  scan.angle_increment = 2.0 * kScanPi / beams;
  scan.range_max = range_max;
  for (int i = 0; i < beams; ++i) {
    const auto hit = rayCast(world, scan.angle(static_cast<std::size_t>(i)));
    const double noise = sigma * random.normal();
    scan.ranges.push_back(hit && *hit <= range_max ? static_cast<float>(*hit + noise)
                                                   : std::numeric_limits<float>::infinity());
  }
  return scan;
}

/// A 3D lidar's cloud of the world's (vertical, 3 m high) surfaces [m]: `rings` rings from -15
/// to +15 degrees of elevation, `columns` azimuths a turn, points within range_max only.
inline std::vector<Eigen::Vector3f> castCloud(const World& world, int rings, int columns,
                                              double range_max = 30.0) {
  std::vector<Eigen::Vector3f> points;
  points.reserve(static_cast<std::size_t>(rings) * columns);
  for (int c = 0; c < columns; ++c) {
    const double angle = -kScanPi + 2.0 * kScanPi * c / columns;
    const auto hit = rayCast(world, angle);
    if (!hit || *hit > range_max) continue;
    for (int r = 0; r < rings; ++r) {
      const double elevation = (-15.0 + 30.0 * r / std::max(rings - 1, 1)) * kScanPi / 180.0;
      const double z = *hit * std::tan(elevation);
      if (z < -0.5 || z > 2.5) continue;  // below the floor or above the walls (sensor 0.5 m up)
      points.emplace_back(static_cast<float>(*hit * std::cos(angle)),
                          static_cast<float>(*hit * std::sin(angle)), static_cast<float>(z));
    }
  }
  return points;
}

/// The room: 6 m x 4 m around the sensor (walls x = -2.5 and 3.5, y = -1.8 and 2.2),
/// a box, a round pillar, a 0.9 m doorway in the wall y = 2.2 (x within [-1, -0.1]) with a
/// corridor wall behind it at y = 3.7.
inline World roomWorld() {
  World world;
  world.walls.push_back({{-2.5, -1.8}, {3.5, -1.8}});
  world.walls.push_back({{3.5, -1.8}, {3.5, 2.2}});
  world.walls.push_back({{3.5, 2.2}, {-0.1, 2.2}});
  world.walls.push_back({{-1.0, 2.2}, {-2.5, 2.2}});
  world.walls.push_back({{-2.5, 2.2}, {-2.5, -1.8}});
  world.walls.push_back({{-3.0, 3.7}, {2.0, 3.7}});  // the corridor behind the doorway
  world.addBox(1.5, 0.6, 2.0, 1.1);
  world.pillars.push_back({{-1.4, -0.9}, 0.15});
  return world;
}

/// An 8 m x 6 m room (x within [-3, 5], y within [-3, 3]) with ten round objects, 0.1 m to
/// 0.4 m in radius, placed at random (seeded) at least 0.3 m from the sensor.
inline World objectRoomWorld() {
  std::mt19937_64 random(40);
  std::uniform_real_distribution<double> x(-2.5, 4.5), y(-2.5, 2.5), r(0.1, 0.4);
  World world;
  world.addBox(-3.0, -3.0, 5.0, 3.0);
  while (world.pillars.size() < 10) {
    const WorldCircle c{{x(random), y(random)}, r(random)};
    if (c.centre.norm() > c.radius + 0.3) world.pillars.push_back(c);
  }
  return world;
}

}  // namespace ellipse_collision::test

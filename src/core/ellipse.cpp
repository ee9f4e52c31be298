#include "ellipse_collision/core/ellipse.h"

#include <charconv>
#include <cmath>

namespace ellipse_collision::core {
namespace {

// Shortest text that reads back as the same double, so a message shows exactly what was given.
std::string formatValue(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

}  // namespace

std::string invalidReason(const Ellipse& ellipse) {
  const std::pair<const char*, double> finite_fields[] = {
      {"center.x", ellipse.center.x()}, {"center.y", ellipse.center.y()},
      {"radius_x", ellipse.radius_x},   {"radius_y", ellipse.radius_y},
      {"angle", ellipse.angle}};
  for (const auto& [name, value] : finite_fields) {
    if (!std::isfinite(value)) {
      return std::string(name) + " = " + formatValue(value) + " is not finite";
    }
  }
  if (!(ellipse.radius_x > 0.0)) {
    return "radius_x = " + formatValue(ellipse.radius_x) + " must be > 0";
  }
  if (!(ellipse.radius_y > 0.0)) {
    return "radius_y = " + formatValue(ellipse.radius_y) + " must be > 0";
  }
  const std::pair<const char*, double> radii[] = {{"radius_x", ellipse.radius_x},
                                                  {"radius_y", ellipse.radius_y}};
  for (const auto& [name, value] : radii) {
    if (value < kMinRadius || value > kMaxRadius) {
      return std::string(name) + " = " + formatValue(value) + " is outside [" +
             formatValue(kMinRadius) + ", " + formatValue(kMaxRadius) + "] m";
    }
  }
  const std::pair<const char*, double> coordinates[] = {{"center.x", ellipse.center.x()},
                                                        {"center.y", ellipse.center.y()}};
  for (const auto& [name, value] : coordinates) {
    if (std::abs(value) > kMaxCoordinate) {
      return std::string(name) + " = " + formatValue(value) + " is outside [-" +
             formatValue(kMaxCoordinate) + ", " + formatValue(kMaxCoordinate) + "] m";
    }
  }
  return {};
}

}  // namespace ellipse_collision::core

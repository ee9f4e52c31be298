#include "ellipse_collision/ros/ellipse_spec.h"

#include <array>
#include <charconv>
#include <cmath>

namespace ellipse_collision {

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  // Shortest text that reads back to the same double: 0.1 stays "0.1", 20 stays "20".
  std::array<char, 64> buffer;
  const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
  return std::string(buffer.data(), end);
}

std::optional<FieldError> findInvalidField(const EllipseSpec& spec, const std::string& frame_key) {
  if (spec.name.empty()) return FieldError{"name", "a non-empty string", "''"};
  if (spec.frame_id.empty()) return FieldError{frame_key, "a non-empty tf frame id", "''"};
  if (spec.frame_id.front() == '/') {
    return FieldError{frame_key, "a tf2 frame id without a leading '/'", "'" + spec.frame_id + "'"};
  }
  // The ranges are the core's (invalidReason()), checked here to name the field as given.
  const std::string coordinate_range =
      "[-" + formatNumber(core::kMaxCoordinate) + ", " + formatNumber(core::kMaxCoordinate) + "]";
  const std::string radius_range =
      "[" + formatNumber(core::kMinRadius) + ", " + formatNumber(core::kMaxRadius) + "]";
  const struct {
    const char* key;
    double value;
  } coordinates[] = {{"x", spec.x}, {"y", spec.y}};
  for (const auto& field : coordinates) {
    if (!std::isfinite(field.value)) {
      return FieldError{field.key, "a finite number", formatNumber(field.value)};
    }
    if (std::abs(field.value) > core::kMaxCoordinate) {
      return FieldError{field.key, "a number within " + coordinate_range,
                        formatNumber(field.value)};
    }
  }
  if (!std::isfinite(spec.angle))
    return FieldError{"angle", "a finite number", formatNumber(spec.angle)};
  const struct {
    const char* key;
    double value;
  } radii[] = {{"radius_x", spec.radius_x}, {"radius_y", spec.radius_y}};
  for (const auto& radius : radii) {
    if (!std::isfinite(radius.value) || !(radius.value > 0.0)) {
      return FieldError{radius.key, "a finite number > 0", formatNumber(radius.value)};
    }
    if (radius.value < core::kMinRadius || radius.value > core::kMaxRadius) {
      return FieldError{radius.key, "a number within " + radius_range, formatNumber(radius.value)};
    }
  }
  if (!std::isfinite(spec.padding) || !(spec.padding >= 0.0)) {
    return FieldError{"padding", "a finite number >= 0", formatNumber(spec.padding)};
  }
  if (spec.padding > core::kMaxRadius) {
    return FieldError{"padding", "a number within [0, " + formatNumber(core::kMaxRadius) + "]",
                      formatNumber(spec.padding)};
  }
  return std::nullopt;
}

std::string describeRequestError(const std::string& entry, const FieldError& error) {
  return entry + "." + error.key + " = " + error.actual + ": expected " + error.expected;
}

core::Ellipse paddedEllipse(const EllipseSpec& spec, double global_padding) {
  core::Ellipse e;
  e.center = Eigen::Vector2d(spec.x, spec.y);
  e.radius_x = spec.radius_x + spec.padding + global_padding;
  e.radius_y = spec.radius_y + spec.padding + global_padding;
  e.angle = spec.angle;
  return e;
}

}  // namespace ellipse_collision

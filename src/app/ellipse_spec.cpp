#include "ellipse_collision/app/ellipse_spec.h"

#include <cmath>

#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

using core::formatNumber;

std::optional<FieldError> findInvalidField(const EllipseSpec& spec, const std::string& frame_key) {
  if (spec.name.empty()) return FieldError{"name", "a non-empty string", "''"};
  if (spec.frame_id.empty()) return FieldError{frame_key, "a non-empty tf frame id", "''"};
  if (spec.frame_id.front() == '/') {
    return FieldError{frame_key, "a tf2 frame id without a leading '/'", "'" + spec.frame_id + "'"};
  }
  // The core's rules (core/ellipse.h), checked field by field to name the field as given.
  const std::pair<const char*, std::optional<core::ValueViolation>> fields[] = {
      {"x", core::coordinateViolation(spec.x)},
      {"y", core::coordinateViolation(spec.y)},
      {"angle", core::angleViolation(spec.angle)},
      {"radius_x", core::radiusViolation(spec.radius_x)},
      {"radius_y", core::radiusViolation(spec.radius_y)}};
  for (const auto& [key, violation] : fields) {
    if (violation) return fieldError(key, *violation);
  }
  if (spec.ellipsoid) {
    const EllipsoidPart& part = *spec.ellipsoid;
    const std::pair<const char*, std::optional<core::ValueViolation>> depth[] = {
        {"z", core::coordinateViolation(part.z)},
        {"roll", core::angleViolation(part.roll)},
        {"pitch", core::angleViolation(part.pitch)}};
    for (const auto& [key, violation] : depth) {
      if (violation) return fieldError(key, *violation);
    }
    // radius_z = 0 is how a message says "planar" (msg/Ellipse.msg): a tilt or height given
    // with it is an ellipsoid whose depth was left out, refused rather than read as flat.
    if (part.radius_z == 0.0) {
      const std::pair<const char*, double> tilt[] = {
          {"z", part.z}, {"roll", part.roll}, {"pitch", part.pitch}};
      for (const auto& [key, value] : tilt) {
        if (value != 0.0) {
          return FieldError{key,
                            "0 when radius_z = 0 (a planar ellipse); z, roll and pitch describe "
                            "an ellipsoid, which needs radius_z > 0",
                            formatNumber(value)};
        }
      }
    }
    if (const auto violation = core::radiusViolation(part.radius_z)) {
      return fieldError("radius_z", *violation);
    }
  }
  if (!std::isfinite(spec.padding) || !(spec.padding >= 0.0)) {
    return FieldError{"padding", "a finite number >= 0", formatNumber(spec.padding)};
  }
  if (spec.padding > core::kMaxRadius) {
    return FieldError{"padding", "a number within [0, " + formatNumber(core::kMaxRadius) + "]",
                      formatNumber(spec.padding)};
  }
  // The core's motion limits (core/first_contact.h), so that every stored velocity can be given
  // to firstContact().
  const struct {
    const char* key;
    double value;
    double max;
    const char* unit;
  } velocities[] = {
      {"vx", spec.vx, core::kMaxSpeed, "m/s"},
      {"vy", spec.vy, core::kMaxSpeed, "m/s"},
      {"angular_velocity", spec.angular_velocity, core::kMaxAngularVelocity, "rad/s"}};
  for (const auto& v : velocities) {
    if (!(std::fabs(v.value) <= v.max)) {
      return FieldError{v.key,
                        std::string("a finite number within [") + formatNumber(-v.max) + ", " +
                            formatNumber(v.max) + "] " + v.unit,
                        formatNumber(v.value)};
    }
  }
  return std::nullopt;
}

std::optional<FieldError> findInvalidPaddedField(const EllipseSpec& spec, double global_padding,
                                                 const std::string& frame_key) {
  if (auto invalid = findInvalidField(spec, frame_key)) return invalid;
  // The same sums as paddedEllipse(), so that what passes here passes the core's invalidReason().
  const core::Ellipse padded = paddedEllipse(spec, global_padding);
  const struct {
    const char* key;
    double value;
    double padded;
  } radii[] = {{"radius_x", spec.radius_x, padded.radius_x},
               {"radius_y", spec.radius_y, padded.radius_y},
               {"radius_z", spec.ellipsoid ? spec.ellipsoid->radius_z : 1.0,
                spec.ellipsoid ? paddedEllipsoid(spec, global_padding).radii.z() : 1.0}};
  for (const auto& radius : radii) {
    if (!(radius.padded >= core::kMinRadius && radius.padded <= core::kMaxRadius)) {
      return FieldError{radius.key,
                        "a number whose padded radius (" + std::string(radius.key) + " + padding " +
                            formatNumber(spec.padding) + " + global padding " +
                            formatNumber(global_padding) + " = " + formatNumber(radius.padded) +
                            ") lies within [" + formatNumber(core::kMinRadius) + ", " +
                            formatNumber(core::kMaxRadius) + "]",
                        formatNumber(radius.value)};
    }
  }
  return std::nullopt;
}

core::Ellipse paddedEllipse(const EllipseSpec& spec, double global_padding) {
  core::Ellipse e;
  e.center = Eigen::Vector2d(spec.x, spec.y);
  e.radius_x = spec.radius_x + spec.padding + global_padding;
  e.radius_y = spec.radius_y + spec.padding + global_padding;
  e.angle = spec.angle;
  return e;
}

EllipseSpec planarSpec(const core::Ellipse& ellipse, const std::string& name,
                       const std::string& frame) {
  EllipseSpec spec;
  spec.name = name;
  spec.frame_id = frame;
  spec.x = ellipse.center.x();
  spec.y = ellipse.center.y();
  spec.angle = ellipse.angle;
  spec.radius_x = ellipse.radius_x;
  spec.radius_y = ellipse.radius_y;
  return spec;
}

core::Ellipsoid paddedEllipsoid(const EllipseSpec& spec, double global_padding) {
  const EllipsoidPart& part = *spec.ellipsoid;
  // Summed in paddedEllipse()'s order, so that the radii findInvalidPaddedField() passed are the
  // very ones the core gets (padding + global padding first could round above kMaxRadius).
  const auto grown = [&spec, global_padding](double radius) {
    return radius + spec.padding + global_padding;
  };
  core::Ellipsoid e;
  e.center = Eigen::Vector3d(spec.x, spec.y, part.z);
  e.orientation = Eigen::AngleAxisd(spec.angle, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(part.pitch, Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(part.roll, Eigen::Vector3d::UnitX());
  e.radii = Eigen::Vector3d(grown(spec.radius_x), grown(spec.radius_y), grown(part.radius_z));
  return e;
}

core::ProjectionResult placeInPlane(const EllipseSpec& spec, double global_padding,
                                    const Eigen::Isometry3d& fixed_from_frame) {
  if (spec.ellipsoid) {
    return core::shadowOnPlane(paddedEllipsoid(spec, global_padding), fixed_from_frame, spec.name);
  }
  return core::projectToPlane(paddedEllipse(spec, global_padding), fixed_from_frame, spec.name);
}

core::Motion ownMotion(const EllipseSpec& spec, const Eigen::Isometry3d& target_from_frame) {
  const Eigen::Vector3d v = target_from_frame.linear() * Eigen::Vector3d(spec.vx, spec.vy, 0.0);
  return core::Motion{v.head<2>(), spec.angular_velocity * target_from_frame.linear()(2, 2)};
}

}  // namespace ellipse_collision::app

#pragma once

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <string>

namespace ellipse_collision::core {

/// A closed 2D ellipse: {center + R(angle) * diag(radius_x, radius_y) * u : |u| <= 1}.
struct Ellipse {
  Eigen::Vector2d center{0.0, 0.0};  ///< [m]
  double radius_x{1.0};              ///< semi-axis along the ellipse's own x axis [m], > 0
  double radius_y{1.0};              ///< semi-axis along the ellipse's own y axis [m], > 0
  double angle{0.0};                 ///< counter-clockwise from the frame's x axis to the ellipse's x axis [rad]
};

/// The lengths the collision tests accept [m]. Far wider than any robot needs, and narrow enough
/// that no ratio or square formed by the tests can overflow or underflow a double.
constexpr double kMinRadius = 1e-9;
constexpr double kMaxRadius = 1e9;
constexpr double kMaxCoordinate = 1e9;

/// A value that breaks the rule of its field: the rule, the value, and for Range the accepted
/// closed interval. The rules live here once; each edge only renders a violation in its own words
/// (invalidReason() below, the application layer's field errors for requests and configuration).
struct ValueViolation {
  enum class Rule {
    Finite,    ///< NaN or infinite
    Positive,  ///< finite but not > 0
    Range,     ///< finite (and > 0 where required) but outside [min, max]
  };
  Rule rule{Rule::Finite};
  double value{0.0};
  double min{0.0};
  double max{0.0};
  bool must_be_positive{false};  ///< the field's rule also asks for > 0 (radii)
};

/// The rules themselves, as cheap tests (NaN fails every comparison, so each is also a finiteness
/// test). Everything below is defined through them.
/// A centre coordinate [m]: finite, within [-kMaxCoordinate, kMaxCoordinate].
inline bool coordinateOk(double value) { return value >= -kMaxCoordinate && value <= kMaxCoordinate; }
/// A radius [m]: finite, > 0, within [kMinRadius, kMaxRadius].
inline bool radiusOk(double value) { return value >= kMinRadius && value <= kMaxRadius; }
/// An angle [rad]: finite.
inline bool angleOk(double value) { return std::isfinite(value); }

/// All five fields keep their rules: invalidReason() would be empty (and costs no string).
inline bool isValid(const Ellipse& e) {
  return coordinateOk(e.center.x()) && coordinateOk(e.center.y()) && radiusOk(e.radius_x) &&
         radiusOk(e.radius_y) && angleOk(e.angle);
}

/// Which part of its field's rule a value breaks; nothing when it keeps it.
std::optional<ValueViolation> coordinateViolation(double value);
std::optional<ValueViolation> radiusViolation(double value);
std::optional<ValueViolation> angleViolation(double value);

/// A violation of field `key` in invalidReason()'s words ("radius_x = -1 must be > 0"), for
/// the other shapes that keep the same field rules (Ellipsoid).
std::string renderViolation(const char* key, const ValueViolation& violation);

/// Why `ellipse` cannot be checked, naming the field and its value ("radius_x = -1 must be > 0"),
/// or an empty string when it is valid: all fields finite, both radii > 0 and within
/// [kMinRadius, kMaxRadius], centre coordinates within [-kMaxCoordinate, kMaxCoordinate].
std::string invalidReason(const Ellipse& ellipse);

/// Radius of the smallest circle about the centre that contains the ellipse [m].
inline double boundingRadius(const Ellipse& e) { return e.radius_x > e.radius_y ? e.radius_x : e.radius_y; }

/// Radius of the largest circle about the centre that the ellipse contains [m].
inline double inscribedRadius(const Ellipse& e) { return e.radius_x < e.radius_y ? e.radius_x : e.radius_y; }

}  // namespace ellipse_collision::core

#pragma once

#include <optional>
#include <string>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision {

/// A named ellipse attached to a tf frame, as configured or requested (the fields of msg Ellipse).
struct EllipseSpec {
  std::string name;      ///< unique across links and obstacles
  std::string frame_id;  ///< tf frame whose xy-plane holds the ellipse
  double x{0.0};         ///< centre in frame_id [m]
  double y{0.0};         ///< centre in frame_id [m]
  double angle{0.0};     ///< counter-clockwise from frame_id's x axis to the ellipse's x axis [rad]
  double radius_x{0.0};  ///< [m], > 0
  double radius_y{0.0};  ///< [m], > 0
  double padding{0.0};   ///< added to both radii [m], >= 0
};

/// The first field of a spec that cannot be used: its key, what was expected and what was found.
struct FieldError {
  std::string key;
  std::string expected;
  std::string actual;
};

/// Checks every field of `spec` except whether its frame exists (that needs tf): name and frame
/// non-empty, frame without a leading '/', all numbers finite, radii > 0, padding >= 0, and the
/// core's ranges (|x|, |y| <= kMaxCoordinate; radii within [kMinRadius, kMaxRadius]).
/// `frame_key` is how the caller spells the frame field ("frame_id" in messages, "frame" in YAML).
std::optional<FieldError> findInvalidField(const EllipseSpec& spec,
                                           const std::string& frame_key = "frame_id");

/// "obstacles[2].radius_x = -1: expected a finite number > 0" for requests.
std::string describeRequestError(const std::string& entry, const FieldError& error);

/// The ellipse in its own frame with both radii grown by spec.padding + global_padding [m].
core::Ellipse paddedEllipse(const EllipseSpec& spec, double global_padding);

/// A number as it would be read back: shortest round-trip form, "nan", "inf", "-inf".
std::string formatNumber(double value);

}  // namespace ellipse_collision

#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::app {

/// Why one field of a request, message or configuration entry cannot be used: its key, what was
/// expected and what was found. Validation yields this; each edge renders it (a service answer,
/// a start-up error, a log line) and adds where the entry is.
struct FieldError {
  std::string key;
  std::string expected;
  std::string actual;
};

/// "obstacles[2]": how messages name entry `index` of list `field`.
std::string entryName(const std::string& field, std::size_t index);

/// "obstacles[2].radius_x = -1: expected a finite number > 0".
std::string describeFieldError(const std::string& entry, const FieldError& error);

/// The range rule of a setting: `value` within [min, max] (within (min, max] when `min_excluded`);
/// NaN is within no range. The violation reads "a number within [min, max]", or nothing.
std::optional<FieldError> findOutsideRange(const std::string& key, double value, double min,
                                           double max, bool min_excluded = false);

/// The field error for a violation of one of the core's value rules (core/ellipse.h), in the
/// words requests and configuration use.
FieldError fieldError(const std::string& key, const core::ValueViolation& violation);

}  // namespace ellipse_collision::app

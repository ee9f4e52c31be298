#include "ellipse_collision/app/field_error.h"

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

std::string entryName(const std::string& field, std::size_t index) {
  return field + "[" + std::to_string(index) + "]";
}

std::string describeFieldError(const std::string& entry, const FieldError& error) {
  return entry + "." + error.key + " = " + error.actual + ": expected " + error.expected;
}

std::optional<FieldError> findOutsideRange(const std::string& key, double value, double min,
                                           double max, bool min_excluded) {
  const bool above_min = min_excluded ? value > min : value >= min;
  if (above_min && value <= max) return std::nullopt;
  return FieldError{key,
                    std::string("a number within ") + (min_excluded ? "(" : "[") +
                        core::formatNumber(min) + ", " + core::formatNumber(max) + "]",
                    core::formatNumber(value)};
}

FieldError fieldError(const std::string& key, const core::ValueViolation& violation) {
  using Rule = core::ValueViolation::Rule;
  std::string expected;
  switch (violation.rule) {
    case Rule::Finite:
    case Rule::Positive:
      expected = violation.must_be_positive ? "a finite number > 0" : "a finite number";
      break;
    case Rule::Range:
      expected = "a number within [" + core::formatNumber(violation.min) + ", " +
                 core::formatNumber(violation.max) + "]";
      break;
  }
  return {key, expected, core::formatNumber(violation.value)};
}

}  // namespace ellipse_collision::app

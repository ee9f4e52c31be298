#include "ellipse_collision/core/ellipse.h"

#include <cmath>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::core {
namespace {

std::optional<ValueViolation> finiteViolation(double value, bool must_be_positive) {
  if (std::isfinite(value)) return std::nullopt;
  ValueViolation violation;
  violation.rule = ValueViolation::Rule::Finite;
  violation.value = value;
  violation.must_be_positive = must_be_positive;
  return violation;
}

std::optional<ValueViolation> rangeViolation(double value, double min, double max,
                                             bool must_be_positive) {
  if (value >= min && value <= max) return std::nullopt;
  return ValueViolation{ValueViolation::Rule::Range, value, min, max, must_be_positive};
}

}  // namespace

std::string renderViolation(const char* key, const ValueViolation& violation) {
  const std::string head = std::string(key) + " = " + formatNumber(violation.value);
  switch (violation.rule) {
    case ValueViolation::Rule::Finite:
      return head + " is not finite";
    case ValueViolation::Rule::Positive:
      return head + " must be > 0";
    case ValueViolation::Rule::Range:
      break;
  }
  return head + " is outside [" + formatNumber(violation.min) + ", " +
         formatNumber(violation.max) + "] m";
}

std::optional<ValueViolation> coordinateViolation(double value) {
  if (coordinateOk(value)) return std::nullopt;
  if (auto violation = finiteViolation(value, false)) return violation;
  return rangeViolation(value, -kMaxCoordinate, kMaxCoordinate, false);
}

std::optional<ValueViolation> radiusViolation(double value) {
  if (radiusOk(value)) return std::nullopt;
  if (auto violation = finiteViolation(value, true)) return violation;
  if (!(value > 0.0)) {
    return ValueViolation{ValueViolation::Rule::Positive, value, 0.0, 0.0, true};
  }
  return rangeViolation(value, kMinRadius, kMaxRadius, true);
}

std::optional<ValueViolation> angleViolation(double value) {
  if (angleOk(value)) return std::nullopt;
  return finiteViolation(value, false);
}

std::string invalidReason(const Ellipse& ellipse) {
  // Called for every ellipse of every scene check: the valid case costs five comparisons.
  if (coordinateOk(ellipse.center.x()) && coordinateOk(ellipse.center.y()) &&
      radiusOk(ellipse.radius_x) && radiusOk(ellipse.radius_y) && angleOk(ellipse.angle)) {
    return {};
  }
  const std::pair<const char*, std::optional<ValueViolation>> fields[] = {
      {"center.x", coordinateViolation(ellipse.center.x())},
      {"center.y", coordinateViolation(ellipse.center.y())},
      {"radius_x", radiusViolation(ellipse.radius_x)},
      {"radius_y", radiusViolation(ellipse.radius_y)},
      {"angle", angleViolation(ellipse.angle)}};
  // The gravest problem first, whichever field has it: not finite, then not > 0, then out of
  // range (radii before the centre).
  for (const auto rule : {ValueViolation::Rule::Finite, ValueViolation::Rule::Positive}) {
    for (const auto& [key, violation] : fields) {
      if (violation && violation->rule == rule) return renderViolation(key, *violation);
    }
  }
  for (const int index : {2, 3, 0, 1}) {
    const auto& [key, violation] = fields[index];
    if (violation) return renderViolation(key, *violation);
  }
  return {};
}

}  // namespace ellipse_collision::core

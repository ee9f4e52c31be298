#include "scene_entry_ref.h"

#include <cmath>

#include "ellipse_collision/core/number_format.h"
#include "scene_entry.h"

namespace ellipse_collision::core::detail {

std::string warningDistanceProblem(const SceneRules& rules) {
  if (!std::isfinite(rules.warning_distance) || rules.warning_distance < 0.0) {
    return "warning_distance = " + formatNumber(rules.warning_distance) +
           " must be finite and >= 0";
  }
  return {};
}

std::string entryProblem(std::size_t i, const EntryRef& entry, NameSet& names) {
  // Built only for an error: per entry it would cost more than the whole check.
  const auto where = [i] { return "ellipses[" + std::to_string(i) + "]"; };
  if (entry.name->empty()) return where() + ".name is empty";
  if (!names.insert(*entry.name)) return where() + ".name = '" + *entry.name + "' is a duplicate";
  // The cheap test first: invalidReason() returns a string, called on every entry of every check.
  if (isValid(*entry.ellipse)) return {};
  return invalidEntryReason("ellipses", i, {*entry.name, entry.role, *entry.ellipse});
}

}  // namespace ellipse_collision::core::detail

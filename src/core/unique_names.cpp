#include "ellipse_collision/core/unique_names.h"

#include <functional>

namespace ellipse_collision::core {

std::optional<NameProblem> findNameProblem(const std::vector<std::string>& names) {
  return findNameProblem(names.size(), [&](std::size_t i) -> std::string_view { return names[i]; });
}

namespace detail {

NameSet::NameSet(std::size_t capacity) {
  std::size_t slots = 16;
  while (slots < 2 * capacity) slots *= 2;  // at most half full: short probe sequences
  slots_.assign(slots, {});
}

bool NameSet::insert(std::string_view name) {
  const std::size_t mask = slots_.size() - 1;
  const std::size_t hash = std::hash<std::string_view>{}(name);
  for (std::size_t k = hash & mask;; k = (k + 1) & mask) {
    if (slots_[k].data() == nullptr) {
      slots_[k] = name;
      return true;
    }
    if (slots_[k] == name) return false;
  }
}

}  // namespace detail
}  // namespace ellipse_collision::core

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
  slots_.assign(slots, 0);
  names_.reserve(capacity);
}

void NameSet::prefetch(std::string_view name) const {
  // A table that stays in the cache gains nothing, and would pay a second hash per name (at
  // 1,000 names about as much as the whole bare pair pass).
  if (slots_.size() < kPrefetchFromSlots) return;
  __builtin_prefetch(&slots_[std::hash<std::string_view>{}(name) & (slots_.size() - 1)]);
}

bool NameSet::insert(std::string_view name) {
  const std::size_t mask = slots_.size() - 1;
  const std::uint64_t hash = std::hash<std::string_view>{}(name);
  // The slot from the low bits, the tag from the high ones: independent of each other.
  const std::uint64_t tag = hash >> 32;
  for (std::size_t k = hash & mask;; k = (k + 1) & mask) {
    const std::uint64_t slot = slots_[k];
    if (slot == 0) {
      names_.push_back(name);
      slots_[k] = (tag << 32) | static_cast<std::uint64_t>(names_.size());
      return true;
    }
    if ((slot >> 32) == tag && names_[(slot & 0xffffffffu) - 1] == name) return false;
  }
}

}  // namespace detail
}  // namespace ellipse_collision::core

#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ellipse_collision::core {

/// Where a list of names stops being a list of distinct, non-empty names.
struct NameProblem {
  enum class Kind { Empty, Duplicate };
  Kind kind{Kind::Empty};
  std::size_t index{0};        ///< the offending entry
  std::size_t first_index{0};  ///< Duplicate: the earlier entry with the same name
};

/// The one uniqueness check of the package (scenes, configuration, requests, the registry): the
/// first entry, in order, whose name is empty or repeats an earlier one. `name_of(i)` gives the
/// name of entry i < count as something convertible to std::string_view; the names must outlive
/// the call. Open addressing over views in one array: a set of string copies (or an
/// unordered_set with a node per name) would cost more than all the pair tests of a large scene.
template <class NameOf>
std::optional<NameProblem> findNameProblem(std::size_t count, NameOf&& name_of);

/// The same for a plain list of names.
std::optional<NameProblem> findNameProblem(const std::vector<std::string>& names);

namespace detail {

/// The names seen so far, as views (no copies). At most 2^32 - 1 of them.
class NameSet {
 public:
  explicit NameSet(std::size_t capacity);
  /// False iff `name` was inserted before; inserts it otherwise.
  bool insert(std::string_view name);
  /// Starts loading the slot where insert(name) will look, for a call some names later
  /// (kPrefetchAhead): beyond some 10,000 names the slots outgrow the cache, and each insert
  /// waited on memory.
  void prefetch(std::string_view name) const;
  static constexpr std::size_t kPrefetchAhead = 8;
  /// Below this many slots (512 kB, some 30,000 names) prefetch() does nothing.
  static constexpr std::size_t kPrefetchFromSlots = std::size_t{1} << 16;

 private:
  /// Per slot 0 (free), or 32 bits of the name's hash above its index in names_ plus one. A probe
  /// reads a name only where those hash bits match: names of one length (obstacle_17,
  /// obstacle_42) were compared byte by byte at every occupied slot, a read from wherever each
  /// name is stored (at 100,000 names, most of the check's time).
  std::vector<std::uint64_t> slots_;
  std::vector<std::string_view> names_;
};

}  // namespace detail

template <class NameOf>
std::optional<NameProblem> findNameProblem(std::size_t count, NameOf&& name_of) {
  detail::NameSet seen(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (i + detail::NameSet::kPrefetchAhead < count) {
      seen.prefetch(name_of(i + detail::NameSet::kPrefetchAhead));
    }
    const std::string_view name = name_of(i);
    if (name.empty()) return NameProblem{NameProblem::Kind::Empty, i, i};
    if (!seen.insert(name)) {
      // Only on the error path: find where the name stood first.
      std::size_t first = 0;
      while (std::string_view(name_of(first)) != name) ++first;
      return NameProblem{NameProblem::Kind::Duplicate, i, first};
    }
  }
  return std::nullopt;
}

}  // namespace ellipse_collision::core

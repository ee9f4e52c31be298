#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// What an ellipse stands for decides which pairs are checked: link-obstacle always, link-link
/// iff self collision is on, obstacle-obstacle never, query against every link and obstacle,
/// query-query never. The order Query < Link < Obstacle also orders the names within a pair.
enum class EllipseRole { Query, Link, Obstacle };

/// A named ellipse already placed in the common fixed frame.
struct NamedEllipse {
  std::string name;  ///< unique within one scene, non-empty
  EllipseRole role{EllipseRole::Link};
  Ellipse ellipse;
};

/// Named ellipses stored by column: the ellipses in one packed array, the names and roles beside
/// it. A pass over the geometry alone (checkValidatedScene() streaming 100,000 obstacles past the
/// links, bandwidth-bound) then reads 48 bytes per entry, not the 96 of a NamedEllipse with its
/// name. Entry i is (name(i), role(i), ellipse(i)).
class Scene {
 public:
  Scene() = default;
  /// The entries of `entries`, in order.
  explicit Scene(const std::vector<NamedEllipse>& entries);

  void reserve(std::size_t count);
  void push_back(std::string name, EllipseRole role, const Ellipse& ellipse);
  void push_back(const NamedEllipse& entry) { push_back(entry.name, entry.role, entry.ellipse); }
  /// Puts `entries` before the first entry, in their order.
  void insertFront(const std::vector<NamedEllipse>& entries);
  /// Removes the first `count` entries.
  void eraseFront(std::size_t count);
  /// Keeps the first `count` entries (count <= size()).
  void truncate(std::size_t count);
  void clear() { truncate(0); }

  std::size_t size() const { return ellipses_.size(); }
  bool empty() const { return ellipses_.empty(); }
  const std::string& name(std::size_t i) const { return names_[i]; }
  EllipseRole role(std::size_t i) const { return roles_[i]; }
  const Ellipse& ellipse(std::size_t i) const { return ellipses_[i]; }
  /// The geometry alone is rewritten in place (a cache refilling last check's scene).
  Ellipse& ellipse(std::size_t i) { return ellipses_[i]; }
  /// The packed column of ellipses, entry i at [i].
  const std::vector<Ellipse>& ellipses() const { return ellipses_; }

  /// Entry i as a record (a copy).
  NamedEllipse entry(std::size_t i) const { return {names_[i], roles_[i], ellipses_[i]}; }
  /// Every entry as records (copies), in order.
  std::vector<NamedEllipse> entries() const;

  /// Identifies the storage: a moved scene keeps it, one that grew past its capacity does not.
  const void* storage() const { return names_.data(); }

 private:
  std::vector<std::string> names_;
  std::vector<EllipseRole> roles_;
  std::vector<Ellipse> ellipses_;
};

}  // namespace ellipse_collision::core

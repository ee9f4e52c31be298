#pragma once

// The entries of a scene as the scene check and the nearest-partner search read them, and the
// rules both apply to them: which pairs are wanted, in which order a pair is written, how an entry
// is refused. Internal to the core (src/core).

#include <set>
#include <string>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/scene.h"
#include "ellipse_collision/core/scene_check.h"
#include "ellipse_collision/core/unique_names.h"

namespace ellipse_collision::core::detail {

/// One entry of a scene wherever it is stored (a NamedEllipse, or a Scene's columns): what the
/// pair rules, the pair tests and the answer read of it.
struct EntryRef {
  const std::string* name;
  EllipseRole role;
  const Ellipse* ellipse;
};

inline EntryRef refOf(const NamedEllipse& entry) { return {&entry.name, entry.role, &entry.ellipse}; }
inline EntryRef refOf(const Scene& scene, std::size_t i) {
  return {&scene.name(i), scene.role(i), &scene.ellipse(i)};
}

// distance() is accurate to about epsilon times the radii and the centre distance (distance.h),
// the bound below to a few epsilon of the same: a margin of 1e-9 of them covers both many times
// over, so a pair the bound rules out is one distance() could never have reported.
constexpr double kBoundMargin = 1e-9;

/// A lower bound on distance(a, b) [m]: each ellipse lies within its bounding circle.
inline double distanceLowerBound(const Ellipse& a, const Ellipse& b) {
  const double centres = (b.center - a.center).norm();
  const double reach = boundingRadius(a) + boundingRadius(b);
  return centres - reach - kBoundMargin * (centres + reach);
}

/// Why rules.warning_distance is refused ("warning_distance = -1 must be finite and >= 0"), or "".
std::string warningDistanceProblem(const SceneRules& rules);

/// What is wrong with entry `i`, or "". `names` collects the names for the duplicate rule.
std::string entryProblem(std::size_t i, const EntryRef& entry, NameSet& names);

/// Lower role first, then lower name: a pair reads the same whichever way round the loop met it.
inline bool comesFirst(const EntryRef& a, const EntryRef& b) {
  return a.role != b.role ? a.role < b.role : *a.name < *b.name;
}

inline NearPair nearPair(const std::string& a, const std::string& b, const Clearance& clearance) {
  return {a, b, clearance.distance, clearance.point_a, clearance.point_b};
}

/// pairWanted() on entries wherever they are stored.
inline bool wanted(const EntryRef& a, const EntryRef& b, const SceneRules& rules,
            const std::set<std::string>& only_names) {
  const bool a_query = a.role == EllipseRole::Query;
  const bool b_query = b.role == EllipseRole::Query;
  if (a_query && b_query) return false;
  if (!a_query && !b_query) {
    if (a.role == EllipseRole::Obstacle && b.role == EllipseRole::Obstacle) return false;
    if (a.role == EllipseRole::Link && b.role == EllipseRole::Link && !rules.self_collision) {
      return false;
    }
  }
  if (rules.allowed.contains(*a.name, *b.name)) return false;
  return only_names.empty() || only_names.count(*a.name) != 0 || only_names.count(*b.name) != 0;
}

}  // namespace ellipse_collision::core::detail

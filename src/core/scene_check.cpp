#include "ellipse_collision/scene_check.h"

#include <algorithm>
#include <tuple>

#include "ellipse_collision/eigenvalue_test.h"
#include "ellipse_collision/overlap.h"

namespace ellipse_collision {
namespace {

std::string validate(const std::vector<NamedEllipse>& ellipses) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < ellipses.size(); ++i) {
    const NamedEllipse& entry = ellipses[i];
    const std::string where = "ellipses[" + std::to_string(i) + "]";
    if (entry.name.empty()) return where + ".name is empty";
    if (!names.insert(entry.name).second)
      return where + ".name = '" + entry.name + "' is a duplicate";
    const std::string invalid = invalidReason(entry.ellipse);
    if (!invalid.empty()) return where + " ('" + entry.name + "'): " + invalid;
  }
  return {};
}

/// Lower role first, then lower name: a pair reads the same whichever way round the loop met it.
bool comesFirst(const NamedEllipse& a, const NamedEllipse& b) {
  return std::tie(a.role, a.name) < std::tie(b.role, b.name);
}

}  // namespace

bool pairWanted(const NamedEllipse& a, const NamedEllipse& b, const SceneRules& rules,
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
  if (rules.allowed.contains(a.name, b.name)) return false;
  return only_names.empty() || only_names.count(a.name) != 0 || only_names.count(b.name) != 0;
}

SceneCheckResult checkScene(const std::vector<NamedEllipse>& ellipses, const SceneRules& rules,
                            const std::set<std::string>& only_names) {
  SceneCheckResult result;
  result.error = validate(ellipses);
  if (!result.error.empty()) return result;

  // The one pair loop. A broadphase would replace the nested loop by its candidate pairs; the sort
  // below makes the answer independent of the order in which candidates arrive.
  struct Found {
    const NamedEllipse* first;
    const NamedEllipse* second;
    double contact_scale;
  };
  std::vector<Found> found;
  for (std::size_t i = 0; i < ellipses.size(); ++i) {
    for (std::size_t j = i + 1; j < ellipses.size(); ++j) {
      const bool i_first = comesFirst(ellipses[i], ellipses[j]);
      const NamedEllipse& first = i_first ? ellipses[i] : ellipses[j];
      const NamedEllipse& second = i_first ? ellipses[j] : ellipses[i];
      if (!pairWanted(first, second, rules, only_names)) continue;
      if (!overlap(first.ellipse, second.ellipse)) continue;
      // Always called in canonical order, so swapping the inputs cannot change a rounding bit.
      found.push_back({&first, &second, contactScale(first.ellipse, second.ellipse)});
    }
  }

  std::sort(found.begin(), found.end(), [](const Found& x, const Found& y) {
    return std::tie(x.first->role, x.first->name, x.second->role, x.second->name) <
           std::tie(y.first->role, y.first->name, y.second->role, y.second->name);
  });
  result.collisions.reserve(found.size());
  for (const Found& pair : found) {
    result.collisions.push_back({pair.first->name, pair.second->name, pair.contact_scale});
  }
  return result;
}

}  // namespace ellipse_collision

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/scene_check.h"
#include "scene_entry_ref.h"

// nearestTo(): the nearest wanted partner of one entry of a scene (scene_check.h).

namespace ellipse_collision::core {
namespace {

using detail::EntryRef;

/// Every entry passes the scene check's rules, one pass in index order.
std::string validateEntries(const std::vector<EntryRef>& entries, const SceneRules& rules) {
  std::string problem = detail::warningDistanceProblem(rules);
  if (!problem.empty()) return problem;
  // One pass, entry by entry as a reader checks them (a second pass over 100,000 entries costs
  // as much as the pair tests); the set of names is the one findNameProblem() uses.
  detail::NameSet names(entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i + detail::NameSet::kPrefetchAhead < entries.size()) {
      names.prefetch(*entries[i + detail::NameSet::kPrefetchAhead].name);
    }
    problem = detail::entryProblem(i, entries[i], names);
    if (!problem.empty()) return problem;
  }
  return {};
}

/// nearestTo() on entries wherever they are stored.
NearestResult nearestAmong(const std::vector<EntryRef>& entries, const SceneRules& rules,
                           const std::string& name) {
  NearestResult result;
  result.error = validateEntries(entries, rules);
  if (!result.error.empty()) return result;
  const auto found = std::find_if(entries.begin(), entries.end(),
                                  [&name](const EntryRef& e) { return *e.name == name; });
  if (found == entries.end()) {
    result.error = "name = '" + name + "' is not in the scene";
    return result;
  }
  const EntryRef* target = &*found;

  // Partners by increasing lower bound: once the bound reaches the best distance found, no later
  // partner can be nearer. Ties in the bound keep CollidingPair order, which settles equal answers.
  struct Partner {
    const EntryRef* first;  // canonical order of the pair
    const EntryRef* second;
    double bound;
  };
  std::vector<Partner> partners;
  for (const EntryRef& other : entries) {
    if (&other == target) continue;
    const bool target_first = detail::comesFirst(*target, other);
    const EntryRef& first = target_first ? *target : other;
    const EntryRef& second = target_first ? other : *target;
    if (!detail::wanted(first, second, rules, {})) continue;
    partners.push_back({&first, &second, detail::distanceLowerBound(*first.ellipse, *second.ellipse)});
  }
  const auto before = [target](const Partner& x, const Partner& y) {
    const EntryRef& x_other = x.first == target ? *x.second : *x.first;
    const EntryRef& y_other = y.first == target ? *y.second : *y.first;
    return detail::comesFirst(x_other, y_other);
  };
  std::sort(partners.begin(), partners.end(), [&before](const Partner& x, const Partner& y) {
    return x.bound != y.bound ? x.bound < y.bound : before(x, y);
  });

  const Partner* best = nullptr;
  Clearance best_clearance;
  double best_scale = 0.0;  // contact scale of the best colliding partner
  for (const Partner& partner : partners) {
    if (best && best_clearance.separated && partner.bound >= best_clearance.distance) break;
    // An overlapping pair has a bound below 0, so the loop reaches every colliding partner.
    if (best && !best_clearance.separated && partner.bound > 0.0) break;
    const Clearance clearance = distance(*partner.first->ellipse, *partner.second->ellipse);
    bool better = false;
    if (!clearance.separated) {
      const double scale = contactScale(*partner.first->ellipse, *partner.second->ellipse);
      better = !best || best_clearance.separated || scale < best_scale ||
               (scale == best_scale && before(partner, *best));
      if (better) best_scale = scale;
    } else if (!best || best_clearance.separated) {
      better = !best || clearance.distance < best_clearance.distance ||
               (clearance.distance == best_clearance.distance && before(partner, *best));
    }
    if (better) {
      best = &partner;
      best_clearance = clearance;
    }
  }
  if (!best) return result;

  result.found = true;
  result.nearest = detail::nearPair(*best->first->name, *best->second->name, best_clearance);
  if (best->first != target) {
    std::swap(result.nearest.name_a, result.nearest.name_b);
    std::swap(result.nearest.point_a, result.nearest.point_b);
  }
  return result;
}

}  // namespace

NearestResult nearestTo(const std::vector<NamedEllipse>& ellipses, const SceneRules& rules,
                        const std::string& name) {
  std::vector<EntryRef> entries;
  entries.reserve(ellipses.size());
  for (const NamedEllipse& entry : ellipses) entries.push_back(detail::refOf(entry));
  return nearestAmong(entries, rules, name);
}

NearestResult nearestTo(const Scene& scene, const SceneRules& rules, const std::string& name) {
  std::vector<EntryRef> entries;
  entries.reserve(scene.size());
  for (std::size_t i = 0; i < scene.size(); ++i) entries.push_back(detail::refOf(scene, i));
  return nearestAmong(entries, rules, name);
}
}  // namespace ellipse_collision::core

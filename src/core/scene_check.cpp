#include "ellipse_collision/scene_check.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <tuple>

#include "ellipse_collision/distance.h"
#include "ellipse_collision/eigenvalue_test.h"
#include "ellipse_collision/overlap.h"

namespace ellipse_collision {
namespace {

// distance() is accurate to about epsilon times the radii and the centre distance (distance.h),
// the bound below to a few epsilon of the same: a margin of 1e-9 of them covers both many times
// over, so a pair the bound rules out is one distance() could never have reported.
constexpr double kBoundMargin = 1e-9;

/// A lower bound on distance(a, b) [m]: each ellipse lies within its bounding circle.
double distanceLowerBound(const Ellipse& a, const Ellipse& b) {
  const double centres = (b.center - a.center).norm();
  const double reach = boundingRadius(a) + boundingRadius(b);
  return centres - reach - kBoundMargin * (centres + reach);
}

std::string validate(const std::vector<NamedEllipse>& ellipses, const SceneRules& rules) {
  if (!std::isfinite(rules.warning_distance) || rules.warning_distance < 0.0) {
    char text[64];
    const auto end = std::to_chars(text, text + sizeof(text), rules.warning_distance).ptr;
    return "warning_distance = " + std::string(text, end) + " must be finite and >= 0";
  }
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

NearPair nearPair(const NamedEllipse& a, const NamedEllipse& b, const Clearance& clearance) {
  return {a.name, b.name, clearance.distance, clearance.point_a, clearance.point_b};
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
  result.error = validate(ellipses, rules);
  if (!result.error.empty()) return result;
  const double warning_distance = rules.warning_distance;

  // The one pair loop. A broadphase would replace the nested loop by its candidate pairs; the sort
  // below makes the answer independent of the order in which candidates arrive.
  struct Found {
    const NamedEllipse* first;
    const NamedEllipse* second;
    double contact_scale;  // collisions only
    Clearance clearance;   // warnings only
  };
  std::vector<Found> collisions;
  std::vector<Found> warnings;
  for (std::size_t i = 0; i < ellipses.size(); ++i) {
    for (std::size_t j = i + 1; j < ellipses.size(); ++j) {
      const bool i_first = comesFirst(ellipses[i], ellipses[j]);
      const NamedEllipse& first = i_first ? ellipses[i] : ellipses[j];
      const NamedEllipse& second = i_first ? ellipses[j] : ellipses[i];
      if (!pairWanted(first, second, rules, only_names)) continue;
      // Always called in canonical order, so swapping the inputs cannot change a rounding bit.
      if (overlap(first.ellipse, second.ellipse)) {
        collisions.push_back({&first, &second, contactScale(first.ellipse, second.ellipse), {}});
        continue;
      }
      if (warning_distance <= 0.0 ||
          distanceLowerBound(first.ellipse, second.ellipse) >= warning_distance) {
        continue;
      }
      const Clearance clearance = distance(first.ellipse, second.ellipse);
      if (clearance.separated && clearance.distance < warning_distance) {
        warnings.push_back({&first, &second, 0.0, clearance});
      }
    }
  }

  const auto canonical = [](const Found& x, const Found& y) {
    return std::tie(x.first->role, x.first->name, x.second->role, x.second->name) <
           std::tie(y.first->role, y.first->name, y.second->role, y.second->name);
  };
  std::sort(collisions.begin(), collisions.end(), canonical);
  std::sort(warnings.begin(), warnings.end(), canonical);
  result.collisions.reserve(collisions.size());
  for (const Found& pair : collisions) {
    result.collisions.push_back({pair.first->name, pair.second->name, pair.contact_scale});
  }
  result.warnings.reserve(warnings.size());
  for (const Found& pair : warnings) {
    result.warnings.push_back(nearPair(*pair.first, *pair.second, pair.clearance));
  }
  return result;
}

NearestResult nearestTo(const std::vector<NamedEllipse>& ellipses, const SceneRules& rules,
                        const std::string& name) {
  NearestResult result;
  result.error = validate(ellipses, rules);
  if (!result.error.empty()) return result;
  const auto target = std::find_if(ellipses.begin(), ellipses.end(),
                                   [&name](const NamedEllipse& e) { return e.name == name; });
  if (target == ellipses.end()) {
    result.error = "name = '" + name + "' is not in the scene";
    return result;
  }

  // Partners by increasing lower bound: once the bound reaches the best distance found, no later
  // partner can be nearer. Ties in the bound keep CollidingPair order, which settles equal answers.
  struct Partner {
    const NamedEllipse* first;  // canonical order of the pair
    const NamedEllipse* second;
    double bound;
  };
  std::vector<Partner> partners;
  for (const NamedEllipse& other : ellipses) {
    if (&other == &*target) continue;
    const bool target_first = comesFirst(*target, other);
    const NamedEllipse& first = target_first ? *target : other;
    const NamedEllipse& second = target_first ? other : *target;
    if (!pairWanted(first, second, rules, {})) continue;
    partners.push_back({&first, &second, distanceLowerBound(first.ellipse, second.ellipse)});
  }
  const auto before = [&target](const Partner& x, const Partner& y) {
    const NamedEllipse& x_other = x.first == &*target ? *x.second : *x.first;
    const NamedEllipse& y_other = y.first == &*target ? *y.second : *y.first;
    return std::tie(x_other.role, x_other.name) < std::tie(y_other.role, y_other.name);
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
    const Clearance clearance = distance(partner.first->ellipse, partner.second->ellipse);
    bool better = false;
    if (!clearance.separated) {
      const double scale = contactScale(partner.first->ellipse, partner.second->ellipse);
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
  result.nearest = nearPair(*best->first, *best->second, best_clearance);
  if (best->first != &*target) {
    std::swap(result.nearest.name_a, result.nearest.name_b);
    std::swap(result.nearest.point_a, result.nearest.point_b);
  }
  return result;
}

}  // namespace ellipse_collision

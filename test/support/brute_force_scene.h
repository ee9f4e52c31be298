#pragma once

// The reference a scene check is held to: every pair, exact tests on all of them, no bound, no
// box, no grid. Shared by the scene gtests and the scene fuzz target (header-only: the fuzz build
// compiles it standalone).
#include <algorithm>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core::test {

/// The scene sorted in reporting order (lower role first, then lower name).
inline std::vector<const NamedEllipse*> inPairOrder(const std::vector<NamedEllipse>& scene) {
  std::vector<const NamedEllipse*> sorted;
  for (const NamedEllipse& e : scene) sorted.push_back(&e);
  std::sort(sorted.begin(), sorted.end(), [](const NamedEllipse* x, const NamedEllipse* y) {
    return std::tie(x->role, x->name) < std::tie(y->role, y->name);
  });
  return sorted;
}

/// What checkScene() must answer, from overlap(), contactScale() and distance() on every wanted
/// pair, in the documented order.
inline SceneCheckResult bruteForceScene(const std::vector<NamedEllipse>& scene,
                                        const SceneRules& rules,
                                        const std::set<std::string>& only_names) {
  const std::vector<const NamedEllipse*> sorted = inPairOrder(scene);
  SceneCheckResult expected;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    for (std::size_t j = i + 1; j < sorted.size(); ++j) {
      const NamedEllipse& a = *sorted[i];
      const NamedEllipse& b = *sorted[j];
      if (!pairWanted(a, b, rules, only_names)) continue;
      if (overlap(a.ellipse, b.ellipse)) {
        expected.collisions.push_back({a.name, b.name, contactScale(a.ellipse, b.ellipse)});
        continue;
      }
      if (rules.warning_distance <= 0.0) continue;
      const Clearance c = distance(a.ellipse, b.ellipse);
      if (c.separated && c.distance < rules.warning_distance) {
        expected.warnings.push_back({a.name, b.name, c.distance, c.point_a, c.point_b});
      }
    }
  }
  return expected;
}

/// What nearestTo(scene, rules, target.name) must answer: every partner the rules allow (no name
/// filter); a colliding partner of smallest contactScale() beats any separated one; among equals
/// the first in pair order wins. `found` false when no partner is wanted.
inline NearestResult bruteForceNearest(const std::vector<NamedEllipse>& scene,
                                       const SceneRules& rules, const NamedEllipse& target) {
  NearestResult answer;
  bool colliding = false;
  double best_scale = 0.0;
  for (const NamedEllipse* other : inPairOrder(scene)) {
    if (other == &target) continue;
    const bool target_first = std::tie(target.role, target.name) < std::tie(other->role, other->name);
    const NamedEllipse& first = target_first ? target : *other;
    const NamedEllipse& second = target_first ? *other : target;
    if (!pairWanted(first, second, rules, {})) continue;
    const Clearance c = distance(first.ellipse, second.ellipse);
    const NearPair candidate{target.name, other->name, c.distance,
                             target_first ? c.point_a : c.point_b,
                             target_first ? c.point_b : c.point_a};
    if (!c.separated) {
      const double scale = contactScale(first.ellipse, second.ellipse);
      if (!answer.found || !colliding || scale < best_scale) {
        answer.nearest = candidate;
        best_scale = scale;
      }
      answer.found = colliding = true;
    } else if (!answer.found || (!colliding && c.distance < answer.nearest.distance)) {
      answer.nearest = candidate;
      answer.found = true;
    }
  }
  return answer;
}

}  // namespace ellipse_collision::core::test

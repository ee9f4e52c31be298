#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/first_contact.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core {

/// Two ellipses apart now that touch within the horizon; names ordered as in CollidingPair.
struct PredictedContact {
  std::string name_a;
  std::string name_b;
  double time{0.0};  ///< first contact [s] after now, > 0
};

/// The answer of predictContacts().
struct PredictionResult {
  std::vector<PredictedContact> predicted;  ///< sorted by time, then (name_a, name_b)
  std::vector<std::string> refused;  ///< pairs whose motions break firstContact()'s limits, and why
  std::size_t pair_tests{0};         ///< firstContact() calls (a statistic)
};

/// Every pair the rules and the name filter want (pairWanted()) that is apart now and, with each
/// ellipse moving by its motion (motions[i] for ellipses[i], in the same frame), touches within
/// `horizon` [s], at the time firstContact() gives. Pairs in collision now are not repeated here:
/// those that overlap(), or, when `colliding` is given, exactly the pairs it lists (name_a, name_b
/// in CollidingPair order; a pair not listed that overlaps is then reported at time 0 — the caller
/// moved the ellipses on from the poses its check was made at, and the pair touched since).
/// Pairs where neither moves are skipped (apart now, apart throughout).
/// Broadphase: each ellipse's swept bound over the horizon (sweptBox(): its bounding circle at
/// both ends of its path; a turn about its own centre stays inside the circle) through the
/// uniform grid (overlappingBoxPairs()); only pairs whose swept boxes meet reach firstContact().
/// Preconditions: valid ellipses (checkScene() accepted them), horizon finite and >= 0.
PredictionResult predictContacts(
    const std::vector<NamedEllipse>& ellipses, const std::vector<Motion>& motions,
    const SceneRules& rules, const std::set<std::string>& only_names, double horizon,
    const std::set<std::pair<std::string, std::string>>* colliding = nullptr);

}  // namespace ellipse_collision::core

#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/scene.h"

namespace ellipse_collision::core {

/// Unordered name pairs that are never reported (an allowed-collision matrix).
class AllowedPairs {
 public:
  void add(const std::string& a, const std::string& b) { pairs_.insert(ordered(a, b)); }
  bool contains(const std::string& a, const std::string& b) const {
    // Asked for every candidate pair: without allowed pairs, no copies of the two names.
    return !pairs_.empty() && pairs_.count(ordered(a, b)) != 0;
  }
  std::size_t size() const { return pairs_.size(); }
  /// Every pair, each ordered by name.
  const std::set<std::pair<std::string, std::string>>& pairs() const { return pairs_; }

 private:
  static std::pair<std::string, std::string> ordered(const std::string& a, const std::string& b) {
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  }
  std::set<std::pair<std::string, std::string>> pairs_;
};

/// The scene-wide rules for which pairs are checked.
struct SceneRules {
  bool self_collision{true};  ///< also check link against link
  AllowedPairs allowed;       ///< never reported
  /// Separated pairs closer than this are reported as warnings [m]; finite, >= 0; 0 = none.
  double warning_distance{0.0};
};

/// Two ellipses in collision. name_a is the one of lower role (Query < Link < Obstacle), by name
/// within the same role.
struct CollidingPair {
  std::string name_a;
  std::string name_b;
  double contact_scale{
      0.0};  ///< contactScale(a, b): <= 1; both scaled by it about their centres touch
};

/// Two ellipses and how far apart they are: a warning pair (separated, closer than the warning
/// distance) or the nearest partner of one ellipse. Names are ordered as in CollidingPair, except
/// in nearestTo()'s answer, whose name_a is the ellipse asked about.
struct NearPair {
  std::string name_a;
  std::string name_b;
  double distance{0.0};               ///< distance() between the two [m]; 0 when they overlap
  Eigen::Vector2d point_a{0.0, 0.0};  ///< point of a's rim closest to b [m]; origin if overlapping
  Eigen::Vector2d point_b{0.0, 0.0};  ///< point of b's rim closest to a [m]; origin if overlapping
};

/// Either the colliding and warning pairs or why the scene cannot be checked.
struct SceneCheckResult {
  std::vector<CollidingPair> collisions;  ///< sorted by (role_a, name_a, role_b, name_b)
  std::vector<NearPair> warnings;  ///< separated but closer than warning_distance; same order
  std::string error;               ///< empty on success
  /// Pairs the broadphase and the rules left for the exact test (overlap() calls): a statistic
  /// for tests and benchmarks, not part of the answer.
  std::size_t pair_tests{0};
  bool ok() const { return error.empty(); }
};

/// Whether the rules and the name filter ask for the pair (a, b) to be checked at all, before any
/// geometry. `only_names` empty means every pair; otherwise a pair is wanted iff at least one of
/// its names is listed (a listed name that is not in the scene matches nothing).
bool pairWanted(const NamedEllipse& a, const NamedEllipse& b, const SceneRules& rules,
                const std::set<std::string>& only_names);

/// Checks every wanted pair of `ellipses` with overlap() and reports the colliding ones with their
/// contactScale(). With rules.warning_distance > 0 it also reports the wanted pairs that are
/// separated but closer than that, with their distance() and witness points: a pair whose centres
/// are at least both bounding radii plus the warning distance apart is ruled out without calling
/// distance() (with a margin for rounding, so the answer is the same as calling it on every pair).
/// Candidate pairs come from a broadphase (broadphase.h): a BoxGrid over the queries' and links'
/// tight boxes, grown by the warning distance, which each obstacle's bounding-circle box is
/// streamed through, so the time grows linearly with the obstacles; the answer is bit for bit that
/// of testing every pair.
/// The result depends only on the set of ellipses, not on their order; the time is least with the
/// queries and links before the obstacles (the scene is then read once, not twice). Refused with an error
/// naming the entry: an empty or duplicate name, or an invalid ellipse; or a warning distance that
/// is negative or not finite.
SceneCheckResult checkScene(const std::vector<NamedEllipse>& ellipses, const SceneRules& rules,
                            const std::set<std::string>& only_names = {});

/// checkScene() for a caller that vouches for its scene, so that the check does no work per
/// obstacle but the broadphase's, on the scene's packed column of ellipses: every name non-empty and distinct (a registry keyed by name),
/// every obstacle's ellipse valid (isValid(), tested where it was made: projectToPlane() refuses
/// an invalid projection), and the queries and links first: entries [0, first_obstacle) are
/// queries and links, the rest obstacles. The same answer bit for bit as checkScene(), without
/// hashing every name and testing every field and role of every obstacle on every call (at
/// 10,000 obstacles that cost twice the broadphase), so names and rules cost in proportion to the
/// movers and the pairs tested. Still refuses, naming the entry, what costs nothing per
/// obstacle: a warning distance that is negative or not finite, first_obstacle beyond the
/// scene, an obstacle or an invalid ellipse among the movers, and an invalid obstacle whose
/// bounding-circle box meets a mover's box (tested before any pair work). A scene that breaks
/// the rest of the promise (an invalid obstacle far from every mover, a query or link after
/// first_obstacle, duplicate names) gets an unspecified answer, with no undefined behaviour
/// (fuzz_scene feeds it broken scenes under the sanitizers).
SceneCheckResult checkValidatedScene(const Scene& scene, std::size_t first_obstacle,
                                   const SceneRules& rules,
                                   const std::set<std::string>& only_names = {});

/// The answer of nearestTo(): the nearest partner of one ellipse, or why there is none.
struct NearestResult {
  bool found{false};  ///< false when no wanted pair involves the ellipse
  NearPair nearest;   ///< name_a is the ellipse asked about; distance 0 if it collides
  std::string error;  ///< empty on success
  bool ok() const { return error.empty(); }
};

/// Of all ellipses the rules pair with the one named `name` (the name filter of checkScene() does
/// not apply), the one at the smallest distance(). If it collides with any, the answer is the
/// partner of smallest contactScale() at distance 0 (points at the origin). Ties go to the partner
/// first in CollidingPair order. Partners whose bounding circles are farther than the best distance
/// found so far are ruled out without calling distance(), as in checkScene(). Refused like
/// checkScene(), and when no ellipse is named `name`.
NearestResult nearestTo(const std::vector<NamedEllipse>& ellipses, const SceneRules& rules,
                        const std::string& name);
/// nearestTo() of the entries of `scene`.
NearestResult nearestTo(const Scene& scene, const SceneRules& rules, const std::string& name);

}  // namespace ellipse_collision::core

#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/ellipse.h"

namespace ellipse_collision {

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

/// Unordered name pairs that are never reported (an allowed-collision matrix).
class AllowedPairs {
 public:
  void add(const std::string& a, const std::string& b) { pairs_.insert(ordered(a, b)); }
  bool contains(const std::string& a, const std::string& b) const {
    return pairs_.count(ordered(a, b)) != 0;
  }
  std::size_t size() const { return pairs_.size(); }

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
};

/// Two ellipses in collision. name_a is the one of lower role (Query < Link < Obstacle), by name
/// within the same role.
struct CollidingPair {
  std::string name_a;
  std::string name_b;
  double contact_scale{
      0.0};  ///< contactScale(a, b): <= 1; both scaled by it about their centres touch
};

/// Either the colliding pairs or why the scene cannot be checked.
struct SceneCheckResult {
  std::vector<CollidingPair> collisions;  ///< sorted by (role_a, name_a, role_b, name_b)
  std::string error;                      ///< empty on success
  bool ok() const { return error.empty(); }
};

/// Whether the rules and the name filter ask for the pair (a, b) to be checked at all, before any
/// geometry. `only_names` empty means every pair; otherwise a pair is wanted iff at least one of
/// its names is listed (a listed name that is not in the scene matches nothing).
bool pairWanted(const NamedEllipse& a, const NamedEllipse& b, const SceneRules& rules,
                const std::set<std::string>& only_names);

/// Checks every wanted pair of `ellipses` with overlap() and reports the colliding ones with their
/// contactScale(). The result depends only on the set of ellipses, not on their order. Refused with
/// an error naming the entry: an empty or duplicate name, or an invalid ellipse.
SceneCheckResult checkScene(const std::vector<NamedEllipse>& ellipses, const SceneRules& rules,
                            const std::set<std::string>& only_names = {});

}  // namespace ellipse_collision

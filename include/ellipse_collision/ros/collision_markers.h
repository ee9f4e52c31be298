#pragma once

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision {

/// Builds the rviz view of a check: one flat CYLINDER per ellipse in the fixed frame (scale.x =
/// 2 radius_x, scale.y = 2 radius_y), namespace `links` or `obstacles`, red when in collision,
/// orange when apart but predicted to touch within ~prediction_horizon (names in `predicted`),
/// yellow when only in a warning pair, green otherwise; and in namespace `clearance` one LINE_LIST
/// segment per warning pair, between its witness points. No marker carries text (rviz warns about
/// text on other types). Ids are chosen by preferredId(), so an ellipse's marker can be found from
/// its name; an id is never reused for another name, and what the previous array showed but this
/// one does not gets a DELETE.
class CollisionMarkers {
 public:
  static constexpr double kThickness = 0.02;  ///< cylinder height [m]: flat, yet visible edge-on
  static constexpr double kLineWidth = 0.02;  ///< clearance lines [m]
  static constexpr const char* kClearanceNamespace = "clearance";

  /// The next MarkerArray to publish. `placed` holds links and obstacles (queries are skipped) in
  /// `fixed_frame`; `collisions` and `warnings` the check's pairs among them. Remembers what it
  /// returned, so call it only for arrays that are actually published.
  visualization_msgs::MarkerArray update(const std::vector<core::NamedEllipse>& placed,
                                         const std::vector<core::CollidingPair>& collisions,
                                         const std::vector<core::NearPair>& warnings,
                                         const std::string& fixed_frame, const ros::Time& stamp,
                                         const std::set<std::string>& predicted = {});

  static const char* nameSpace(core::EllipseRole role);

  /// The id of the ellipse named `name` in its namespace: a 31-bit FNV-1a hash of the name, the
  /// same in every run. Only if another name of the namespace took it first (a hash clash) does
  /// the ellipse get the next free id instead.
  static std::int32_t preferredId(const std::string& name);
  /// The same for the clearance line of a warning pair (names in the pair's order).
  static std::int32_t preferredId(const std::string& name_a, const std::string& name_b);

 private:
  using Key = std::pair<std::string, std::int32_t>;  // (ns, id)
  std::int32_t idFor(const std::string& ns, const std::string& key, std::int32_t preferred);

  struct Ids {
    std::map<std::string, std::int32_t> by_key;
    std::set<std::int32_t> taken;
  };
  std::map<std::string, Ids> ids_;  // ns -> ids handed out
  std::set<Key> shown_;
};

}  // namespace ellipse_collision

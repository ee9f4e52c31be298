#pragma once

#include <ros/time.h>
#include <visualization_msgs/MarkerArray.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/scene_check.h"

namespace ellipse_collision {

/// Builds the rviz view of a check: one flat CYLINDER per ellipse in the fixed frame (scale.x =
/// 2 radius_x, scale.y = 2 radius_y, text = the ellipse's name), namespace `links` or `obstacles`,
/// green when clear and red when in collision. A name keeps its id for the node's lifetime, and an
/// ellipse that was shown by the previous array but is gone now gets a DELETE.
class CollisionMarkers {
 public:
  static constexpr double kThickness = 0.02;  ///< cylinder height [m]: flat, yet visible edge-on

  /// The next MarkerArray to publish. `placed` holds links and obstacles (not queries) in
  /// `fixed_frame`; `colliding` the names that appear in a colliding pair. Remembers what it
  /// returned, so call it only for arrays that are actually published.
  visualization_msgs::MarkerArray update(const std::vector<NamedEllipse>& placed,
                                         const std::set<std::string>& colliding,
                                         const std::string& fixed_frame, const ros::Time& stamp);

  static const char* nameSpace(EllipseRole role);

 private:
  using Key = std::pair<std::string, int>;  // (ns, id)
  int idFor(const std::string& ns, const std::string& name);

  std::map<std::string, std::map<std::string, int>> ids_;  // ns -> name -> id
  std::set<Key> shown_;
};

}  // namespace ellipse_collision

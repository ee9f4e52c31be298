#include "ellipse_collision/ros/collision_markers.h"

#include <cmath>

namespace ellipse_collision {

const char* CollisionMarkers::nameSpace(EllipseRole role) {
  return role == EllipseRole::Link ? "links" : "obstacles";
}

int CollisionMarkers::idFor(const std::string& ns, const std::string& name) {
  std::map<std::string, int>& ids = ids_[ns];
  // Never reused: a name that comes back gets its old id, a new name the next free one.
  return ids.emplace(name, static_cast<int>(ids.size())).first->second;
}

visualization_msgs::MarkerArray CollisionMarkers::update(const std::vector<NamedEllipse>& placed,
                                                         const std::set<std::string>& colliding,
                                                         const std::string& fixed_frame,
                                                         const ros::Time& stamp) {
  visualization_msgs::MarkerArray array;
  std::set<Key> shown_now;
  for (const NamedEllipse& named : placed) {
    if (named.role == EllipseRole::Query) continue;
    visualization_msgs::Marker marker;
    marker.header.frame_id = fixed_frame;
    marker.header.stamp = stamp;
    marker.ns = nameSpace(named.role);
    marker.id = idFor(marker.ns, named.name);
    marker.type = visualization_msgs::Marker::CYLINDER;
    marker.text =
        named.name;  // rviz ignores it for cylinders; it tells tools which ellipse this is
    marker.action = visualization_msgs::Marker::ADD;
    marker.pose.position.x = named.ellipse.center.x();
    marker.pose.position.y = named.ellipse.center.y();
    marker.pose.position.z = 0.0;
    marker.pose.orientation.z = std::sin(named.ellipse.angle / 2);
    marker.pose.orientation.w = std::cos(named.ellipse.angle / 2);
    marker.scale.x = 2 * named.ellipse.radius_x;
    marker.scale.y = 2 * named.ellipse.radius_y;
    marker.scale.z = kThickness;
    const bool in_collision = colliding.count(named.name) != 0;
    marker.color.r = in_collision ? 0.9f : 0.1f;
    marker.color.g = in_collision ? 0.1f : 0.8f;
    marker.color.b = 0.1f;
    marker.color.a = 0.6f;
    shown_now.insert({marker.ns, marker.id});
    array.markers.push_back(marker);
  }
  for (const Key& key : shown_) {
    if (shown_now.count(key)) continue;
    visualization_msgs::Marker deletion;
    deletion.header.frame_id = fixed_frame;
    deletion.header.stamp = stamp;
    deletion.ns = key.first;
    deletion.id = key.second;
    deletion.action = visualization_msgs::Marker::DELETE;
    deletion.pose.orientation.w = 1.0;
    array.markers.push_back(deletion);
  }
  shown_ = std::move(shown_now);
  return array;
}

}  // namespace ellipse_collision

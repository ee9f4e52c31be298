#include "ellipse_collision/ros/collision_markers.h"

#include <cmath>

namespace ellipse_collision {
namespace {

using visualization_msgs::Marker;

constexpr std::uint32_t kIdMask = 0x7fffffffu;  // marker ids are int32; keep them >= 0

std::uint32_t fnv1a(const std::string& bytes, std::uint32_t hash = 2166136261u) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 16777619u;
  }
  return hash;
}

/// One string per ordered pair of names; the length first keeps ("ab", "c") and ("a", "bc") apart.
std::string pairKey(const std::string& name_a, const std::string& name_b) {
  return std::to_string(name_a.size()) + ":" + name_a + name_b;
}

/// A colour of the view (r, g, b in [0, 1]).
struct Colour {
  float r, g, b;
};
constexpr Colour kRed{0.9f, 0.1f, 0.1f};
constexpr Colour kYellow{0.9f, 0.85f, 0.1f};
constexpr Colour kOrange{1.0f, 0.5f, 0.0f};
constexpr Colour kGreen{0.1f, 0.8f, 0.1f};
constexpr float kEllipseAlpha = 0.6f;

void setColour(Marker& marker, const Colour& colour, float alpha) {
  marker.color.r = colour.r;
  marker.color.g = colour.g;
  marker.color.b = colour.b;
  marker.color.a = alpha;
}

Marker emptyMarker(const std::string& fixed_frame, const ros::Time& stamp, const std::string& ns,
                   std::int32_t id) {
  Marker marker;
  marker.header.frame_id = fixed_frame;
  marker.header.stamp = stamp;
  marker.ns = ns;
  marker.id = id;
  marker.pose.orientation.w = 1.0;
  return marker;
}

geometry_msgs::Point point(const Eigen::Vector2d& xy, double z) {
  geometry_msgs::Point p;
  p.x = xy.x();
  p.y = xy.y();
  p.z = z;
  return p;
}

}  // namespace

const char* CollisionMarkers::nameSpace(core::EllipseRole role) {
  return role == core::EllipseRole::Link ? "links" : "obstacles";
}

std::int32_t CollisionMarkers::preferredId(const std::string& name) {
  return static_cast<std::int32_t>(fnv1a(name) & kIdMask);
}

std::int32_t CollisionMarkers::preferredId(const std::string& name_a, const std::string& name_b) {
  return static_cast<std::int32_t>(fnv1a(pairKey(name_a, name_b)) & kIdMask);
}

std::int32_t CollisionMarkers::idFor(const std::string& ns, const std::string& key,
                                     std::int32_t preferred) {
  Ids& ids = ids_[ns];
  const auto known = ids.by_key.find(key);
  if (known != ids.by_key.end()) return known->second;
  // Never reused: a key that comes back finds its old id above, a clash takes the next free one.
  std::int32_t id = preferred;
  while (ids.taken.count(id)) {
    id = static_cast<std::int32_t>((static_cast<std::uint32_t>(id) + 1) & kIdMask);
  }
  ids.taken.insert(id);
  ids.by_key.emplace(key, id);
  return id;
}

visualization_msgs::MarkerArray CollisionMarkers::update(
    const std::vector<core::NamedEllipse>& placed,
    const std::vector<core::CollidingPair>& collisions, const std::vector<core::NearPair>& warnings,
    const std::string& fixed_frame, const ros::Time& stamp,
    const std::set<std::string>& predicted) {
  std::set<std::string> colliding;
  for (const core::CollidingPair& pair : collisions) colliding.insert({pair.name_a, pair.name_b});
  std::set<std::string> warned;
  for (const core::NearPair& pair : warnings) warned.insert({pair.name_a, pair.name_b});

  visualization_msgs::MarkerArray array;
  std::set<Key> shown_now;
  for (const core::NamedEllipse& named : placed) {
    if (named.role == core::EllipseRole::Query) continue;
    const std::string ns = nameSpace(named.role);
    Marker marker =
        emptyMarker(fixed_frame, stamp, ns, idFor(ns, named.name, preferredId(named.name)));
    marker.type = Marker::CYLINDER;
    marker.action = Marker::ADD;
    marker.pose.position.x = named.ellipse.center.x();
    marker.pose.position.y = named.ellipse.center.y();
    marker.pose.position.z = 0.0;
    marker.pose.orientation.z = std::sin(named.ellipse.angle / 2);
    marker.pose.orientation.w = std::cos(named.ellipse.angle / 2);
    marker.scale.x = 2 * named.ellipse.radius_x;
    marker.scale.y = 2 * named.ellipse.radius_y;
    marker.scale.z = kThickness;
    // A collision outranks a warning: an ellipse in both kinds of pair is red.
    const Colour& colour = colliding.count(named.name)   ? kRed
                           : predicted.count(named.name) ? kOrange
                           : warned.count(named.name)    ? kYellow
                                                         : kGreen;
    setColour(marker, colour, kEllipseAlpha);
    shown_now.insert({marker.ns, marker.id});
    array.markers.push_back(marker);
  }
  for (const core::NearPair& pair : warnings) {
    Marker line = emptyMarker(fixed_frame, stamp, kClearanceNamespace,
                              idFor(kClearanceNamespace, pairKey(pair.name_a, pair.name_b),
                                    preferredId(pair.name_a, pair.name_b)));
    line.type = Marker::LINE_LIST;
    line.action = Marker::ADD;
    line.scale.x = kLineWidth;
    // Just above the cylinders' top faces, so the line is not hidden inside them.
    line.points = {point(pair.point_a, kThickness), point(pair.point_b, kThickness)};
    setColour(line, kYellow, 1.0f);
    shown_now.insert({line.ns, line.id});
    array.markers.push_back(line);
  }
  for (const Key& key : shown_) {
    if (shown_now.count(key)) continue;
    Marker deletion = emptyMarker(fixed_frame, stamp, key.first, key.second);
    deletion.action = Marker::DELETE;
    array.markers.push_back(deletion);
  }
  shown_ = std::move(shown_now);
  return array;
}

}  // namespace ellipse_collision

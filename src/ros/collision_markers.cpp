#include "ellipse_collision/ros/collision_markers.h"

#include <utility>

#include "ellipse_collision/core/ellipse_polygon.h"
#include "ellipse_collision/ros/blank_marker.h"

namespace ellipse_collision {
namespace {

using visualization_msgs::Marker;
using Action = app::MarkerLayout::Action;

void setColour(Marker& marker, const MarkerStateStyle& style, float alpha) {
  marker.color.r = style.r;
  marker.color.g = style.g;
  marker.color.b = style.b;
  marker.color.a = alpha;
}

geometry_msgs::Point point(const Eigen::Vector2d& xy, double z) {
  geometry_msgs::Point p;
  p.x = xy.x();
  p.y = xy.y();
  p.z = z;
  return p;
}

}  // namespace

void CollisionMarkers::render(const app::MarkerLayout::Changes& changes,
                              visualization_msgs::MarkerArray& array) const {
  array.markers.reserve(array.markers.size() + changes.fills.size() + changes.lines.size());
  for (const app::MarkerLayout::FillChange& fill : changes.fills) {
    Marker marker = blankMarker(fixed_frame_, stamp_, nameSpace(fill.role), fill.id);
    if (fill.action == Action::Delete) {
      marker.action = Marker::DELETE;
      array.markers.push_back(std::move(marker));
      continue;
    }
    marker.type = Marker::TRIANGLE_LIST;
    marker.action = Marker::ADD;
    // rviz scales a triangle list's vertices by `scale`.
    marker.scale.x = marker.scale.y = marker.scale.z = 1.0;
    setColour(marker, style(fill.state), kEllipseAlpha);
    // Sized once and written in place: growing it point by point (and a vector of triangles per
    // marker before that) was a tenth of a cycle when every obstacle moves.
    std::size_t points = 0;
    for (std::size_t i = 0; i < fill.ellipses.size(); ++i) {
      points += core::ellipseTrianglePoints(fill.ellipses[i]);
    }
    marker.points.resize(points);
    geometry_msgs::Point* out = marker.points.data();
    for (std::size_t i = 0; i < fill.ellipses.size(); ++i) {
      core::forEachTrianglePoint(fill.ellipses[i],
                                 [&out](const Eigen::Vector2d& p) { *out++ = point(p, 0.0); });
    }
    array.markers.push_back(std::move(marker));
  }
  for (const app::MarkerLayout::LineChange& change : changes.lines) {
    Marker line = blankMarker(fixed_frame_, stamp_, kClearanceNamespace, change.id);
    if (change.action == Action::Delete) {
      line.action = Marker::DELETE;
      array.markers.push_back(std::move(line));
      continue;
    }
    line.type = Marker::LINE_LIST;
    line.action = Marker::ADD;
    line.scale.x = kLineWidth;
    // Just above the filled ellipses, so the line is drawn over them.
    line.points = {point(change.point_a, kLineHeight), point(change.point_b, kLineHeight)};
    setColour(line, style(MarkerState::Warning), 1.0f);
    array.markers.push_back(std::move(line));
  }
}

visualization_msgs::MarkerArray CollisionMarkers::update(
    const core::Scene& placed, const std::vector<core::CollidingPair>& collisions,
    const std::vector<core::NearPair>& warnings, const std::string& fixed_frame,
    const ros::Time& stamp, const std::set<std::string>& predicted) {
  fixed_frame_ = fixed_frame;
  stamp_ = stamp;
  visualization_msgs::MarkerArray array;
  render(layout_.update(placed, collisions, warnings, predicted), array);
  return array;
}

std::size_t CollisionMarkers::appendRefresh(visualization_msgs::MarkerArray& array,
                                            double fraction) {
  std::set<std::pair<std::string, std::int32_t>> in_array;
  for (const Marker& marker : array.markers) in_array.emplace(marker.ns, marker.id);
  const std::size_t before = array.markers.size();
  render(layout_.refresh(fraction, in_array), array);
  return array.markers.size() - before;
}

visualization_msgs::MarkerArray CollisionMarkers::fullArray() const {
  visualization_msgs::MarkerArray array;
  Marker clear = blankMarker(fixed_frame_, stamp_, "", 0);
  clear.action = Marker::DELETEALL;
  array.markers.push_back(clear);
  render(layout_.full(), array);
  return array;
}

}  // namespace ellipse_collision

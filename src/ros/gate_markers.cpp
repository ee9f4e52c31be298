#include "ellipse_collision/ros/gate_markers.h"

#include <array>
#include <cstdint>

#include "ellipse_collision/core/ellipse_polygon.h"
#include "ellipse_collision/ros/blank_marker.h"

namespace ellipse_collision {
namespace {

/// A closed outline of `ellipse` (its drawn polygon, first vertex repeated).
void outline(visualization_msgs::Marker& m, const core::Ellipse& ellipse, double width,
             const std_msgs::ColorRGBA& colour) {
  m.type = visualization_msgs::Marker::LINE_STRIP;
  m.action = visualization_msgs::Marker::ADD;
  m.scale.x = width;
  m.color = colour;
  std::array<Eigen::Vector2d, core::kMaxDrawSegments> vertices;
  const int n = core::drawnPolygonInto(ellipse, vertices.data());
  m.points.resize(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) {
    m.points[static_cast<std::size_t>(i)].x = vertices[static_cast<std::size_t>(i % n)].x();
    m.points[static_cast<std::size_t>(i)].y = vertices[static_cast<std::size_t>(i % n)].y();
  }
}

}  // namespace

visualization_msgs::MarkerArray GateMarkers::update(const app::GateDecision& decision,
                                                    const std::string& frame_id,
                                                    const ros::Time& stamp) {
  const app::GateMarkerLayout::Drawing drawing = layout_.update(decision);
  std_msgs::ColorRGBA colour;
  colour.r = drawing.colour.r;
  colour.g = drawing.colour.g;
  colour.b = drawing.colour.b;
  colour.a = drawing.colour.a;
  visualization_msgs::MarkerArray array;
  for (const app::GateMarkerLayout::Outline& shown : drawing.outlines) {
    visualization_msgs::Marker m = blankMarker(frame_id, stamp, shown.ns, shown.id);
    if (shown.show) {
      outline(m, shown.ellipse, shown.width, colour);
    } else {
      m.action = visualization_msgs::Marker::DELETE;
    }
    array.markers.push_back(std::move(m));
  }
  visualization_msgs::Marker contact =
      blankMarker(frame_id, stamp, app::GateMarkerLayout::kContactNamespace, 0);
  if (drawing.show_contact) {
    contact.type = visualization_msgs::Marker::SPHERE;
    contact.action = visualization_msgs::Marker::ADD;
    contact.pose.position.x = drawing.contact_point.x();
    contact.pose.position.y = drawing.contact_point.y();
    contact.scale.x = contact.scale.y = contact.scale.z = app::GateMarkerLayout::kContactSize;
    contact.color = colour;
  } else {
    contact.action = visualization_msgs::Marker::DELETE;
  }
  array.markers.push_back(std::move(contact));
  return array;
}

}  // namespace ellipse_collision

#include "ellipse_collision/ros/gate_markers.h"

#include <array>
#include <cstdint>

#include "ellipse_collision/core/ellipse_polygon.h"
#include "ellipse_collision/ros/blank_marker.h"

namespace ellipse_collision {
namespace {

std_msgs::ColorRGBA actionColour(app::GateAction action) {
  std_msgs::ColorRGBA colour;
  colour.a = 1.0f;
  switch (action) {
    case app::GateAction::Pass:
    case app::GateAction::Disabled:
      colour.g = 0.8f;
      break;
    case app::GateAction::Slow:
    case app::GateAction::Escape:
      colour.r = 1.0f;
      colour.g = 0.8f;
      break;
    default:
      colour.r = 1.0f;
      break;
  }
  return colour;
}

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
  visualization_msgs::MarkerArray array;
  const std_msgs::ColorRGBA colour = actionColour(decision.action);
  for (std::size_t i = 0; i < decision.outline.size(); ++i) {
    visualization_msgs::Marker m =
        blankMarker(frame_id, stamp, "gate_outline", static_cast<std::int32_t>(i));
    outline(m, decision.outline[i].ellipse, 0.01, colour);
    array.markers.push_back(std::move(m));
  }
  for (std::size_t i = decision.outline.size(); i < outline_count_; ++i) {
    visualization_msgs::Marker m =
        blankMarker(frame_id, stamp, "gate_outline", static_cast<std::int32_t>(i));
    m.action = visualization_msgs::Marker::DELETE;
    array.markers.push_back(std::move(m));
  }
  outline_count_ = decision.outline.size();

  visualization_msgs::Marker obstacle = blankMarker(frame_id, stamp, "gate_obstacle", 0);
  visualization_msgs::Marker contact = blankMarker(frame_id, stamp, "gate_contact", 0);
  if (decision.contact_predicted && !decision.obstacle.empty()) {
    outline(obstacle, decision.obstacle_ellipse, 0.03, colour);
    contact.type = visualization_msgs::Marker::SPHERE;
    contact.action = visualization_msgs::Marker::ADD;
    contact.pose.position.x = decision.contact_point.x();
    contact.pose.position.y = decision.contact_point.y();
    contact.scale.x = contact.scale.y = contact.scale.z = 0.08;
    contact.color = colour;
  } else {
    obstacle.action = visualization_msgs::Marker::DELETE;
    contact.action = visualization_msgs::Marker::DELETE;
  }
  array.markers.push_back(std::move(obstacle));
  array.markers.push_back(std::move(contact));
  return array;
}

}  // namespace ellipse_collision

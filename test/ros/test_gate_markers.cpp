// The gate's decision as rviz shows it (ros/gate_markers.h), read through test/ros/marker_view.h:
// every outline a closed line strip with its vertices on the ellipse's rim (long double), in the
// action's colour, in the given frame and stamp; the contact sphere at the contact point; what a
// later decision no longer draws deleted from the view. No master.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ellipse_collision/ros/gate_markers.h"
#include "marker_view.h"

namespace ellipse_collision {
namespace {

using app::GateMarkerLayout;

app::GateDecision decision(app::GateAction action, int links, bool contact) {
  app::GateDecision d;
  d.action = action;
  for (int i = 0; i < links; ++i) {
    d.outline.push_back({"link_" + std::to_string(i), core::EllipseRole::Link,
                         core::Ellipse{{0.5 * i, -0.25}, 0.3, 0.1, 0.2 * i}});
  }
  if (contact) {
    d.contact_predicted = true;
    d.obstacle = "crate";
    d.obstacle_ellipse = core::Ellipse{{2.0, 1.0}, 0.4, 0.2, -0.5};
    d.contact_point = {1.75, 0.5};
  }
  return d;
}

/// The largest |normalised form - 1| of the strip's vertices on `e`, in long double.
long double worstRimError(const visualization_msgs::Marker& m, const core::Ellipse& e) {
  const long double c = std::cos((long double)e.angle), s = std::sin((long double)e.angle);
  long double worst = 0;
  for (const geometry_msgs::Point& p : m.points) {
    const long double dx = p.x - (long double)e.center.x(), dy = p.y - (long double)e.center.y();
    const long double u = (c * dx + s * dy) / e.radius_x, v = (-s * dx + c * dy) / e.radius_y;
    worst = std::max(worst, std::fabs(u * u + v * v - 1));
  }
  return worst;
}

TEST(GateMarkers, OutlinesAreClosedStripsOnTheRimsInTheActionsColour) {
  GateMarkers markers;
  const app::GateDecision slow = decision(app::GateAction::Slow, 2, true);
  const ros::Time stamp(12, 500);
  const visualization_msgs::MarkerArray array = markers.update(slow, "map", stamp);
  const test::MarkerView view({array});
  ASSERT_EQ(view.shown().size(), 4u) << "two links, the obstacle, the contact";
  const GateMarkerLayout::Colour yellow = GateMarkerLayout::colourOf(app::GateAction::Slow);
  for (int i = 0; i < 2; ++i) {
    const visualization_msgs::Marker& m = view.shown().at({GateMarkerLayout::kOutlineNamespace, i});
    EXPECT_EQ(m.type, visualization_msgs::Marker::LINE_STRIP);
    EXPECT_EQ(m.header.frame_id, "map");
    EXPECT_EQ(m.header.stamp, stamp);
    EXPECT_EQ(m.scale.x, GateMarkerLayout::kOutlineWidth);
    EXPECT_EQ(m.color.r, yellow.r);
    EXPECT_EQ(m.color.g, yellow.g);
    EXPECT_EQ(m.color.a, yellow.a);
    ASSERT_GE(m.points.size(), 9u);
    EXPECT_EQ(m.points.front(), m.points.back()) << "closed";
    EXPECT_LT(worstRimError(m, slow.outline[i].ellipse), 1e-12L);
  }
  const visualization_msgs::Marker& obstacle =
      view.shown().at({GateMarkerLayout::kObstacleNamespace, 0});
  EXPECT_EQ(obstacle.scale.x, GateMarkerLayout::kObstacleWidth);
  EXPECT_LT(worstRimError(obstacle, slow.obstacle_ellipse), 1e-12L);
  const visualization_msgs::Marker& contact =
      view.shown().at({GateMarkerLayout::kContactNamespace, 0});
  EXPECT_EQ(contact.type, visualization_msgs::Marker::SPHERE);
  EXPECT_EQ(contact.pose.position.x, 1.75);
  EXPECT_EQ(contact.pose.position.y, 0.5);
  EXPECT_EQ(contact.scale.z, GateMarkerLayout::kContactSize);
  EXPECT_EQ(contact.color.g, yellow.g);
}

TEST(GateMarkers, WhatALaterDecisionNoLongerDrawsLeavesTheView) {
  GateMarkers markers;
  test::MarkerView view;
  view.apply(markers.update(decision(app::GateAction::Stop, 3, true), "odom", ros::Time(1)));
  ASSERT_EQ(view.shown().size(), 5u);
  const visualization_msgs::MarkerArray pass =
      markers.update(decision(app::GateAction::Pass, 1, false), "odom", ros::Time(2));
  view.apply(pass);
  ASSERT_EQ(view.shown().size(), 1u) << "one link left; obstacle and contact deleted";
  const visualization_msgs::Marker& link = view.shown().begin()->second;
  EXPECT_EQ(link.ns, GateMarkerLayout::kOutlineNamespace);
  const GateMarkerLayout::Colour green = GateMarkerLayout::colourOf(app::GateAction::Pass);
  EXPECT_EQ(link.color.g, green.g);
  EXPECT_EQ(link.color.r, green.r);
  // Deleted link outlines are not sent again; the obstacle and the contact are sent with every
  // decision, as DELETE while there is none.
  const visualization_msgs::MarkerArray again =
      markers.update(decision(app::GateAction::Pass, 1, false), "odom", ros::Time(3));
  ASSERT_EQ(again.markers.size(), 3u);
  int deletes = 0;
  for (const visualization_msgs::Marker& m : again.markers) {
    if (m.action == visualization_msgs::Marker::DELETE) {
      ++deletes;
      EXPECT_NE(m.ns, GateMarkerLayout::kOutlineNamespace);
    }
    EXPECT_EQ(m.header.stamp, ros::Time(3));
  }
  EXPECT_EQ(deletes, 2);
  view.apply(again);
  EXPECT_EQ(view.shown().size(), 1u);
}

}  // namespace
}  // namespace ellipse_collision

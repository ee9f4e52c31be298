// The gate's rviz drawing without ROS: what each decision shows, what it deletes, and the colour
// of each action from the one stop rule.
#include <gtest/gtest.h>

#include <string>

#include "ellipse_collision/app/gate_marker_layout.h"

namespace ellipse_collision::app {
namespace {

GateDecision decisionWithLinks(GateAction action, int links, bool limiting) {
  GateDecision decision;
  decision.action = action;
  for (int i = 0; i < links; ++i) {
    core::Ellipse e;
    e.center = {0.1 * i, 0.0};
    e.radius_x = 0.2;
    e.radius_y = 0.1;
    decision.outline.push_back({"link_" + std::to_string(i), core::EllipseRole::Link, e});
  }
  if (limiting) {
    decision.contact_predicted = true;
    decision.obstacle = "wall";
    decision.obstacle_ellipse.center = {2.0, 0.0};
    decision.obstacle_ellipse.radius_x = 0.05;
    decision.obstacle_ellipse.radius_y = 1.0;
    decision.contact_point = {1.9, 0.0};
  }
  return decision;
}

TEST(GateMarkerLayout, ShowsEachLinkAndTheLimitingPairThenDeletesWhatWentAway) {
  GateMarkerLayout layout;
  auto drawing = layout.update(decisionWithLinks(GateAction::Slow, 3, true));
  ASSERT_EQ(drawing.outlines.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_STREQ(drawing.outlines[i].ns, GateMarkerLayout::kOutlineNamespace);
    EXPECT_EQ(drawing.outlines[i].id, i);
    EXPECT_TRUE(drawing.outlines[i].show);
    EXPECT_DOUBLE_EQ(drawing.outlines[i].ellipse.center.x(), 0.1 * i);
  }
  EXPECT_STREQ(drawing.outlines[3].ns, GateMarkerLayout::kObstacleNamespace);
  EXPECT_TRUE(drawing.outlines[3].show);
  EXPECT_DOUBLE_EQ(drawing.outlines[3].ellipse.center.x(), 2.0);
  EXPECT_TRUE(drawing.show_contact);
  EXPECT_DOUBLE_EQ(drawing.contact_point.x(), 1.9);

  // One link and no contact: links 1 and 2, the obstacle and the contact are deleted, once.
  drawing = layout.update(decisionWithLinks(GateAction::Pass, 1, false));
  ASSERT_EQ(drawing.outlines.size(), 4u);
  EXPECT_TRUE(drawing.outlines[0].show);
  EXPECT_FALSE(drawing.outlines[1].show);
  EXPECT_EQ(drawing.outlines[1].id, 1);
  EXPECT_FALSE(drawing.outlines[2].show);
  EXPECT_EQ(drawing.outlines[2].id, 2);
  EXPECT_FALSE(drawing.outlines[3].show);
  EXPECT_FALSE(drawing.show_contact);
  drawing = layout.update(decisionWithLinks(GateAction::Pass, 1, false));
  EXPECT_EQ(drawing.outlines.size(), 2u) << "deleted ids are not deleted again";
}

TEST(GateMarkerLayout, ColourFollowsTheStopRule) {
  for (GateAction action :
       {GateAction::Pass, GateAction::Slow, GateAction::Stop, GateAction::Escape,
        GateAction::Timeout, GateAction::Incomplete, GateAction::Disabled}) {
    const auto colour = GateMarkerLayout::colourOf(action);
    const bool red = colour.r == 1.0f && colour.g == 0.0f;
    EXPECT_EQ(red, stops(action)) << toString(action);
  }
  const auto slow = GateMarkerLayout::colourOf(GateAction::Slow);
  EXPECT_EQ(slow.g, 0.8f);  // yellow
  const auto pass = GateMarkerLayout::colourOf(GateAction::Disabled);
  EXPECT_EQ(pass.r, 0.0f);  // green
}

}  // namespace
}  // namespace ellipse_collision::app

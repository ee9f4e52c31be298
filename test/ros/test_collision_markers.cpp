// rviz markers built from a check: shape, colour, namespaces, stable ids and deletion; no master.
#include <gtest/gtest.h>

#include <cmath>

#include "ellipse_collision/ros/collision_markers.h"

namespace ellipse_collision {
namespace {

NamedEllipse named(const std::string& name, EllipseRole role, double x = 0.0, double y = 0.0) {
  NamedEllipse e;
  e.name = name;
  e.role = role;
  e.ellipse.center = Eigen::Vector2d(x, y);
  e.ellipse.radius_x = 0.5;
  e.ellipse.radius_y = 0.2;
  e.ellipse.angle = 0.0;
  return e;
}

const visualization_msgs::Marker* find(const visualization_msgs::MarkerArray& array,
                                       const std::string& ns, int id) {
  for (const auto& m : array.markers) {
    if (m.ns == ns && m.id == id) return &m;
  }
  return nullptr;
}

const ros::Time kStamp(100, 5);

TEST(CollisionMarkers, EachEllipseIsAFlatCylinderWithItsPoseAndDiameters) {
  CollisionMarkers markers;
  NamedEllipse arm = named("arm", EllipseRole::Link, 1.0, 2.0);
  arm.ellipse.angle = M_PI / 3;
  const auto array = markers.update({arm}, {}, "odom", kStamp);
  ASSERT_EQ(array.markers.size(), 1u);
  const visualization_msgs::Marker& m = array.markers[0];
  EXPECT_EQ(m.header.frame_id, "odom");
  EXPECT_EQ(m.header.stamp, kStamp);
  EXPECT_EQ(m.type, visualization_msgs::Marker::CYLINDER);
  EXPECT_EQ(m.text, "arm");
  EXPECT_EQ(m.action, visualization_msgs::Marker::ADD);
  EXPECT_EQ(m.pose.position.x, 1.0);
  EXPECT_EQ(m.pose.position.y, 2.0);
  // Yaw of pi/3 as a quaternion about z: (0, 0, sin(pi/6), cos(pi/6)) = (0, 0, 1/2, sqrt(3)/2).
  EXPECT_NEAR(m.pose.orientation.z, 0.5, 1e-15);
  EXPECT_NEAR(m.pose.orientation.w, std::sqrt(3.0) / 2, 1e-15);
  EXPECT_EQ(m.scale.x, 1.0);
  EXPECT_EQ(m.scale.y, 0.4);
  EXPECT_EQ(m.scale.z, CollisionMarkers::kThickness);
}

TEST(CollisionMarkers, RedWhenInCollisionGreenWhenClear) {
  CollisionMarkers markers;
  const auto array = markers.update(
      {named("arm", EllipseRole::Link), named("box", EllipseRole::Obstacle)}, {"box"}, "m", kStamp);
  const auto* arm = find(array, "links", 0);
  const auto* box = find(array, "obstacles", 0);
  ASSERT_TRUE(arm && box);
  EXPECT_GT(arm->color.g, 0.5f);
  EXPECT_LT(arm->color.r, 0.5f);
  EXPECT_GT(box->color.r, 0.5f);
  EXPECT_LT(box->color.g, 0.5f);
  EXPECT_GT(box->color.a, 0.0f);
}

TEST(CollisionMarkers, LinksAndObstaclesHaveTheirOwnNamespacesAndQueriesAreNotDrawn) {
  CollisionMarkers markers;
  const auto array =
      markers.update({named("arm", EllipseRole::Link), named("probe", EllipseRole::Query),
                      named("box", EllipseRole::Obstacle)},
                     {}, "m", kStamp);
  ASSERT_EQ(array.markers.size(), 2u);
  EXPECT_EQ(array.markers[0].ns, "links");
  EXPECT_EQ(array.markers[1].ns, "obstacles");
}

TEST(CollisionMarkers, IdsStayWithTheirNamesWhateverTheOrder) {
  CollisionMarkers markers;
  const auto first = markers.update(
      {named("a", EllipseRole::Obstacle), named("b", EllipseRole::Obstacle)}, {}, "m", kStamp);
  const auto second =
      markers.update({named("c", EllipseRole::Obstacle), named("b", EllipseRole::Obstacle),
                      named("a", EllipseRole::Obstacle)},
                     {}, "m", kStamp);
  EXPECT_EQ(first.markers[0].id, 0);   // a
  EXPECT_EQ(first.markers[1].id, 1);   // b
  EXPECT_EQ(second.markers[0].id, 2);  // c, new
  EXPECT_EQ(second.markers[1].id, 1);  // b
  EXPECT_EQ(second.markers[2].id, 0);  // a
}

TEST(CollisionMarkers, VanishedEllipseIsDeletedOnceAndKeepsItsIdWhenItReturns) {
  CollisionMarkers markers;
  markers.update({named("a", EllipseRole::Obstacle), named("b", EllipseRole::Obstacle)}, {}, "m",
                 kStamp);
  const auto without_a = markers.update({named("b", EllipseRole::Obstacle)}, {}, "m", kStamp);
  const auto* deletion = find(without_a, "obstacles", 0);
  ASSERT_TRUE(deletion);
  EXPECT_EQ(deletion->action, visualization_msgs::Marker::DELETE);
  EXPECT_EQ(without_a.markers.size(), 2u);

  const auto again = markers.update({named("b", EllipseRole::Obstacle)}, {}, "m", kStamp);
  EXPECT_EQ(again.markers.size(), 1u);  // no second DELETE

  const auto back = markers.update(
      {named("b", EllipseRole::Obstacle), named("a", EllipseRole::Obstacle)}, {}, "m", kStamp);
  const auto* a = find(back, "obstacles", 0);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->action, visualization_msgs::Marker::ADD);
}

TEST(CollisionMarkers, SameNameInBothNamespacesGetsIndependentIds) {
  CollisionMarkers markers;
  markers.update({named("x", EllipseRole::Obstacle), named("y", EllipseRole::Obstacle)}, {}, "m",
                 kStamp);
  const auto array = markers.update({named("link", EllipseRole::Link)}, {}, "m", kStamp);
  const auto* link = find(array, "links", 0);
  ASSERT_TRUE(link);
  EXPECT_EQ(link->action, visualization_msgs::Marker::ADD);
}

}  // namespace
}  // namespace ellipse_collision

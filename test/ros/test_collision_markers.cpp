// rviz markers built from a check: shape, colour, namespaces, clearance lines, ids and deletion;
// no master.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "ellipse_collision/ros/collision_markers.h"

namespace ellipse_collision {
namespace {

core::NamedEllipse named(const std::string& name, core::EllipseRole role, double x = 0.0, double y = 0.0) {
  core::NamedEllipse e;
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

/// The marker of the ellipse `name`, found by the documented id rule.
const visualization_msgs::Marker* ellipseMarker(const visualization_msgs::MarkerArray& array,
                                                const std::string& ns, const std::string& name) {
  return find(array, ns, CollisionMarkers::preferredId(name));
}

bool isRed(const visualization_msgs::Marker& m) { return m.color.r > 0.5f && m.color.g < 0.5f; }
bool isGreen(const visualization_msgs::Marker& m) { return m.color.g > 0.5f && m.color.r < 0.5f; }
bool isYellow(const visualization_msgs::Marker& m) {
  return m.color.r > 0.5f && m.color.g > 0.5f && m.color.b < 0.5f;
}

core::NearPair nearPair(const std::string& a, const std::string& b, Eigen::Vector2d point_a,
                  Eigen::Vector2d point_b) {
  return core::NearPair{a, b, (point_b - point_a).norm(), point_a, point_b};
}

const ros::Time kStamp(100, 5);

TEST(CollisionMarkers, EachEllipseIsAFlatCylinderWithItsPoseAndDiametersAndNoText) {
  CollisionMarkers markers;
  core::NamedEllipse arm = named("arm", core::EllipseRole::Link, 1.0, 2.0);
  arm.ellipse.angle = M_PI / 3;
  const auto array = markers.update({arm}, {}, {}, "odom", kStamp);
  ASSERT_EQ(array.markers.size(), 1u);
  const visualization_msgs::Marker& m = array.markers[0];
  EXPECT_EQ(m.header.frame_id, "odom");
  EXPECT_EQ(m.header.stamp, kStamp);
  EXPECT_EQ(m.type, visualization_msgs::Marker::CYLINDER);
  EXPECT_EQ(m.text, "");  // rviz warns "Non-empty text is ignored" on every other type
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

TEST(CollisionMarkers, RedInCollisionYellowInAWarningPairGreenOtherwise) {
  CollisionMarkers markers;
  const auto array = markers.update(
      {named("arm", core::EllipseRole::Link), named("hand", core::EllipseRole::Link),
       named("box", core::EllipseRole::Obstacle), named("cup", core::EllipseRole::Obstacle),
       named("far", core::EllipseRole::Obstacle)},
      {{"arm", "box", 0.5}},
      {nearPair("arm", "cup", {0, 0}, {1, 0}), nearPair("hand", "cup", {0, 0}, {0, 1})}, "m",
      kStamp);
  const auto* arm = ellipseMarker(array, "links", "arm");
  const auto* hand = ellipseMarker(array, "links", "hand");
  const auto* box = ellipseMarker(array, "obstacles", "box");
  const auto* cup = ellipseMarker(array, "obstacles", "cup");
  const auto* far = ellipseMarker(array, "obstacles", "far");
  ASSERT_TRUE(arm && hand && box && cup && far);
  EXPECT_TRUE(isRed(*arm)) << "a collision outranks a warning";
  EXPECT_TRUE(isRed(*box));
  EXPECT_TRUE(isYellow(*hand));
  EXPECT_TRUE(isYellow(*cup));
  EXPECT_TRUE(isGreen(*far));
  EXPECT_FALSE(isYellow(*arm) || isYellow(*far) || isRed(*hand) || isGreen(*cup));
  EXPECT_GT(box->color.a, 0.0f);
}

bool isOrange(const visualization_msgs::Marker& m) {
  return m.color.r > 0.9f && m.color.g > 0.3f && m.color.g < 0.7f && m.color.b < 0.2f;
}

TEST(CollisionMarkers, OrangeForAPredictedContactBelowRedAboveYellow) {
  CollisionMarkers markers;
  const auto array = markers.update(
      {named("arm", core::EllipseRole::Link), named("hand", core::EllipseRole::Link),
       named("box", core::EllipseRole::Obstacle), named("cup", core::EllipseRole::Obstacle),
       named("far", core::EllipseRole::Obstacle)},
      {{"arm", "box", 0.5}}, {nearPair("hand", "cup", {0, 0}, {0, 1})}, "m", kStamp,
      {"arm", "hand", "far"});
  const auto* arm = ellipseMarker(array, "links", "arm");
  const auto* hand = ellipseMarker(array, "links", "hand");
  const auto* cup = ellipseMarker(array, "obstacles", "cup");
  const auto* far = ellipseMarker(array, "obstacles", "far");
  ASSERT_TRUE(arm && hand && cup && far);
  EXPECT_TRUE(isRed(*arm)) << "a collision outranks a predicted contact";
  EXPECT_TRUE(isOrange(*hand)) << "a predicted contact outranks a warning";
  EXPECT_TRUE(isOrange(*far));
  EXPECT_TRUE(isYellow(*cup));
  EXPECT_FALSE(isRed(*hand) || isYellow(*hand) || isGreen(*hand));
}

TEST(CollisionMarkers, LinksAndObstaclesHaveTheirOwnNamespacesAndQueriesAreNotDrawn) {
  CollisionMarkers markers;
  const auto array =
      markers.update({named("arm", core::EllipseRole::Link), named("probe", core::EllipseRole::Query),
                      named("box", core::EllipseRole::Obstacle)},
                     {}, {}, "m", kStamp);
  ASSERT_EQ(array.markers.size(), 2u);
  EXPECT_EQ(array.markers[0].ns, "links");
  EXPECT_EQ(array.markers[1].ns, "obstacles");
}

TEST(CollisionMarkers, IdsFollowTheNamesWhateverTheOrderOrHistory) {
  CollisionMarkers markers;
  const auto first = markers.update(
      {named("a", core::EllipseRole::Obstacle), named("b", core::EllipseRole::Obstacle)}, {}, {}, "m", kStamp);
  const auto second =
      markers.update({named("c", core::EllipseRole::Obstacle), named("b", core::EllipseRole::Obstacle),
                      named("a", core::EllipseRole::Obstacle)},
                     {}, {}, "m", kStamp);
  CollisionMarkers fresh;  // another run that meets the names in another order
  const auto other_run = fresh.update(
      {named("c", core::EllipseRole::Obstacle), named("a", core::EllipseRole::Obstacle)}, {}, {}, "m", kStamp);
  EXPECT_EQ(first.markers[0].id, second.markers[2].id);      // a
  EXPECT_EQ(first.markers[1].id, second.markers[1].id);      // b
  EXPECT_EQ(other_run.markers[0].id, second.markers[0].id);  // c
  EXPECT_EQ(other_run.markers[1].id, first.markers[0].id);   // a
  std::set<int> ids;
  for (const auto& m : second.markers) ids.insert(m.id);
  EXPECT_EQ(ids.size(), 3u);
}

TEST(CollisionMarkers, PreferredIdIsTheFnv1aHashOfTheNameInThirtyOneBits) {
  // FNV-1a 32 of "" is 0x811c9dc5 and of "a" 0xe40c292c (published test vectors), masked to 31
  // bits.
  EXPECT_EQ(CollisionMarkers::preferredId(""), 0x011c9dc5);
  EXPECT_EQ(CollisionMarkers::preferredId("a"), 0x640c292c);
  EXPECT_GE(CollisionMarkers::preferredId("\xff\xfe any name"), 0);
  EXPECT_NE(CollisionMarkers::preferredId("ab", "c"), CollisionMarkers::preferredId("a", "bc"));
  EXPECT_NE(CollisionMarkers::preferredId("a", "b"), CollisionMarkers::preferredId("b", "a"));
}

TEST(CollisionMarkers, HashClashGivesTheLaterNameTheNextFreeIdForGood) {
  // "costarring" and "liquid" are a known FNV-1a 32 collision.
  ASSERT_EQ(CollisionMarkers::preferredId("costarring"), CollisionMarkers::preferredId("liquid"));
  CollisionMarkers markers;
  const auto both = markers.update(
      {named("costarring", core::EllipseRole::Obstacle), named("liquid", core::EllipseRole::Obstacle)}, {}, {},
      "m", kStamp);
  const int preferred = CollisionMarkers::preferredId("liquid");
  EXPECT_EQ(both.markers[0].id, preferred);
  EXPECT_EQ(both.markers[1].id, preferred + 1);
  // liquid keeps its id even once costarring is gone.
  const auto later = markers.update({named("liquid", core::EllipseRole::Obstacle)}, {}, {}, "m", kStamp);
  EXPECT_EQ(ellipseMarker(later, "obstacles", "costarring")->action,
            visualization_msgs::Marker::DELETE);
  EXPECT_EQ(find(later, "obstacles", preferred + 1)->action, visualization_msgs::Marker::ADD);
}

TEST(CollisionMarkers, VanishedEllipseIsDeletedOnceAndKeepsItsIdWhenItReturns) {
  CollisionMarkers markers;
  markers.update({named("a", core::EllipseRole::Obstacle), named("b", core::EllipseRole::Obstacle)}, {}, {},
                 "m", kStamp);
  const auto without_a = markers.update({named("b", core::EllipseRole::Obstacle)}, {}, {}, "m", kStamp);
  const auto* deletion = ellipseMarker(without_a, "obstacles", "a");
  ASSERT_TRUE(deletion);
  EXPECT_EQ(deletion->action, visualization_msgs::Marker::DELETE);
  EXPECT_EQ(without_a.markers.size(), 2u);

  const auto again = markers.update({named("b", core::EllipseRole::Obstacle)}, {}, {}, "m", kStamp);
  EXPECT_EQ(again.markers.size(), 1u);  // no second DELETE

  const auto back = markers.update(
      {named("b", core::EllipseRole::Obstacle), named("a", core::EllipseRole::Obstacle)}, {}, {}, "m", kStamp);
  const auto* a = ellipseMarker(back, "obstacles", "a");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->action, visualization_msgs::Marker::ADD);
}

TEST(CollisionMarkers, SameNameInBothNamespacesIsNoClash) {
  CollisionMarkers markers;
  const auto array = markers.update(
      {named("x", core::EllipseRole::Obstacle), named("x", core::EllipseRole::Link)}, {}, {}, "m", kStamp);
  ASSERT_EQ(array.markers.size(), 2u);
  EXPECT_EQ(array.markers[0].id, CollisionMarkers::preferredId("x"));
  EXPECT_EQ(array.markers[1].id, CollisionMarkers::preferredId("x"));
}

TEST(CollisionMarkers, WarningPairIsALineBetweenItsWitnessPointsAboveTheEllipses) {
  CollisionMarkers markers;
  const auto array = markers.update(
      {named("arm", core::EllipseRole::Link), named("cup", core::EllipseRole::Obstacle, 3.0, 0.0)}, {},
      {nearPair("arm", "cup", {0.5, 0.25}, {2.5, -0.25})}, "odom", kStamp);
  const auto* line = find(array, CollisionMarkers::kClearanceNamespace,
                          CollisionMarkers::preferredId("arm", "cup"));
  ASSERT_TRUE(line);
  EXPECT_EQ(std::string(CollisionMarkers::kClearanceNamespace), "clearance");
  EXPECT_EQ(line->type, visualization_msgs::Marker::LINE_LIST);
  EXPECT_EQ(line->action, visualization_msgs::Marker::ADD);
  EXPECT_EQ(line->header.frame_id, "odom");
  EXPECT_EQ(line->text, "");
  EXPECT_EQ(line->scale.x, CollisionMarkers::kLineWidth);
  EXPECT_EQ(line->pose.orientation.w, 1.0);
  ASSERT_EQ(line->points.size(), 2u);
  EXPECT_EQ(line->points[0].x, 0.5);
  EXPECT_EQ(line->points[0].y, 0.25);
  EXPECT_EQ(line->points[1].x, 2.5);
  EXPECT_EQ(line->points[1].y, -0.25);
  // Above the cylinders' top faces (kThickness / 2), so it is not hidden inside them.
  EXPECT_GT(line->points[0].z, CollisionMarkers::kThickness / 2);
  EXPECT_EQ(line->points[1].z, line->points[0].z);
  EXPECT_TRUE(isYellow(*line));
  EXPECT_EQ(line->color.a, 1.0f);
}

TEST(CollisionMarkers, ClearanceLineKeepsItsIdAndIsDeletedWhenThePairGoesAway) {
  CollisionMarkers markers;
  const std::vector<core::NamedEllipse> placed = {named("arm", core::EllipseRole::Link),
                                            named("cup", core::EllipseRole::Obstacle),
                                            named("box", core::EllipseRole::Obstacle)};
  const int arm_cup = CollisionMarkers::preferredId("arm", "cup");
  const int arm_box = CollisionMarkers::preferredId("arm", "box");
  markers.update(placed, {}, {nearPair("arm", "cup", {0, 0}, {1, 0})}, "m", kStamp);
  const auto moved = markers.update(
      placed, {}, {nearPair("arm", "box", {0, 0}, {0, 1}), nearPair("arm", "cup", {0, 0}, {2, 0})},
      "m", kStamp);
  ASSERT_TRUE(find(moved, "clearance", arm_cup));
  EXPECT_EQ(find(moved, "clearance", arm_cup)->points[1].x, 2.0);
  ASSERT_TRUE(find(moved, "clearance", arm_box));

  const auto gone =
      markers.update(placed, {}, {nearPair("arm", "box", {0, 0}, {0, 1})}, "m", kStamp);
  ASSERT_TRUE(find(gone, "clearance", arm_cup));
  EXPECT_EQ(find(gone, "clearance", arm_cup)->action, visualization_msgs::Marker::DELETE);
  EXPECT_EQ(find(gone, "clearance", arm_box)->action, visualization_msgs::Marker::ADD);
  EXPECT_TRUE(isGreen(*ellipseMarker(gone, "obstacles", "cup")));

  const auto none = markers.update(placed, {}, {}, "m", kStamp);
  EXPECT_EQ(find(none, "clearance", arm_box)->action, visualization_msgs::Marker::DELETE);
  EXPECT_FALSE(find(none, "clearance", arm_cup));  // deleted once only
}

}  // namespace
}  // namespace ellipse_collision

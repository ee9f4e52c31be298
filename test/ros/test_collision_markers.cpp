// rviz markers built from a check, read as rviz would show them (MarkerView): which filled
// triangles cover each ellipse and in what colour, namespaces, clearance lines, stable ids,
// DELETE, and that only changes are sent; no master.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/ellipse_polygon.h"
#include "ellipse_collision/ros/collision_markers.h"
#include "marker_view.h"

namespace ellipse_collision {
namespace {

using test::fillOf;
using test::fillsOf;
using test::isGreen;
using test::isRed;
using test::isYellow;
using test::makeEllipse;
using test::MarkerView;
using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

core::NamedEllipse named(const std::string& name, core::EllipseRole role, double x = 0.0,
                         double y = 0.0) {
  core::NamedEllipse e;
  e.name = name;
  e.role = role;
  e.ellipse = makeEllipse(x, y, 0.5, 0.2);
  return e;
}
/// CollisionMarkers::update() of the entries, stored by column as the node stores them.
MarkerArray update(CollisionMarkers& markers, const std::vector<core::NamedEllipse>& placed,
                   const std::vector<core::CollidingPair>& collisions,
                   const std::vector<core::NearPair>& warnings, const std::string& fixed_frame,
                   const ros::Time& stamp, const std::set<std::string>& predicted = {}) {
  return markers.update(core::Scene(placed), collisions, warnings, fixed_frame, stamp, predicted);
}
constexpr core::EllipseRole kLink = core::EllipseRole::Link;
constexpr core::EllipseRole kObstacle = core::EllipseRole::Obstacle;

const Marker* find(const MarkerArray& array, const std::string& ns, int id) {
  for (const auto& m : array.markers) {
    if (m.ns == ns && m.id == id) return &m;
  }
  return nullptr;
}

core::NearPair nearPair(const std::string& a, const std::string& b, Eigen::Vector2d point_a,
                        Eigen::Vector2d point_b) {
  return core::NearPair{a, b, (point_b - point_a).norm(), point_a, point_b};
}

/// The triangles of a view's markers of one namespace, each as its sorted vertices, sorted: what
/// is drawn, whatever the order within and across markers.
std::vector<std::array<double, 6>> drawnTriangles(const MarkerView& view, const std::string& ns) {
  std::vector<std::array<double, 6>> triangles;
  for (const auto& [key, m] : view.shown()) {
    if (key.first != ns) continue;
    for (std::size_t i = 0; i + 2 < m.points.size(); i += 3) {
      std::array<std::pair<double, double>, 3> v{{{m.points[i].x, m.points[i].y},
                                                  {m.points[i + 1].x, m.points[i + 1].y},
                                                  {m.points[i + 2].x, m.points[i + 2].y}}};
      std::sort(v.begin(), v.end());
      triangles.push_back(
          {v[0].first, v[0].second, v[1].first, v[1].second, v[2].first, v[2].second});
    }
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

const ros::Time kStamp(100, 5);

TEST(CollisionMarkers, EachEllipseIsDrawnAsFilledTrianglesOnItsRimInTheFixedFrameAndNoText) {
  CollisionMarkers markers;
  core::NamedEllipse arm = named("arm", kLink, 1.0, 2.0);
  arm.ellipse.angle = M_PI / 3;
  const MarkerArray array = update(markers, {arm}, {}, {}, "odom", kStamp);
  ASSERT_EQ(array.markers.size(), 1u);
  const Marker& m = array.markers[0];
  EXPECT_EQ(m.header.frame_id, "odom");
  EXPECT_EQ(m.header.stamp, kStamp);
  EXPECT_EQ(m.type, Marker::TRIANGLE_LIST);
  EXPECT_EQ(m.action, Marker::ADD);
  EXPECT_EQ(m.ns, "links");
  EXPECT_EQ(m.text, "");  // rviz warns "Non-empty text is ignored" on every other type
  EXPECT_EQ(m.color.a, CollisionMarkers::kEllipseAlpha);
  EXPECT_EQ(m.points.size(), 3u * (core::drawSegments(arm.ellipse) - 2));
  MarkerView view;
  view.apply(array);
  EXPECT_EQ(fillOf(view, "links", arm.ellipse), &view.shown().begin()->second);
  // The same ellipse unrotated, shifted or resized is not what is drawn.
  EXPECT_FALSE(fillOf(view, "links", makeEllipse(1.0, 2.0, 0.5, 0.2, 0.0)));
  EXPECT_FALSE(fillOf(view, "links", makeEllipse(1.0, 2.01, 0.5, 0.2, M_PI / 3)));
  EXPECT_FALSE(fillOf(view, "links", makeEllipse(1.0, 2.0, 0.5, 0.21, M_PI / 3)));
  EXPECT_FALSE(fillOf(view, "obstacles", arm.ellipse));
}

TEST(CollisionMarkers, RedInCollisionYellowInAWarningPairGreenOtherwise) {
  CollisionMarkers markers;
  const std::vector<core::NamedEllipse> placed = {
      named("arm", kLink, 0, 0), named("hand", kLink, 0, 1), named("box", kObstacle, 0, 2),
      named("cup", kObstacle, 0, 3), named("far", kObstacle, 0, 4)};
  MarkerView view;
  view.apply(update(markers, 
      placed, {{"arm", "box", 0.5}},
      {nearPair("arm", "cup", {0, 0}, {1, 0}), nearPair("hand", "cup", {0, 0}, {0, 1})}, "m",
      kStamp));
  EXPECT_TRUE(isRed(fillOf(view, "links", placed[0].ellipse))) << "a collision outranks a warning";
  EXPECT_TRUE(isYellow(fillOf(view, "links", placed[1].ellipse)));
  EXPECT_TRUE(isRed(fillOf(view, "obstacles", placed[2].ellipse)));
  EXPECT_TRUE(isYellow(fillOf(view, "obstacles", placed[3].ellipse)));
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[4].ellipse)));
  // One marker per namespace and state: links red, links yellow, obstacles red, yellow, green.
  EXPECT_EQ(view.shown().size(), 5u + 2u);  // and two clearance lines
  EXPECT_EQ(fillOf(view, "links", placed[0].ellipse)->id,
            CollisionMarkers::fillId(MarkerState::Collision, 0));
  EXPECT_EQ(fillOf(view, "obstacles", placed[4].ellipse)->id,
            CollisionMarkers::fillId(MarkerState::Free, 0));
}

TEST(CollisionMarkers, StateTableIsInRankOrderWithDistinctCodesAndColours) {
  std::set<std::int32_t> codes;
  std::set<std::array<float, 3>> colours;
  for (std::size_t i = 0; i < kMarkerStates.size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(kMarkerStates[i].state), i);
    codes.insert(kMarkerStates[i].code);
    colours.insert({kMarkerStates[i].r, kMarkerStates[i].g, kMarkerStates[i].b});
  }
  EXPECT_EQ(codes.size(), kMarkerStates.size());
  EXPECT_EQ(colours.size(), kMarkerStates.size());
  EXPECT_STREQ(CollisionMarkers::style(MarkerState::Collision).name, "collision");
  // The colours the README's legend and the demo_screenshot test name.
  EXPECT_EQ(CollisionMarkers::style(MarkerState::Collision).r, 0.9f);
  EXPECT_EQ(CollisionMarkers::style(MarkerState::Warning).g, 0.85f);
  EXPECT_EQ(CollisionMarkers::style(MarkerState::Free).g, 0.8f);
  EXPECT_EQ(CollisionMarkers::style(MarkerState::Predicted).g, 0.5f);  // orange
}

bool isOrange(const Marker* m) {
  return m && m->color.r > 0.9f && m->color.g > 0.3f && m->color.g < 0.7f && m->color.b < 0.2f;
}

TEST(CollisionMarkers, OrangeForAPredictedContactBelowRedAboveYellow) {
  CollisionMarkers markers;
  const std::vector<core::NamedEllipse> placed = {
      named("arm", kLink, 0, 0), named("hand", kLink, 0, 1), named("box", kObstacle, 0, 2),
      named("cup", kObstacle, 0, 3), named("far", kObstacle, 0, 4)};
  MarkerView view;
  view.apply(update(markers, placed, {{"arm", "box", 0.5}},
                            {nearPair("hand", "cup", {0, 0}, {0, 1})}, "m", kStamp,
                            {"arm", "hand", "far"}));
  EXPECT_TRUE(isRed(fillOf(view, "links", placed[0].ellipse)))
      << "a collision outranks a predicted contact";
  EXPECT_TRUE(isOrange(fillOf(view, "links", placed[1].ellipse)))
      << "a predicted contact outranks a warning";
  EXPECT_TRUE(isOrange(fillOf(view, "obstacles", placed[4].ellipse)));
  EXPECT_TRUE(isYellow(fillOf(view, "obstacles", placed[3].ellipse)));
  EXPECT_FALSE(isRed(fillOf(view, "links", placed[1].ellipse)) ||
               isYellow(fillOf(view, "links", placed[1].ellipse)) ||
               isGreen(fillOf(view, "links", placed[1].ellipse)));
  EXPECT_EQ(fillOf(view, "links", placed[1].ellipse)->id,
            CollisionMarkers::fillId(MarkerState::Predicted, 0));
}

TEST(CollisionMarkers, LinksAndObstaclesHaveTheirOwnNamespacesAndQueriesAreNotDrawn) {
  CollisionMarkers markers;
  core::NamedEllipse probe = named("probe", core::EllipseRole::Query, 5, 5);
  const MarkerArray array = update(markers, 
      {named("arm", kLink), probe, named("box", kObstacle, 0, 3)}, {}, {}, "m", kStamp);
  ASSERT_EQ(array.markers.size(), 2u);
  EXPECT_EQ(array.markers[0].ns, "links");
  EXPECT_EQ(array.markers[1].ns, "obstacles");
  MarkerView view;
  view.apply(array);
  EXPECT_TRUE(fillsOf(view, "links", probe.ellipse).empty());
  EXPECT_TRUE(fillsOf(view, "obstacles", probe.ellipse).empty());
}

TEST(CollisionMarkers, SameNameInBothNamespacesIsDrawnInEach) {
  CollisionMarkers markers;
  MarkerView view;
  view.apply(
      update(markers, {named("x", kObstacle, 0, 0), named("x", kLink, 0, 1)}, {}, {}, "m", kStamp));
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", makeEllipse(0, 0, 0.5, 0.2))));
  EXPECT_TRUE(isGreen(fillOf(view, "links", makeEllipse(0, 1, 0.5, 0.2))));
}

TEST(CollisionMarkers, UnchangedSceneSendsNothingAndAChangeOnlyTheMarkersItTouches) {
  CollisionMarkers markers;
  std::vector<core::NamedEllipse> placed = {named("arm", kLink, 0, 0)};
  for (int i = 0; i < 1000; ++i) placed.push_back(named("o" + std::to_string(i), kObstacle, i, 10));
  MarkerView view;
  const MarkerArray first = update(markers, placed, {}, {}, "m", kStamp);
  view.apply(first);
  EXPECT_TRUE(update(markers, placed, {}, {}, "m", kStamp).markers.empty());
  EXPECT_TRUE(update(markers, placed, {}, {}, "m", ros::Time(101)).markers.empty()) << "time alone";

  // The link moves: only the link marker is sent.
  placed[0].ellipse.center.x() = 0.5;
  const MarkerArray moved = update(markers, placed, {}, {}, "m", kStamp);
  ASSERT_EQ(moved.markers.size(), 1u);
  EXPECT_EQ(moved.markers[0].ns, "links");
  view.apply(moved);
  EXPECT_TRUE(isGreen(fillOf(view, "links", placed[0].ellipse)));
  EXPECT_TRUE(fillsOf(view, "links", makeEllipse(0, 0, 0.5, 0.2)).empty());

  // One obstacle turns red: its bucket's green marker and a red one, nothing else; a small share
  // of the first array's bytes (1,000 obstacles are 32 buckets of about 31).
  const MarkerArray red = update(markers, placed, {{"arm", "o7", 0.5}}, {}, "m", kStamp);
  std::set<std::pair<std::string, int>> sent;
  for (const Marker& m : red.markers) sent.insert({m.ns, m.id});
  // links: red ADD, green DELETE (arm was its only ellipse); obstacles: red ADD, and the green
  // marker of o7's bucket without it.
  EXPECT_EQ(red.markers.size(), 4u);
  EXPECT_LT(test::wireBytes(red), test::wireBytes(first) / 10);
  view.apply(red);
  EXPECT_TRUE(isRed(fillOf(view, "links", placed[0].ellipse)));
  EXPECT_TRUE(isRed(fillOf(view, "obstacles", placed[8].ellipse)));  // o7
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[9].ellipse)));
  EXPECT_TRUE(update(markers, placed, {{"arm", "o7", 0.5}}, {}, "m", kStamp).markers.empty());
}

TEST(CollisionMarkers, VanishedEllipseIsRemovedFromItsMarkerAndAnEmptiedMarkerDeletedOnce) {
  CollisionMarkers markers;
  MarkerView view;
  view.apply(update(markers, {named("a", kObstacle, 0, 0), named("b", kObstacle, 0, 1)}, {}, {}, "m",
                            kStamp));
  ASSERT_TRUE(fillOf(view, "obstacles", makeEllipse(0, 0, 0.5, 0.2)));
  const int id = fillOf(view, "obstacles", makeEllipse(0, 0, 0.5, 0.2))->id;

  const MarkerArray without_a = update(markers, {named("b", kObstacle, 0, 1)}, {}, {}, "m", kStamp);
  ASSERT_EQ(without_a.markers.size(), 1u);
  EXPECT_EQ(without_a.markers[0].action, Marker::ADD);  // the green marker, now b alone
  view.apply(without_a);
  EXPECT_TRUE(fillsOf(view, "obstacles", makeEllipse(0, 0, 0.5, 0.2)).empty());
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", makeEllipse(0, 1, 0.5, 0.2))));

  const MarkerArray none = update(markers, {}, {}, {}, "m", kStamp);
  ASSERT_EQ(none.markers.size(), 1u);
  EXPECT_EQ(none.markers[0].action, Marker::DELETE);
  EXPECT_EQ(none.markers[0].ns, "obstacles");
  EXPECT_EQ(none.markers[0].id, id);
  view.apply(none);
  EXPECT_TRUE(view.shown().empty());
  EXPECT_TRUE(update(markers, {}, {}, {}, "m", kStamp).markers.empty()) << "deleted once only";

  const MarkerArray back = update(markers, {named("a", kObstacle, 0, 0)}, {}, {}, "m", kStamp);
  ASSERT_EQ(back.markers.size(), 1u);
  EXPECT_EQ(back.markers[0].id, id) << "the same state and bucket, the same id";
}

TEST(CollisionMarkers, AStateThatEmptiesIsDeletedAndTheEllipseShownInItsNewColour) {
  CollisionMarkers markers;
  const std::vector<core::NamedEllipse> placed = {named("arm", kLink, 0, 0),
                                                  named("box", kObstacle, 0, 1)};
  MarkerView view;
  view.apply(update(markers, placed, {{"arm", "box", 0.5}}, {}, "m", kStamp));
  const MarkerArray clear = update(markers, placed, {}, {}, "m", kStamp);
  int deletions = 0;
  for (const Marker& m : clear.markers) {
    if (m.action == Marker::DELETE) {
      ++deletions;
      EXPECT_EQ(m.id, CollisionMarkers::fillId(MarkerState::Collision, 0));
    }
  }
  EXPECT_EQ(deletions, 2);  // the red marker of links and of obstacles
  view.apply(clear);
  EXPECT_TRUE(isGreen(fillOf(view, "links", placed[0].ellipse)));
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[1].ellipse)));
  EXPECT_EQ(view.shown().size(), 2u);
}

TEST(CollisionMarkers, IdsDependOnStateAndPlaceNotOnTheOrderOfTheScene) {
  CollisionMarkers one;
  CollisionMarkers other;
  std::vector<core::NamedEllipse> placed;
  for (int i = 0; i < 2000; ++i) placed.push_back(named("o" + std::to_string(i), kObstacle, i, 0));
  std::vector<core::NamedEllipse> reversed(placed.rbegin(), placed.rend());
  update(one, {named("z", kObstacle)}, {}, {}, "m", kStamp);  // a different history
  MarkerView a;
  MarkerView b;
  a.apply(update(one, placed, {}, {}, "m", kStamp));
  b.apply(update(other, reversed, {}, {}, "m", kStamp));
  EXPECT_FALSE(drawnTriangles(a, "obstacles").empty());
  EXPECT_EQ(drawnTriangles(a, "obstacles"), drawnTriangles(b, "obstacles"));
  std::set<int> ids_a;
  std::set<int> ids_b;
  for (const auto& [key, m] : a.shown()) ids_a.insert(key.second);
  for (const auto& [key, m] : b.shown()) ids_b.insert(key.second);
  EXPECT_EQ(ids_a, ids_b);
  for (const int i : {0, 777, 1999}) {
    const Marker* fill = fillOf(a, "obstacles", placed[i].ellipse);
    ASSERT_TRUE(fill);
    EXPECT_EQ(fill->id, fillOf(b, "obstacles", placed[i].ellipse)->id);
  }
}

TEST(CollisionMarkers, ManyEllipsesAreSplitIntoBoundedMarkersThatRegroupWhenTheCountChanges) {
  CollisionMarkers markers;
  std::vector<core::NamedEllipse> placed;
  for (int i = 0; i < 10000; ++i) placed.push_back(named("o" + std::to_string(i), kObstacle, i, 0));
  MarkerView view;
  view.apply(update(markers, placed, {}, {}, "m", kStamp));
  // 10,000 / 32 -> 512 buckets, about 20 ellipses each.
  EXPECT_EQ(view.shown().size(), 512u);
  std::size_t points = 0;
  for (const auto& [key, m] : view.shown()) {
    // A bucket holds at most twice its mean share here (about 20 of each 10,000 / 512).
    EXPECT_LE(m.points.size(), 2 * CollisionMarkers::kEllipsesPerMarker * 3 *
                                   (core::drawSegments(placed[0].ellipse) - 2))
        << "bucket " << key.second;
    points += m.points.size();
  }
  EXPECT_EQ(points, 10000u * 3 * (core::drawSegments(placed[0].ellipse) - 2));  // each ellipse once
  for (const int i : {0, 1234, 9999})
    EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[i].ellipse)));

  // Down to 7 (fewer than a quarter of 32 per bucket even at B = 2): one bucket; the other 511
  // markers are deleted, the rest drawn again.
  placed.resize(7);
  view.apply(update(markers, placed, {}, {}, "m", kStamp));
  ASSERT_EQ(view.shown().size(), 1u);
  EXPECT_EQ(view.shown().begin()->second.id, CollisionMarkers::fillId(MarkerState::Free, 0));
  EXPECT_EQ(view.shown().begin()->second.points.size(),
            7u * 3 * (core::drawSegments(placed[0].ellipse) - 2));
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[6].ellipse)));
}

TEST(CollisionMarkers, BeyondAThousandBucketsTheBucketsGrowNotTheirCount) {
  // rviz spends a draw call per marker and frame (kMaxBuckets): 40,000 obstacles would be 2,048
  // buckets of about 20 at 32 per bucket; they are 1,024 of about 39.
  CollisionMarkers markers;
  std::vector<core::NamedEllipse> placed;
  for (int i = 0; i < 40000; ++i) placed.push_back(named("o" + std::to_string(i), kObstacle, i, 0));
  MarkerView view;
  view.apply(update(markers, placed, {}, {}, "m", kStamp));
  EXPECT_EQ(view.shown().size(), 1024u);
  const std::size_t per_ellipse = 3 * (core::drawSegments(placed[0].ellipse) - 2);
  std::size_t points = 0, largest = 0;
  for (const auto& [key, m] : view.shown()) {
    points += m.points.size();
    largest = std::max(largest, m.points.size());
  }
  EXPECT_EQ(points, 40000u * per_ellipse);  // each ellipse once
  EXPECT_GT(largest, 32u * per_ellipse);    // more than 32 per bucket now...
  EXPECT_LE(largest, 2u * 40000 / 1024 * per_ellipse);  // ...and at most twice the mean share
}

/// 10,000 obstacles on a 100 x 100 grid at 0.6 m (a 59.4 m square field), named row by row.
std::vector<core::NamedEllipse> gridOfObstacles() {
  std::vector<core::NamedEllipse> placed;
  for (int i = 0; i < 10000; ++i) {
    core::NamedEllipse e = named("o" + std::to_string(i), kObstacle, 0.6 * (i % 100), 0.6 * (i / 100));
    e.ellipse.radius_x = 0.2;
    e.ellipse.radius_y = 0.1;
    placed.push_back(e);
  }
  return placed;
}

/// The box a viewer culls a marker by: around all its points.
core::BoundingBox boxOfMarker(const Marker& m) {
  core::BoundingBox box{m.points[0].x, m.points[0].y, m.points[0].x, m.points[0].y};
  for (const auto& p : m.points) {
    box = {std::min(box.min_x, p.x), std::min(box.min_y, p.y), std::max(box.max_x, p.x),
           std::max(box.max_y, p.y)};
  }
  return box;
}

TEST(CollisionMarkers, BucketsAreByPlaceSoAViewOfOnePartOfTheFieldMeetsFewMarkers) {
  // rviz culls a marker whose box is out of view. Buckets by a hash of the name would each
  // spread over the whole field: every one of the 512 markers would meet any view.
  CollisionMarkers markers;
  const std::vector<core::NamedEllipse> placed = gridOfObstacles();
  MarkerView view;
  view.apply(update(markers, placed, {}, {}, "m", kStamp));
  ASSERT_EQ(view.shown().size(), 512u);
  const core::BoundingBox part{27.0, 27.0, 33.0, 33.0};  // 6 x 6 m in the middle: 1 % of it
  int meeting = 0;
  double area = 0.0;
  for (const auto& [key, m] : view.shown()) {
    const core::BoundingBox box = boxOfMarker(m);
    meeting += core::boxesOverlap(box, part);
    area += (box.max_x - box.min_x) * (box.max_y - box.min_y);
  }
  EXPECT_LE(meeting, 12);
  EXPECT_LE(area, 1.1 * 60.0 * 60.0) << "the markers' boxes barely overlap";
}

TEST(CollisionMarkers, AChangeInOnePlaceResendsOnlyTheMarkersOfThatPlace) {
  // A link touches six neighbouring obstacles: they turn red together. Hashed by name they would
  // sit in six buckets, twelve markers to re-send (six green, six red); by place in one or two.
  CollisionMarkers markers;
  std::vector<core::NamedEllipse> placed = gridOfObstacles();
  placed.push_back(named("arm", kLink, 30.0, 30.0));
  const MarkerArray first = update(markers, placed, {}, {}, "m", kStamp);
  std::vector<core::CollidingPair> touching;
  for (const int i : {5050, 5051, 5052, 5150, 5151, 5152}) {
    touching.push_back({"arm", "o" + std::to_string(i), 0.5});
  }
  const MarkerArray red = update(markers, placed, touching, {}, "m", kStamp);
  int obstacle_markers = 0;
  for (const Marker& m : red.markers) obstacle_markers += m.ns == "obstacles";
  EXPECT_LE(obstacle_markers, 4);
  EXPECT_LT(test::wireBytes(red), test::wireBytes(first) / 100);
  MarkerView view;
  view.apply(first);
  view.apply(red);
  for (const int i : {5050, 5152}) EXPECT_TRUE(isRed(fillOf(view, "obstacles", placed[i].ellipse)));
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[5053].ellipse)));
}

TEST(CollisionMarkers, AnEllipseThatCrossesTheFieldMovesToTheMarkerOfItsNewPlace) {
  CollisionMarkers markers;
  std::vector<core::NamedEllipse> placed = gridOfObstacles();
  MarkerView view;
  view.apply(update(markers, placed, {}, {}, "m", kStamp));
  const int old_id = fillOf(view, "obstacles", placed[0].ellipse)->id;
  placed[0].ellipse.center = {59.5, 59.7};  // corner to corner
  const MarkerArray moved = update(markers, placed, {}, {}, "m", kStamp);
  EXPECT_EQ(moved.markers.size(), 2u) << "the marker it left and the one it joined";
  view.apply(moved);
  const Marker* now = fillOf(view, "obstacles", placed[0].ellipse);
  ASSERT_TRUE(now);
  EXPECT_NE(now->id, old_id);
  const core::BoundingBox box = boxOfMarker(*now);
  EXPECT_GT(box.min_x, 40.0);  // a marker of that corner, not stretched across the field
  EXPECT_GT(box.min_y, 40.0);
  EXPECT_TRUE(fillsOf(view, "obstacles", makeEllipse(0, 0, 0.2, 0.1)).empty());
  EXPECT_TRUE(update(markers, placed, {}, {}, "m", kStamp).markers.empty());
}

/// A random scene that evolves update by update: moves, removals and returns among 600 names (10
/// links), a crowd of 3,000 obstacles arriving at cycle 20 (B changes), and collisions and
/// warnings among them.
class EvolvingScene {
 public:
  struct Step {
    std::vector<core::NamedEllipse> placed;
    std::vector<core::CollidingPair> collisions;
    std::vector<core::NearPair> warnings;
  };

  explicit EvolvingScene(unsigned seed) : random_(seed) {
    for (int i = 0; i < 600; ++i) scene_[nameOf(i)] = named(nameOf(i), roleOf(i), i % 30, i / 30);
  }

  Step next(int cycle) {
    for (int k = 0; k < 20; ++k) {  // moves, removals and returns
      const int i = pick_(random_);
      if (scene_.count(nameOf(i)) && k % 4 == 0) {
        scene_.erase(nameOf(i));
      } else {
        scene_[nameOf(i)] = named(nameOf(i), roleOf(i), i % 30 + shift_(random_), i / 30);
      }
    }
    if (cycle == 20) {  // a crowd arrives: the obstacles are regrouped into more buckets
      for (int i = 0; i < 3000; ++i)
        scene_["c" + std::to_string(i)] = named("c" + std::to_string(i), kObstacle, i, 50);
    }
    Step step;
    for (const auto& [name, e] : scene_) step.placed.push_back(e);
    for (int k = 0; k < 5; ++k) {
      const int i = pick_(random_);
      const std::string other = "o" + std::to_string(10 + i % 590);
      if (!scene_.count(other)) continue;
      if (k % 2) {
        step.collisions.push_back({"l" + std::to_string(i % 10), other, 0.5});
      } else {
        step.warnings.push_back(
            nearPair("l" + std::to_string(i % 10), other, {0, 0}, {shift_(random_), 1}));
      }
    }
    return step;
  }

  const std::map<std::string, core::NamedEllipse>& scene() const { return scene_; }
  static std::string nameOf(int i) { return (i < 10 ? "l" : "o") + std::to_string(i); }

 private:
  static core::EllipseRole roleOf(int i) { return i < 10 ? kLink : kObstacle; }

  std::mt19937 random_;
  std::uniform_int_distribution<int> pick_{0, 599};
  std::uniform_real_distribution<double> shift_{-0.5, 0.5};
  std::map<std::string, core::NamedEllipse> scene_;
};

MarkerArray update(CollisionMarkers& markers, const EvolvingScene::Step& step) {
  return update(markers, step.placed, step.collisions, step.warnings, "m", kStamp);
}

/// Whether `view` draws what `truth` draws: the same markers, colours and triangles.
::testing::AssertionResult sameDrawing(const MarkerView& view, const MarkerView& truth) {
  if (view.shown().size() != truth.shown().size()) {
    return ::testing::AssertionFailure()
           << view.shown().size() << " markers shown, " << truth.shown().size() << " wanted";
  }
  for (const auto& [key, m] : truth.shown()) {
    const Marker* mine = view.find(key.first, key.second);
    if (!mine) return ::testing::AssertionFailure() << key.first << "/" << key.second << " missing";
    if (mine->color.r != m.color.r || mine->color.g != m.color.g) {
      return ::testing::AssertionFailure() << key.first << "/" << key.second << " colour differs";
    }
  }
  for (const std::string ns : {"links", "obstacles", "clearance"}) {
    if (drawnTriangles(view, ns) != drawnTriangles(truth, ns)) {
      return ::testing::AssertionFailure() << ns << ": other triangles drawn";
    }
  }
  return ::testing::AssertionSuccess();
}

MarkerView viewOf(const MarkerArray& array) {
  MarkerView view;
  view.apply(array);
  return view;
}

TEST(CollisionMarkers, EllipsesCrowdingIntoOnePlaceAreCutAnewThereSoNoMarkerGrowsUnbounded) {
  // 10,000 obstacles on the grid (512 buckets of about 20); then 600 new ones appear in one
  // spot, as where a robot maps new ground: their cell would hold 600, re-sent whole on every
  // change there. The part of the field around it is cut anew in that same update; the rest of
  // the field keeps its markers and sends nothing.
  CollisionMarkers markers;
  std::vector<core::NamedEllipse> placed = gridOfObstacles();
  MarkerView view;
  const MarkerArray first = update(markers, placed, {}, {}, "m", kStamp);
  view.apply(first);
  ASSERT_EQ(view.shown().size(), 512u);
  for (int i = 0; i < 600; ++i) {
    core::NamedEllipse e = named("new" + std::to_string(i), kObstacle, 10.0 + 0.001 * (i % 23),
                                 10.0 + 0.001 * i);
    e.ellipse.radius_x = 0.2;
    e.ellipse.radius_y = 0.1;
    placed.push_back(e);
  }
  const MarkerArray crowded = update(markers, placed, {}, {}, "m", kStamp);
  EXPECT_LE(crowded.markers.size(), 64u) << "a part of the field, not all 512 markers";
  EXPECT_LT(test::wireBytes(crowded), test::wireBytes(first) / 4);
  view.apply(crowded);
  const std::size_t per_ellipse = 3 * (core::drawSegments(placed[0].ellipse) - 2);
  std::size_t largest = 0, points = 0;
  for (const auto& [key, m] : view.shown()) {
    largest = std::max(largest, m.points.size());
    points += m.points.size();
  }
  EXPECT_EQ(points, 10600u * per_ellipse) << "each ellipse drawn once";
  EXPECT_LE(largest, 2u * 32 * per_ellipse);
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[10599].ellipse)));
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[9999].ellipse)));
  EXPECT_TRUE(sameDrawing(view, viewOf(markers.fullArray())));
  EXPECT_TRUE(update(markers, placed, {}, {}, "m", kStamp).markers.empty()) << "and it settles";

  // Many at one point, which no cut can part: cut once, then left as they are.
  for (int i = 0; i < 300; ++i) placed.push_back(named("same" + std::to_string(i), kObstacle, 40, 40));
  EXPECT_FALSE(update(markers, placed, {}, {}, "m", kStamp).markers.empty());
  EXPECT_TRUE(update(markers, placed, {}, {}, "m", kStamp).markers.empty()) << "not cut again";
}

TEST(CollisionMarkers, ChangesAppliedInOrderShowWhatTheFullArrayShows) {
  // A random scene evolves; after every update the view built from the changes alone must equal
  // the view a new subscriber builds from fullArray() (which starts with DELETEALL).
  EvolvingScene evolving(16);
  CollisionMarkers markers;
  MarkerView changes;
  changes.apply(MarkerArray());  // nothing yet
  for (int cycle = 0; cycle < 40; ++cycle) {
    const EvolvingScene::Step step = evolving.next(cycle);
    changes.apply(update(markers, step));
    ASSERT_TRUE(sameDrawing(changes, viewOf(markers.fullArray()))) << "cycle " << cycle;
    // And every ellipse is drawn once, in the colour of its state.
    std::set<std::string> colliding;
    for (const auto& c : step.collisions) colliding.insert({c.name_a, c.name_b});
    for (const int i : {0, 5, 100, 333, 599}) {
      const std::string name = EvolvingScene::nameOf(i);
      if (!evolving.scene().count(name)) continue;
      const Marker* fill =
          fillOf(changes, i < 10 ? "links" : "obstacles", evolving.scene().at(name).ellipse);
      ASSERT_TRUE(fill) << name;
      if (colliding.count(name)) {
        EXPECT_TRUE(isRed(*fill)) << name;
      }
    }
  }
}

TEST(CollisionMarkers, ASubscriberThatLostArraysIsWholeAgainOneRefreshPeriodAfterTheLastLoss) {
  // Two builders see the same evolving scene; a slow subscriber of each loses the same half of
  // the arrays in the first 40 cycles (a publisher queue overflowing), then receives everything.
  // With a refresh sweep of 10 updates the view is whole 10 updates after the last loss, while
  // the scene keeps changing; without it the losses stay.
  EvolvingScene evolving(21);
  CollisionMarkers refreshing, plain;
  MarkerView healed, broken;
  std::mt19937 losses(5);
  constexpr double kPerUpdate = 0.1;  // of the refresh period
  for (int cycle = 0; cycle < 60; ++cycle) {
    const EvolvingScene::Step step = evolving.next(cycle);
    MarkerArray with_refresh = update(refreshing, step);
    refreshing.appendRefresh(with_refresh, kPerUpdate);
    const MarkerArray without = update(plain, step);
    const bool lost = cycle < 40 && losses() % 2 == 0;
    if (!lost) {
      healed.apply(with_refresh);
      broken.apply(without);
    }
    if (cycle >= 50) {
      EXPECT_TRUE(sameDrawing(healed, viewOf(refreshing.fullArray()))) << "cycle " << cycle;
    }
  }
  EXPECT_FALSE(sameDrawing(broken, viewOf(plain.fullArray())))
      << "the losses changed nothing: this test shows no healing";
}

TEST(CollisionMarkers, RefreshSweepResendsEveryMarkerOncePerPeriodAsItIsAndDeletesWhatWentAway) {
  CollisionMarkers markers;
  std::vector<core::NamedEllipse> placed = {named("arm", kLink), named("hand", kLink, 0, 1)};
  for (int i = 0; i < 200; ++i) placed.push_back(named("o" + std::to_string(i), kObstacle, i, 5));
  update(markers, placed, {{"arm", "o1", 0.5}}, {nearPair("arm", "o2", {0, 0}, {1, 5})}, "m",
         kStamp);
  // The collision and the warning end: their red fill and the line are deleted, once.
  const MarkerArray ended = update(markers, placed, {}, {}, "m", kStamp);
  std::set<std::pair<std::string, int>> deleted;
  for (const Marker& m : ended.markers) {
    if (m.action == Marker::DELETE) deleted.emplace(m.ns, m.id);
  }
  // Red for arm (links) and o1 (obstacles), yellow for o2 (arm is red), and the line.
  ASSERT_EQ(deleted.size(), 4u);

  // The scene stands still: each update sends nothing but a quarter of the sweep.
  const MarkerView truth = viewOf(markers.fullArray());
  std::map<std::pair<std::string, int>, int> resent;
  MarkerView view = truth;
  for (int k = 0; k < 4; ++k) {
    MarkerArray array = update(markers, placed, {}, {}, "m", kStamp);
    ASSERT_TRUE(array.markers.empty());
    const std::size_t appended = markers.appendRefresh(array, 0.25);
    EXPECT_EQ(appended, array.markers.size());
    EXPECT_GT(appended, 0u);
    for (const Marker& m : array.markers) ++resent[{m.ns, m.id}];
    view.apply(array);
  }
  // Every marker shown once more, and every deleted id deleted once more; nothing else.
  std::map<std::pair<std::string, int>, int> wanted;
  for (const auto& [key, m] : truth.shown()) wanted[key] = 1;
  for (const auto& key : deleted) wanted[key] = 1;
  EXPECT_EQ(resent, wanted);
  EXPECT_TRUE(sameDrawing(view, truth));

  // No share, no markers; a long gap owes one sweep, not five.
  MarkerArray none;
  EXPECT_EQ(markers.appendRefresh(none, 0.0), 0u);
  EXPECT_TRUE(none.markers.empty());
  MarkerArray gap;
  EXPECT_EQ(markers.appendRefresh(gap, 5.0), wanted.size());
}

TEST(CollisionMarkers, RefreshSkipsWhatTheArrayAlreadySendsSoNoIdGoesTwice) {
  CollisionMarkers markers;
  std::vector<core::NamedEllipse> placed = {named("arm", kLink)};
  for (int i = 0; i < 100; ++i) placed.push_back(named("o" + std::to_string(i), kObstacle, i, 5));
  update(markers, placed, {}, {}, "m", kStamp);
  placed[0].ellipse.center.x() += 0.5;  // the arm's marker changes
  MarkerArray array = update(markers, placed, {}, {}, "m", kStamp);
  ASSERT_EQ(array.markers.size(), 1u);
  const std::size_t appended = markers.appendRefresh(array, 1.0);  // a whole sweep at once
  std::set<std::pair<std::string, int>> ids;
  for (const Marker& m : array.markers) {
    EXPECT_TRUE(ids.emplace(m.ns, m.id).second) << m.ns << "/" << m.id << " twice";
  }
  EXPECT_EQ(appended + 1, viewOf(markers.fullArray()).shown().size());
  EXPECT_TRUE(sameDrawing(viewOf(array), viewOf(markers.fullArray())));
}

TEST(CollisionMarkers, FullArrayStartsWithDeleteAll) {
  CollisionMarkers markers;
  update(markers, {named("a", kObstacle)}, {}, {}, "m", kStamp);
  const MarkerArray full = markers.fullArray();
  ASSERT_EQ(full.markers.size(), 2u);
  EXPECT_EQ(full.markers[0].action, Marker::DELETEALL);
  EXPECT_EQ(full.markers[1].action, Marker::ADD);
}

/// FNV-1a, 32 bits, written from its definition: the test's own.
std::uint32_t fnv1aOracle(const std::string& bytes) {
  std::uint32_t hash = 0x811c9dc5u;
  for (const unsigned char c : bytes) hash = (hash ^ c) * 0x01000193u;
  return hash;
}

TEST(CollisionMarkers, ClearanceLineIdIsTheFnv1aHashOfThePairInThirtyOneBits) {
  // The oracle first, on published test vectors: "" -> 0x811c9dc5, "a" -> 0xe40c292c.
  ASSERT_EQ(fnv1aOracle(""), 0x811c9dc5u);
  ASSERT_EQ(fnv1aOracle("a"), 0xe40c292cu);
  // The pair's key is the first name's length, ':', then both names.
  EXPECT_EQ(CollisionMarkers::preferredId("arm", "box"),
            static_cast<std::int32_t>(fnv1aOracle("3:armbox") & 0x7fffffffu));
  EXPECT_GE(CollisionMarkers::preferredId("\xff\xfe any name", "b"), 0);
  EXPECT_NE(CollisionMarkers::preferredId("ab", "c"), CollisionMarkers::preferredId("a", "bc"));
  EXPECT_NE(CollisionMarkers::preferredId("a", "b"), CollisionMarkers::preferredId("b", "a"));
}

TEST(CollisionMarkers, ClearanceHashClashGivesTheLaterPairTheNextFreeIdWhileItIsShown) {
  // ("arm", "o398824") and ("arm", "o768140") clash in 31-bit FNV-1a (found by search).
  ASSERT_EQ(CollisionMarkers::preferredId("arm", "o398824"),
            CollisionMarkers::preferredId("arm", "o768140"));
  const int preferred = CollisionMarkers::preferredId("arm", "o398824");
  const std::vector<core::NamedEllipse> placed = {
      named("arm", kLink), named("o398824", kObstacle, 0, 2), named("o768140", kObstacle, 0, 4)};
  CollisionMarkers markers;
  const MarkerArray both = update(markers, 
      placed, {},
      {nearPair("arm", "o398824", {0, 0}, {0, 1}), nearPair("arm", "o768140", {0, 0}, {0, 2})}, "m",
      kStamp);
  ASSERT_TRUE(find(both, "clearance", preferred));
  ASSERT_TRUE(find(both, "clearance", preferred + 1));
  EXPECT_EQ(find(both, "clearance", preferred)->points[1].y, 1.0);
  EXPECT_EQ(find(both, "clearance", preferred + 1)->points[1].y, 2.0);
  // The later pair keeps its id once the first is gone.
  const MarkerArray later =
      update(markers, placed, {}, {nearPair("arm", "o768140", {0, 0}, {0, 3})}, "m", kStamp);
  EXPECT_EQ(find(later, "clearance", preferred)->action, Marker::DELETE);
  EXPECT_EQ(find(later, "clearance", preferred + 1)->action, Marker::ADD);
  EXPECT_EQ(find(later, "clearance", preferred + 1)->points[1].y, 3.0);
  // Once both are gone, nothing of them is kept: the later pair comes back on its preferred id.
  const MarkerArray none = update(markers, placed, {}, {}, "m", kStamp);
  EXPECT_EQ(find(none, "clearance", preferred + 1)->action, Marker::DELETE);
  const MarkerArray back =
      update(markers, placed, {}, {nearPair("arm", "o768140", {0, 0}, {0, 4})}, "m", kStamp);
  ASSERT_TRUE(find(back, "clearance", preferred));
  EXPECT_EQ(find(back, "clearance", preferred)->action, Marker::ADD);
  EXPECT_EQ(find(back, "clearance", preferred)->points[1].y, 4.0);
}

TEST(CollisionMarkers, LinesOfPairsLongGoneLeaveTheRefreshSweep) {
  // A new pair comes near and goes every update, 3 x kSweptLineDeletions of them (tracked
  // obstacles with ever new names): the sweep sends DELETE for the last kSweptLineDeletions lines
  // deleted only, and the ADD of the one line shown.
  const std::size_t pairs = 3 * CollisionMarkers::kSweptLineDeletions;
  CollisionMarkers markers;
  for (std::size_t k = 0; k < pairs; ++k) {
    const std::string track = "track_" + std::to_string(k);
    update(markers, {named("arm", kLink), named(track, kObstacle, 0, 2)}, {},
           {nearPair("arm", track, {0, 0}, {0, 1})}, "m", kStamp);
  }
  // The last line goes too.
  MarkerArray sweep = update(markers, {named("arm", kLink)}, {}, {}, "m", kStamp);
  sweep.markers.clear();
  markers.appendRefresh(sweep, 1.0);
  std::size_t line_deletions = 0;
  for (const Marker& m : sweep.markers) {
    if (m.ns == "clearance") {
      EXPECT_EQ(m.action, Marker::DELETE);
      ++line_deletions;
    }
  }
  EXPECT_EQ(line_deletions, CollisionMarkers::kSweptLineDeletions);
  // The newest are among them, the oldest not.
  const auto swept = [&sweep](const std::string& track) {
    return find(sweep, "clearance", CollisionMarkers::preferredId("arm", track)) != nullptr;
  };
  EXPECT_TRUE(swept("track_" + std::to_string(pairs - 1)));
  EXPECT_FALSE(swept("track_0"));
}

TEST(CollisionMarkers, WarningPairIsALineBetweenItsWitnessPointsAboveTheEllipses) {
  CollisionMarkers markers;
  const MarkerArray array =
      update(markers, {named("arm", kLink), named("cup", kObstacle, 3.0, 0.0)}, {},
                     {nearPair("arm", "cup", {0.5, 0.25}, {2.5, -0.25})}, "odom", kStamp);
  const Marker* line = find(array, CollisionMarkers::kClearanceNamespace,
                            CollisionMarkers::preferredId("arm", "cup"));
  ASSERT_TRUE(line);
  EXPECT_EQ(std::string(CollisionMarkers::kClearanceNamespace), "clearance");
  EXPECT_EQ(line->type, Marker::LINE_LIST);
  EXPECT_EQ(line->action, Marker::ADD);
  EXPECT_EQ(line->header.frame_id, "odom");
  EXPECT_EQ(line->text, "");
  EXPECT_EQ(line->scale.x, CollisionMarkers::kLineWidth);
  EXPECT_EQ(line->pose.orientation.w, 1.0);
  ASSERT_EQ(line->points.size(), 2u);
  EXPECT_EQ(line->points[0].x, 0.5);
  EXPECT_EQ(line->points[0].y, 0.25);
  EXPECT_EQ(line->points[1].x, 2.5);
  EXPECT_EQ(line->points[1].y, -0.25);
  // Above the filled ellipses (z = 0), so it is drawn over them.
  EXPECT_GT(line->points[0].z, 0.0);
  EXPECT_EQ(line->points[1].z, line->points[0].z);
  EXPECT_TRUE(isYellow(*line));
  EXPECT_EQ(line->color.a, 1.0f);
}

TEST(CollisionMarkers, ClearanceLineIsResentWhenItMovesAndDeletedOnceWhenThePairGoesAway) {
  CollisionMarkers markers;
  const std::vector<core::NamedEllipse> placed = {
      named("arm", kLink), named("cup", kObstacle, 0, 2), named("box", kObstacle, 0, 4)};
  const int arm_cup = CollisionMarkers::preferredId("arm", "cup");
  const int arm_box = CollisionMarkers::preferredId("arm", "box");
  MarkerView view;
  view.apply(update(markers, placed, {}, {nearPair("arm", "cup", {0, 0}, {1, 0})}, "m", kStamp));
  const MarkerArray moved = update(markers, 
      placed, {}, {nearPair("arm", "box", {0, 0}, {0, 1}), nearPair("arm", "cup", {0, 0}, {2, 0})},
      "m", kStamp);
  ASSERT_TRUE(find(moved, "clearance", arm_cup));
  EXPECT_EQ(find(moved, "clearance", arm_cup)->points[1].x, 2.0);
  ASSERT_TRUE(find(moved, "clearance", arm_box));
  view.apply(moved);

  const MarkerArray gone =
      update(markers, placed, {}, {nearPair("arm", "box", {0, 0}, {0, 1})}, "m", kStamp);
  ASSERT_TRUE(find(gone, "clearance", arm_cup));
  EXPECT_EQ(find(gone, "clearance", arm_cup)->action, Marker::DELETE);
  EXPECT_FALSE(find(gone, "clearance", arm_box)) << "unchanged: not sent again";
  view.apply(gone);
  EXPECT_TRUE(view.find("clearance", arm_box));
  EXPECT_FALSE(view.find("clearance", arm_cup));
  EXPECT_TRUE(isGreen(fillOf(view, "obstacles", placed[1].ellipse)));
  EXPECT_TRUE(isYellow(fillOf(view, "obstacles", placed[2].ellipse)));

  const MarkerArray none = update(markers, placed, {}, {}, "m", kStamp);
  EXPECT_EQ(find(none, "clearance", arm_box)->action, Marker::DELETE);
  EXPECT_FALSE(find(none, "clearance", arm_cup));  // deleted once only
}

}  // namespace
}  // namespace ellipse_collision

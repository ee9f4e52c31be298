// Ellipses attached to frames placed into the fixed frame's plane for one check
// (app/frame_placer.h): each frame looked up once, unavailable, stale and edge-on frames said
// why, a placed ellipse being placeInPlane()'s bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "ellipse_collision/app/frame_placer.h"
#include "frame_table.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

using test::circle;

using test::FrameTable;
using test::yawedPose;

bool sameEllipse(const core::Ellipse& a, const core::Ellipse& b) {
  return a.center == b.center && a.radius_x == b.radius_x && a.radius_y == b.radius_y &&
         a.angle == b.angle;
}

TEST(FramePlacer, APlacedEllipseIsPlaceInPlaneOfItsFrameWithNameAndRole) {
  std::map<std::string, int> lookups;
  const FrameTable table{{{"arm", yawedPose(1.0, 2.0, 0.4)}}, {}, &lookups};
  FramePlacer placer(table, 0.05);
  EllipseSpec spec = circle("hand", "arm", 0.3, 0.0, 0.1);
  spec.radius_x = 0.2;
  spec.angle = 0.25;
  const FramePlacer::Placement placed = placer.place(spec, core::EllipseRole::Obstacle);
  ASSERT_EQ(placed.status, FramePlacer::Status::Placed) << placed.error;
  EXPECT_EQ(placed.error, "");
  EXPECT_EQ(placed.ellipse.name, "hand");
  EXPECT_EQ(placed.ellipse.role, core::EllipseRole::Obstacle);
  EXPECT_TRUE(sameEllipse(placed.ellipse.ellipse,
                          placeInPlane(spec, 0.05, yawedPose(1.0, 2.0, 0.4)).ellipse));
  // Against the rigid motion in long double: centre R (0.3, 0) + (1, 2), radii + 0.05.
  const long double c = std::cos(0.4L), s = std::sin(0.4L);
  EXPECT_NEAR(placed.ellipse.ellipse.center.x(), static_cast<double>(1.0L + 0.3L * c), 1e-15);
  EXPECT_NEAR(placed.ellipse.ellipse.center.y(), static_cast<double>(2.0L + 0.3L * s), 1e-15);
  EXPECT_NEAR(placed.ellipse.ellipse.radius_x, 0.25, 1e-15);
  EXPECT_NEAR(placed.ellipse.ellipse.radius_y, 0.15, 1e-15);
  EXPECT_NEAR(placed.ellipse.ellipse.angle, 0.65, 1e-15);
}

TEST(FramePlacer, EachFrameIsLookedUpOnceUntilTheFramesAreTakenAway) {
  std::map<std::string, int> lookups;
  const FrameTable table{{{"arm", yawedPose(0, 0, 0)}}, {}, &lookups};
  FramePlacer placer(table, 0.0);
  for (int i = 0; i < 3; ++i) {
    placer.place(circle("a" + std::to_string(i), "arm", 0.1 * i, 0.0, 0.1),
                 core::EllipseRole::Link);
    placer.place(circle("b" + std::to_string(i), "cart", 0.0, 0.0, 0.1), core::EllipseRole::Link);
  }
  EXPECT_TRUE(placer.lookup("arm").ok);
  EXPECT_EQ(lookups, (std::map<std::string, int>{{"arm", 1}, {"cart", 1}}));
  const std::map<std::string, FrameTransform> frames = placer.takeFrames();
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_TRUE(frames.at("arm").ok);
  EXPECT_FALSE(frames.at("cart").ok);
  EXPECT_EQ(frames.at("cart").error, "no frame 'cart'");
  EXPECT_TRUE(placer.takeFrames().empty()) << "handed over, the placement starts empty";
  placer.place(circle("c", "arm", 0.0, 0.0, 0.1), core::EllipseRole::Link);
  EXPECT_EQ(lookups["arm"], 2);
}

TEST(FramePlacer, AnUnavailableFrameIsSaidWithTheLookupsError) {
  std::map<std::string, int> lookups;
  FramePlacer placer(FrameTable{{}, {}, &lookups}, 0.0);
  const FramePlacer::Placement placed =
      placer.place(circle("rock", "cart", 0.0, 0.0, 0.1), core::EllipseRole::Obstacle);
  EXPECT_EQ(placed.status, FramePlacer::Status::FrameUnavailable);
  EXPECT_EQ(placed.error, "no frame 'cart'");
  EXPECT_EQ(placed.ellipse.name, "rock");
  EXPECT_FALSE(placer.usable(placer.lookup("cart")));
}

TEST(FramePlacer, AStaleFrameIsNotPlacedAtItsOldPoseAndItsAgeIsGiven) {
  std::map<std::string, int> lookups;
  const FrameTable table{
      {{"arm", yawedPose(0, 0, 0)}, {"map", yawedPose(0, 0, 0)}}, {{"arm", 9.25}}, &lookups};
  FramePlacer placer(table, 0.0, Freshness{0.5, 10.0});
  const FramePlacer::Placement stale =
      placer.place(circle("hand", "arm", 0.0, 0.0, 0.1), core::EllipseRole::Link);
  EXPECT_EQ(stale.status, FramePlacer::Status::Stale);
  EXPECT_EQ(stale.age_s, 0.75);
  EXPECT_EQ(stale.error,
            "transform of frame 'arm' is 0.75 s old, older than max_transform_age 0.5 s");
  EXPECT_FALSE(placer.usable(placer.lookup("arm")));
  // A timeless frame is never stale.
  const FramePlacer::Placement timeless =
      placer.place(circle("rock", "map", 0.0, 0.0, 0.1), core::EllipseRole::Obstacle);
  EXPECT_EQ(timeless.status, FramePlacer::Status::Placed);
  EXPECT_TRUE(placer.usable(placer.lookup("map")));
  // Without the rule the same transform is placed.
  std::map<std::string, int> more;
  FramePlacer unruled(FrameTable{table.poses, table.stamps, &more}, 0.0);
  EXPECT_EQ(unruled.place(circle("hand", "arm", 0.0, 0.0, 0.1), core::EllipseRole::Link).status,
            FramePlacer::Status::Placed);
}

TEST(FramePlacer, AnEdgeOnFrameIsDegenerateAndNamesTheEllipse) {
  std::map<std::string, int> lookups;
  Eigen::Isometry3d edge_on = Eigen::Isometry3d::Identity();
  edge_on.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  FramePlacer placer(FrameTable{{{"plate", edge_on}}, {}, &lookups}, 0.0);
  const FramePlacer::Placement placed =
      placer.place(circle("plate_link", "plate", 0.0, 0.0, 0.2), core::EllipseRole::Link);
  EXPECT_EQ(placed.status, FramePlacer::Status::Degenerate);
  EXPECT_EQ(placed.error,
            placeInPlane(circle("plate_link", "plate", 0.0, 0.0, 0.2), 0.0, edge_on).error);
  EXPECT_NE(placed.error.find("plate_link"), std::string::npos) << placed.error;
  EXPECT_TRUE(placer.usable(placer.lookup("plate"))) << "the frame itself is fine";
}

}  // namespace
}  // namespace ellipse_collision::app

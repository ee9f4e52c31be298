// Named ellipses stored by column (core/scene.h): entries kept in order through every edit, the
// geometry rewritten in place, the storage kept by a move.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/core/scene.h"

namespace ellipse_collision::core {
namespace {

NamedEllipse named(const std::string& name, EllipseRole role, double x) {
  return {name, role, Ellipse{{x, 0.0}, 0.5, 0.25, 0.0}};
}

std::vector<std::string> names(const Scene& scene) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < scene.size(); ++i) out.push_back(scene.name(i));
  return out;
}

TEST(Scene, EntriesKeepTheirOrderNameRoleAndEllipse) {
  const Scene scene({named("arm", EllipseRole::Link, 1.0),
                     named("rock", EllipseRole::Obstacle, 2.0),
                     named("probe", EllipseRole::Query, 3.0)});
  ASSERT_EQ(scene.size(), 3u);
  EXPECT_FALSE(scene.empty());
  EXPECT_EQ(names(scene), (std::vector<std::string>{"arm", "rock", "probe"}));
  EXPECT_EQ(scene.role(1), EllipseRole::Obstacle);
  EXPECT_EQ(scene.ellipse(2).center.x(), 3.0);
  EXPECT_EQ(scene.ellipses().size(), 3u);
  EXPECT_EQ(&scene.ellipses()[1], &scene.ellipse(1)) << "one packed column";
  const NamedEllipse record = scene.entry(1);
  EXPECT_EQ(record.name, "rock");
  EXPECT_EQ(record.role, EllipseRole::Obstacle);
  const std::vector<NamedEllipse> records = scene.entries();
  ASSERT_EQ(records.size(), 3u);
  EXPECT_EQ(records[2].name, "probe");
  EXPECT_EQ(records[2].ellipse.radius_y, 0.25);
}

TEST(Scene, InsertFrontEraseFrontAndTruncateEditEveryColumnAlike) {
  Scene scene({named("a", EllipseRole::Link, 1.0), named("b", EllipseRole::Obstacle, 2.0)});
  scene.insertFront({named("q1", EllipseRole::Query, -1.0), named("q2", EllipseRole::Query, -2.0)});
  EXPECT_EQ(names(scene), (std::vector<std::string>{"q1", "q2", "a", "b"}));
  EXPECT_EQ(scene.role(1), EllipseRole::Query);
  EXPECT_EQ(scene.ellipse(1).center.x(), -2.0);
  EXPECT_EQ(scene.role(3), EllipseRole::Obstacle);
  scene.insertFront({});
  EXPECT_EQ(scene.size(), 4u);
  scene.eraseFront(2);
  EXPECT_EQ(names(scene), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(scene.ellipse(0).center.x(), 1.0);
  EXPECT_EQ(scene.role(0), EllipseRole::Link);
  scene.eraseFront(0);
  EXPECT_EQ(scene.size(), 2u);
  scene.truncate(1);
  EXPECT_EQ(names(scene), std::vector<std::string>{"a"});
  EXPECT_EQ(scene.ellipses().size(), 1u);
  scene.clear();
  EXPECT_TRUE(scene.empty());
  EXPECT_TRUE(scene.entries().empty());
}

TEST(Scene, TheGeometryIsRewrittenInPlaceWithoutTouchingNames) {
  Scene scene({named("a", EllipseRole::Link, 1.0)});
  scene.ellipse(0).center = {7.0, 8.0};
  scene.ellipse(0).angle = 0.5;
  EXPECT_EQ(scene.entry(0).ellipse.center, Eigen::Vector2d(7.0, 8.0));
  EXPECT_EQ(scene.entry(0).ellipse.angle, 0.5);
  EXPECT_EQ(scene.name(0), "a");
}

TEST(Scene, AMoveKeepsTheStorageAndGrowingPastTheCapacityDoesNot) {
  Scene scene;
  scene.reserve(4);
  scene.push_back(named("a", EllipseRole::Link, 1.0));
  const void* storage = scene.storage();
  scene.push_back("b", EllipseRole::Obstacle, Ellipse{});
  EXPECT_EQ(scene.storage(), storage) << "within the reserved capacity";
  Scene moved = std::move(scene);
  EXPECT_EQ(moved.storage(), storage);
  EXPECT_EQ(names(moved), (std::vector<std::string>{"a", "b"}));
  for (int i = 0; i < 3; ++i) moved.push_back("n" + std::to_string(i), EllipseRole::Obstacle, {});
  EXPECT_NE(moved.storage(), storage) << "5 entries in room for 4: reallocated";
}

}  // namespace
}  // namespace ellipse_collision::core

// The link-fitting rules without ROS: selection, skipped links, a projection that spans no area,
// invalid shapes named by link, and the `links:` YAML's numbers in a form YAML 1.1 reads as floats.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ellipse_collision/app/link_fitting.h"

namespace ellipse_collision::app {
namespace {

core::CollisionShape box(double x, double y, double z) {
  core::CollisionShape shape;
  shape.type = core::CollisionShape::Box;
  shape.box_size = {x, y, z};
  return shape;
}

TEST(LinkFitting, SelectionProblemsNameTheEntry) {
  const std::vector<std::string> model = {"base", "arm"};
  LinkFitOptions options;
  EXPECT_EQ(findLinkSelectionProblem(model, options), "");
  options.links = {"arm", "gripper"};
  EXPECT_EQ(findLinkSelectionProblem(model, options),
            "links[1] = 'gripper': not a link of the robot model");
  options.links = {""};
  EXPECT_EQ(findLinkSelectionProblem(model, options), "links[0]: expected a link name, got ''");
  options.links = {};
  options.padding = -0.1;
  EXPECT_NE(findLinkSelectionProblem(model, options).find("padding = -0.1"), std::string::npos);
  EXPECT_EQ(selectedLinks(model, LinkFitOptions{}), model);
}

TEST(LinkFitting, SkipsLinksWithoutGeometryAndFitsTheOthers) {
  const LinkFitResult result =
      fitLinkEllipses({{"footprint", {}}, {"base", {box(0.4, 0.2, 0.1)}}}, 0.02);
  ASSERT_TRUE(result.ok()) << result.error;
  EXPECT_EQ(result.skipped, std::vector<std::string>{"footprint: no collision geometry"});
  ASSERT_EQ(result.links.size(), 1u);
  EXPECT_EQ(result.links[0].name, "base");
  EXPECT_EQ(result.links[0].frame_id, "base");
  EXPECT_EQ(result.links[0].padding, 0.02);
  EXPECT_NEAR(result.links[0].radius_x, 0.2 * std::sqrt(2.0), 1e-9);
}

TEST(LinkFitting, AVerticalPlateSeenEdgeOnGetsAThinEllipse) {
  // A triangle in the link's xz-plane: its projection along z is the segment x in [0, 0.3].
  core::CollisionShape plate;
  plate.type = core::CollisionShape::Mesh;
  plate.mesh_vertices = {{0.0, 0.0, 0.0}, {0.3, 0.0, 0.0}, {0.0, 0.0, 0.2}};
  const LinkFitResult result = fitLinkEllipses({{"plate", {plate}}}, 0.0);
  ASSERT_TRUE(result.ok()) << result.error;
  ASSERT_EQ(result.links.size(), 1u);
  EXPECT_NEAR(result.links[0].x, 0.15, 1e-9);
  EXPECT_NEAR(result.links[0].radius_x, 0.15, 1e-6);
  EXPECT_NEAR(result.links[0].radius_y, kLinkMinRadius, 1e-12);
}

TEST(LinkFitting, InvalidShapeIsAnErrorNamingTheLink) {
  const LinkFitResult result = fitLinkEllipses({{"arm", {box(0.4, -0.2, 0.1)}}}, 0.0);
  EXPECT_FALSE(result.ok());
  EXPECT_EQ(result.error.rfind("link 'arm': ", 0), 0u) << result.error;
  EXPECT_TRUE(result.links.empty());
}

TEST(LinkFitting, YamlNumbersReadBackAsFloats) {
  EllipseSpec spec;
  spec.name = spec.frame_id = "l";
  spec.x = 1e-05;
  spec.y = -2.5e+20;
  spec.angle = 0.0;
  spec.radius_x = 0.5;
  spec.radius_y = 1e20;
  spec.padding = 0.0;
  EXPECT_EQ(linksYaml({spec}, {"a comment"}),
            "# a comment\nlinks:\n  - {name: 'l', frame: 'l', x: 1.0e-05, y: -2.5e+20, angle: 0, "
            "radius_x: 0.5, radius_y: 1.0e+20, padding: 0}\n");
  EXPECT_EQ(linksYaml({}), "links: []\n");
}

}  // namespace
}  // namespace ellipse_collision::app

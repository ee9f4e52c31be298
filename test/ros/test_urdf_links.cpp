// URDF links to ellipses (ros/urdf_links.h, app/link_fitting.h) on test/fixtures/: every
// geometry type with origin offsets and a mesh, checked for containment of the true geometry's
// sampled points and for area against closed forms; mesh files (STL ASCII and binary, Collada
// Z_UP / Y_UP / X_UP with units and node transforms) read where rviz draws them; the errors; the
// `links:` YAML of fit_link_ellipses read back by the node's configuration parser;
// ~links_from_urdf. No master.
#include <gtest/gtest.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "ellipse_collision/ros/node_config.h"
#include "ellipse_collision/ros/urdf_links.h"

namespace ellipse_collision {
namespace {

const std::string kFixtures = std::string(ELLIPSE_COLLISION_SOURCE_DIR) + "/test/fixtures/";
const std::string kEveryGeometry = kFixtures + "every_geometry.urdf";
constexpr double kPi = 3.14159265358979323846;

std::map<std::string, app::EllipseSpec> fitFile(const std::string& path,
                                                const app::LinkFitOptions& options = {}) {
  std::map<std::string, app::EllipseSpec> by_name;
  for (const auto& spec : fitUrdfLinks(readUrdfFile(path), "file '" + path + "'", options).links) {
    by_name[spec.name] = spec;
  }
  return by_name;
}

/// The ellipse's normalised quadratic form at p: <= 1 inside.
double quadraticForm(const app::EllipseSpec& e, double px, double py) {
  const double dx = px - e.x, dy = py - e.y;
  const double c = std::cos(e.angle), s = std::sin(e.angle);
  const double u = (c * dx + s * dy) / e.radius_x, v = (-s * dx + c * dy) / e.radius_y;
  return u * u + v * v;
}

double area(const app::EllipseSpec& e) { return kPi * e.radius_x * e.radius_y; }

/// Points on a circle of radius r about (cx, cy), densely sampled.
std::vector<std::pair<double, double>> circle(double cx, double cy, double r, int n = 20000) {
  std::vector<std::pair<double, double>> points;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    points.emplace_back(cx + r * std::cos(a), cy + r * std::sin(a));
  }
  return points;
}

void expectContains(const app::EllipseSpec& e, const std::vector<std::pair<double, double>>& points) {
  double worst = 0.0;
  for (const auto& [x, y] : points) worst = std::max(worst, quadraticForm(e, x, y));
  EXPECT_LE(worst, 1.0 + 1e-12) << e.name << ": a point of the geometry lies outside";
}

TEST(UrdfLinks, BoxWithRotatedOffsetOriginIsItsRectangleEllipse) {
  const auto e = fitFile(kEveryGeometry).at("box_link");
  // Minimum-area ellipse of a w x h rectangle: its axes, radii w / sqrt(2), h / sqrt(2).
  const double c = std::cos(0.3), s = std::sin(0.3);
  std::vector<std::pair<double, double>> corners;
  for (const double u : {-0.2, 0.2}) {
    for (const double v : {-0.1, 0.1}) corners.emplace_back(0.1 + c * u - s * v, 0.05 + s * u + c * v);
  }
  expectContains(e, corners);
  EXPECT_NEAR(area(e) / (kPi * 0.4 * 0.2 / 2.0) - 1.0, 0.0, 1e-6);
  EXPECT_NEAR(e.x, 0.1, 1e-9);
  EXPECT_NEAR(e.y, 0.05, 1e-9);
  EXPECT_NEAR(e.angle, 0.3, 1e-6);
  EXPECT_EQ(e.frame_id, "box_link");
}

TEST(UrdfLinks, UprightCylinderAndSphereAreTheirDiscs) {
  const auto fits = fitFile(kEveryGeometry);
  const auto& cylinder = fits.at("cylinder_link");
  expectContains(cylinder, circle(0.0, 0.2, 0.15));
  EXPECT_NEAR(area(cylinder) / (kPi * 0.15 * 0.15) - 1.0, 0.0, 1e-6);
  const auto& sphere = fits.at("sphere_link");
  expectContains(sphere, circle(0.3, -0.1, 0.2));
  EXPECT_NEAR(area(sphere) / (kPi * 0.2 * 0.2) - 1.0, 0.0, 1e-6);
  EXPECT_NEAR(sphere.x, 0.3, 1e-9);
  EXPECT_NEAR(sphere.y, -0.1, 1e-9);
}

TEST(UrdfLinks, LyingCylinderIsItsRectangleEllipse) {
  const auto e = fitFile(kEveryGeometry).at("lying_cylinder_link");
  // Seen along z, a cylinder lying along x is the 0.6 x 0.2 rectangle (its end discs project to
  // segments): radii 0.6 / sqrt(2), 0.2 / sqrt(2) about (-0.2, 0.1). Check the rim densely.
  std::vector<std::pair<double, double>> rim;
  for (const auto& [x, y] : circle(0.0, 0.0, 0.1)) {
    rim.emplace_back(-0.2 + 0.3, 0.1 + y);
    rim.emplace_back(-0.2 - 0.3, 0.1 + y);
    rim.emplace_back(-0.2 + 3.0 * x, 0.1 + 0.1);
    rim.emplace_back(-0.2 + 3.0 * x, 0.1 - 0.1);
  }
  expectContains(e, rim);
  EXPECT_NEAR(area(e) / (kPi * 0.6 * 0.2 / 2.0) - 1.0, 0.0, 1e-6);
  EXPECT_NEAR(e.x, -0.2, 1e-9);
  EXPECT_NEAR(e.y, 0.1, 1e-9);
}

TEST(UrdfLinks, ScaledMeshIsItsTrianglesSteinerEllipse) {
  const auto e = fitFile(kEveryGeometry).at("mesh_link");
  // Triangle (0.05, 0) (0.25, 0) (0.05, 0.1): the Steiner circumellipse, centred at the centroid,
  // of area 4 pi / (3 sqrt(3)) times the triangle's.
  expectContains(e, {{0.05, 0.0}, {0.25, 0.0}, {0.05, 0.1}});
  EXPECT_NEAR(area(e) / (4.0 * kPi / (3.0 * std::sqrt(3.0)) * 0.01) - 1.0, 0.0, 1e-6);
  EXPECT_NEAR(e.x, 0.05 + 0.2 / 3.0, 1e-9);
  EXPECT_NEAR(e.y, 0.1 / 3.0, 1e-9);
}

TEST(UrdfLinks, MeshThroughFileUri) {
  std::string xml = readUrdfFile(kEveryGeometry);
  const std::string package_uri = "package://ellipse_collision/test/fixtures/tetrahedron.stl";
  xml.replace(xml.find(package_uri), package_uri.size(), "file://" + kFixtures + "tetrahedron.stl");
  app::LinkFitOptions options;
  options.links = {"mesh_link"};
  const auto result = fitUrdfLinks(xml, "test", options);
  ASSERT_EQ(result.links.size(), 1u);
  EXPECT_NEAR(area(result.links[0]) / (4.0 * kPi / (3.0 * std::sqrt(3.0)) * 0.01) - 1.0, 0.0, 1e-6);
}

TEST(UrdfLinks, SeveralElementsOfOneLinkShareTheEllipse) {
  const auto e = fitFile(kEveryGeometry).at("two_boxes_link");
  std::vector<std::pair<double, double>> corners;
  for (const double x : {-0.35, -0.25, 0.25, 0.35}) {
    for (const double y : {-0.05, 0.05}) corners.emplace_back(x, y);
  }
  expectContains(e, corners);
  // Axis-aligned by symmetry, held by the outer corners (p, q): radii p sqrt(2), q sqrt(2).
  EXPECT_NEAR(area(e) / (2.0 * kPi * 0.35 * 0.05) - 1.0, 0.0, 1e-6);
}

TEST(UrdfLinks, LinksWithoutCollisionGeometryAreReportedAndSkipped) {
  const std::string xml = readUrdfFile(kEveryGeometry);
  const auto result = fitUrdfLinks(xml, "test", {});
  EXPECT_EQ(result.links.size(), 6u);
  ASSERT_EQ(result.skipped.size(), 1u);
  EXPECT_EQ(result.skipped[0], "base_footprint: no collision geometry");
}

TEST(UrdfLinks, SelectionPaddingAndOrder) {
  app::LinkFitOptions options;
  options.links = {"sphere_link", "box_link"};
  options.padding = 0.05;
  const auto result = fitUrdfLinks(readUrdfFile(kEveryGeometry), "test", options);
  ASSERT_EQ(result.links.size(), 2u);
  EXPECT_EQ(result.links[0].name, "sphere_link");
  EXPECT_EQ(result.links[1].name, "box_link");
  EXPECT_EQ(result.links[0].padding, 0.05);
}

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const UrdfError& error) {
    return error.what();
  }
  return "";
}

TEST(UrdfLinks, ErrorsNameTheFileParameterLinkAndUri) {
  const std::string broken = kFixtures + "broken.urdf";
  EXPECT_NE(errorOf([&] { fitUrdfLinks(readUrdfFile(broken), "file '" + broken + "'", {}); })
                .find("file '" + broken + "': not a valid URDF"),
            std::string::npos);
  EXPECT_NE(errorOf([] { readUrdfFile("/nonexistent/robot.urdf"); }).find("'/nonexistent/robot.urdf'"),
            std::string::npos);
  const std::string mesh_error = errorOf(
      [] { fitUrdfLinks(readUrdfFile(kFixtures + "missing_mesh.urdf"), "file 'm.urdf'", {}); });
  EXPECT_NE(mesh_error.find("link 'arm'"), std::string::npos) << mesh_error;
  EXPECT_NE(mesh_error.find("package://ellipse_collision/test/fixtures/no_such_mesh.stl"),
            std::string::npos)
      << mesh_error;
  app::LinkFitOptions options;
  options.links = {"box_link", "gripper"};
  EXPECT_EQ(errorOf([&] { fitUrdfLinks(readUrdfFile(kEveryGeometry), "file 'r.urdf'", options); }),
            "file 'r.urdf': links[1] = 'gripper': not a link of the robot model");
  options.links = {"box_link", "box_link"};
  EXPECT_EQ(errorOf([&] { fitUrdfLinks(readUrdfFile(kEveryGeometry), "file 'r.urdf'", options); }),
            "file 'r.urdf': links[1] = 'box_link': named twice");
}

// Mesh formats: test/fixtures/tall_box_meshes.urdf has one link per mesh file of one box, x
// 0.254..0.3556, y 0.127..0.3302, z 0.0508..0.6604 m (4 x 8 x 24 in, 10 x 5 x 2 in from the
// origin: exact in millimetres and inches), each read where rviz draws its file. Seen along z it is the 0.1016 x 0.2032 rectangle centred at (0.3048, 0.2286): the
// minimum ellipse has its axes, radii 0.1016 / sqrt(2) and 0.2032 / sqrt(2), the long one along y.
// A Z_UP Collada file fitted in assimp's Y-up frame would show the box's side: 0.1016 x 0.6096
// about (0.3048, 0.3556).

const std::string kTallBoxMeshes = kFixtures + "tall_box_meshes.urdf";

struct AlignedBox {
  Eigen::Vector3d min, max;  // [m]
};

const AlignedBox kTallBox{{0.254, 0.127, 0.0508}, {0.3556, 0.3302, 0.6604}};

/// assimp reads vertices as float (ai_real) and transforms them in float: a few ulps of 0.66 m
/// (6e-8 each; the fixtures' worst vertex is 4.7e-8 off, their worst fit 2.1e-8 off the STL's).
constexpr double kVertexTolerance = 2e-7;

std::vector<Eigen::Vector3d> cornersOf(const std::vector<AlignedBox>& boxes) {
  std::vector<Eigen::Vector3d> corners;
  for (const AlignedBox& box : boxes) {
    for (int i = 0; i < 8; ++i) {
      corners.emplace_back((i & 1) ? box.max.x() : box.min.x(), (i & 2) ? box.max.y() : box.min.y(),
                           (i & 4) ? box.max.z() : box.min.z());
    }
  }
  return corners;
}

/// Every vertex read is a corner of one of `boxes` and every corner is read (the fixtures'
/// triangles use the corners only). One failure each, naming the farthest vertex.
void expectVerticesAreTheCorners(const std::vector<Eigen::Vector3d>& vertices,
                                 const std::vector<AlignedBox>& boxes) {
  const std::vector<Eigen::Vector3d> corners = cornersOf(boxes);
  std::vector<bool> read(corners.size(), false);
  double worst = 0.0;
  Eigen::Vector3d worst_vertex = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& vertex : vertices) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < corners.size(); ++c) {
      const double distance = (vertex - corners[c]).norm();
      nearest = std::min(nearest, distance);
      if (distance <= kVertexTolerance) read[c] = true;  // boxes may share corners
    }
    if (nearest > worst) {
      worst = nearest;
      worst_vertex = vertex;
    }
  }
  EXPECT_LE(worst, kVertexTolerance)
      << "vertex (" << worst_vertex.transpose() << ") is no corner of the expected boxes";
  std::size_t unread = 0;
  for (std::size_t c = 0; c < corners.size(); ++c) unread += read[c] ? 0 : 1;
  EXPECT_EQ(unread, 0u) << "corners not read, of " << corners.size();
}

/// The vertices of `link`'s single mesh in the model `urdf_xml`.
std::vector<Eigen::Vector3d> meshVerticesOf(const std::string& urdf_xml, const std::string& link) {
  const auto links = readUrdfLinks(urdf_xml, "test", {link});
  if (links.size() != 1 || links[0].shapes.size() != 1) return {};
  return links[0].shapes[0].mesh_vertices;
}

/// An ellipse as its long and short radius and the long axis' direction, which do not depend on
/// which radius the fit calls x.
struct EllipseAxes {
  double major, minor, major_angle;
};

EllipseAxes axesOf(const app::EllipseSpec& e) {
  const double major_angle = e.radius_x >= e.radius_y ? e.angle : e.angle + kPi / 2.0;
  return {std::max(e.radius_x, e.radius_y), std::min(e.radius_x, e.radius_y), major_angle};
}

/// The angle between two axis directions: 0 for the same line, whatever the multiple of pi.
double axisAngleBetween(double a, double b) { return std::abs(std::remainder(a - b, kPi)); }

/// `e` is the tall box's ellipse: centre, radii and long axis (along y) from the closed form.
void expectTallBoxEllipse(const app::EllipseSpec& e) {
  SCOPED_TRACE(e.name);
  EXPECT_NEAR(e.x, 0.3048, kVertexTolerance);
  EXPECT_NEAR(e.y, 0.2286, kVertexTolerance);
  const EllipseAxes axes = axesOf(e);
  EXPECT_NEAR(axes.major, 0.2032 / std::sqrt(2.0), kVertexTolerance);
  EXPECT_NEAR(axes.minor, 0.1016 / std::sqrt(2.0), kVertexTolerance);
  EXPECT_LE(axisAngleBetween(axes.major_angle, kPi / 2.0), 1e-5);
}

/// `e` equals `reference` (the STL's fit) within the vertices' float rounding.
void expectSameEllipse(const app::EllipseSpec& e, const app::EllipseSpec& reference) {
  SCOPED_TRACE(e.name + " against " + reference.name);
  EXPECT_NEAR(e.x, reference.x, kVertexTolerance);
  EXPECT_NEAR(e.y, reference.y, kVertexTolerance);
  const EllipseAxes axes = axesOf(e), expected = axesOf(reference);
  EXPECT_NEAR(axes.major, expected.major, kVertexTolerance);
  EXPECT_NEAR(axes.minor, expected.minor, kVertexTolerance);
  EXPECT_LE(axisAngleBetween(axes.major_angle, expected.major_angle), 1e-5);
}

/// The Collada links of kTallBoxMeshes whose file holds the box as one mesh, and the one that
/// builds it from two halves placed by node transforms.
const std::vector<std::string> kColladaWholeBoxLinks = {"collada_z_up", "collada_z_up_millimetres",
                                                        "collada_y_up_inches", "collada_x_up"};
const std::string kColladaNodesLink = "collada_z_up_nodes";

TEST(MeshFormats, EveryTallBoxMeshIsReadWhereRvizDrawsIt) {
  const std::string xml = readUrdfFile(kTallBoxMeshes);
  std::vector<std::string> whole_box_links = kColladaWholeBoxLinks;
  whole_box_links.insert(whole_box_links.begin(), "stl");
  for (const std::string& link : whole_box_links) {
    SCOPED_TRACE(link);
    expectVerticesAreTheCorners(meshVerticesOf(xml, link), {kTallBox});
  }
  // Two half boxes placed by node transforms (in millimetres, below the Z_UP root).
  const AlignedBox lower{kTallBox.min, {kTallBox.max.x(), kTallBox.max.y(), 0.3556}};
  const AlignedBox upper{{kTallBox.min.x(), kTallBox.min.y(), 0.3556}, kTallBox.max};
  SCOPED_TRACE(kColladaNodesLink);
  expectVerticesAreTheCorners(meshVerticesOf(xml, kColladaNodesLink), {lower, upper});
}

TEST(MeshFormats, EveryColladaTallBoxFitsTheEllipseOfTheStl) {
  const auto fits = fitFile(kTallBoxMeshes);
  const app::EllipseSpec& stl = fits.at("stl");
  expectTallBoxEllipse(stl);
  std::vector<std::string> collada_links = kColladaWholeBoxLinks;
  collada_links.push_back(kColladaNodesLink);
  for (const std::string& link : collada_links) {
    expectTallBoxEllipse(fits.at(link));
    expectSameEllipse(fits.at(link), stl);
  }
}

/// `triangles` (corner indices into `corners`) as a binary STL file: 80-byte header, the
/// little-endian uint32 triangle count, then per triangle its normal and three vertices as
/// little-endian float32 and a uint16 attribute. The normals are left zero: only positions count.
void writeBinaryStl(const std::string& path, const std::vector<Eigen::Vector3d>& corners,
                    const std::vector<std::array<int, 3>>& triangles) {
  static_assert(sizeof(float) == 4, "STL stores IEEE float32");
  std::ofstream file(path, std::ios::binary);
  const std::string header(80, ' ');
  file.write(header.data(), 80);
  auto putLittleEndian = [&file](std::uint32_t bits, int bytes) {
    for (int b = 0; b < bytes; ++b) file.put(static_cast<char>((bits >> (8 * b)) & 0xFFu));
  };
  auto putFloat = [&](double value) {
    const float single = static_cast<float>(value);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &single, 4);
    putLittleEndian(bits, 4);
  };
  putLittleEndian(static_cast<std::uint32_t>(triangles.size()), 4);
  for (const auto& triangle : triangles) {
    for (int i = 0; i < 3; ++i) putFloat(0.0);
    for (const int corner : triangle) {
      for (int i = 0; i < 3; ++i) putFloat(corners[corner][i]);
    }
    putLittleEndian(0, 2);
  }
}

TEST(MeshFormats, BinaryStlTallBoxReadsAndFitsLikeTheAsciiOne) {
  // The triangles of the fixtures: corner i has x, y, z at their maximum where bit 0, 1, 2 is set.
  const std::vector<std::array<int, 3>> triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                                                     {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                                                     {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  const std::string path = testing::TempDir() + "tall_box_binary.stl";
  writeBinaryStl(path, cornersOf({kTallBox}), triangles);
  std::string xml = readUrdfFile(kTallBoxMeshes);
  const std::string ascii_uri = "package://ellipse_collision/test/fixtures/tall_box.stl";
  xml.replace(xml.find(ascii_uri), ascii_uri.size(), "file://" + path);
  expectVerticesAreTheCorners(meshVerticesOf(xml, "stl"), {kTallBox});
  app::LinkFitOptions options;
  options.links = {"stl"};
  const auto result = fitUrdfLinks(xml, "test", options);
  ASSERT_EQ(result.links.size(), 1u);
  expectTallBoxEllipse(result.links[0]);
  expectSameEllipse(result.links[0], fitFile(kTallBoxMeshes).at("stl"));
}

std::string runCommand(const std::string& command) {
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return output;
  char buffer[4096];
  for (std::size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  pclose(pipe);
  return output;
}

/// `yaml_text` as rosparam loads it: PyYAML, then XML-RPC (what reaches the parameter server).
XmlRpc::XmlRpcValue asRosparamLoadsIt(const std::string& yaml_text) {
  const std::string path = testing::TempDir() + "fit_link_ellipses_output.yaml";
  std::ofstream(path) << yaml_text;
  const std::string xml = runCommand(
      "python3 -c 'import sys, yaml, xmlrpc.client; "
      "print(xmlrpc.client.dumps((yaml.safe_load(open(sys.argv[1])),)))' " + path);
  int offset = static_cast<int>(xml.find("<value>"));
  XmlRpc::XmlRpcValue value;
  if (offset >= 0) value.fromXml(xml, &offset);
  return value;
}

TEST(FitLinkEllipsesTool, PrintsALinksBlockTheNodeConfigurationReadsBackExactly) {
  const std::string yaml = runCommand(std::string(FIT_LINK_ELLIPSES_BIN) + " " + kEveryGeometry +
                                      " --padding 0.00001 2>/dev/null");
  ASSERT_NE(yaml.find("links:"), std::string::npos) << yaml;
  const NodeConfig config = parseNodeConfig(asRosparamLoadsIt(yaml));
  app::LinkFitOptions options;
  options.padding = 0.00001;
  const auto expected = fitUrdfLinks(readUrdfFile(kEveryGeometry), "test", options).links;
  ASSERT_EQ(config.links.size(), expected.size()) << yaml;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(expected[i].name);
    EXPECT_EQ(config.links[i].name, expected[i].name);
    EXPECT_EQ(config.links[i].frame_id, expected[i].frame_id);
    EXPECT_EQ(config.links[i].x, expected[i].x);  // bit for bit
    EXPECT_EQ(config.links[i].y, expected[i].y);
    EXPECT_EQ(config.links[i].angle, expected[i].angle);
    EXPECT_EQ(config.links[i].radius_x, expected[i].radius_x);
    EXPECT_EQ(config.links[i].radius_y, expected[i].radius_y);
    EXPECT_EQ(config.links[i].padding, expected[i].padding);
  }
}

TEST(FitLinkEllipsesTool, PrintsTheUprightEllipseOfAZUpColladaMesh) {
  const std::string yaml = runCommand(std::string(FIT_LINK_ELLIPSES_BIN) + " " + kTallBoxMeshes +
                                      " --links collada_z_up 2>/dev/null");
  const NodeConfig config = parseNodeConfig(asRosparamLoadsIt(yaml));
  ASSERT_EQ(config.links.size(), 1u) << yaml;
  expectTallBoxEllipse(config.links[0]);
}

TEST(FitLinkEllipsesTool, BadUrdfExitsOneNamingTheFile) {
  const std::string broken = kFixtures + "broken.urdf";
  const std::string output =
      runCommand(std::string(FIT_LINK_ELLIPSES_BIN) + " " + broken + " 2>&1; echo \"exit $?\"");
  EXPECT_NE(output.find("file '" + broken + "'"), std::string::npos) << output;
  EXPECT_NE(output.find("exit 1"), std::string::npos) << output;
}

/// The node's reader with the parameter server replaced by fixture files named by `param`.
app::LinkFitResult fitFixture(const std::string& param, const app::LinkFitOptions& options) {
  return fitUrdfLinks(readUrdfFile(kFixtures + param), "parameter '" + param + "'", options);
}

TEST(LinksFromUrdf, AppendsFittedLinksToConfiguredOnes) {
  XmlRpc::XmlRpcValue params;
  params["links"][0]["name"] = "tool";
  params["links"][0]["frame"] = "tool0";
  for (const char* key : {"x", "y", "angle"}) params["links"][0][key] = 0.0;
  params["links"][0]["radius_x"] = 0.1;
  params["links"][0]["radius_y"] = 0.1;
  params["links_from_urdf"]["param"] = "every_geometry.urdf";
  params["links_from_urdf"]["links"][0] = "sphere_link";
  params["links_from_urdf"]["links"][1] = "base_footprint";
  params["links_from_urdf"]["padding"] = 0.02;
  params["allowed_pairs"][0][0] = "tool";
  params["allowed_pairs"][0][1] = "sphere_link";
  const NodeConfig config = parseNodeConfig(params, fitFixture);
  ASSERT_EQ(config.links.size(), 2u);
  EXPECT_EQ(config.links[1].name, "sphere_link");
  EXPECT_EQ(config.links[1].padding, 0.02);
  EXPECT_EQ(config.urdf_links_skipped,
            std::vector<std::string>{"base_footprint: no collision geometry"});
  EXPECT_EQ(config.monitor.check.rules.allowed.size(), 1u);
}

/// Which fitted links of `path` are ellipsoids, under `shape`.
std::map<std::string, bool> ellipsoidLinks(const std::string& path, app::LinkShape shape) {
  app::LinkFitOptions options;
  options.shape = shape;
  std::map<std::string, bool> ellipsoid;
  for (const auto& [name, spec] : fitFile(path, options)) ellipsoid[name] = spec.ellipsoid.has_value();
  return ellipsoid;
}

TEST(LinksFromUrdf, DefaultShapeFitsEllipsoidsForLinksThatTiltAndPlanarEllipsesForTheRest) {
  // The default is auto. The arm's links sit behind a pitching and a rolling shoulder.
  EXPECT_EQ(app::LinkFitOptions{}.shape, app::LinkShape::Auto);
  const std::string arm = kFixtures + "two_link_arm.urdf";
  EXPECT_EQ(ellipsoidLinks(arm, app::LinkShape::Auto),
            (std::map<std::string, bool>{{"forearm", true}, {"upper_arm", true}}));
  // ... and equal what shape: ellipsoid fits.
  EXPECT_EQ(fitFile(arm, {}).at("upper_arm").ellipsoid->radius_z,
            fitFile(arm, {{}, 0.0, app::LinkShape::Ellipsoid}).at("upper_arm").ellipsoid->radius_z);
  // The demo robot turns every joint about a vertical axis: planar, the same as shape: planar.
  const std::string demo = std::string(ELLIPSE_COLLISION_SOURCE_DIR) + "/demo/urdf/demo_robot.urdf";
  const auto automatic = fitFile(demo, {}), planar = fitFile(demo, {{}, 0.0, app::LinkShape::Planar});
  ASSERT_FALSE(automatic.empty());
  ASSERT_EQ(automatic.size(), planar.size());
  for (const auto& [name, spec] : automatic) {
    EXPECT_FALSE(spec.ellipsoid) << name;
    EXPECT_EQ(spec.radius_x, planar.at(name).radius_x) << name;
    EXPECT_EQ(spec.radius_y, planar.at(name).radius_y) << name;
  }
  // Fixed mounts: yawed, or upside down, stay planar; rolled by 90 degrees it is an ellipsoid.
  const std::string mounts = R"(<robot name="mounts"><link name="base"/>
    <link name="yawed"><collision><geometry><box size="0.2 0.1 0.05"/></geometry></collision></link>
    <link name="flipped"><collision><geometry><box size="0.2 0.1 0.05"/></geometry></collision></link>
    <link name="rolled"><collision><geometry><box size="0.2 0.1 0.05"/></geometry></collision></link>
    <joint name="a" type="fixed"><parent link="base"/><child link="yawed"/>
      <origin rpy="0 0 1.2"/></joint>
    <joint name="b" type="fixed"><parent link="base"/><child link="flipped"/>
      <origin rpy="3.141592653589793 0 0"/></joint>
    <joint name="c" type="fixed"><parent link="base"/><child link="rolled"/>
      <origin rpy="1.5707963267948966 0 0"/></joint></robot>)";
  std::map<std::string, bool> ellipsoid;
  for (const auto& spec : fitUrdfLinks(mounts, "mounts", {}).links) {
    ellipsoid[spec.name] = spec.ellipsoid.has_value();
  }
  EXPECT_EQ(ellipsoid,
            (std::map<std::string, bool>{{"flipped", false}, {"rolled", true}, {"yawed", false}}));
}

std::string configErrorOf(const XmlRpc::XmlRpcValue& params) {
  try {
    parseNodeConfig(params, fitFixture);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

TEST(LinksFromUrdf, ErrorsNameTheParameter) {
  XmlRpc::XmlRpcValue params;
  params["links_from_urdf"]["param"] = "broken.urdf";
  EXPECT_EQ(configErrorOf(params).find("parameter ~links_from_urdf: parameter 'broken.urdf': not a "
                                       "valid URDF"),
            0u)
      << configErrorOf(params);
  params["links_from_urdf"]["param"] = "every_geometry.urdf";
  params["links_from_urdf"]["padding"] = -1.0;
  EXPECT_NE(configErrorOf(params).find("key 'padding'"), std::string::npos);
  params["links_from_urdf"]["padding"] = 0.0;
  params["links_from_urdf"]["shape"] = "sideways";
  EXPECT_NE(configErrorOf(params).find("key 'shape': expected 'auto', 'planar' or 'ellipsoid'"),
            std::string::npos)
      << configErrorOf(params);
  params["links_from_urdf"]["shape"] = "auto";
  EXPECT_EQ(configErrorOf(params), "");
  params["links_from_urdf"]["link"] = "typo";
  EXPECT_NE(configErrorOf(params).find("unknown key 'link'"), std::string::npos);
  XmlRpc::XmlRpcValue no_reader;
  no_reader["links_from_urdf"]["param"] = "robot_description";
  EXPECT_THROW(parseNodeConfig(no_reader), ConfigError);
}

}  // namespace
}  // namespace ellipse_collision

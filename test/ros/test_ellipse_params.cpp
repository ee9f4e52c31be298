// The node's ellipse lists, allowed pairs and links_from_urdf (src/ros/ellipse_params.cpp):
// parseEllipseList(), params::readAllowedPairs() and params::readLinksFromUrdf() on their own and
// through the node's configuration, every refusal naming the entry, the key and the value; no ROS
// master needed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ellipse_collision/ros/ellipse_params.h"
#include "node_config_fixture.h"

namespace ellipse_collision {
namespace {

using test::ellipseEntry;
using test::errorOf;
using test::pair;
using test::refusalOf;
using test::validParams;
using XmlRpc::XmlRpcValue;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(EllipseParams, EveryNumberKeyRefusesNaNNamingEntryKeyAndValue) {
  for (const char* key :
       {"x", "y", "angle", "radius_x", "radius_y", "padding", "z", "roll", "pitch", "radius_z"}) {
    XmlRpcValue list;
    list[0] = ellipseEntry("post", "map");
    list[1] = ellipseEntry("crate", "map");
    list[1]["radius_z"] = 0.3;  // an ellipsoid, so that z, roll and pitch are read
    list[1][key] = kNaN;
    const std::string refusal = refusalOf([&] { parseEllipseList(list, "obstacles", 0.0); });
    EXPECT_CONTAINS(refusal, "obstacles[1] (name 'crate'), key '" + std::string(key) + "'");
    EXPECT_CONTAINS(refusal, "got nan");
  }
}

TEST(EllipseParams, AListIsReadInOrderWithTheGlobalPaddingChecked) {
  XmlRpcValue list;
  list[0] = ellipseEntry("post", "map", 1.5, 0.25);
  list[1] = ellipseEntry("wall", "odom", -2, 1);
  const std::vector<app::EllipseSpec> specs = parseEllipseList(list, "obstacles", 0.0);
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[0].name, "post");
  EXPECT_EQ(specs[0].x, 1.5);
  EXPECT_EQ(specs[0].radius_x, 0.25);
  EXPECT_EQ(specs[1].frame_id, "odom");
  EXPECT_EQ(specs[1].x, -2.0);
  EXPECT_FALSE(specs[1].ellipsoid);
  // The same radius refused once the global padding takes it below the core's minimum.
  list[0]["radius_x"] = 1e-9;
  EXPECT_CONTAINS(refusalOf([&] { parseEllipseList(list, "obstacles", -1e-9); }),
                  "obstacles[0] (name 'post'), key 'radius_x'");
  EXPECT_EQ(refusalOf([&] { parseEllipseList(list, "obstacles", 0.0); }), "");
}

TEST(EllipseParams, AllowedPairsNameTwoDefinedAndDifferentNames) {
  const std::map<std::string, std::string> defined = {{"arm", "links[0]"},
                                                      {"table", "obstacles[0]"}};
  XmlRpcValue list;
  list[0] = pair("arm", "table");
  const auto pairs = params::readAllowedPairs(list, defined);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].first, "arm");
  EXPECT_EQ(pairs[0].second, "table");
  list[1] = pair("table", "chair");
  EXPECT_EQ(refusalOf([&] { params::readAllowedPairs(list, defined); }),
            "allowed_pairs[1][1] = 'chair': expected the name of a configured link or obstacle, "
            "got an unknown name");
  list[1] = pair("table", "table");
  EXPECT_EQ(refusalOf([&] { params::readAllowedPairs(list, defined); }),
            "allowed_pairs[1]: expected two different names, got 'table' twice");
  list[1][1] = 4;
  EXPECT_EQ(refusalOf([&] { params::readAllowedPairs(list, defined); }),
            "allowed_pairs[1][1]: expected a link or obstacle name, got 4 (an int)");
  EXPECT_EQ(refusalOf([&] { params::readAllowedPairs(XmlRpcValue("arm"), defined); }),
            "parameter ~allowed_pairs, key 'allowed_pairs': expected a list of [name_a, name_b], "
            "got 'arm' (a string)");
}

TEST(EllipseParams, LinksFromUrdfPassesItsKeysToTheFitterAndNamesItsFailures) {
  std::string asked_param;
  app::LinkFitOptions asked;
  const UrdfLinkFitter fitter = [&](const std::string& param, const app::LinkFitOptions& options) {
    asked_param = param;
    asked = options;
    app::LinkFitResult result;
    result.skipped.push_back("base_footprint: no collision geometry");
    return result;
  };
  XmlRpcValue value;
  value["padding"] = 0.02;
  value["shape"] = "planar";
  value["links"][0] = "upper_arm";
  value["links"][1] = "forearm";
  const app::LinkFitResult fitted = params::readLinksFromUrdf(value, fitter);
  EXPECT_EQ(asked_param, "robot_description") << "the default";
  EXPECT_EQ(asked.padding, 0.02);
  EXPECT_EQ(asked.shape, app::LinkShape::Planar);
  EXPECT_EQ(asked.links, (std::vector<std::string>{"upper_arm", "forearm"}));
  EXPECT_EQ(fitted.skipped.size(), 1u);
  value["param"] = "arm_description";
  params::readLinksFromUrdf(value, fitter);
  EXPECT_EQ(asked_param, "arm_description");

  const auto refusal = [&](const XmlRpcValue& v) {
    return refusalOf([&] { params::readLinksFromUrdf(v, fitter); });
  };
  XmlRpcValue bad = value;
  bad["padding"] = kNaN;
  EXPECT_CONTAINS(refusal(bad), "parameter ~links_from_urdf, key 'padding'");
  EXPECT_CONTAINS(refusal(bad), "got nan");
  bad["padding"] = -0.5;
  EXPECT_CONTAINS(refusal(bad), "got -0.5");
  bad = value;
  bad["shape"] = "sphere";
  EXPECT_EQ(refusal(bad),
            "parameter ~links_from_urdf, key 'shape': expected 'auto', 'planar' or 'ellipsoid', "
            "got 'sphere'");
  bad = value;
  bad["param"] = "";
  EXPECT_EQ(refusal(bad),
            "parameter ~links_from_urdf, key 'param': expected a parameter name, got ''");
  bad = value;
  bad["links"][1] = 2;
  EXPECT_EQ(refusal(bad),
            "parameter ~links_from_urdf, key 'links[1]': expected a string, got 2 (an int)");
  bad = value;
  bad["urdf"] = "robot.urdf";
  EXPECT_CONTAINS(refusal(bad), "parameter ~links_from_urdf: unknown key 'urdf'");
  EXPECT_EQ(refusalOf([&] {
              params::readLinksFromUrdf(
                  value, [](const std::string&, const app::LinkFitOptions&) -> app::LinkFitResult {
                    throw std::runtime_error("parameter 'arm_description' not set");
                  });
            }),
            "parameter ~links_from_urdf: parameter 'arm_description' not set");
  EXPECT_EQ(refusalOf([&] { params::readLinksFromUrdf(value, UrdfLinkFitter()); }),
            "parameter ~links_from_urdf: no URDF reader in this program");
}

TEST(EllipseParams, MissingEntryKeyNamesEntryAndKey) {
  XmlRpcValue p = validParams();
  XmlRpcValue entry = ellipseEntry("wrist", "wrist_link");
  XmlRpcValue without_radius_y;
  for (auto it = entry.begin(); it != entry.end(); ++it) {
    if (it->first != "radius_y") without_radius_y[it->first] = it->second;
  }
  p["links"][2] = without_radius_y;
  const std::string error = errorOf(p);
  EXPECT_CONTAINS(error, "links[2] (name 'wrist')");
  EXPECT_CONTAINS(error, "missing key 'radius_y'");
}

TEST(EllipseParams, WrongTypeNamesEntryKeyExpectedAndActual) {
  XmlRpcValue p = validParams();
  p["obstacles"][0]["radius_x"] = "big";
  EXPECT_EQ(errorOf(p),
            "obstacles[0] (name 'table'), key 'radius_x': expected a number, got 'big' (a string)");
}

TEST(EllipseParams, NonPositiveRadiusStopsTheNode) {
  XmlRpcValue p = validParams();
  p["links"][1]["radius_x"] = 0.0;
  EXPECT_EQ(errorOf(p),
            "links[1] (name 'hand'), key 'radius_x': expected a finite number > 0, got 0");
  p = validParams();
  p["links"][0]["radius_y"] = -0.3;
  EXPECT_CONTAINS(errorOf(p), "links[0] (name 'arm'), key 'radius_y'");
  EXPECT_CONTAINS(errorOf(p), "got -0.3");
}

TEST(EllipseParams, NonFiniteNumbersStopTheNode) {
  XmlRpcValue p = validParams();
  p["links"][0]["x"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(errorOf(p), "links[0] (name 'arm'), key 'x': expected a finite number, got nan");
  p = validParams();
  p["obstacles"][0]["angle"] = std::numeric_limits<double>::infinity();
  EXPECT_CONTAINS(errorOf(p), "obstacles[0] (name 'table'), key 'angle'");
  p = validParams();
  p["padding"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_CONTAINS(errorOf(p), "parameter ~padding, key 'padding': expected a finite number >= 0");
}

TEST(EllipseParams, NegativePaddingStopsTheNode) {
  XmlRpcValue p = validParams();
  p["links"][1]["padding"] = -0.01;
  EXPECT_CONTAINS(errorOf(p), "links[1] (name 'hand'), key 'padding'");
  p = validParams();
  p["padding"] = -1;
  EXPECT_CONTAINS(errorOf(p), "parameter ~padding");
}

TEST(EllipseParams, AllowedPairWithUnknownNameStopsTheNode) {
  XmlRpcValue p = validParams();
  p["allowed_pairs"][1] = pair("table", "hnad");
  const std::string error = errorOf(p);
  EXPECT_CONTAINS(error, "allowed_pairs[1][1] = 'hnad'");
  EXPECT_CONTAINS(error, "unknown name");
}

TEST(EllipseParams, AllowedPairMustBeTwoDifferentNames) {
  XmlRpcValue p = validParams();
  p["allowed_pairs"][0] = pair("arm", "arm");
  EXPECT_CONTAINS(errorOf(p), "allowed_pairs[0]: expected two different names");
  p = validParams();
  p["allowed_pairs"][0] = "arm";
  EXPECT_CONTAINS(errorOf(p), "allowed_pairs[0]: expected a list of two names");
}

TEST(EllipseParams, LinksAndObstaclesMayBeEllipsoidsWithRadiusZ) {
  // The same keys, rules and messages for both lists; the other entry of each stays planar.
  for (const std::string list : {"links", "obstacles"}) {
    SCOPED_TRACE(list);
    XmlRpcValue p = validParams();
    p["obstacles"][1] = ellipseEntry("chair", "map", -3.0, 0.3);
    p[list][0]["radius_z"] = 0.06;
    p[list][0]["roll"] = 0.5;
    p[list][0]["z"] = 0.1;
    const NodeConfig config = parseNodeConfig(p);
    const std::vector<app::EllipseSpec>& specs = list == "links" ? config.links : config.obstacles;
    ASSERT_EQ(specs.size(), 2u);
    ASSERT_TRUE(specs[0].ellipsoid);
    EXPECT_EQ(specs[0].ellipsoid->radius_z, 0.06);
    EXPECT_EQ(specs[0].ellipsoid->roll, 0.5);
    EXPECT_EQ(specs[0].ellipsoid->pitch, 0.0);
    EXPECT_EQ(specs[0].ellipsoid->z, 0.1);
    EXPECT_FALSE(specs[1].ellipsoid);

    const std::string entry = list + "[0] (name '" + (list == "links" ? "arm" : "table") + "')";
    p = validParams();
    p[list][0]["pitch"] = 0.3;  // an ellipsoid key without radius_z
    EXPECT_EQ(errorOf(p), entry +
                              ": missing key 'radius_z' (z, roll and pitch describe an "
                              "ellipsoid, which needs radius_z)");
    p = validParams();
    p[list][0]["radius_z"] = -1.0;
    EXPECT_EQ(errorOf(p), entry + ", key 'radius_z': expected a finite number > 0, got -1");
    p[list][0]["radius_z"] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(errorOf(p), entry + ", key 'radius_z': expected a finite number > 0, got nan");
    p[list][0]["radius_z"] = 0.0;
    p[list][0]["roll"] = 1.5;
    EXPECT_EQ(errorOf(p), entry +
                              ", key 'roll': expected 0 when radius_z = 0 (a planar ellipse); "
                              "z, roll and pitch describe an ellipsoid, which needs radius_z > "
                              "0, got 1.5");
    p = validParams();
    p[list][0]["radius_z"] = 0.1;
    p[list][0]["yaw"] = 0.1;  // the yaw is `angle`
    EXPECT_CONTAINS(errorOf(p), entry + ": unknown key 'yaw'");
  }
  XmlRpcValue p = validParams();
  p["links_from_urdf"]["shape"] = "sphere";
  EXPECT_CONTAINS(errorOf(p), "shape");
}

TEST(EllipseParams, EllipseListsMustBeListsOfDicts) {
  XmlRpcValue p = validParams();
  p["obstacles"] = "none";
  EXPECT_CONTAINS(errorOf(p), "parameter ~obstacles, key 'obstacles': expected a list of ellipses");
  p = validParams();
  p["links"][0] = 3;
  EXPECT_CONTAINS(errorOf(p), "links[0]: expected a dict with keys");
}

TEST(EllipseParams, EmptyOrSlashedFrameOfAnEntryStopsTheNode) {
  XmlRpcValue p = validParams();
  p["links"][0]["frame"] = "";
  EXPECT_CONTAINS(errorOf(p),
                  "links[0] (name 'arm'), key 'frame': expected a non-empty tf frame id");
  p = validParams();
  p["links"][0]["frame"] = "/arm_link";
  EXPECT_CONTAINS(errorOf(p), "key 'frame': expected a tf2 frame id without a leading '/'");
  p = validParams();
  p["links"][0]["name"] = "";
  EXPECT_CONTAINS(errorOf(p), "links[0] (name ''), key 'name'");
}

TEST(EllipseParams, PaddedRadiiBeyondTheCoreRangeStopTheNode) {
  // radius + entry padding + global padding must stay within [kMinRadius, kMaxRadius].
  XmlRpcValue p = validParams();  // global padding 0.01
  p["links"][0]["radius_x"] = core::kMaxRadius;
  std::string error = errorOf(p);
  EXPECT_CONTAINS(error,
                  "links[0] (name 'arm'), key 'radius_x': expected a number whose padded "
                  "radius (radius_x + padding 0 + global padding 0.01 = ");
  EXPECT_CONTAINS(error, ") lies within [1e-09, 1e+09], got 1e+09");

  p = validParams();
  p["obstacles"][0]["radius_y"] = 6e8;
  p["obstacles"][0]["padding"] = 5e8;  // each within range, the sum is not
  EXPECT_CONTAINS(errorOf(p), "obstacles[0] (name 'table'), key 'radius_y'");
  EXPECT_CONTAINS(errorOf(p), "got 6e+08");

  p = validParams();
  p["padding"] = 6e8;
  p["links"][1]["radius_x"] = 5e8;  // the global padding pushes it over
  EXPECT_CONTAINS(errorOf(p), "links[1] (name 'hand'), key 'radius_x'");

  p = validParams();
  p["padding"] = 0.0;
  p["links"][0]["radius_x"] = core::kMaxRadius;  // exactly at the limit, unpadded: accepted
  EXPECT_EQ(parseNodeConfig(p).links[0].radius_x, core::kMaxRadius);
}

}  // namespace
}  // namespace ellipse_collision

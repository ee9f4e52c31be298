// params::readFleet() (src/ros/fleet_params.cpp): the `fleet` dict's keys, types and defaults, and
// every refusal naming the key and the value (the ranges through the node's configuration, which
// applies them to the default settings too); no ROS master needed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/ros/param_sections.h"
#include "node_config_fixture.h"

namespace ellipse_collision {
namespace {

using test::errorOf;
using test::refusalOf;
using test::sourceEntry;
using test::validParams;
using XmlRpc::XmlRpcValue;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(FleetParams, KeysAreReadAndTheRobotNameDefaultsToTheOneGiven) {
  XmlRpcValue value;
  value["rate"] = 5;
  const app::FleetSettings read = params::readFleet(value, "r3");
  EXPECT_EQ(read.robot_name, "r3");
  EXPECT_EQ(read.rate, 5.0);
  EXPECT_EQ(read.topic, app::FleetSettings().topic);
  EXPECT_EQ(read.frame, app::FleetSettings().frame);
  EXPECT_TRUE(read.enabled);
  value["robot_name"] = "cart";
  EXPECT_EQ(params::readFleet(value, "r3").robot_name, "cart");
}

TEST(FleetParams, WrongTypesAndShapesNameTheKeyExpectedAndActual) {
  XmlRpcValue value;
  value["rate"] = "often";
  EXPECT_EQ(refusalOf([&] { params::readFleet(value, "r1"); }),
            "parameter ~fleet, key 'fleet/rate': expected a number, got 'often' (a string)");
  for (const char* key : {"topic", "frame", "robot_name"}) {
    value = XmlRpcValue();
    value[key] = 7;
    EXPECT_EQ(refusalOf([&] { params::readFleet(value, "r1"); }),
              "parameter ~fleet, key 'fleet/" + std::string(key) +
                  "': expected a string, got 7 (an int)");
  }
  EXPECT_EQ(refusalOf([&] { params::readFleet(XmlRpcValue(true), "r1"); }),
            "parameter ~fleet, key 'fleet': expected a dict {enabled, topic, frame, robot_name, "
            "rate}, got true (a bool)");
}

TEST(FleetParams, TheRateOutsideItsRangeStopsTheNodeNamingTheValue) {
  const std::pair<double, const char*> bad[] = {{kNaN, "got nan"},    {kInf, "got inf"},
                                                {-1.0, "got -1"},     {0.0, "got 0"},
                                                {100.5, "got 100.5"}, {1e12, "got 1e+12"}};
  for (const auto& [rate, actual] : bad) {
    XmlRpcValue p = validParams();
    p["fleet"]["rate"] = rate;
    EXPECT_EQ(errorOf(p), std::string("parameter ~fleet, key 'fleet/rate': expected a number "
                                      "within (0, 100], ") +
                              actual);
  }
  XmlRpcValue p = validParams();
  p["fleet"]["topic"] = "";
  EXPECT_EQ(errorOf(p),
            "parameter ~fleet, key 'fleet/topic': expected a non-empty topic name, got ''");
}

TEST(FleetParams, FleetSettingsDefaultToPublishingTheNamespaceInMap) {
  const NodeConfig defaults = parseNodeConfig(validParams(), {}, "r7");
  EXPECT_TRUE(defaults.fleet.enabled);
  EXPECT_EQ(defaults.fleet.topic, "/fleet/footprints");
  EXPECT_EQ(defaults.fleet.frame, "map");
  EXPECT_EQ(defaults.fleet.robot_name, "r7");
  EXPECT_EQ(defaults.fleet.rate, 10.0);
  XmlRpcValue p = validParams();
  p["fleet"]["enabled"] = false;
  p["fleet"]["frame"] = "world";
  p["fleet"]["robot_name"] = "forklift_2";
  p["fleet"]["rate"] = 20;
  p["fleet"]["topic"] = "/site/footprints";
  const NodeConfig config = parseNodeConfig(p, {}, "r7");
  EXPECT_FALSE(config.fleet.enabled);
  EXPECT_EQ(config.fleet.frame, "world");
  EXPECT_EQ(config.fleet.robot_name, "forklift_2");
  EXPECT_EQ(config.fleet.rate, 20.0);
  EXPECT_EQ(config.fleet.topic, "/site/footprints");
}

TEST(FleetParams, BadFleetSettingsStopTheNodeNamingTheKey) {
  const auto with = [](void (*change)(XmlRpcValue&)) {
    XmlRpcValue p = validParams();
    change(p["fleet"]);
    return errorOf(p);
  };
  EXPECT_CONTAINS(with([](XmlRpcValue& f) { f["robot_name"] = "a/b"; }),
                  "key 'fleet/robot_name': expected a non-empty name without '/', got 'a/b'");
  EXPECT_CONTAINS(with([](XmlRpcValue& f) { f["rate"] = 0.0; }), "key 'fleet/rate'");
  EXPECT_CONTAINS(with([](XmlRpcValue& f) { f["rate"] = std::nan(""); }), "key 'fleet/rate'");
  EXPECT_CONTAINS(with([](XmlRpcValue& f) { f["frame"] = "/map"; }), "key 'fleet/frame'");
  EXPECT_CONTAINS(with([](XmlRpcValue& f) { f["enabled"] = "yes"; }), "key 'fleet/enabled'");
  EXPECT_CONTAINS(with([](XmlRpcValue& f) { f["rates"] = 1.0; }), "~fleet/rates: unknown key");
}

}  // namespace
}  // namespace ellipse_collision

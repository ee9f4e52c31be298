// params::readGate() (src/ros/gate_params.cpp): the `gate` dict's keys, types and defaults, and
// every refusal naming the key and the value; no ROS master needed.
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

/// The number keys of `gate`, each with a value inside its range that no default has.
const std::pair<const char*, double> kGateNumbers[] = {{"horizon", 4.5},
                                                       {"time_before_collision", 2.5},
                                                       {"stop_time", 0.25},
                                                       {"margin", 0.03},
                                                       {"resolution", 0.02},
                                                       {"cmd_vel_timeout", 0.75},
                                                       {"max_linear_speed", 2.5},
                                                       {"max_angular_speed", 1.5},
                                                       {"reaction_time", 0.15},
                                                       {"max_linear_deceleration", 1.25},
                                                       {"max_angular_deceleration", 2.25}};

double field(const app::GateConfig& gate, const std::string& key) {
  if (key == "horizon") return gate.timing.horizon;
  if (key == "time_before_collision") return gate.timing.time_before_collision;
  if (key == "stop_time") return gate.timing.stop_time;
  if (key == "margin") return gate.timing.margin;
  if (key == "resolution") return gate.timing.resolution;
  if (key == "cmd_vel_timeout") return gate.cmd_vel_timeout_s;
  if (key == "max_linear_speed") return gate.max_linear_speed;
  if (key == "max_angular_speed") return gate.max_angular_speed;
  if (key == "reaction_time") return gate.base.reaction_time;
  if (key == "max_linear_deceleration") return gate.base.linear_deceleration;
  if (key == "max_angular_deceleration") return gate.base.angular_deceleration;
  ADD_FAILURE() << "no field for " << key;
  return kNaN;
}

TEST(GateParams, AnEmptyDictIsTheDefaultGate) {
  XmlRpcValue value;
  value["enabled"] = false;  // a dict with one key, the default's value
  const app::GateConfig read = params::readGate(value);
  const app::GateConfig defaults;
  EXPECT_EQ(read.enabled, defaults.enabled);
  EXPECT_EQ(read.robot_frame, defaults.robot_frame);
  EXPECT_EQ(read.odom_topic, defaults.odom_topic);
  EXPECT_EQ(read.on_incomplete, defaults.on_incomplete);
  for (const auto& [key, unused] : kGateNumbers) {
    EXPECT_EQ(field(read, key), field(defaults, key)) << key;
  }
}

TEST(GateParams, EveryKeyIsReadIntoItsField) {
  XmlRpcValue value;
  value["enabled"] = true;
  value["robot_frame"] = "base_footprint";
  value["odom_topic"] = "/odom";
  value["on_incomplete"] = "pass";
  for (const auto& [key, number] : kGateNumbers) value[key] = number;
  const app::GateConfig read = params::readGate(value);
  EXPECT_TRUE(read.enabled);
  EXPECT_EQ(read.robot_frame, "base_footprint");
  EXPECT_EQ(read.odom_topic, "/odom");
  EXPECT_EQ(read.on_incomplete, app::OnIncomplete::Pass);
  for (const auto& [key, number] : kGateNumbers) EXPECT_EQ(field(read, key), number) << key;
}

TEST(GateParams, EveryNumberKeyRefusesNaNInfinityNegativeAndHugeValuesNamingKeyAndValue) {
  const std::pair<double, const char*> bad[] = {
      {kNaN, "got nan"}, {kInf, "got inf"}, {-1.0, "got -1"}, {1e12, "got 1e+12"}};
  for (const auto& [key, unused] : kGateNumbers) {
    for (const auto& [number, actual] : bad) {
      XmlRpcValue value;
      value[key] = number;
      const std::string refusal = refusalOf([&] { params::readGate(value); });
      EXPECT_CONTAINS(refusal, "parameter ~gate, key 'gate/" + std::string(key) + "': expected ");
      EXPECT_CONTAINS(refusal, actual);
    }
  }
}

TEST(GateParams, WrongTypesNameTheKeyExpectedAndActual) {
  for (const auto& [key, unused] : kGateNumbers) {
    XmlRpcValue value;
    value[key] = "fast";
    EXPECT_EQ(refusalOf([&] { params::readGate(value); }),
              "parameter ~gate, key 'gate/" + std::string(key) +
                  "': expected a number, got 'fast' (a string)");
  }
  XmlRpcValue value;
  value["enabled"] = 1;
  EXPECT_EQ(refusalOf([&] { params::readGate(value); }),
            "parameter ~gate, key 'gate/enabled': expected true or false, got 1 (an int)");
  value = XmlRpcValue();
  value["robot_frame"] = 3.5;
  EXPECT_EQ(refusalOf([&] { params::readGate(value); }),
            "parameter ~gate, key 'gate/robot_frame': expected a string, got 3.5 (a double)");
  value = XmlRpcValue();
  value["odom_topic"] = false;
  EXPECT_EQ(refusalOf([&] { params::readGate(value); }),
            "parameter ~gate, key 'gate/odom_topic': expected a string, got false (a bool)");
  value = XmlRpcValue();
  value["on_incomplete"] = true;
  EXPECT_EQ(refusalOf([&] { params::readGate(value); }),
            "parameter ~gate, key 'gate/on_incomplete': expected a string, got true (a bool)");
}

TEST(GateParams, TheRobotFrameIsANonEmptyFrameWithoutALeadingSlash) {
  XmlRpcValue value;
  value["robot_frame"] = "";
  EXPECT_EQ(refusalOf([&] { params::readGate(value); }),
            "parameter ~gate, key 'gate/robot_frame': expected a non-empty tf frame id, got ''");
  value["robot_frame"] = "/base_link";
  EXPECT_EQ(refusalOf([&] { params::readGate(value); }),
            "parameter ~gate, key 'gate/robot_frame': expected a tf2 frame id without a leading "
            "'/', got '/base_link'");
}

TEST(GateParams, NotADictIsRefusedWithWhatItIs) {
  XmlRpcValue list;
  list[0] = 1.0;
  EXPECT_EQ(refusalOf([&] { params::readGate(list); }),
            "parameter ~gate, key 'gate': expected a dict of gate parameters, got a list of 1");
}

TEST(GateParams, TheGateIsOffByDefaultAndItsKeysAreReadAndRangeChecked) {
  EXPECT_FALSE(parseNodeConfig(validParams()).monitor.gate.enabled);
  XmlRpcValue p = validParams();
  p["gate"]["enabled"] = true;
  p["gate"]["robot_frame"] = "base_footprint";
  p["gate"]["horizon"] = 4;
  p["gate"]["time_before_collision"] = 2.0;
  p["gate"]["stop_time"] = 0.5;
  p["gate"]["on_incomplete"] = "pass";
  const NodeConfig config = parseNodeConfig(p);
  EXPECT_TRUE(config.monitor.gate.enabled);
  EXPECT_EQ(config.monitor.gate.robot_frame, "base_footprint");
  EXPECT_EQ(config.monitor.gate.timing.horizon, 4.0);
  EXPECT_EQ(config.monitor.gate.timing.time_before_collision, 2.0);
  EXPECT_EQ(config.monitor.gate.timing.stop_time, 0.5);
  EXPECT_EQ(config.monitor.gate.on_incomplete, app::OnIncomplete::Pass);

  p["gate"]["stop_time"] = 3.0;
  EXPECT_EQ(errorOf(p),
            "parameter ~gate, key 'gate/stop_time': expected a number within [0, 2] (at "
            "most gate/time_before_collision), got 3");
  p["gate"]["stop_time"] = 0.5;
  p["gate"]["on_incomplete"] = "maybe";
  EXPECT_EQ(errorOf(p),
            "parameter ~gate, key 'gate/on_incomplete': expected 'stop' or 'pass', got 'maybe'");
  p["gate"]["on_incomplete"] = "stop";
  p["gate"]["horizen"] = 3.0;
  EXPECT_NE(errorOf(p).find("parameter ~gate/horizen: unknown key"), std::string::npos)
      << errorOf(p);
  XmlRpcValue q = validParams();
  q["gate"]["horizon"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(errorOf(q).find("key 'gate/horizon'"), std::string::npos) << errorOf(q);
  q = validParams();
  q["gate"] = true;
  EXPECT_NE(errorOf(q).find("expected a dict of gate parameters"), std::string::npos) << errorOf(q);
}

}  // namespace
}  // namespace ellipse_collision

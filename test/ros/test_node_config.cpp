// Parsing and validation of the node's parameters from XmlRpc values; no ROS master needed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ellipse_collision/ros/node_config.h"

namespace ellipse_collision {
namespace {

using XmlRpc::XmlRpcValue;

XmlRpcValue ellipseEntry(const std::string& name, const std::string& frame, double x = 0.0,
                         double radius = 0.2) {
  XmlRpcValue e;
  e["name"] = name;
  e["frame"] = frame;
  e["x"] = x;
  e["y"] = 0.0;
  e["angle"] = 0.0;
  e["radius_x"] = radius;
  e["radius_y"] = radius;
  return e;
}

XmlRpcValue pair(const std::string& a, const std::string& b) {
  XmlRpcValue p;
  p[0] = a;
  p[1] = b;
  return p;
}

/// A complete valid configuration: links arm, hand; obstacle table; allowed pair (arm, hand).
XmlRpcValue validParams() {
  XmlRpcValue p;
  p["fixed_frame"] = "map";
  p["rate"] = 5.0;
  p["tf_timeout"] = 0.5;
  p["padding"] = 0.01;
  p["self_collision"] = false;
  p["warning_distance"] = 0.25;
  p["links"][0] = ellipseEntry("arm", "arm_link");
  p["links"][1] = ellipseEntry("hand", "hand_link", 1.0, 0.1);
  p["links"][1]["padding"] = 0.02;
  p["obstacles"][0] = ellipseEntry("table", "map", 3.0, 0.5);
  p["allowed_pairs"][0] = pair("arm", "hand");
  return p;
}

/// The ConfigError message of parsing `params`, or "" when it parses.
std::string errorOf(const XmlRpcValue& params) {
  try {
    parseNodeConfig(params);
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

TEST(NodeConfig, ValidConfigurationIsReadCompletely) {
  const NodeConfig config = parseNodeConfig(validParams());
  EXPECT_EQ(config.monitor.check.fixed_frame, "map");
  EXPECT_EQ(config.monitor.rate_hz, 5.0);
  EXPECT_EQ(config.tf_timeout_s, 0.5);
  EXPECT_EQ(config.monitor.check.global_padding_m, 0.01);
  EXPECT_FALSE(config.monitor.check.rules.self_collision);
  EXPECT_EQ(config.monitor.check.rules.warning_distance, 0.25);
  ASSERT_EQ(config.links.size(), 2u);
  EXPECT_EQ(config.links[1].name, "hand");
  EXPECT_EQ(config.links[1].frame_id, "hand_link");
  EXPECT_EQ(config.links[1].x, 1.0);
  EXPECT_EQ(config.links[1].radius_y, 0.1);
  EXPECT_EQ(config.links[1].padding, 0.02);
  EXPECT_EQ(config.links[0].padding, 0.0);
  ASSERT_EQ(config.obstacles.size(), 1u);
  EXPECT_EQ(config.obstacles[0].name, "table");
  ASSERT_EQ(config.monitor.check.rules.allowed.size(), 1u);
  EXPECT_TRUE(config.monitor.check.rules.allowed.contains("arm", "hand"));
}

TEST(NodeConfig, OptionalKeysTakeTheirDocumentedDefaults) {
  XmlRpcValue p;
  p["links"].setSize(0);
  const NodeConfig config = parseNodeConfig(p);
  EXPECT_EQ(config.monitor.check.fixed_frame, "base_link");
  EXPECT_EQ(config.monitor.rate_hz, 10.0);
  EXPECT_EQ(config.tf_timeout_s, 0.1);
  EXPECT_EQ(config.monitor.check.global_padding_m, 0.0);
  EXPECT_TRUE(config.monitor.check.rules.self_collision);
  EXPECT_EQ(config.monitor.check.rules.warning_distance, 0.0);
  EXPECT_TRUE(config.links.empty());
  EXPECT_TRUE(config.obstacles.empty());
  EXPECT_EQ(config.monitor.check.rules.allowed.size(), 0u);
  EXPECT_EQ(config.marker_refresh_period_s, 10.0);
}

TEST(NodeConfig, IntegersAreAcceptedWhereNumbersAreExpected) {
  XmlRpcValue p = validParams();
  p["rate"] = 20;
  p["links"][0]["radius_x"] = 1;
  p["links"][0]["x"] = -3;
  const NodeConfig config = parseNodeConfig(p);
  EXPECT_EQ(config.monitor.rate_hz, 20.0);
  EXPECT_EQ(config.links[0].radius_x, 1.0);
  EXPECT_EQ(config.links[0].x, -3.0);
}

TEST(NodeConfig, MissingLinksStopsTheNode) {
  XmlRpcValue p;
  p["rate"] = 1.0;
  EXPECT_CONTAINS(errorOf(p), "~links");
  EXPECT_CONTAINS(errorOf(XmlRpcValue()), "~links");
}

TEST(NodeConfig, MissingEntryKeyNamesEntryAndKey) {
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

TEST(NodeConfig, WrongTypeNamesEntryKeyExpectedAndActual) {
  XmlRpcValue p = validParams();
  p["obstacles"][0]["radius_x"] = "big";
  EXPECT_EQ(errorOf(p),
            "obstacles[0] (name 'table'), key 'radius_x': expected a number, got 'big' (a string)");
}

TEST(NodeConfig, NonPositiveRadiusStopsTheNode) {
  XmlRpcValue p = validParams();
  p["links"][1]["radius_x"] = 0.0;
  EXPECT_EQ(errorOf(p),
            "links[1] (name 'hand'), key 'radius_x': expected a finite number > 0, got 0");
  p = validParams();
  p["links"][0]["radius_y"] = -0.3;
  EXPECT_CONTAINS(errorOf(p), "links[0] (name 'arm'), key 'radius_y'");
  EXPECT_CONTAINS(errorOf(p), "got -0.3");
}

TEST(NodeConfig, NonFiniteNumbersStopTheNode) {
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

TEST(NodeConfig, NegativePaddingStopsTheNode) {
  XmlRpcValue p = validParams();
  p["links"][1]["padding"] = -0.01;
  EXPECT_CONTAINS(errorOf(p), "links[1] (name 'hand'), key 'padding'");
  p = validParams();
  p["padding"] = -1;
  EXPECT_CONTAINS(errorOf(p), "parameter ~padding");
}

TEST(NodeConfig, DuplicateNameAcrossLinksAndObstaclesStopsTheNode) {
  XmlRpcValue p = validParams();
  p["obstacles"][1] = ellipseEntry("arm", "map");
  EXPECT_EQ(errorOf(p),
            "obstacles[1] (name 'arm'), key 'name': expected a name used by no other entry, got a "
            "duplicate of links[0]");
}

TEST(NodeConfig, AllowedPairWithUnknownNameStopsTheNode) {
  XmlRpcValue p = validParams();
  p["allowed_pairs"][1] = pair("table", "hnad");
  const std::string error = errorOf(p);
  EXPECT_CONTAINS(error, "allowed_pairs[1][1] = 'hnad'");
  EXPECT_CONTAINS(error, "unknown name");
}

TEST(NodeConfig, AllowedPairMustBeTwoDifferentNames) {
  XmlRpcValue p = validParams();
  p["allowed_pairs"][0] = pair("arm", "arm");
  EXPECT_CONTAINS(errorOf(p), "allowed_pairs[0]: expected two different names");
  p = validParams();
  p["allowed_pairs"][0] = "arm";
  EXPECT_CONTAINS(errorOf(p), "allowed_pairs[0]: expected a list of two names");
}

TEST(NodeConfig, UnknownKeysStopTheNodeInsteadOfBeingIgnored) {
  XmlRpcValue p = validParams();
  p["self_colision"] = true;
  EXPECT_CONTAINS(errorOf(p), "parameter ~self_colision: unknown key");
  p = validParams();
  p["links"][0]["radius"] = 0.2;
  EXPECT_CONTAINS(errorOf(p), "links[0] (name 'arm'): unknown key 'radius'");
}

TEST(NodeConfig, LinksAndObstaclesMayBeEllipsoidsWithRadiusZ) {
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
    EXPECT_EQ(errorOf(p), entry + ": missing key 'radius_z' (z, roll and pitch describe an "
                                  "ellipsoid, which needs radius_z)");
    p = validParams();
    p[list][0]["radius_z"] = -1.0;
    EXPECT_EQ(errorOf(p), entry + ", key 'radius_z': expected a finite number > 0, got -1");
    p[list][0]["radius_z"] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(errorOf(p), entry + ", key 'radius_z': expected a finite number > 0, got nan");
    p[list][0]["radius_z"] = 0.0;
    p[list][0]["roll"] = 1.5;
    EXPECT_EQ(errorOf(p), entry + ", key 'roll': expected 0 when radius_z = 0 (a planar ellipse); "
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

TEST(NodeConfig, ScalarParametersAreTypeChecked) {
  XmlRpcValue p = validParams();
  p["rate"] = "fast";
  EXPECT_EQ(errorOf(p), "parameter ~rate, key 'rate': expected a number, got 'fast' (a string)");
  p = validParams();
  p["rate"] = -1.0;
  EXPECT_CONTAINS(errorOf(p), "parameter ~rate, key 'rate': expected a finite number >= 0, got -1");
  p = validParams();
  p["self_collision"] = 1;
  EXPECT_EQ(
      errorOf(p),
      "parameter ~self_collision, key 'self_collision': expected true or false, got 1 (an int)");
  p = validParams();
  p["fixed_frame"] = "/map";
  EXPECT_CONTAINS(errorOf(p), "parameter ~fixed_frame, key 'fixed_frame'");
}

TEST(NodeConfig, WarningDistanceMustBeAFiniteNumberNotBelowZero) {
  XmlRpcValue p = validParams();
  p["warning_distance"] = 1;  // an int is a number
  EXPECT_EQ(parseNodeConfig(p).monitor.check.rules.warning_distance, 1.0);
  const std::pair<double, const char*> bad[] = {
      {-0.1, "got -0.1"},
      {std::numeric_limits<double>::quiet_NaN(), "got nan"},
      {std::numeric_limits<double>::infinity(), "got inf"}};
  for (const auto& [value, actual] : bad) {
    p["warning_distance"] = value;
    EXPECT_EQ(errorOf(p), std::string("parameter ~warning_distance, key 'warning_distance': ") +
                              "expected a finite number >= 0, " + actual);
  }
  p["warning_distance"] = "near";
  EXPECT_CONTAINS(errorOf(p), "key 'warning_distance': expected a number, got 'near' (a string)");
}

TEST(NodeConfig, EllipseListsMustBeListsOfDicts) {
  XmlRpcValue p = validParams();
  p["obstacles"] = "none";
  EXPECT_CONTAINS(errorOf(p), "parameter ~obstacles, key 'obstacles': expected a list of ellipses");
  p = validParams();
  p["links"][0] = 3;
  EXPECT_CONTAINS(errorOf(p), "links[0]: expected a dict with keys");
}

TEST(NodeConfig, EmptyOrSlashedFrameOfAnEntryStopsTheNode) {
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

TEST(NodeConfig, RateIsZeroOrWithinItsDocumentedRange) {
  XmlRpcValue p = validParams();
  for (double ok : {0.0, kMinRateHz, kMaxRateHz, 1e-3, 1e3}) {
    p["rate"] = ok;
    EXPECT_EQ(parseNodeConfig(p).monitor.rate_hz, ok);
  }
  // 1e-12 Hz: a period of 1e12 s, beyond ros::Duration; 1e12 Hz: a period that rounds to 0.
  const std::pair<double, const char*> bad[] = {
      {1e-12, "got 1e-12"}, {9.99e-4, "got 0.000999"}, {1000.5, "got 1000.5"}, {1e12, "got 1e+12"}};
  for (const auto& [value, actual] : bad) {
    p["rate"] = value;
    EXPECT_EQ(errorOf(p), std::string("parameter ~rate, key 'rate': expected 0 or a number within "
                                      "[0.001, 1000], ") +
                              actual);
  }
  p["rate"] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(errorOf(p), "parameter ~rate, key 'rate': expected a finite number >= 0, got inf");
}

TEST(NodeConfig, StartUpAndReconfigureRefuseTheSameValuesFromOneRangeTable) {
  // Every reconfigurable scalar: just past its range (or negative where it has no upper bound) is
  // refused at start-up and by the reconfigure rule with the same expectation text; its bound is
  // accepted by both.
  struct Field {
    const char* key;
    double app::TunableSettings::*member;
  };
  const Field fields[] = {{"rate", &app::TunableSettings::rate_hz},
                          {"prediction_horizon", &app::TunableSettings::prediction_horizon_s},
                          {"padding", &app::TunableSettings::padding_m},
                          {"warning_distance", &app::TunableSettings::warning_distance_m},
                          {"max_transform_age", &app::TunableSettings::max_transform_age_s},
                          {"obstacle_timeout", &app::TunableSettings::obstacle_timeout_s}};
  for (const Field& field : fields) {
    const app::SettingRange& range = app::settingRange(field.key);
    const double outside = std::isinf(range.max) ? -1.0 : range.max * 1.5;
    XmlRpcValue p = validParams();
    p[field.key] = outside;
    app::TunableSettings tunable;
    tunable.*field.member = outside;
    const auto refused = app::findInvalidTunable(tunable);
    ASSERT_TRUE(refused) << field.key;
    EXPECT_EQ(refused->key, field.key);
    EXPECT_EQ(errorOf(p), "parameter ~" + std::string(field.key) + ", key '" + field.key +
                              "': expected " + refused->expected + ", got " + refused->actual);
    // (At the padding's bound every link's radius would pass kMaxRadius: refused for the links.)
    if (!std::isinf(range.max) && std::string(field.key) != "padding") {
      p[field.key] = range.max;
      tunable.*field.member = range.max;
      EXPECT_EQ(errorOf(p), "") << field.key;
      EXPECT_FALSE(app::findInvalidTunable(tunable)) << field.key;
    }
  }
  EXPECT_THROW(app::settingRange("no_such_parameter"), std::invalid_argument);
}

TEST(NodeConfig, TfTimeoutIsWithinItsDocumentedRange) {
  XmlRpcValue p = validParams();
  for (double ok : {0.0, 1e-9, kMaxDurationS}) {
    p["tf_timeout"] = ok;
    EXPECT_EQ(parseNodeConfig(p).tf_timeout_s, ok);
  }
  p["tf_timeout"] = 3600.5;
  EXPECT_EQ(errorOf(p),
            "parameter ~tf_timeout, key 'tf_timeout': expected a number within [0, 3600], got "
            "3600.5");
  p["tf_timeout"] = 1e12;  // every service call would fail building ros::Duration
  EXPECT_EQ(errorOf(p),
            "parameter ~tf_timeout, key 'tf_timeout': expected a number within [0, 3600], got "
            "1e+12");
}

TEST(NodeConfig, MarkerRefreshPeriodIsZeroOrWithinItsDocumentedRange) {
  XmlRpcValue p = validParams();
  for (double ok : {0.0, 0.5, kMaxDurationS}) {
    p["marker_refresh_period"] = ok;
    EXPECT_EQ(parseNodeConfig(p).marker_refresh_period_s, ok);
  }
  p["marker_refresh_period"] = -1.0;
  EXPECT_EQ(errorOf(p),
            "parameter ~marker_refresh_period, key 'marker_refresh_period': expected a finite "
            "number >= 0, got -1");
  p["marker_refresh_period"] = 3600.5;
  EXPECT_EQ(errorOf(p),
            "parameter ~marker_refresh_period, key 'marker_refresh_period': expected a number "
            "within [0, 3600], got 3600.5");
  p["marker_refresh_period"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_CONTAINS(errorOf(p), "parameter ~marker_refresh_period, key 'marker_refresh_period'");
  EXPECT_CONTAINS(errorOf(p), "nan");
}

TEST(NodeConfig, GlobalPaddingIsWithinTheCoreRadiusRange) {
  XmlRpcValue p;
  p["links"].setSize(0);  // no entries: the padding's own range is checked
  p["padding"] = core::kMaxRadius;
  EXPECT_EQ(parseNodeConfig(p).monitor.check.global_padding_m, core::kMaxRadius);
  p["padding"] = 1.5e9;
  EXPECT_EQ(errorOf(p),
            "parameter ~padding, key 'padding': expected a number within [0, 1e+09], got 1.5e+09");
  p = validParams();
  p["padding"] = 1e12;
  EXPECT_CONTAINS(errorOf(p), "parameter ~padding, key 'padding'");
}

TEST(NodeConfig, PaddedRadiiBeyondTheCoreRangeStopTheNode) {
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

TEST(NodeConfig, TheGateIsOffByDefaultAndItsKeysAreReadAndRangeChecked) {
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

TEST(NodeConfig, TheIncidentRecorderIsOnByDefaultAndItsKeysAreReadAndChecked) {
  const app::IncidentSettings defaults = parseNodeConfig(validParams()).monitor.incident;
  EXPECT_TRUE(defaults.enabled);
  EXPECT_EQ(defaults.actions.size(), 4u);
  EXPECT_EQ(defaults.directory, "");
  XmlRpcValue p = validParams();
  p["incident"]["enabled"] = false;
  p["incident"]["before"] = 5;
  p["incident"]["after"] = 1.5;
  p["incident"]["min_interval"] = 0.0;
  p["incident"]["max_files"] = 3;
  p["incident"]["max_megabytes"] = 50.0;
  p["incident"]["directory"] = "/var/incidents";
  p["incident"]["actions"][0] = "STOP";
  p["incident"]["actions"][1] = "SLOW";
  const app::IncidentSettings read = parseNodeConfig(p).monitor.incident;
  EXPECT_FALSE(read.enabled);
  EXPECT_EQ(read.before_s, 5.0);
  EXPECT_EQ(read.after_s, 1.5);
  EXPECT_EQ(read.min_interval_s, 0.0);
  EXPECT_EQ(read.max_files, 3u);
  EXPECT_EQ(read.max_megabytes, 50.0);
  EXPECT_EQ(read.directory, "/var/incidents");
  EXPECT_EQ(read.actions,
            (std::vector<core::GateAction>{core::GateAction::Stop, core::GateAction::Slow}));

  p["incident"]["actions"][1] = "HALT";
  EXPECT_EQ(errorOf(p),
            "parameter ~incident, key 'incident/actions': expected gate actions among PASS, SLOW, "
            "STOP, ESCAPE, TIMEOUT, INCOMPLETE, DISABLED, got 'HALT'");
  p["incident"]["actions"][1] = "STOP";
  EXPECT_NE(errorOf(p).find("'STOP' twice"), std::string::npos) << errorOf(p);
  p["incident"]["actions"][1] = "SLOW";
  p["incident"]["max_files"] = 2.5;
  EXPECT_NE(errorOf(p).find("key 'incident/max_files': expected a whole number"), std::string::npos)
      << errorOf(p);
  p["incident"]["max_files"] = 3;
  p["incident"]["before"] = 0.0;
  EXPECT_EQ(errorOf(p),
            "parameter ~incident, key 'incident/before': expected a number within (0, 600], got 0");
  p["incident"]["before"] = std::numeric_limits<double>::infinity();
  EXPECT_NE(errorOf(p).find("key 'incident/before'"), std::string::npos) << errorOf(p);
  p["incident"]["before"] = 5;
  p["incident"]["afterwards"] = 1.0;
  EXPECT_NE(errorOf(p).find("parameter ~incident/afterwards: unknown key"), std::string::npos)
      << errorOf(p);
  XmlRpcValue q = validParams();
  q["incident"] = "on";
  EXPECT_NE(errorOf(q).find("expected a dict of incident parameters"), std::string::npos)
      << errorOf(q);
}

XmlRpcValue sourceEntry(const std::string& name, const std::string& type,
                        const std::string& topic) {
  XmlRpcValue e;
  e["name"] = name;
  e["type"] = type;
  e["topic"] = topic;
  return e;
}

TEST(NodeConfig, SourcesAreReadWithTheirScanSettings) {
  XmlRpcValue p = validParams();
  EXPECT_TRUE(parseNodeConfig(p).monitor.sources.empty()) << "only ~obstacles by default";
  p["sources"][0] = sourceEntry("front_scan", "scan", "front/scan");
  p["sources"][0]["timeout"] = 0.5;
  p["sources"][0]["range_noise_sigma"] = 0.02;
  p["sources"][0]["min_cluster_points"] = 3;
  p["sources"][1] = sourceEntry("people", "ellipses", "~people");
  const NodeConfig config = parseNodeConfig(p);
  ASSERT_EQ(config.monitor.sources.size(), 2u);
  const app::SourceSpec& front = config.monitor.sources[0];
  EXPECT_EQ(front.name, "front_scan");
  EXPECT_EQ(front.type, app::SourceType::Scan);
  EXPECT_EQ(front.topic, "front/scan");
  EXPECT_EQ(front.timeout_s, 0.5);
  EXPECT_EQ(front.scan.range_noise_sigma, 0.02);
  EXPECT_EQ(front.scan.min_cluster_points, 3);
  EXPECT_EQ(front.scan.min_radius, app::ScanObstacleSettings().min_radius);
  EXPECT_EQ(config.monitor.sources[1].type, app::SourceType::Ellipses);
  EXPECT_EQ(config.monitor.sources[1].timeout_s, 0.0) << "no watchdog by default";
  // Tracked by default, in the node's fixed frame; a source may say otherwise.
  EXPECT_TRUE(front.tracking.enabled);
  EXPECT_EQ(front.tracking.fixed_frame, config.monitor.check.fixed_frame);
  p["sources"][0]["tracking"]["fixed_frame"] = "odom";
  p["sources"][0]["tracking"]["confirm_count"] = 5;
  const NodeConfig tracked = parseNodeConfig(p);
  EXPECT_EQ(tracked.monitor.sources[0].tracking.fixed_frame, "odom");
  EXPECT_EQ(tracked.monitor.sources[0].tracking.confirm_count, 5);
}

TEST(NodeConfig, BadSourcesStopTheNodeNamingEntryKeyAndValue) {
  const auto with = [](void (*change)(XmlRpcValue&)) {
    XmlRpcValue p = validParams();
    p["sources"][0] = sourceEntry("front_scan", "scan", "front/scan");
    p["sources"][1] = sourceEntry("rear_scan", "scan", "rear/scan");
    change(p["sources"]);
    return errorOf(p);
  };
  EXPECT_EQ(with([](XmlRpcValue&) {}), "");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[1]["name"] = "front_scan"; }),
                  "key 'sources[1].name': expected a name used by no other source, got "
                  "'front_scan', the name of sources[0]");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[1]["topic"] = "front/scan"; }),
                  "key 'sources[1].topic'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["topic"] = ""; }), "key 'sources[0].topic'");
  EXPECT_CONTAINS(
      with([](XmlRpcValue& s) { s[0]["type"] = "sonar"; }),
      "key 'sources[0].type': expected 'ellipses', 'scan', 'cloud', 'range' or 'robots', got "
      "'sonar'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["timeout"] = std::nan(""); }),
                  "key 'sources[0].timeout'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["timeout"] = -1.0; }), "key 'sources[0].timeout'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["timeout"] = "soon"; }),
                  "key 'sources[0].timeout': expected a number");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["min_radius"] = -1.0; }),
                  "key 'sources[0].min_radius'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[1]["colour"] = "red"; }), "key 'sources[1].colour'");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) {
                    s[1]["type"] = "ellipses";
                    s[1]["min_radius"] = 0.1;
                  }),
                  "key 'sources[1].min_radius'")
      << "scan settings belong to scan sources";
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["tracking"]["confirm_count"] = 1; }),
                  "key 'sources[0].tracking/confirm_count': expected a number within [2, 1000], "
                  "got 1");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0]["tracking"]["max_sped"] = 1.0; }),
                  "key 'sources[0].tracking/max_sped': expected one of enabled");
  EXPECT_CONTAINS(with([](XmlRpcValue& s) {
                    s[1]["type"] = "ellipses";
                    s[1]["tracking"]["enabled"] = false;
                  }),
                  "key 'sources[1].tracking'")
      << "tracking belongs to scan and cloud sources";
  EXPECT_CONTAINS(with([](XmlRpcValue& s) { s[0] = XmlRpcValue("front"); }), "key 'sources[0]'");
  XmlRpcValue no_topic = validParams();
  no_topic["sources"][0]["name"] = "a";
  no_topic["sources"][0]["type"] = "scan";
  EXPECT_CONTAINS(errorOf(no_topic), "key 'sources[0].topic': expected a value (required)");
  XmlRpcValue not_a_list = validParams();
  not_a_list["sources"] = "front";
  EXPECT_CONTAINS(errorOf(not_a_list), "key 'sources'");
}

TEST(NodeConfig, FleetSettingsDefaultToPublishingTheNamespaceInMap) {
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

TEST(NodeConfig, BadFleetSettingsStopTheNodeNamingTheKey) {
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

TEST(NodeConfig, ARobotsSourceListensOnTheFleetTopicAndIsWatchedOnlyWhenRequired) {
  XmlRpcValue p = validParams();
  p["fleet"]["topic"] = "/site/footprints";
  p["sources"][0]["name"] = "fleet";
  p["sources"][0]["type"] = "robots";
  const NodeConfig config = parseNodeConfig(p, {}, "r1");
  ASSERT_EQ(config.monitor.sources.size(), 1u);
  const app::SourceSpec& robots = config.monitor.sources[0];
  EXPECT_EQ(robots.type, app::SourceType::Robots);
  EXPECT_EQ(robots.topic, "/site/footprints") << "fleet/topic by default";
  EXPECT_EQ(robots.timeout_s, app::kDefaultRobotsTimeoutS);
  EXPECT_FALSE(robots.required);
  EXPECT_FALSE(app::watchesSilence(robots)) << "robots leave: no INCOMPLETE by default";
  p["sources"][0]["required"] = true;
  p["sources"][0]["timeout"] = 2.0;
  const NodeConfig required = parseNodeConfig(p, {}, "r1");
  EXPECT_TRUE(app::watchesSilence(required.monitor.sources[0]));
  EXPECT_EQ(required.monitor.sources[0].timeout_s, 2.0);
  p["sources"][0]["timeout"] = 0.0;
  EXPECT_CONTAINS(errorOf(p), "key 'sources[0].timeout': expected a number within (0, 3600]");
  p["sources"][0]["timeout"] = 1.0;
  p["sources"][0]["min_radius"] = 0.1;
  EXPECT_CONTAINS(errorOf(p), "key 'sources[0].min_radius'");
  XmlRpcValue scan = validParams();
  scan["sources"][0] = sourceEntry("front_scan", "scan", "front/scan");
  scan["sources"][0]["required"] = true;
  EXPECT_CONTAINS(errorOf(scan), "key 'sources[0].required'") << "robots sources only";
}

}  // namespace
}  // namespace ellipse_collision

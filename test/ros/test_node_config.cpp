// Parsing and validation of the node's parameters from XmlRpc values, the scalars and the assembly
// of the sections (each section's reader has its test file: test_gate_params.cpp, ...); no ROS
// master needed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ellipse_collision/ros/node_config.h"
#include "node_config_fixture.h"

namespace ellipse_collision {
namespace {

using test::ellipseEntry;
using test::errorOf;
using test::validParams;
using XmlRpc::XmlRpcValue;

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

TEST(NodeConfig, DuplicateNameAcrossLinksAndObstaclesStopsTheNode) {
  XmlRpcValue p = validParams();
  p["obstacles"][1] = ellipseEntry("arm", "map");
  EXPECT_EQ(errorOf(p),
            "obstacles[1] (name 'arm'), key 'name': expected a name used by no other entry, got a "
            "duplicate of links[0]");
}

TEST(NodeConfig, UnknownKeysStopTheNodeInsteadOfBeingIgnored) {
  XmlRpcValue p = validParams();
  p["self_colision"] = true;
  EXPECT_CONTAINS(errorOf(p), "parameter ~self_colision: unknown key");
  p = validParams();
  p["links"][0]["radius"] = 0.2;
  EXPECT_CONTAINS(errorOf(p), "links[0] (name 'arm'): unknown key 'radius'");
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

}  // namespace
}  // namespace ellipse_collision

// The node's scalar parameters that may change while it runs (app/tunable_settings.h): the one
// range table, the messages of refused values, and the log lines of the settings and changes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "ellipse_collision/app/tunable_settings.h"

namespace ellipse_collision::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(TunableSettings, TheRangeRuleIsTheOneTheStartUpUses) {
  EXPECT_FALSE(findOutsideSettingRange("rate", 0.0, kMinRateHz, kMaxRateHz, true));
  EXPECT_EQ(findOutsideSettingRange("rate", 1e-4, kMinRateHz, kMaxRateHz, true)->expected,
            "0 or a number within [0.001, 1000]");
  EXPECT_EQ(findOutsideSettingRange("rate", -1.0, kMinRateHz, kMaxRateHz, true)->expected,
            "a finite number >= 0");
  EXPECT_EQ(findNegativeSetting("warning_distance", INFINITY)->actual, "inf");
  EXPECT_FALSE(findInvalidTunable(TunableSettings{}));
}

TEST(TunableSettings, TheRangeTableHoldsTheDocumentedBounds) {
  const auto expectRange = [](const char* key, double min, double max, bool zero_allowed) {
    const SettingRange& range = settingRange(key);
    EXPECT_STREQ(range.key, key);
    EXPECT_EQ(range.min, min) << key;
    EXPECT_EQ(range.max, max) << key;
    EXPECT_EQ(range.zero_allowed, zero_allowed) << key;
  };
  expectRange("rate", 1e-3, 1e3, true);
  expectRange("prediction_horizon", 0.0, 60.0, false);
  expectRange("padding", 0.0, 1e9, false);
  expectRange("warning_distance", 0.0, std::numeric_limits<double>::infinity(), false);
  for (const char* key : {"tf_timeout", "max_transform_age", "obstacle_timeout",
                          "obstacle_store_period", "marker_refresh_period"}) {
    expectRange(key, 0.0, 3600.0, false);
  }
  EXPECT_THROW(settingRange("Rate"), std::invalid_argument) << "keys are case-sensitive";
  EXPECT_THROW(settingRange("gate/horizon"), std::invalid_argument) << "gate/ has its own rule";
}

/// The message of `value` for `key` by the table, or "accepted".
std::string byTable(const std::string& key, double value) {
  const auto error = findOutsideSettingRange(key, value);
  return error ? describeFieldError("~", *error) : std::string("accepted");
}

TEST(TunableSettings, ValuesAreRefusedByTheTableNamingKeyAndValue) {
  EXPECT_EQ(byTable("rate", 0.0), "accepted");
  EXPECT_EQ(byTable("rate", 1e3), "accepted");
  EXPECT_EQ(byTable("rate", 1e-3), "accepted");
  EXPECT_EQ(byTable("rate", 1e-4), "~.rate = 1e-04: expected 0 or a number within [0.001, 1000]");
  EXPECT_EQ(byTable("rate", 1000.5),
            "~.rate = 1000.5: expected 0 or a number within [0.001, 1000]");
  EXPECT_EQ(byTable("tf_timeout", 3600.5),
            "~.tf_timeout = 3600.5: expected a number within [0, 3600]");
  EXPECT_EQ(byTable("max_transform_age", kNaN),
            "~.max_transform_age = nan: expected a finite number >= 0");
  EXPECT_EQ(byTable("obstacle_timeout", -1e-9),
            "~.obstacle_timeout = -1e-09: expected a finite number >= 0");
  EXPECT_EQ(byTable("prediction_horizon", 60.000000000000007),
            "~.prediction_horizon = 60.00000000000001: expected a number within [0, 60]");
  EXPECT_EQ(byTable("warning_distance", 1e300), "accepted") << "no upper bound";
  EXPECT_EQ(byTable("warning_distance", std::numeric_limits<double>::infinity()),
            "~.warning_distance = inf: expected a finite number >= 0");
  EXPECT_EQ(byTable("padding", -0.0), "accepted") << "-0 is 0";
}

TEST(TunableSettings, TheFirstBadSettingIsNamedInStartUpOrder) {
  TunableSettings settings;
  settings.rate_hz = -1.0;
  settings.prediction_horizon_s = 61.0;
  settings.gate.timing.horizon = 0.0;
  EXPECT_EQ(findInvalidTunable(settings)->key, "prediction_horizon");
  settings.prediction_horizon_s = 0.0;
  EXPECT_EQ(findInvalidTunable(settings)->key, "rate");
  settings.rate_hz = 0.0;
  settings.obstacle_timeout_s = 4000.0;
  EXPECT_EQ(findInvalidTunable(settings)->key, "obstacle_timeout") << "before the gate's";
  settings.obstacle_timeout_s = 0.0;
  EXPECT_EQ(findInvalidTunable(settings)->key, "gate/horizon");
  settings.gate.timing.horizon = 3.0;
  EXPECT_FALSE(findInvalidTunable(settings));
}

TEST(TunableSettings, TheLogLineGivesEveryValueWithItsUnit) {
  EXPECT_EQ(describeTunable(TunableSettings{}),
            "prediction_horizon 0 s, rate 10 Hz, padding 0 m, warning_distance 0 m, "
            "max_transform_age 0.5 s, obstacle_timeout 0 s, gate/enabled false, gate/horizon 3 s, "
            "gate/time_before_collision 1.5 s, gate/stop_time 0.3 s, gate/margin 0.05 m, "
            "gate/resolution 0.01, gate/cmd_vel_timeout 0.5 s, gate/on_incomplete stop, "
            "gate/max_linear_speed 5 m/s, gate/max_angular_speed 5 rad/s, gate/reaction_time 0 s, "
            "gate/max_linear_deceleration 0 m/s^2, gate/max_angular_deceleration 0 rad/s^2");
}

TEST(TunableSettings, EveryChangedValueIsListedOldToNewAndNothingElse) {
  const TunableSettings before;
  TunableSettings after;
  after.gate.on_incomplete = OnIncomplete::Pass;
  EXPECT_EQ(describeTunableChanges(before, after), "gate/on_incomplete stop -> pass");
  after.gate.base.angular_deceleration = 2.5;
  after.prediction_horizon_s = 0.1;
  EXPECT_EQ(describeTunableChanges(before, after),
            "prediction_horizon 0 -> 0.1 s; gate/on_incomplete stop -> pass; "
            "gate/max_angular_deceleration 0 -> 2.5 rad/s^2");
  // Settings outside the log line (not reconfigurable) are no change.
  TunableSettings frame = before;
  frame.gate.robot_frame = "base_footprint";
  frame.gate.odom_topic = "/odom";
  EXPECT_EQ(describeTunableChanges(before, frame), "");
  // A value that differs by its last bit shows as a change.
  TunableSettings nudged = before;
  nudged.rate_hz = std::nextafter(10.0, 11.0);
  EXPECT_EQ(describeTunableChanges(before, nudged), "rate 10 -> 10.000000000000002 Hz");
}

}  // namespace
}  // namespace ellipse_collision::app

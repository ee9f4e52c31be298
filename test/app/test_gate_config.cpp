// The velocity gate's configuration (app/gate_config.h): each range refused naming its key and
// value, the policy for incomplete data, and the warning about an ideal base.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ellipse_collision/app/gate_config.h"

namespace ellipse_collision::app {
namespace {

TEST(GateSettings, DefaultsAreValidAndEachRangeIsRefusedNamingTheKey) {
  EXPECT_FALSE(findInvalidGateSetting(GateConfig()));
  const auto refused = [](void (*change)(GateConfig&)) {
    GateConfig config;
    change(config);
    const auto invalid = findInvalidGateSetting(config);
    return invalid ? invalid->key + " = " + invalid->actual : std::string("accepted");
  };
  EXPECT_EQ(refused([](GateConfig& c) { c.timing.horizon = 0.0; }), "gate/horizon = 0");
  EXPECT_EQ(refused([](GateConfig& c) { c.timing.horizon = NAN; }), "gate/horizon = nan");
  EXPECT_EQ(refused([](GateConfig& c) { c.timing.time_before_collision = 4.0; }),
            "gate/time_before_collision = 4");
  EXPECT_EQ(refused([](GateConfig& c) { c.timing.stop_time = 2.0; }), "gate/stop_time = 2");
  EXPECT_EQ(refused([](GateConfig& c) { c.timing.margin = -0.1; }), "gate/margin = -0.1");
  EXPECT_EQ(refused([](GateConfig& c) { c.timing.resolution = 0.0; }), "gate/resolution = 0");
  EXPECT_EQ(refused([](GateConfig& c) { c.cmd_vel_timeout_s = INFINITY; }),
            "gate/cmd_vel_timeout = inf");
  EXPECT_EQ(refused([](GateConfig& c) { c.max_linear_speed = 0.0; }), "gate/max_linear_speed = 0");
  EXPECT_EQ(refused([](GateConfig& c) { c.max_angular_speed = 21.0; }),
            "gate/max_angular_speed = 21");
  EXPECT_EQ(refused([](GateConfig& c) { c.robot_frame = "/base_link"; }),
            "gate/robot_frame = '/base_link'");
  EXPECT_EQ(refused([](GateConfig& c) { c.robot_frame = ""; }), "gate/robot_frame = ''");
}

/// The whole message of the first invalid setting of `config`, or "accepted".
std::string refusal(const GateConfig& config) {
  const auto invalid = findInvalidGateSetting(config);
  return invalid ? describeFieldError("config", *invalid) : std::string("accepted");
}

TEST(GateSettings, MessagesGiveTheRangeAndTheKeyThatBoundsIt) {
  GateConfig config;
  config.timing.time_before_collision = 4.0;  // above the horizon 3
  EXPECT_EQ(refusal(config),
            "config.gate/time_before_collision = 4: expected a number within [0, 3] (at most "
            "gate/horizon)");
  config = GateConfig();
  config.timing.stop_time = 1.75;  // above time_before_collision 1.5
  EXPECT_EQ(refusal(config),
            "config.gate/stop_time = 1.75: expected a number within [0, 1.5] (at most "
            "gate/time_before_collision)");
  config = GateConfig();
  config.timing.horizon = -1.0;
  EXPECT_EQ(refusal(config), "config.gate/horizon = -1: expected a number within (0, 60]");
  config = GateConfig();
  config.max_linear_speed = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(refusal(config),
            "config.gate/max_linear_speed = nan: expected a number within (0, 100]");
}

TEST(GateSettings, BaseDynamicsAreRefusedUnderTheirNodeKeys) {
  GateConfig config;
  config.base.reaction_time = 5.5;
  EXPECT_EQ(refusal(config), "config.gate/reaction_time = 5.5: expected a number within [0, 5]");
  config = GateConfig();
  config.base.linear_deceleration = -0.25;
  EXPECT_EQ(refusal(config),
            "config.gate/max_linear_deceleration = -0.25: expected a number within [0, 100]");
  config = GateConfig();
  config.base.angular_deceleration = std::numeric_limits<double>::infinity();
  EXPECT_EQ(refusal(config),
            "config.gate/max_angular_deceleration = inf: expected a number within [0, 100]");
}

TEST(GateSettings, RangeEndsAreAcceptedAsDocumented) {
  GateConfig config;
  config.cmd_vel_timeout_s = 0.0;  // off
  EXPECT_EQ(refusal(config), "accepted");
  config.cmd_vel_timeout_s = core::kMaxGateHorizonS;
  config.max_linear_speed = kMaxGateSpeed;
  config.max_angular_speed = kMaxGateTurnRate;
  config.base = {core::kMaxReactionTimeS, core::kMaxDeceleration, core::kMaxDeceleration};
  EXPECT_EQ(refusal(config), "accepted");
  config.max_linear_speed = std::nextafter(kMaxGateSpeed, 1e9);
  EXPECT_EQ(findInvalidGateSetting(config)->key, "gate/max_linear_speed");
  config.max_linear_speed = kMaxGateSpeed;
  config.cmd_vel_timeout_s = -0.0;
  EXPECT_EQ(refusal(config), "accepted") << "-0 is 0";
}

TEST(GateSettings, TheFrameIsCheckedBeforeTheTiming) {
  GateConfig config;
  config.robot_frame = "/base_link";
  config.timing.horizon = 0.0;
  EXPECT_EQ(refusal(config),
            "config.gate/robot_frame = '/base_link': expected a tf2 frame id without a leading "
            "'/'");
}

TEST(GateFieldError, ACoreViolationTakesThePrefixOnBothKeys) {
  core::GateSettingViolation violation;
  violation.field = "stop_time";
  violation.value = 2.0;
  violation.min = 0.0;
  violation.max = 1.0;
  violation.max_field = "time_before_collision";
  const FieldError error = gateFieldError(violation, "safety/");
  EXPECT_EQ(error.key, "safety/stop_time");
  EXPECT_EQ(error.actual, "2");
  EXPECT_EQ(error.expected, "a number within [0, 1] (at most safety/time_before_collision)");
  violation.max_field = nullptr;
  violation.min_excluded = true;
  violation.value = 0.0;
  EXPECT_EQ(gateFieldError(violation).expected, "a number within (0, 1]");
  EXPECT_EQ(gateFieldError(violation).key, "gate/stop_time");
}

TEST(OnIncomplete, BothPoliciesReadBackAndAnythingElseIsRefusedNamed) {
  for (const OnIncomplete policy : {OnIncomplete::Stop, OnIncomplete::Pass}) {
    OnIncomplete parsed = policy == OnIncomplete::Stop ? OnIncomplete::Pass : OnIncomplete::Stop;
    EXPECT_FALSE(parseOnIncomplete(toString(policy), &parsed));
    EXPECT_EQ(parsed, policy);
  }
  EXPECT_STREQ(toString(OnIncomplete::Stop), "stop");
  EXPECT_STREQ(toString(OnIncomplete::Pass), "pass");
  for (const std::string text : {"Stop", "", " pass", "halt"}) {
    OnIncomplete parsed = OnIncomplete::Pass;
    const auto error = parseOnIncomplete(text, &parsed);
    ASSERT_TRUE(error) << text;
    EXPECT_EQ(describeFieldError("config", *error),
              "config.gate/on_incomplete = '" + text + "': expected 'stop' or 'pass'");
    EXPECT_EQ(parsed, OnIncomplete::Pass) << "a refused text leaves the policy as it was";
  }
}

TEST(IdealBaseWarning, OnlyAnEnabledGateWithEveryLimitZeroIsWarned) {
  GateConfig config;
  EXPECT_EQ(idealBaseWarning(config), "") << "a disabled gate decides nothing";
  config.enabled = true;
  const std::string warning = idealBaseWarning(config);
  for (const char* key :
       {"gate/max_linear_deceleration", "gate/max_angular_deceleration", "gate/reaction_time"}) {
    EXPECT_NE(warning.find(key), std::string::npos) << key;
  }
  config.base.reaction_time = 0.1;
  EXPECT_EQ(idealBaseWarning(config), "");
  config.base = {};
  config.base.angular_deceleration = 1.0;
  EXPECT_EQ(idealBaseWarning(config), "");
}

}  // namespace
}  // namespace ellipse_collision::app

// The health report behind /diagnostics (app/check_health.h): which states are OK, WARN and ERROR,
// and what the message says. No master.
#include <gtest/gtest.h>

#include "ellipse_collision/app/check_health.h"

namespace ellipse_collision::app {
namespace {

using Level = CheckHealth::Level;

CheckHealth afterCheck(const CheckOutcome& outcome, CheckHealthInputs inputs = {}) {
  inputs.outcome = &outcome;
  return assessCheckHealth(inputs);
}

TEST(CheckHealth, BeforeTheFirstCheckItIsOkAndSaysSo) {
  const CheckHealth health = assessCheckHealth({});
  EXPECT_EQ(health.level, Level::Ok);
  EXPECT_EQ(health.message, "no check yet");
}

TEST(CheckHealth, TheSceneStateIsTheMessageWhenNothingIsWrong) {
  CheckOutcome outcome;
  outcome.complete = true;
  EXPECT_EQ(afterCheck(outcome).message, "clear");
  outcome.warnings.push_back({"arm", "crate", 0.05, {}, {}});
  EXPECT_EQ(afterCheck(outcome).message, "closer than the warning distance");
  outcome.predicted.push_back({"arm", "cart", 0.75});
  EXPECT_EQ(afterCheck(outcome).message, "contact predicted in 0.75 s (arm / cart)");
  outcome.collisions.push_back({"arm", "crate", 0.9});
  const CheckHealth health = afterCheck(outcome);
  EXPECT_EQ(health.message, "in collision");
  EXPECT_EQ(health.level, Level::Ok) << "a collision is the answer, not a fault of the checker";
}

TEST(CheckHealth, AMissingFrameWarnsAndAfterOneSecondIsAnError) {
  CheckOutcome outcome;
  outcome.stale_frames = {"gripper"};
  outcome.skipped = {"hand: frame 'gripper' stale"};
  CheckHealthInputs inputs;
  inputs.missing_for_s = {{"gripper", 0.96}};
  CheckHealth health = afterCheck(outcome, inputs);
  EXPECT_EQ(health.level, Level::Warn);
  EXPECT_EQ(health.message, "frames stale: gripper; skipped: hand: frame 'gripper' stale");
  EXPECT_EQ(health.missing_for, std::vector<std::string>{"gripper: 1"});
  inputs.missing_for_s = {{"gripper", kMaxMissingS + 0.01}};
  health = afterCheck(outcome, inputs);
  EXPECT_EQ(health.level, Level::Error);
  EXPECT_NE(health.message.find("a frame has been unavailable or stale for more than 1 s"),
            std::string::npos)
      << health.message;
}

TEST(CheckHealth, AFailedCheckIsAnErrorAndRefusedInputsAndStoreFailuresWarn) {
  CheckOutcome outcome;
  CheckHealthInputs inputs;
  inputs.obstacles_error = "ellipses[3].radius_x = nan: expected a finite number";
  EXPECT_EQ(afterCheck(outcome, inputs).level, Level::Warn);
  inputs.obstacles_error.clear();
  inputs.store_error = "cannot fsync '/x/store.tmp': Input/output error";
  CheckHealth health = afterCheck(outcome, inputs);
  EXPECT_EQ(health.level, Level::Warn);
  EXPECT_EQ(health.message, "obstacle store: cannot fsync '/x/store.tmp': Input/output error");
  inputs.check_failure = "scene refused";
  health = afterCheck(outcome, inputs);
  EXPECT_EQ(health.level, Level::Error);
  EXPECT_EQ(health.message,
            "last check failed: scene refused; obstacle store: cannot fsync '/x/store.tmp': "
            "Input/output error");
}

}  // namespace
}  // namespace ellipse_collision::app

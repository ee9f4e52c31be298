// What the velocity gate does with a command (core/gate_action.h): each action's name and the
// one rule of which actions stop the robot.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "ellipse_collision/core/gate_action.h"

namespace ellipse_collision::core {
namespace {

constexpr GateAction kEveryAction[] = {
    GateAction::Pass,    GateAction::Slow,       GateAction::Stop,    GateAction::Escape,
    GateAction::Timeout, GateAction::Incomplete, GateAction::Disabled};

TEST(GateAction, EachActionHasItsOwnUpperCaseName) {
  EXPECT_STREQ(toString(GateAction::Pass), "PASS");
  EXPECT_STREQ(toString(GateAction::Slow), "SLOW");
  EXPECT_STREQ(toString(GateAction::Stop), "STOP");
  EXPECT_STREQ(toString(GateAction::Escape), "ESCAPE");
  EXPECT_STREQ(toString(GateAction::Timeout), "TIMEOUT");
  EXPECT_STREQ(toString(GateAction::Incomplete), "INCOMPLETE");
  EXPECT_STREQ(toString(GateAction::Disabled), "DISABLED");
  std::set<std::string> names;
  for (const GateAction action : kEveryAction) names.insert(toString(action));
  EXPECT_EQ(names.size(), 7u);
}

TEST(GateAction, StopTimeoutAndIncompleteStopTheRobot) {
  EXPECT_TRUE(stops(GateAction::Stop));
  EXPECT_TRUE(stops(GateAction::Timeout));
  EXPECT_TRUE(stops(GateAction::Incomplete));
  EXPECT_FALSE(stops(GateAction::Slow));
  EXPECT_FALSE(stops(GateAction::Escape));
  EXPECT_FALSE(stops(GateAction::Pass));
  EXPECT_FALSE(stops(GateAction::Disabled));
}

TEST(GateAction, AValueOutsideTheEnumIsNamedAndCountedAsAStop) {
  // A corrupted value must not read as a pass in a log or on ~gate_state.
  const auto corrupted = static_cast<GateAction>(99);
  EXPECT_STREQ(toString(corrupted), "STOP");
  EXPECT_TRUE(stops(corrupted)) << "counted, logged and drawn as the stop it is named";
}

}  // namespace
}  // namespace ellipse_collision::core

// A velocity command's own rule and its scaling (app/velocity_command.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ellipse_collision/app/velocity_command.h"

namespace ellipse_collision::app {
namespace {

TEST(GateCommandRule, NonFiniteOrAbsurdComponentsAreNamed) {
  const GateConfig config;  // 5 m/s, 5 rad/s
  VelocityCommand command;
  EXPECT_FALSE(findInvalidCommand(command, config));
  command.linear.x() = NAN;
  auto invalid = findInvalidCommand(command, config);
  ASSERT_TRUE(invalid);
  EXPECT_EQ(describeFieldError("cmd_vel", *invalid),
            "cmd_vel.linear.x = nan: expected a number within [-5, 5]");
  command.linear.x() = 5.0;
  command.angular.y() = -INFINITY;
  invalid = findInvalidCommand(command, config);
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->key, "angular.y");
  command.angular.y() = 0.0;
  command.linear.z() = 5.5;
  invalid = findInvalidCommand(command, config);
  ASSERT_TRUE(invalid);
  EXPECT_EQ(invalid->key, "linear.z");
}

TEST(GateCommandRule, EveryComponentIsNamedAsInTheMessageAndLimitsAreInclusive) {
  GateConfig config;
  config.max_linear_speed = 0.75;
  config.max_angular_speed = 1.25;
  const char* const keys[] = {"linear.x",  "linear.y",  "linear.z",
                              "angular.x", "angular.y", "angular.z"};
  for (int i = 0; i < 6; ++i) {
    const double limit = i < 3 ? 0.75 : 1.25;
    VelocityCommand command;
    Eigen::Vector3d& part = i < 3 ? command.linear : command.angular;
    for (const double at_limit : {limit, -limit}) {
      part[i % 3] = at_limit;
      EXPECT_FALSE(findInvalidCommand(command, config)) << keys[i] << " = " << at_limit;
    }
    part[i % 3] = -std::nextafter(limit, 10.0);
    const auto invalid = findInvalidCommand(command, config);
    ASSERT_TRUE(invalid) << keys[i];
    EXPECT_EQ(invalid->key, keys[i]);
    EXPECT_EQ(invalid->expected,
              i < 3 ? "a number within [-0.75, 0.75]" : "a number within [-1.25, 1.25]");
    EXPECT_EQ(std::stod(invalid->actual), part[i % 3]) << "the value as given, read back exactly";
  }
}

TEST(GateCommandRule, TheFirstBadComponentInMessageOrderIsReported) {
  const GateConfig config;
  VelocityCommand command;
  command.angular.x() = std::numeric_limits<double>::quiet_NaN();
  command.linear.y() = 6.0;
  EXPECT_EQ(findInvalidCommand(command, config)->key, "linear.y") << "linear before angular";
  command.linear.y() = 0.0;
  command.angular.z() = 9.0;
  EXPECT_EQ(findInvalidCommand(command, config)->key, "angular.x") << "x before z";
}

TEST(ScaledCommand, EveryComponentIsMultipliedExactly) {
  VelocityCommand command;
  command.linear = {0.5, -1.5, 0.25};
  command.angular = {3.0, -0.125, 2.0};
  const VelocityCommand half = scaledCommand(command, 0.5);  // powers of two: exact products
  EXPECT_EQ(half.linear, Eigen::Vector3d(0.25, -0.75, 0.125));
  EXPECT_EQ(half.angular, Eigen::Vector3d(1.5, -0.0625, 1.0));
  const VelocityCommand stopped = scaledCommand(command, 0.0);
  EXPECT_EQ(stopped.linear, Eigen::Vector3d::Zero());
  EXPECT_EQ(stopped.angular, Eigen::Vector3d::Zero());
  const VelocityCommand same = scaledCommand(command, 1.0);
  EXPECT_EQ(same.linear, command.linear);
  EXPECT_EQ(same.angular, command.angular);
  // Three tenths, not a power of two: each component is the one rounded product.
  const VelocityCommand slowed = scaledCommand(command, 0.3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(slowed.linear[i], command.linear[i] * 0.3);
    EXPECT_EQ(slowed.angular[i], command.angular[i] * 0.3);
  }
}

}  // namespace
}  // namespace ellipse_collision::app

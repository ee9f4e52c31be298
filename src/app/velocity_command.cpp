#include "ellipse_collision/app/velocity_command.h"

#include <string>

namespace ellipse_collision::app {

VelocityCommand scaledCommand(const VelocityCommand& command, double k) {
  return {command.linear * k, command.angular * k};
}

std::optional<FieldError> findInvalidCommand(const VelocityCommand& command,
                                             const GateConfig& config) {
  static const char* const kAxes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (auto e = findOutsideRange(std::string("linear.") + kAxes[i], command.linear[i],
                                  -config.max_linear_speed, config.max_linear_speed)) {
      return e;
    }
  }
  for (int i = 0; i < 3; ++i) {
    if (auto e = findOutsideRange(std::string("angular.") + kAxes[i], command.angular[i],
                                  -config.max_angular_speed, config.max_angular_speed)) {
      return e;
    }
  }
  return std::nullopt;
}

}  // namespace ellipse_collision::app

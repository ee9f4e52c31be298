#pragma once

#include <Eigen/Core>
#include <optional>

#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/app/gate_config.h"

namespace ellipse_collision::app {

/// A velocity command as geometry_msgs/Twist holds it.
struct VelocityCommand {
  Eigen::Vector3d linear{0.0, 0.0, 0.0};   ///< [m/s]
  Eigen::Vector3d angular{0.0, 0.0, 0.0};  ///< [rad/s]
};

/// `command` with every component times `k`.
VelocityCommand scaledCommand(const VelocityCommand& command, double k);

/// A command's own rule: every component finite, each linear one within +-max_linear_speed and
/// each angular one within +-max_angular_speed. The violation names the field as in the message
/// ("linear.x", "nan", "a number within [-5, 5]"; the caller names the message), or nothing.
std::optional<FieldError> findInvalidCommand(const VelocityCommand& command,
                                             const GateConfig& config);

}  // namespace ellipse_collision::app

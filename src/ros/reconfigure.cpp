#include "ellipse_collision/ros/reconfigure.h"

#include <cmath>
#include <string>

#include "ellipse_collision/app/gate_config.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision {
namespace {

/// A request at a slider's bound: the bounds lie outside every accepted range, and a request
/// beyond them arrives clamped to them, so it is refused by name rather than taken. (NaN is left
/// to the settings' own rule.)
std::optional<app::FieldError> atBound(const std::string& key, double value, double min,
                                       double max) {
  if (std::isnan(value) || (value > min && value < max)) return std::nullopt;
  return app::FieldError{key,
                         "a value inside the reconfigure bounds (" + core::formatNumber(min) +
                             ", " + core::formatNumber(max) + ")",
                         core::formatNumber(value) + " (a request beyond a bound arrives as it)"};
}

}  // namespace

std::optional<app::FieldError> applyCheckParameters(const CheckParametersConfig& config,
                                                    app::TunableSettings* base) {
  const CheckParametersConfig& min = CheckParametersConfig::__getMin__();
  const CheckParametersConfig& max = CheckParametersConfig::__getMax__();
  const struct {
    const char* key;
    double value, min, max;
    double* target;
  } fields[] = {
      {"rate", config.rate, min.rate, max.rate, &base->rate_hz},
      {"padding", config.padding, min.padding, max.padding, &base->padding_m},
      {"warning_distance", config.warning_distance, min.warning_distance, max.warning_distance,
       &base->warning_distance_m},
      {"max_transform_age", config.max_transform_age, min.max_transform_age,
       max.max_transform_age, &base->max_transform_age_s},
      {"obstacle_timeout", config.obstacle_timeout, min.obstacle_timeout, max.obstacle_timeout,
       &base->obstacle_timeout_s},
      {"prediction_horizon", config.prediction_horizon, min.prediction_horizon,
       max.prediction_horizon, &base->prediction_horizon_s},
  };
  std::optional<app::FieldError> bound;
  for (const auto& field : fields) {
    if (!bound) bound = atBound(field.key, field.value, field.min, field.max);
    *field.target = field.value;
  }
  return bound;
}

std::optional<app::FieldError> applyGateParameters(const GateParametersConfig& config,
                                                   app::TunableSettings* base) {
  const GateParametersConfig& min = GateParametersConfig::__getMin__();
  const GateParametersConfig& max = GateParametersConfig::__getMax__();
  app::GateConfig& gate = base->gate;
  const struct {
    const char* key;
    double value, min, max;
    double* target;
  } fields[] = {
      {"gate/horizon", config.horizon, min.horizon, max.horizon, &gate.timing.horizon},
      {"gate/time_before_collision", config.time_before_collision, min.time_before_collision,
       max.time_before_collision, &gate.timing.time_before_collision},
      {"gate/stop_time", config.stop_time, min.stop_time, max.stop_time, &gate.timing.stop_time},
      {"gate/margin", config.margin, min.margin, max.margin, &gate.timing.margin},
      {"gate/resolution", config.resolution, min.resolution, max.resolution,
       &gate.timing.resolution},
      {"gate/cmd_vel_timeout", config.cmd_vel_timeout, min.cmd_vel_timeout, max.cmd_vel_timeout,
       &gate.cmd_vel_timeout_s},
      {"gate/max_linear_speed", config.max_linear_speed, min.max_linear_speed, max.max_linear_speed,
       &gate.max_linear_speed},
      {"gate/max_angular_speed", config.max_angular_speed, min.max_angular_speed,
       max.max_angular_speed, &gate.max_angular_speed},
      {"gate/reaction_time", config.reaction_time, min.reaction_time, max.reaction_time,
       &gate.base.reaction_time},
      {"gate/max_linear_deceleration", config.max_linear_deceleration, min.max_linear_deceleration,
       max.max_linear_deceleration, &gate.base.linear_deceleration},
      {"gate/max_angular_deceleration", config.max_angular_deceleration,
       min.max_angular_deceleration, max.max_angular_deceleration, &gate.base.angular_deceleration},
  };
  std::optional<app::FieldError> bound;
  for (const auto& field : fields) {
    if (!bound) bound = atBound(field.key, field.value, field.min, field.max);
    *field.target = field.value;
  }
  gate.enabled = config.enabled;
  if (auto unknown = app::parseOnIncomplete(config.on_incomplete, &gate.on_incomplete)) {
    return unknown;
  }
  return bound;
}

void toCheckParameters(const app::TunableSettings& settings, CheckParametersConfig* config) {
  config->rate = settings.rate_hz;
  config->padding = settings.padding_m;
  config->warning_distance = settings.warning_distance_m;
  config->max_transform_age = settings.max_transform_age_s;
  config->obstacle_timeout = settings.obstacle_timeout_s;
  config->prediction_horizon = settings.prediction_horizon_s;
}

void toGateParameters(const app::TunableSettings& settings, GateParametersConfig* config) {
  const app::GateConfig& gate = settings.gate;
  config->enabled = gate.enabled;
  config->horizon = gate.timing.horizon;
  config->time_before_collision = gate.timing.time_before_collision;
  config->stop_time = gate.timing.stop_time;
  config->margin = gate.timing.margin;
  config->resolution = gate.timing.resolution;
  config->cmd_vel_timeout = gate.cmd_vel_timeout_s;
  config->on_incomplete = app::toString(gate.on_incomplete);
  config->max_linear_speed = gate.max_linear_speed;
  config->max_angular_speed = gate.max_angular_speed;
  config->reaction_time = gate.base.reaction_time;
  config->max_linear_deceleration = gate.base.linear_deceleration;
  config->max_angular_deceleration = gate.base.angular_deceleration;
}

}  // namespace ellipse_collision

#include "ellipse_collision/app/gate_config.h"

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

const char* toString(OnIncomplete policy) { return policy == OnIncomplete::Stop ? "stop" : "pass"; }

std::optional<FieldError> parseOnIncomplete(const std::string& text, OnIncomplete* policy) {
  for (const OnIncomplete candidate : {OnIncomplete::Stop, OnIncomplete::Pass}) {
    if (text == toString(candidate)) {
      *policy = candidate;
      return std::nullopt;
    }
  }
  return FieldError{"gate/on_incomplete", "'stop' or 'pass'", "'" + text + "'"};
}

FieldError gateFieldError(const core::GateSettingViolation& v, const std::string& prefix) {
  // A violation lies outside its range; should one ever be made inside it, the range still reads.
  FieldError e = findOutsideRange(prefix + v.field, v.value, v.min, v.max, v.min_excluded)
                     .value_or(FieldError{prefix + v.field,
                                          std::string("a number within ") +
                                              (v.min_excluded ? "(" : "[") +
                                              core::formatNumber(v.min) + ", " +
                                              core::formatNumber(v.max) + "]",
                                          core::formatNumber(v.value)});
  if (v.max_field) e.expected += " (at most " + prefix + v.max_field + ")";
  return e;
}

std::optional<FieldError> findInvalidGateSetting(const GateConfig& config) {
  if (config.robot_frame.empty()) {
    return FieldError{"gate/robot_frame", "a non-empty tf frame id", "''"};
  }
  if (config.robot_frame.front() == '/') {
    return FieldError{"gate/robot_frame", "a tf2 frame id without a leading '/'",
                      "'" + config.robot_frame + "'"};
  }
  // The core's ranges, in the words of the configuration.
  if (const auto v = core::findInvalidGateSettings(config.timing)) return gateFieldError(*v);
  if (auto e = findOutsideRange("gate/cmd_vel_timeout", config.cmd_vel_timeout_s, 0.0,
                                core::kMaxGateHorizonS)) {
    return e;
  }
  if (auto e = findOutsideRange("gate/max_linear_speed", config.max_linear_speed, 0.0,
                                kMaxGateSpeed, true)) {
    return e;
  }
  if (auto e = findOutsideRange("gate/max_angular_speed", config.max_angular_speed, 0.0,
                                kMaxGateTurnRate, true)) {
    return e;
  }
  if (const auto v = core::findInvalidBaseDynamics(config.base)) return gateFieldError(*v);
  return std::nullopt;
}

std::string idealBaseWarning(const GateConfig& config) {
  if (!config.enabled || !config.base.ideal()) return {};
  return "the gate assumes an instantaneous base: gate/max_linear_deceleration, "
         "gate/max_angular_deceleration and gate/reaction_time are 0, so it takes the base to "
         "stop the moment it is told (a real base answers late and brakes at a bounded rate: set "
         "them to the base's)";
}

}  // namespace ellipse_collision::app

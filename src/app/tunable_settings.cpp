#include "ellipse_collision/app/tunable_settings.h"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {

std::optional<FieldError> findNegativeSetting(const std::string& key, double value) {
  if (std::isfinite(value) && value >= 0.0) return std::nullopt;
  return FieldError{key, "a finite number >= 0", core::formatNumber(value)};
}

std::optional<FieldError> findOutsideSettingRange(const std::string& key, double value,
                                                  double min, double max, bool zero_allowed) {
  if (auto negative = findNegativeSetting(key, value)) return negative;
  if (zero_allowed && value == 0.0) return std::nullopt;
  auto outside = findOutsideRange(key, value, min, max);
  if (outside && zero_allowed) outside->expected = "0 or " + outside->expected;
  return outside;
}

namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

const std::array<SettingRange, 9> kSettingRanges{{
    {"rate", kMinRateHz, kMaxRateHz, true},
    {"prediction_horizon", 0.0, kMaxPredictionHorizonS, false},
    {"tf_timeout", 0.0, kMaxDurationS, false},
    {"padding", 0.0, core::kMaxRadius, false},
    {"warning_distance", 0.0, kUnbounded, false},
    {"max_transform_age", 0.0, kMaxDurationS, false},
    {"obstacle_timeout", 0.0, kMaxDurationS, false},
    {"obstacle_store_period", 0.0, kMaxDurationS, false},
    {"marker_refresh_period", 0.0, kMaxDurationS, false},
}};

}  // namespace

const SettingRange& settingRange(const std::string& key) {
  for (const SettingRange& range : kSettingRanges) {
    if (key == range.key) return range;
  }
  throw std::invalid_argument("settingRange: no parameter '" + key + "'");
}

std::optional<FieldError> findOutsideSettingRange(const std::string& key, double value) {
  const SettingRange& range = settingRange(key);
  if (range.max == kUnbounded) return findNegativeSetting(key, value);
  return findOutsideSettingRange(key, value, range.min, range.max, range.zero_allowed);
}

std::optional<FieldError> findInvalidTunable(const TunableSettings& s) {
  const std::pair<const char*, double> values[] = {{"prediction_horizon", s.prediction_horizon_s},
                                                   {"rate", s.rate_hz},
                                                   {"padding", s.padding_m},
                                                   {"warning_distance", s.warning_distance_m},
                                                   {"max_transform_age", s.max_transform_age_s},
                                                   {"obstacle_timeout", s.obstacle_timeout_s}};
  for (const auto& [key, value] : values) {
    if (auto e = findOutsideSettingRange(key, value)) return e;
  }
  return findInvalidGateSetting(s.gate);
}

namespace {

/// Each setting as (key, value text, unit), in the order of findInvalidTunable().
std::vector<std::array<std::string, 3>> fields(const TunableSettings& s) {
  const auto number = [](double value) { return core::formatNumber(value); };
  const GateConfig& g = s.gate;
  return {{"prediction_horizon", number(s.prediction_horizon_s), "s"},
          {"rate", number(s.rate_hz), "Hz"},
          {"padding", number(s.padding_m), "m"},
          {"warning_distance", number(s.warning_distance_m), "m"},
          {"max_transform_age", number(s.max_transform_age_s), "s"},
          {"obstacle_timeout", number(s.obstacle_timeout_s), "s"},
          {"gate/enabled", g.enabled ? "true" : "false", ""},
          {"gate/horizon", number(g.timing.horizon), "s"},
          {"gate/time_before_collision", number(g.timing.time_before_collision), "s"},
          {"gate/stop_time", number(g.timing.stop_time), "s"},
          {"gate/margin", number(g.timing.margin), "m"},
          {"gate/resolution", number(g.timing.resolution), ""},
          {"gate/cmd_vel_timeout", number(g.cmd_vel_timeout_s), "s"},
          {"gate/on_incomplete", toString(g.on_incomplete), ""},
          {"gate/max_linear_speed", number(g.max_linear_speed), "m/s"},
          {"gate/max_angular_speed", number(g.max_angular_speed), "rad/s"},
          {"gate/reaction_time", number(g.base.reaction_time), "s"},
          {"gate/max_linear_deceleration", number(g.base.linear_deceleration), "m/s^2"},
          {"gate/max_angular_deceleration", number(g.base.angular_deceleration), "rad/s^2"}};
}

std::string withUnit(const std::string& text, const std::string& unit) {
  return unit.empty() ? text : text + " " + unit;
}

}  // namespace

std::string describeTunable(const TunableSettings& settings) {
  std::string text;
  for (const auto& [key, value, unit] : fields(settings)) {
    text += (text.empty() ? "" : ", ") + key + " " + withUnit(value, unit);
  }
  return text;
}

std::string describeTunableChanges(const TunableSettings& before, const TunableSettings& after) {
  const auto old_fields = fields(before), new_fields = fields(after);
  std::string text;
  for (std::size_t i = 0; i < new_fields.size(); ++i) {
    if (old_fields[i][1] == new_fields[i][1]) continue;
    text += (text.empty() ? "" : "; ") + new_fields[i][0] + " " + old_fields[i][1] + " -> " +
            withUnit(new_fields[i][1], new_fields[i][2]);
  }
  return text;
}

}  // namespace ellipse_collision::app

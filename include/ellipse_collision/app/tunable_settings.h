#pragma once

#include <optional>
#include <string>

#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/app/gate_config.h"

namespace ellipse_collision::app {

/// Accepted ranges of the node's scalar parameters (documented in config/ellipse_collision.yaml),
/// the same at start-up and when reconfigured. They keep the timer period 1 / rate and the tf
/// timeout well inside ros::Duration (+-2^31 s, 1 ns resolution).
constexpr double kMinRateHz = 1e-3;  ///< rate is 0 or within [kMinRateHz, kMaxRateHz]
constexpr double kMaxRateHz = 1e3;   ///< [Hz]
/// The one bound of every duration parameter: tf_timeout, max_transform_age, obstacle_timeout,
/// obstacle_store_period and marker_refresh_period lie within [0, kMaxDurationS] [s] (an hour:
/// longer is a typo, and keeps ros::Duration far from its range).
constexpr double kMaxDurationS = 3600.0;
/// prediction_horizon within [0, kMaxPredictionHorizonS] [s]: a minute ahead is far beyond what
/// constant velocities predict well, and keeps |angular_velocity| * horizon within the core's turn
/// limit for any turn rate a robot has.
constexpr double kMaxPredictionHorizonS = 60.0;

/// The range of one scalar parameter of the node: finite, >= 0, within [min, max] (max infinite:
/// no upper bound), or exactly 0 when `zero_allowed` ("off").
struct SettingRange {
  const char* key;  ///< as in YAML and dynamic_reconfigure ("rate")
  double min;
  double max;
  bool zero_allowed;
};

/// The one key -> range table of the node's scalar parameters (besides gate/, whose ranges are
/// findInvalidGateSetting()'s): start-up (parseNodeConfig()) and reconfigure (findInvalidTunable())
/// both read it. rate, prediction_horizon, tf_timeout, padding, warning_distance,
/// max_transform_age, obstacle_timeout, obstacle_store_period, marker_refresh_period.
const SettingRange& settingRange(const std::string& key);

/// `value` against settingRange(key): the violation naming the key, or nothing.
std::optional<FieldError> findOutsideSettingRange(const std::string& key, double value);

/// The range rule of a scalar parameter: a finite number >= 0 ("a finite number >= 0"), within
/// [min, max] ("a number within [min, max]"), or exactly 0 when `zero_allowed` (then "0 or a
/// number within ..."). Refused, never clamped. Nothing when `value` passes.
std::optional<FieldError> findOutsideSettingRange(const std::string& key, double value,
                                                  double min, double max,
                                                  bool zero_allowed = false);
/// A finite number >= 0 with no upper bound ("a finite number >= 0"), or nothing.
std::optional<FieldError> findNegativeSetting(const std::string& key, double value);

/// The node's parameters that may change while it runs (dynamic_reconfigure), with the units and
/// defaults of config/ellipse_collision.yaml.
struct TunableSettings {
  double rate_hz{10.0};                ///< periodic checks [Hz]; 0 = only on service calls
  double padding_m{0.0};               ///< added to both radii of every ellipse [m]
  double warning_distance_m{0.0};      ///< separated pairs closer than this are warnings [m]
  double prediction_horizon_s{0.0};    ///< time-to-contact prediction [s]; 0 = off
  double max_transform_age_s{0.5};     ///< older non-static transforms are stale [s]; 0 = off
  double obstacle_timeout_s{0.0};      ///< ~obstacles older than this are dropped [s]; 0 = never
  GateConfig gate;                     ///< `gate/`, robot_frame included (not reconfigurable)
};

/// The first setting outside its range, named by its key ("rate", "gate/stop_time"), in the order
/// the node reads them at start-up, or nothing. The padding's effect on the stored ellipses is
/// the caller's to check (findInvalidPaddedField()).
std::optional<FieldError> findInvalidTunable(const TunableSettings& settings);

/// "rate 10 Hz, padding 0 m, ..., gate/enabled false, ...": every value, for a log line.
std::string describeTunable(const TunableSettings& settings);

/// "rate 10 -> 2 Hz; gate/enabled false -> true": the values that differ, or "".
std::string describeTunableChanges(const TunableSettings& before, const TunableSettings& after);

}  // namespace ellipse_collision::app

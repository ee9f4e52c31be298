#pragma once

#include <optional>

#include "ellipse_collision/CheckParametersConfig.h"
#include "ellipse_collision/GateParametersConfig.h"
#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/app/tunable_settings.h"

namespace ellipse_collision {

/// dynamic_reconfigure's view of app::TunableSettings: the node's top-level parameters
/// (cfg/CheckParameters.cfg, ~) and the gate's (cfg/GateParameters.cfg, ~gate).

/// Writes the values of `config` into `base`. Returns the first value at a slider's bound (or an
/// unknown on_incomplete): dynamic_reconfigure clamps a request to the bounds before the node sees
/// it, so such a value may stand for one beyond them and must be refused; the caller lets the
/// settings' own rule speak first (a bound lies outside the accepted range, so mostly it does).
std::optional<app::FieldError> applyCheckParameters(const CheckParametersConfig& config,
                                                    app::TunableSettings* base);
std::optional<app::FieldError> applyGateParameters(const GateParametersConfig& config,
                                                   app::TunableSettings* base);

/// The values of `settings` in the servers' form (what they report after a change or a refusal).
void toCheckParameters(const app::TunableSettings& settings, CheckParametersConfig* config);
void toGateParameters(const app::TunableSettings& settings, GateParametersConfig* config);

}  // namespace ellipse_collision

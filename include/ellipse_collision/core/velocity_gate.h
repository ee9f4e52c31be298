#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>

#include "ellipse_collision/core/base_braking.h"
#include "ellipse_collision/core/gate_action.h"
#include "ellipse_collision/core/path_check.h"
#include "ellipse_collision/core/twist_motion.h"

namespace ellipse_collision::core {

// The velocity gate's decision: before a planar velocity command is sent, predict where the
// robot's links would first touch an obstacle if the command were held, and pass, scale down or
// stop it. Everything is in the robot frame as it is at t = 0: links at their pose at t = 0,
// obstacles where they are at t = 0 with their Motion. The rules and the search are described in
// doc/velocity_gate.md.

/// Accepted ranges of GateSettings (refused, never clamped): horizon within (0, kMaxGateHorizonS];
/// 0 <= stop_time <= time_before_collision <= horizon; margin within [0, kMaxRadius]; resolution
/// within [kMinGateResolution, 1].
constexpr double kMaxGateHorizonS = 60.0;
constexpr double kMinGateResolution = 1e-3;

/// The gate's parameters.
struct GateSettings {
  double horizon{3.0};                ///< how far ahead contacts are predicted [s]
  double time_before_collision{1.5};  ///< the command is scaled so no contact comes sooner [s]
  double stop_time{0.3};              ///< a contact this soon under the full command stops [s]
  double margin{0.05};                ///< pairs closer than this now are "close" (escape rule) [m]
  double resolution{0.01};            ///< grid of the scale factor: k in {0, res, 2 res, ..., 1}
};

/// What the gate knows of the base it guards. With an ideal base (BaseDynamics all zero) the
/// braking rule is off and the gate judges commands as if the base followed them at once.
struct BaseState {
  BaseDynamics dynamics;
  Twist velocity;              ///< the base's velocity now, robot frame at t = 0
  double command_period{0.0};  ///< how long an output acts before the next one can [s]
};

/// A GateSettings field outside its range: its name ("stop_time"), its value and the range
/// [min, max] ((min, max] when min_excluded) it must lie in; `max_field` names the setting the
/// upper bound is ("time_before_collision"), or is null. The app renders it in its own words.
struct GateSettingViolation {
  const char* field{""};
  double value{0.0};
  double min{0.0};
  double max{0.0};
  bool min_excluded{false};
  const char* max_field{nullptr};
};

/// The first field of `settings` outside its range (in the order horizon, time_before_collision,
/// stop_time, margin, resolution), or nothing: the one home of the gate settings' ranges.
std::optional<GateSettingViolation> findInvalidGateSettings(const GateSettings& settings);

/// Accepted ranges of BaseDynamics: reaction_time within [0, kMaxReactionTimeS] [s], each
/// deceleration within [0, kMaxDeceleration] [m/s^2, rad/s^2] (0 = at once).
constexpr double kMaxReactionTimeS = 5.0;
constexpr double kMaxDeceleration = 100.0;

/// The first field of `dynamics` outside its range, named as the node's keys name it
/// ("reaction_time", "max_linear_deceleration", "max_angular_deceleration"), or nothing.
std::optional<GateSettingViolation> findInvalidBaseDynamics(const BaseDynamics& dynamics);

/// A predicted contact of one link with one obstacle.
struct GateContact {
  bool found{false};
  std::string link;
  std::string obstacle;
  double time{0.0};   ///< [s] after t = 0 under scale * twist
  double scale{1.0};  ///< of the command this contact is predicted under
  /// Where they touch at `time`, in the frame of the scene at t = 0 [m].
  Eigen::Vector2d point{0.0, 0.0};
};

/// The answer of gateTwist().
struct GateResult {
  GateAction action{GateAction::Stop};  ///< Pass, Slow, Stop or Escape
  double scale{0.0};                    ///< send scale * twist; in [0, 1]
  /// The first contact within the horizon under the output command (scale * twist); for Stop,
  /// that of a moving obstacle reaching the standing robot (stopping cannot avoid it).
  GateContact contact;
  /// The contact that decided the scale (under the full command, the one that ruled out the next
  /// larger scale, or the close pair the command pushes in at time 0).
  GateContact limiting;
  /// The nearest pair now among those that can meet within the horizon; has_clearance false
  /// when there is none.
  bool has_clearance{false};
  double clearance{0.0};  ///< distance() now [m]; 0 when overlapping
  std::string clearance_link;
  std::string clearance_obstacle;
  std::string reason;  ///< why, in words, with names, times and scales
  std::string error;   ///< why the command could not be judged (then action Stop, scale 0)
  /// The braking rule (a base that is not ideal): the path of the base's origin from now until
  /// it rests under the output [m]; the free path along the command's arc to the first contact
  /// with a standing obstacle (infinity when none within the braking reach) [m]; whether even
  /// braking now meets an obstacle, and the base's predicted speed at that contact [m/s].
  double braking_distance{0.0};
  double free_distance{std::numeric_limits<double>::infinity()};
  bool unavoidable{false};
  double impact_speed{0.0};
  /// distance() and twistContact() calls: a statistic for tests and benchmarks.
  std::size_t pair_tests{0};
  bool ok() const { return error.empty(); }
};

/// Why gateTwist() cannot judge `twist` in `scene`, naming the field and value ("settings:
/// stop_time = 2 must be within [0, 1.5] (at most time_before_collision)", "obstacle 'wall':
/// radius_x = 0 must be > 0"), or "". Its cost grows with the obstacles: validate a scene once
/// when it changes (gateTwist() checks only the obstacles it looks at).
std::string invalidGateReason(const PathScene& scene, const Twist& twist,
                              const GateSettings& settings);

/// Gates `twist` for the links of `scene` (robot frame at t = 0) against its obstacles (each
/// moving by its Motion), for every pair not in scene.allowed: Stop when a close pair (nearer
/// than margin) is pushed in or a contact comes within stop_time; else the largest scale on the
/// resolution grid whose first contact comes no sooner than time_before_collision (Pass at 1,
/// Slow below, Stop when none; Escape instead of Pass or Slow when pairs are close now and the
/// command moves each apart). Never late: contacts come from twistContact().
///
/// With a real base (`base.dynamics` not ideal) the braking rule also holds: an output is kept
/// only if, after it acts for base.command_period plus the reaction time (the base's current
/// velocity acting first), braking at the limits along its arc ends before any contact, `margin`
/// short of it; the largest such scale on the grid is taken, Stop (unavoidable, with the predicted
/// impact speed) when not even braking now ends clear.
GateResult gateTwist(const PathScene& scene, const Twist& twist, const GateSettings& settings,
                     const BaseState& base = {});

}  // namespace ellipse_collision::core

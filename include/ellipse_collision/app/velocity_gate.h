#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/gate_config.h"
#include "ellipse_collision/app/transform_lookup.h"
#include "ellipse_collision/app/velocity_command.h"
#include "ellipse_collision/core/gate_action.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::app {

using core::GateAction;
using core::stops;
using core::toString;

/// What the gate did with one command (the node's ~gate_state).
struct GateDecision {
  GateAction action{GateAction::Stop};
  double scale{0.0};  ///< output = scale * input (1 for DISABLED)
  VelocityCommand input;
  VelocityCommand output;
  /// A contact within the horizon under the output command (for STOP: of a moving obstacle with
  /// the standing robot), else the limiting one that set the scale.
  bool contact_predicted{false};
  double time_to_contact_s{0.0};  ///< [s] from the command, when contact_predicted
  std::string link;               ///< the limiting link and obstacle ("" when none)
  std::string obstacle;
  Eigen::Vector2d contact_point{0.0, 0.0};  ///< in the fixed frame [m], when contact_predicted
  /// The links in the fixed frame at the predicted contact (or at the horizon when none), under
  /// the output command: the robot's outline to draw. Empty when nothing was predicted.
  std::vector<core::NamedEllipse> outline;
  /// The limiting obstacle where it stands at the command, in the fixed frame (when `obstacle`).
  core::Ellipse obstacle_ellipse;
  /// The braking rule (gate/ decelerations or reaction time set): the base's path from now until
  /// it rests under the output, the free path along the command's arc to the first standing
  /// obstacle (infinity when none in reach) [m]; whether even braking now meets an obstacle, and
  /// the base's predicted speed then [m/s].
  double braking_distance_m{0.0};
  double free_distance_m{std::numeric_limits<double>::infinity()};
  bool unavoidable{false};
  double impact_speed{0.0};
  std::string reason;  ///< why, in words a user reads
};

/// A zero-output decision of `action` for `input` with `reason`.
GateDecision stoppedDecision(GateAction action, const VelocityCommand& input, std::string reason);

/// The robot frame's pose in the fixed frame's plane: position [m] and heading [rad].
struct PlanarPose {
  Eigen::Vector2d position{0.0, 0.0};
  double yaw{0.0};
};

/// The planar part of `pose` (a frame in the fixed frame): its x, y and its heading from its x
/// axis.
PlanarPose planarPose(const Eigen::Isometry3d& pose);

/// An obstacle of a placed scene that moves by its own velocity: its index in the scene, its
/// motion in the fixed frame, and how long before the decision it was where the scene places it
/// (its message's age): the gate judges it where that motion has taken it since.
struct PlacedMotion {
  std::size_t index{0};
  core::Motion motion;
  double since_s{0.0};  ///< [s] >= 0; 0 = placed as of now (unstamped, or no age)
};

/// The gate on a placed scene: `placed` (links and obstacles in the fixed frame) moved into the
/// robot frame at `robot` (links rigidly with it, obstacles by `moving`, by increasing index, each
/// first advanced by its motion over its `since_s`; the others stand still), then core::gateTwist()
/// on the command's planar part (linear.x, linear.y, angular.z) and its answer put back into the
/// fixed frame. A core error stops (an internal failure never passes). `standing`, when given, is
/// the grid of exactly `placed`'s obstacles, its last entries (CheckOutcome::standing): the
/// obstacles near the robot are looked up there instead of scanning all of them, with the same
/// answer bit for bit.
GateDecision gateOnScene(const VelocityCommand& command, const core::Scene& placed,
                         const std::vector<PlacedMotion>& moving, const PlanarPose& robot,
                         const core::AllowedPairs& allowed, const GateConfig& config,
                         const core::BaseState& base = {},
                         const core::IndexedObstacles* standing = nullptr);

/// The no-stop-and-go rule's memory (braking rule on): the last decision by the rules (PASS,
/// SLOW, STOP, ESCAPE), its input, scale and world, and the shortest free way ahead since [m].
struct GateHold {
  VelocityCommand input;
  double scale{1.0};
  std::uint64_t world_revision{0};
  double free_distance_m{0.0};
};

/// What the gate's rules take besides the placed scene and the settings: the base now (its
/// velocity and command period; its dynamics are the settings'), the hold before the decision
/// and the stored obstacles' revision. Recorded with each decision, so that it can be judged
/// again bit for bit (app::replayDecision()).
struct GateMemory {
  core::BaseState base;
  std::optional<GateHold> hold;
  std::uint64_t world_revision{0};
};

/// The gate's rules on a placed scene: gateOnScene() with `memory.base`, then the no-stop-and-go
/// rule (the scale does not rise while input, world and the free way ahead stay as when it fell);
/// `hold`, when given, receives the memory the next decision starts from. The one decision the
/// node and the replay both run.
GateDecision judgeOnScene(const VelocityCommand& command, const core::Scene& placed,
                          const std::vector<PlacedMotion>& moving, const PlanarPose& robot,
                          const core::AllowedPairs& allowed, const GateConfig& config,
                          const GateMemory& memory, std::optional<GateHold>* hold = nullptr,
                          const core::IndexedObstacles* standing = nullptr);

/// What the gate judges a command on, gathered by the monitor from the full check it ran.
struct GateView {
  const CheckOutcome* outcome{nullptr};  ///< the full check (placed scene, completeness)
  FrameTransform robot;                  ///< the robot frame in the fixed frame
  std::string fixed_frame;
  Freshness freshness;  ///< max_transform_age and now, for the robot frame
  /// Obstacle sources whose data is gone ("obstacles from ~obstacles dropped, ..."): incomplete.
  std::vector<std::string> silent_sources;
  /// The placed obstacles that move by their own velocity, by increasing index; the others
  /// stand still.
  std::vector<PlacedMotion> obstacle_motions;
  const core::AllowedPairs* allowed{nullptr};
  /// Changes whenever the stored obstacles change; with no obstacle moving, the same revision is
  /// the same world (the no-stop-and-go rule).
  std::uint64_t world_revision{0};
};

/// The velocity gate's state and policy, without ROS: its settings, whether it is on, the
/// watchdog on silence, the decision on each command and what it counts. Single-threaded.
class VelocityGate {
 public:
  explicit VelocityGate(GateConfig config);

  /// Settings in force (`enabled` as set at start-up, by set_enabled or reconfigure).
  const GateConfig& config() const { return config_; }
  /// New settings (already validated: findInvalidGateSetting()), from the next command on.
  void configure(const GateConfig& config) { config_ = config; }
  void setEnabled(bool enabled) { config_.enabled = enabled; }
  bool enabled() const { return config_.enabled; }

  /// A command arrives at `now_s`: the decision when it needs no check (disabled: DISABLED;
  /// non-finite or absurd: STOP naming the field), recorded; nothing when it must be judged on a
  /// check (then decide()).
  std::optional<GateDecision> screen(const VelocityCommand& command, double now_s);
  /// The decision on a full check: STOP when it failed, INCOMPLETE without a fresh robot frame or
  /// (on_incomplete: stop) with data missing, otherwise gateOnScene(); recorded.
  GateDecision decide(const VelocityCommand& command, const GateView& view);
  /// The base's measured velocity (gate/odom_topic) at `stamp_s`, in the robot frame: the base's
  /// velocity now for the braking rule while it is no older than max(0.5 s, cmd_vel_timeout).
  void measuredVelocity(const VelocityCommand& twist, double stamp_s);
  /// The silence rule: the first call at least cmd_vel_timeout after the last command (or after
  /// the first call, when none came yet) returns one TIMEOUT decision (a zero command); nothing
  /// before the next command. Nothing while the gate is disabled or the timeout is 0.
  std::optional<GateDecision> watchdog(double now_s);

  /// What the braking rule takes as the base now (at `now_s`): its dynamics, its velocity (the
  /// measured one while fresh, else the last output) and how long an output acts (the longest of
  /// the last 20 command intervals, at most 1.25 cmd_vel_timeout; before two commands came,
  /// 1.25 cmd_vel_timeout, or 0.1 s without one).
  core::BaseState baseAt(double now_s) const;

  /// What the rules took for the last decide() (the incident recorder keeps it); nothing when
  /// that decision was made before them (a failed check, INCOMPLETE).
  const std::optional<GateMemory>& lastMemory() const { return last_memory_; }

  /// The gate's values for /diagnostics ("gate", "gate reason", "gate stops", "gate slow-downs").
  std::vector<std::pair<std::string, std::string>> healthValues() const;

 private:
  GateDecision record(GateDecision decision);

  GateConfig config_;
  std::deque<double> intervals_;  ///< between the last commands [s]
  std::optional<double> last_command_at_;
  VelocityCommand last_output_;                                 ///< what the base was last told
  std::optional<std::pair<VelocityCommand, double>> measured_;  ///< odometry and its stamp
  std::optional<GateHold> hold_;           ///< the no-stop-and-go rule's memory (judgeOnScene())
  std::optional<GateMemory> last_memory_;  ///< what the rules took for the last decide()
  bool heard_{false};           ///< a command came, or the watchdog started counting
  double last_command_s_{0.0};  ///< when the last command came (or the watchdog started)
  bool timeout_sent_{false};    ///< the watchdog's zero went out since the last command
  std::string last_action_{"none"};
  std::string last_reason_;
  std::uint64_t stops_{0};
  std::uint64_t slowdowns_{0};
};

}  // namespace ellipse_collision::app

#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/check_health.h"
#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/incident_recorder.h"
#include "ellipse_collision/app/obstacle_persistence.h"
#include "ellipse_collision/app/obstacle_source.h"
#include "ellipse_collision/app/path_request.h"
#include "ellipse_collision/app/placement_cache.h"
#include "ellipse_collision/app/source_freshness.h"
#include "ellipse_collision/app/transform_lookup.h"
#include "ellipse_collision/app/tunable_settings.h"
#include "ellipse_collision/app/velocity_gate.h"

namespace ellipse_collision::app {

/// The rules of the collision node that are not wiring: what the node's parameters decide.
struct MonitorSettings {
  CheckSettings check;
  std::string robot_frame{"base_link"};  ///< ~check_path's moving frame when a request has none
  /// Periodic full checks [Hz]; 0 = none. With them the periodic check publishes the state every
  /// time, and a service call's full check only when the state changed; without them every full
  /// check publishes.
  double rate_hz{10.0};
  double obstacle_timeout_s{0.0};    ///< ~obstacles older than this are dropped [s]; 0 = never
  double prediction_horizon_s{0.0};  ///< time-to-contact prediction [s]; 0 = off
  /// Longest wait before a change from ~obstacles reaches the store [s]; 0 = after every message.
  double obstacle_store_period_s{1.0};
  GateConfig gate;  ///< the velocity gate at start-up (off by default); then gate().config()
  /// The listed obstacle sources (the node's `sources`), beside the default ~obstacles; must pass
  /// findInvalidSources().
  std::vector<SourceSpec> sources;
  /// The incident recorder of the gate's decisions (`incident/`); must pass
  /// findInvalidIncidentSetting().
  IncidentSettings incident;
};

/// Where the runtime obstacles are kept across a crash, and the launch they belong to.
struct StoreOptions {
  std::string path;     ///< "" = off
  std::string session;  ///< roslaunch's /run_id
};

/// What happened at start-up with the obstacle store, for the node to log.
struct StartupNote {
  enum class Level { Info, Warn, Error };
  Level level{Level::Info};
  std::string text;
};

/// The last full check (every stored ellipse at the latest transforms): what the topics show.
struct MonitorState {
  bool valid{false};       ///< a full check succeeded once
  double stamp_s{0.0};     ///< when it ran [s, ROS clock]
  CheckOutcome outcome;    ///< its answer
  double duration_s{0.0};  ///< how long it took [s, wall]
  std::string failure;     ///< why the latest full check failed (the state above is older)
};

/// When a full check's state goes out on ~collisions.
enum class StatePublishing {
  Always,    ///< every time (the periodic check; or every check when none is periodic)
  OnChange,  ///< only when it differs from the state last published (service calls)
};

/// The answer of a service call that changes the stored obstacles.
struct ChangeAnswer {
  ErrorKind error_kind{ErrorKind::None};
  std::string message;  ///< what was done, or why not
  bool success() const { return error_kind == ErrorKind::None; }
};

/// Things the ROS layer must act on or log while a call runs (tf, logging).
struct MonitorHooks {
  /// ROS time went back by `seconds` (a looping bag, a simulator reset): forget every transform.
  std::function<void(double seconds)> time_jumped_back;
  /// `count` topic obstacles were dropped: their message is `age_s` old, past obstacle_timeout.
  std::function<void(std::size_t count, double age_s)> obstacles_expired;
  /// A write of the obstacle store failed, or is refused: why.
  std::function<void(const std::string& error)> store_failed;
};

/// The collision node's algorithm without ROS (ros_package_template's Algorithm half): it owns the
/// stored ellipses, the settings, the placement cache, the published state, the health
/// bookkeeping and the persistence decisions, and answers each request the node receives. The
/// node converts messages, binds tf into TransformLookups, advertises and publishes; it holds no
/// rule. Times are seconds on the ROS clock unless said otherwise. Single-threaded, like the node.
class CollisionMonitor {
 public:
  /// Throws std::invalid_argument on an empty or duplicate configured name (EllipseRegistry), a
  /// source list that breaks findInvalidSources() or incident settings that break
  /// findInvalidIncidentSetting().
  /// Restores the runtime obstacles an earlier run of the same launch left in `store` (see
  /// startupNotes()).
  CollisionMonitor(MonitorSettings settings, const std::vector<EllipseSpec>& links,
                   const std::vector<EllipseSpec>& obstacles, RegistryLimits limits,
                   const StoreOptions& store, MonitorHooks hooks = {});
  /// Writes what the store is behind on before the monitor goes.
  ~CollisionMonitor();
  CollisionMonitor(const CollisionMonitor&) = delete;
  CollisionMonitor& operator=(const CollisionMonitor&) = delete;

  /// What happened with the store at start-up (restored, refused and why).
  const std::vector<StartupNote>& startupNotes() const { return startup_notes_; }

  // ---- checks -----------------------------------------------------------------------------
  /// The periodic check: every stored ellipse at the latest transforms (`latest`; `at` gives a
  /// frame's earlier pose for the velocity estimate), recorded as state(). Returns the outcome:
  /// the state's on success, the failed one otherwise (the state then keeps the last good one).
  const CheckOutcome& periodicCheck(double now_s, const TransformLookup& latest,
                                    const TransformAtLookup& at);
  /// A ~check_collisions call. With no names, no query and stamp 0 it is a full check, recorded
  /// as state() like the periodic one; otherwise a partial check at `stamp_s` (0 = latest), whose
  /// outcome the monitor keeps until the next call. A refused request has error_kind
  /// InvalidRequest and nothing is checked.
  const CheckOutcome& serviceCheck(const CheckRequest& request, double stamp_s, double now_s,
                                   const TransformLookup& lookup, const TransformAtLookup& at);
  /// Whether the last call recorded a new state() (a full check that succeeded): then its markers
  /// and, by statePublishing(), its ~collisions message go out.
  bool stateUpdated() const { return state_updated_; }
  /// How the state recorded by the last call is published.
  StatePublishing statePublishing() const { return publishing_; }
  /// A ~check_path call: fills in the default frames (path frame = the fixed frame, moving frame
  /// = robot_frame), validates, and checks with `lookup_to(target)` giving transforms into
  /// `target`; the obstacle sources silent at `now_s` are listed with the answer.
  PathCheckOutcome checkPath(PathCheckRequest request, double now_s,
                             const std::function<TransformLookup(const std::string&)>& lookup_to);

  // ---- the velocity gate --------------------------------------------------------------------
  /// One ~cmd_vel_in command at `now_s`: screened by the gate (disabled: DISABLED; a non-finite
  /// or absurd one stops, naming the field), otherwise a full check at the latest transforms
  /// (recorded as state(), like a service call's) places the robot and the gate decides on it
  /// (VelocityGate::decide()): obstacles move by their own velocity (vx, vy, angular_velocity),
  /// the links rigidly with gate.robot_frame; topic obstacles dropped by obstacle_timeout count as
  /// incomplete data.
  GateDecision gateCommand(const VelocityCommand& command, double now_s,
                           const TransformLookup& latest, const TransformAtLookup& at);
  /// The gate's silence rule (VelocityGate::watchdog()).
  std::optional<GateDecision> gateWatchdog(double now_s);
  /// The base's measured twist (gate/odom_topic, in the robot frame) at `stamp_s`.
  void gateOdometry(const VelocityCommand& twist, double stamp_s) {
    gate_.measuredVelocity(twist, stamp_s);
  }
  /// ~gate/set_enabled.
  void setGateEnabled(bool enabled) { gate_.setEnabled(enabled); }
  bool gateEnabled() const { return gate_.enabled(); }
  /// The velocity gate: its settings in force, its counts.
  const VelocityGate& gate() const { return gate_; }

  // ---- the incident recorder ------------------------------------------------------------------
  /// Every gate decision goes to it with what it judged (IncidentRecorder).
  const IncidentRecorder& incidents() const { return recorder_; }
  /// ~save_incident at `now_s`: false while the recorder is disabled.
  bool requestIncident(double now_s) { return recorder_.request(now_s); }
  /// The incidents to write by `now_s` (IncidentRecorder::takeFinished()).
  std::vector<Incident> takeIncidents(double now_s) { return recorder_.takeFinished(now_s); }

  // ---- obstacle changes -------------------------------------------------------------------
  /// ~add_obstacles: field rules, a transform for every frame, the registry's name rules, then
  /// durable (the store written) before success.
  ChangeAnswer addObstacles(const std::vector<EllipseSpec>& specs, const TransformLookup& lookup);
  /// ~remove_obstacles, durable before success.
  ChangeAnswer removeObstacles(const std::vector<std::string>& names);
  /// One message of obstacle source `source` (0 = ~obstacles, i = settings().sources[i - 1]),
  /// received at `now_s`: it replaces that source's obstacles alone, or is refused whole (the
  /// previous ones kept). A listed source's obstacles are stored under sourceObstacleName(),
  /// a robots source's under the names they were published with. An accepted message counts
  /// for the source's freshness (SourceFreshness) when `heard` (not when a robots source drops
  /// a silent robot); the store follows ~obstacles within obstacle_store_period. Returns "" or
  /// why refused.
  std::string replaceSourceObstacles(std::size_t source, std::vector<EllipseSpec> specs,
                                     double stamp_s, double now_s, const TransformLookup& lookup,
                                     bool heard = true);
  /// A message of source `source` that could not be turned into obstacles (a cloud without x, y,
  /// z; a broken range reading): `why` is reported for the source, and it does not count as
  /// fresh.
  void sourceMessageRefused(std::size_t source, const std::string& why);
  /// One ~obstacles message: replaceSourceObstacles() of source 0, received at its stamp.
  std::string replaceTopicObstacles(const std::vector<EllipseSpec>& specs, double stamp_s,
                                    const TransformLookup& lookup) {
    return replaceSourceObstacles(0, specs, stamp_s, stamp_s, lookup);
  }
  /// The obstacle sources' freshness: ~obstacles first, then settings().sources.
  const SourceFreshness& sourceFreshness() const { return freshness_; }
  /// The periodic store write: what the store is behind on goes to the writer's thread; the last
  /// write's error, if any, goes to the store_failed hook.
  void writeStoreIfBehind();
  /// Whether the store is written (on, and not refused): the node then runs the periodic write.
  bool storeEnabled() const { return persistence_->enabled(); }
  /// Waits until every queued store write is on disk (tests).
  void flushStore() { persistence_->flush(); }

  // ---- settings that change at run time ----------------------------------------------------
  /// The parameters dynamic_reconfigure may change, as they are now.
  TunableSettings tunable() const;
  /// New values for them: they pass findInvalidTunable(), gate/robot_frame stays as it is (set
  /// at start-up only), and every stored ellipse stays valid under the new padding
  /// (findInvalidPaddedField()). Then every value takes effect from the next check (a new padding
  /// re-projects every ellipse), and nothing is returned; else nothing changes and the violation
  /// names the key and value. The same rules as at start-up, so a value the node would refuse to
  /// start with is refused here too.
  std::optional<FieldError> retune(const TunableSettings& tunable);

  // ---- what the node shows ----------------------------------------------------------------
  const MonitorState& state() const { return state_; }
  const EllipseRegistry& registry() const { return registry_; }
  const MonitorSettings& settings() const { return settings_; }
  /// Health for /diagnostics at `now_s`, and the values a safety consumer reads beside it
  /// ("links", "complete", "missing for [s]", ...), in display order.
  struct Health {
    CheckHealth health;
    std::vector<std::pair<std::string, std::string>> values;
  };
  Health health(double now_s) const;

 private:
  /// The obstacle sources whose data is gone at `now_s`: those silent past their timeouts, and
  /// ~obstacles when obstacle_timeout dropped its obstacles.
  std::vector<std::string> silentSources(double now_s) const;
  /// The note for ~obstacles dropped by obstacle_timeout.
  std::string expiredTopicNote() const;
  /// Every check starts here: a time jump back is passed on (the hook clears tf), topic obstacles
  /// older than obstacle_timeout are dropped.
  void advanceClock(double now_s);
  const CheckOutcome& fullCheck(double now_s, const TransformLookup& latest,
                                const TransformAtLookup& at, StatePublishing publishing,
                                const std::string& min_distance_of);
  /// A successful check's answer is incomplete while a source is silent (SourceFreshness).
  void markSilentSources(CheckOutcome& outcome, double now_s) const;
  /// The time-to-contact step of a successful check (nothing when the horizon is 0); predicted
  /// times count from `reference_s`.
  void predict(CheckOutcome& outcome, const CheckRequest& request, const TransformAtLookup& at,
               double reference_s) const;
  /// The store after a change from the topic or expiry: behind, written at the next period (at
  /// once when obstacle_store_period is 0).
  void topicObstaclesChanged();
  /// After an accepted service call: "" or why the change is not durable.
  std::string persistServiceCall(bool removed_topic_obstacle);
  /// The answer of an accepted service call once it is durable: "<done> N obstacle(s)", or
  /// NotPersisted with why.
  ChangeAnswer durableAnswer(const std::string& done, std::size_t count,
                             bool removed_topic_obstacle);
  void reportStoreError(const std::string& error) const;
  /// Restores what `store` holds for this launch; returns the service_revision it counted and
  /// sets `refusal` when a file at its paths is not the store's.
  std::uint64_t restore(const StoreOptions& store, std::string& refusal);

  MonitorSettings settings_;
  MonitorHooks hooks_;
  EllipseRegistry registry_;
  /// Projections reused from one full check to the next while frames do not move.
  PlacementCache placement_cache_;
  MonitorState state_;
  CheckOutcome failed_check_;
  CheckOutcome partial_check_;
  StatePublishing publishing_{StatePublishing::Always};
  bool state_updated_{false};
  std::vector<StartupNote> startup_notes_;
  std::unique_ptr<ObstaclePersistence> persistence_;  ///< the store's rule and its writer
  /// Why each source's last message was refused ("" = accepted), by source index.
  std::vector<std::string> source_errors_;
  SourceFreshness freshness_;
  std::uint64_t full_checks_{0};
  std::map<std::string, double> missing_since_;  ///< frame -> first full check it was missing
  double last_now_s_{0.0};                       ///< time of the last check, to see jumps back
  std::uint64_t dropped_obstacles_{0};           ///< dropped by obstacle_timeout
  std::uint64_t time_jumps_{0};
  /// Topic obstacles were dropped by obstacle_timeout and no message came since: the gate's
  /// perception is gone.
  bool topic_obstacles_expired_{false};

  /// What the gate judges a command on: the robot frame and the obstacles' own motions from
  /// the full check `outcome`.
  GateView gateView(const CheckOutcome& outcome, double now_s, const TransformLookup& latest) const;
  VelocityGate gate_;
  /// One decision to the recorder, with the scene of `view` (nullptr: decided without one).
  void recordDecision(double now_s, const GateDecision& decision, const GateView* view);
  IncidentRecorder recorder_;
};

}  // namespace ellipse_collision::app

#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/field_error.h"
#include "ellipse_collision/app/velocity_gate.h"
#include "ellipse_collision/core/gate_action.h"
#include "ellipse_collision/core/scene.h"

namespace ellipse_collision::app {

/// The incident recorder's parameters (the node's `incident/` keys, doc/incidents.md).
struct IncidentSettings {
  /// On by default: an incident is only useful if it was being recorded before it happened, it
  /// costs nothing while the gate is off, and the disk it takes is bounded below.
  bool enabled{true};
  double before_s{10.0};  ///< decisions kept before the trigger [s]
  double after_s{2.0};    ///< decisions written after it [s]
  /// The actions that trigger an incident.
  std::vector<core::GateAction> actions{core::GateAction::Stop, core::GateAction::Escape,
                                        core::GateAction::Timeout, core::GateAction::Incomplete};
  double min_interval_s{30.0};  ///< at most one triggered incident per this long [s]
  std::size_t max_files{20};    ///< incident bags kept; the oldest removed first
  double max_megabytes{200.0};  ///< their total size [MB]; the oldest removed first
  std::string directory;        ///< "" = the node's default ($ROS_HOME/ellipse_collision/incidents)
};

constexpr double kMaxIncidentWindowS = 600.0;        ///< before and after within [0, this] [s]
constexpr double kMaxIncidentIntervalS = 86400.0;    ///< min_interval within [0, this] [s]
constexpr double kMaxIncidentFiles = 100000.0;       ///< max_files within [1, this]
constexpr double kMaxIncidentMegabytes = 1000000.0;  ///< max_megabytes within (0, this] [MB]

/// The first `incident/` setting outside its range, its key as in YAML ("incident/before"), or
/// nothing: before in (0, 600], after in [0, 600], min_interval in [0, 86400], max_files a whole
/// number in [1, 100000], max_megabytes in (0, 1e6], actions non-empty and without duplicates.
std::optional<FieldError> findInvalidIncidentSetting(const IncidentSettings& settings);

/// The actions `names` spell ("STOP", "ESCAPE", ... as ~gate_state shows them), or the error of
/// key `incident/actions` naming the unknown or repeated one.
std::optional<FieldError> parseIncidentActions(const std::vector<std::string>& names,
                                               std::vector<core::GateAction>* actions);

/// The placed obstacles of one or more decisions in a row, stored once per change.
struct ObstacleSnapshot {
  std::uint64_t id{0};                        ///< counts from 1, one per change
  std::vector<core::NamedEllipse> obstacles;  ///< in the fixed frame
};

/// An obstacle's own motion in the fixed frame: its index in the decision's ObstacleSnapshot.
struct ObstacleMotion {
  std::size_t index{0};
  core::Motion motion;
  double since_s{0.0};  ///< [s] its message's age at the decision (PlacedMotion::since_s)
};

/// One gate decision and what it judged.
struct RecordedDecision {
  double stamp_s{0.0};  ///< when it was decided [s, ROS clock]
  GateDecision decision;
  /// Whether it was judged on a placed scene (the fields below); a screened command, a TIMEOUT
  /// and a failed check are decided without one.
  bool judged_scene{false};
  bool complete{false};                   ///< the check placed every ellipse from fresh data
  PlanarPose robot;                       ///< the robot frame in the fixed frame
  std::vector<core::NamedEllipse> links;  ///< placed, in the fixed frame
  std::shared_ptr<const ObstacleSnapshot> obstacles;  ///< never null
  std::vector<ObstacleMotion> motions;                ///< the obstacles that move on their own
  /// Obstacle sources ("obstacles" first) and the frames of the check: seconds since their last
  /// message or transform (-1 = none yet; 0 for a timeless transform).
  std::vector<std::pair<std::string, double>> source_ages;
  std::vector<std::pair<std::string, double>> frame_ages;
  /// What the gate's rules took besides the scene (GateMemory); nothing when the decision was
  /// made before them (a screened command, TIMEOUT, a failed check, INCOMPLETE).
  std::optional<GateMemory> memory;
};

/// What the recorder sees of a decision judged on a scene (the gate's GateView).
struct DecisionScene {
  const CheckOutcome* outcome{nullptr};
  PlanarPose robot;
  const std::vector<PlacedMotion>* motions{nullptr};
  std::vector<std::pair<std::string, double>> source_ages;
  const GateMemory* memory{nullptr};  ///< when the gate's rules judged it
};

/// The decisions around one trigger: oldest first.
struct Incident {
  std::string trigger;    ///< the action that triggered it ("STOP"), or "REQUESTED"
  double trigger_s{0.0};  ///< [s, ROS clock]
  std::vector<RecordedDecision> decisions;
};

/// The recorder's rules without ROS: a ring buffer of the last `before_s` of decisions, the
/// trigger rule (a listed action, at most one per min_interval) and the window after it. The
/// obstacles are shared between decisions while they do not change, so a still scene of 10,000
/// obstacles is stored once, not once per decision. Single-threaded, like the monitor.
class IncidentRecorder {
 public:
  explicit IncidentRecorder(IncidentSettings settings);

  const IncidentSettings& settings() const { return settings_; }

  /// One decision at `now_s`, judged on `scene` (nullptr: without one). Nothing while disabled.
  void record(double now_s, const GateDecision& decision, const DecisionScene* scene);
  /// An incident asked for at `now_s` (~save_incident): the buffer as it is, finished at once,
  /// whatever min_interval says. False (nothing) while disabled.
  bool request(double now_s);
  /// The incidents finished by `now_s` (their after window passed), oldest first, handed over.
  std::vector<Incident> takeFinished(double now_s);

  /// Decisions in the buffer, obstacles stored in it (once per change), incidents triggered and
  /// those a min_interval held back (for /diagnostics and the memory figure).
  std::size_t bufferedDecisions() const { return buffer_.size(); }
  std::size_t storedObstacles() const;
  std::uint64_t triggered() const { return triggered_; }
  std::uint64_t suppressed() const { return suppressed_; }

 private:
  /// The obstacles of `placed` from `first_obstacle` on, shared with the last decision's when
  /// they are the same (the same standing grid, else compared).
  std::shared_ptr<const ObstacleSnapshot> snapshotOf(const CheckOutcome& outcome,
                                                     std::size_t first_obstacle);
  void trim(double now_s);
  /// The incident under way goes to finished_ once `now_s` is past its after window.
  void finishPending(double now_s);
  bool triggers(core::GateAction action) const;

  IncidentSettings settings_;
  std::deque<RecordedDecision> buffer_;
  std::optional<Incident> pending_;  ///< collecting its after window
  std::vector<Incident> finished_;
  std::optional<double> last_trigger_s_;
  std::shared_ptr<const ObstacleSnapshot> last_snapshot_;
  /// The standing grid the last snapshot was made with: held so its address is not reused.
  std::shared_ptr<const core::IndexedObstacles> last_standing_;
  std::uint64_t next_snapshot_id_{1};
  std::uint64_t triggered_{0};
  std::uint64_t suppressed_{0};
};

/// One incident file on disk.
struct IncidentFile {
  std::string name;  ///< file name; names sort oldest first (incidentFileName())
  std::uint64_t bytes{0};
};
/// The disk budget: the files to remove, oldest first, so that at most max_files remain and
/// their total is within max_megabytes; the newest is never removed (an incident larger than the
/// budget alone is kept, the only one).
std::vector<std::string> incidentFilesToRemove(std::vector<IncidentFile> files,
                                               std::size_t max_files, double max_megabytes);
/// "incident_20261128T143201.250Z_STOP.bag" for an incident triggered by `trigger` at `wall_s`
/// (seconds since the epoch, UTC): names sort by time.
std::string incidentFileName(double wall_s, const std::string& trigger);

}  // namespace ellipse_collision::app

#include "ellipse_collision/app/collision_monitor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <set>
#include <stdexcept>
#include <utility>

#include "ellipse_collision/app/contact_prediction.h"
#include "ellipse_collision/app/obstacle_store.h"
#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {
namespace {

/// The field rules with this launch's global padding for every obstacle of a store file: the
/// same gate a service call or a topic message passes. "" or the first violation.
std::string findInvalidStored(const StoredObstacles& stored, double global_padding_m) {
  for (const auto& [kind, specs] : {std::pair{"service", &stored.service},
                                    std::pair{"topic", &stored.topic}}) {
    for (const EllipseSpec& spec : *specs) {
      if (const auto invalid = findInvalidPaddedField(spec, global_padding_m)) {
        return describeFieldError(std::string(kind) + " obstacle '" + spec.name + "'", *invalid);
      }
    }
  }
  return {};
}

/// ~obstacles (no watchdog), then the listed sources; throws on a list that breaks the rules.
std::vector<SourceFreshness::Source> freshnessSources(const std::vector<SourceSpec>& sources) {
  if (const auto invalid = findInvalidSources(sources)) {
    throw std::invalid_argument(describeFieldError(invalid->key, *invalid));
  }
  std::vector<SourceFreshness::Source> all{{kDefaultSourceName, 0.0}};
  for (const SourceSpec& source : sources) {
    all.push_back({source.name, watchesSilence(source) ? source.timeout_s : 0.0});
  }
  return all;
}

/// `settings`, or std::invalid_argument naming the key it breaks.
const IncidentSettings& validIncidentSettings(const IncidentSettings& settings) {
  if (const auto invalid = findInvalidIncidentSetting(settings)) {
    throw std::invalid_argument(describeFieldError(invalid->key, *invalid));
  }
  return settings;
}

}  // namespace

CollisionMonitor::CollisionMonitor(MonitorSettings settings, const std::vector<EllipseSpec>& links,
                                   const std::vector<EllipseSpec>& obstacles, RegistryLimits limits,
                                   const StoreOptions& store, MonitorHooks hooks)
    : settings_(std::move(settings)),
      hooks_(std::move(hooks)),
      registry_(links, obstacles, limits),
      source_errors_(settings_.sources.size() + 1),
      freshness_(freshnessSources(settings_.sources)),
      gate_(settings_.gate),
      recorder_(validIncidentSettings(settings_.incident)) {
  std::string refusal;
  const std::uint64_t service_revision = restore(store, refusal);
  persistence_ = std::make_unique<ObstaclePersistence>(store.path, store.session,
                                                       service_revision, refusal);
}

CollisionMonitor::~CollisionMonitor() {
  // The writer writes what is queued before it goes.
  persistence_->writeIfBehind(registry_);
}

std::uint64_t CollisionMonitor::restore(const StoreOptions& store, std::string& refusal) {
  if (store.path.empty()) return 0;
  const LoadedStore loaded = loadObstacleStore(store.path, store.session);
  for (const LoadedStore::Note& note : loaded.notes) {
    startup_notes_.push_back({note.failed ? StartupNote::Level::Error : StartupNote::Level::Info,
                              "obstacle store " + note.text + ", not restored"});
  }
  if (!loaded.not_ours.empty()) {
    refusal = joinText(loaded.not_ours, "; ") + ": refusing to write the obstacle store over it";
    startup_notes_.push_back({StartupNote::Level::Error, refusal});
  }
  // Counted on from what this launch wrote, restored or not: a later record must never lose to
  // a stale one of the same launch.
  const std::uint64_t service_revision = loaded.obstacles.service_revision;
  if (!loaded.found) return service_revision;
  const StoredObstacles& stored = loaded.obstacles;
  std::string error = findInvalidStored(stored, settings_.check.global_padding_m);
  if (error.empty()) error = registry_.restore(stored);
  if (!error.empty()) {
    startup_notes_.push_back(
        {StartupNote::Level::Error, "obstacle store '" + store.path +
                                        "' does not fit the configuration, starting without it: " +
                                        error});
    return service_revision;
  }
  startup_notes_.push_back(
      {StartupNote::Level::Warn, "restarted: restored " + std::to_string(stored.service.size()) +
                                     " service obstacle(s) and " +
                                     std::to_string(stored.topic.size()) +
                                     " topic obstacle(s) from '" + store.path + "'"});
  return service_revision;
}

void CollisionMonitor::advanceClock(double now_s) {
  if (now_s < last_now_s_) {
    // A bag played in a loop, a simulator reset: tf would keep answering from the future.
    if (hooks_.time_jumped_back) hooks_.time_jumped_back(last_now_s_ - now_s);
    missing_since_.clear();
    ++time_jumps_;
  }
  last_now_s_ = now_s;
  const std::size_t dropped =
      registry_.dropExpiredTopicObstacles(now_s, settings_.obstacle_timeout_s);
  if (dropped == 0) return;
  dropped_obstacles_ += dropped;
  topic_obstacles_expired_ = true;
  topicObstaclesChanged();
  if (hooks_.obstacles_expired) hooks_.obstacles_expired(dropped, now_s - registry_.topicStamp());
}

void CollisionMonitor::topicObstaclesChanged() {
  if (!persistence_->enabled()) return;
  persistence_->topicChanged();
  if (settings_.obstacle_store_period_s == 0.0) writeStoreIfBehind();
}

void CollisionMonitor::writeStoreIfBehind() {
  reportStoreError(persistence_->lastError());
  persistence_->writeIfBehind(registry_);
}

void CollisionMonitor::reportStoreError(const std::string& error) const {
  if (!error.empty() && hooks_.store_failed) hooks_.store_failed(error);
}

std::string CollisionMonitor::persistServiceCall(bool removed_topic_obstacle) {
  const std::string error = persistence_->afterServiceCall(registry_, removed_topic_obstacle);
  reportStoreError(error);
  return error;
}

const CheckOutcome& CollisionMonitor::periodicCheck(double now_s, const TransformLookup& latest,
                                                    const TransformAtLookup& at) {
  state_updated_ = false;
  return fullCheck(now_s, latest, at, StatePublishing::Always, "");
}

const CheckOutcome& CollisionMonitor::fullCheck(double now_s, const TransformLookup& latest,
                                                const TransformAtLookup& at,
                                                StatePublishing publishing,
                                                const std::string& min_distance_of) {
  advanceClock(now_s);
  const auto start = std::chrono::steady_clock::now();
  CheckRequest request;
  request.min_distance_of = min_distance_of;
  CheckOutcome outcome =
      runCheck(request, registry_, settings_.check, latest, now_s, &placement_cache_);
  if (!outcome.error.empty()) {
    // Never publish a failed check as "clear": the state keeps the last good one.
    state_.failure = outcome.error;
    outcome.standing.reset();  // nothing is gated on a failed check: free its grid now
    failed_check_ = std::move(outcome);
    return failed_check_;
  }
  markSilentSources(outcome, now_s);
  predict(outcome, request, at, now_s);  // times from the state's stamp
  state_.failure.clear();
  state_.duration_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  state_.valid = true;
  state_.stamp_s = now_s;
  // The replaced state's placement goes back to the cache: the next check refills it instead of
  // copying every name again.
  core::Scene replaced = std::move(state_.outcome.placed);
  state_.outcome = std::move(outcome);
  placement_cache_.recycle(std::move(replaced));
  const CheckOutcome& checked = state_.outcome;
  // Since when each frame has been missing (unavailable or stale), for the health level.
  std::set<std::string> missing(checked.unavailable_frames.begin(),
                                checked.unavailable_frames.end());
  missing.insert(checked.stale_frames.begin(), checked.stale_frames.end());
  for (auto it = missing_since_.begin(); it != missing_since_.end();) {
    it = missing.count(it->first) ? std::next(it) : missing_since_.erase(it);
  }
  for (const std::string& frame : missing) missing_since_.emplace(frame, now_s);
  ++full_checks_;
  state_updated_ = true;
  publishing_ = settings_.rate_hz > 0.0 ? publishing : StatePublishing::Always;
  return checked;
}

const CheckOutcome& CollisionMonitor::serviceCheck(const CheckRequest& request, double stamp_s,
                                                   double now_s, const TransformLookup& lookup,
                                                   const TransformAtLookup& at) {
  state_updated_ = false;
  partial_check_ = CheckOutcome();
  partial_check_.error = validateCheckRequest(request, registry_, settings_.check.global_padding_m);
  if (!partial_check_.error.empty()) {
    partial_check_.error_kind = ErrorKind::InvalidRequest;
    return partial_check_;
  }
  // A full check at the latest time is what the topics show: recorded as the state, published
  // when it changed (or always without a periodic check: then this is how the topics update).
  const bool full_check = request.names.empty() && request.query.empty() && stamp_s == 0.0;
  if (full_check) {
    return fullCheck(now_s, lookup, at, StatePublishing::OnChange, request.min_distance_of);
  }
  advanceClock(now_s);
  // Freshness is measured against now for latest-transform checks, else the requested stamp.
  const double reference_s = stamp_s == 0.0 ? now_s : stamp_s;
  partial_check_ = runCheck(request, registry_, settings_.check, lookup, reference_s);
  if (partial_check_.error.empty()) {
    markSilentSources(partial_check_, now_s);
    predict(partial_check_, request, at, stamp_s == 0.0 ? now_s : stamp_s);
  }
  return partial_check_;
}

void CollisionMonitor::markSilentSources(CheckOutcome& outcome, double now_s) const {
  outcome.silent_sources = freshness_.silent(now_s);
  if (!outcome.silent_sources.empty()) outcome.complete = false;
}

void CollisionMonitor::predict(CheckOutcome& outcome, const CheckRequest& request,
                               const TransformAtLookup& at, double reference_s) const {
  predictAfterCheck(outcome, request, registry_, settings_.check, at,
                    settings_.prediction_horizon_s, reference_s);
}

PathCheckOutcome CollisionMonitor::checkPath(
    PathCheckRequest request, double now_s,
    const std::function<TransformLookup(const std::string&)>& lookup_to) {
  if (request.path_frame.empty()) request.path_frame = settings_.check.fixed_frame;
  if (request.moving_frame.empty()) request.moving_frame = settings_.robot_frame;
  PathCheckOutcome outcome;
  outcome.error = validatePathRequest(request);
  if (!outcome.error.empty()) {
    outcome.error_kind = ErrorKind::InvalidRequest;
    return outcome;
  }
  advanceClock(now_s);
  outcome = runPathCheck(request, registry_, settings_.check, lookup_to(request.moving_frame),
                         lookup_to(request.path_frame), now_s);
  if (outcome.error.empty()) outcome.silent_sources = silentSources(now_s);
  return outcome;
}

std::vector<std::string> CollisionMonitor::silentSources(double now_s) const {
  std::vector<std::string> silent = freshness_.silent(now_s);
  if (topic_obstacles_expired_) silent.push_back(expiredTopicNote());
  return silent;
}

std::string CollisionMonitor::expiredTopicNote() const {
  return "obstacles from ~obstacles dropped, older than obstacle_timeout " +
         core::formatNumber(settings_.obstacle_timeout_s) + " s";
}

ChangeAnswer CollisionMonitor::addObstacles(const std::vector<EllipseSpec>& specs,
                                            const TransformLookup& lookup) {
  std::string error = validateAttached(specs, "obstacles", settings_.check, lookup);
  if (error.empty()) error = registry_.addObstacles(specs, "obstacles");
  if (!error.empty()) return {ErrorKind::InvalidRequest, error};
  return durableAnswer("added", specs.size(), /*removed_topic_obstacle=*/false);
}

ChangeAnswer CollisionMonitor::removeObstacles(const std::vector<std::string>& names) {
  const bool removes_topic_obstacle = registry_.anyTopicObstacle(names);
  const std::string error = registry_.removeObstacles(names, "names");
  if (!error.empty()) return {ErrorKind::InvalidRequest, error};
  return durableAnswer("removed", names.size(), removes_topic_obstacle);
}

ChangeAnswer CollisionMonitor::durableAnswer(const std::string& done, std::size_t count,
                                             bool removed_topic_obstacle) {
  // Durable before success: a node killed right after the answer restores the change.
  const std::string store_error = persistServiceCall(removed_topic_obstacle);
  if (!store_error.empty()) {
    return {ErrorKind::NotPersisted, done + " in memory but not persisted: " + store_error};
  }
  return {ErrorKind::None, done + " " + std::to_string(count) + " obstacle(s)"};
}

std::string CollisionMonitor::replaceSourceObstacles(std::size_t source,
                                                     std::vector<EllipseSpec> specs, double stamp_s,
                                                     double now_s, const TransformLookup& lookup,
                                                     bool heard) {
  if (source >= freshness_.size()) {
    return "source " + std::to_string(source) + ": expected a source index below " +
           std::to_string(freshness_.size());
  }
  std::string field = "ellipses";
  if (source > 0) {
    const SourceSpec& spec_of_source = settings_.sources[source - 1];
    field = "source '" + spec_of_source.name + "' ellipses";
    // Other robots' links keep the names they were published under ("r2/base_link"), grown by
    // the room this robot leaves them to stray from their straight lines.
    if (spec_of_source.type != SourceType::Robots) {
      for (EllipseSpec& spec : specs)
        spec.name = sourceObstacleName(spec_of_source.name, spec.name);
    } else {
      for (EllipseSpec& spec : specs) spec.padding += spec_of_source.padding_m;
    }
  }
  std::string error = validateAttached(specs, field, settings_.check, lookup);
  if (error.empty()) error = registry_.replaceTopicObstacles(specs, field, stamp_s, source);
  if (error.empty() && heard) {
    freshness_.received(source, now_s, specs.size());
    if (source == 0) {
      // Only ~obstacles is expired by obstacle_timeout and kept in the store.
      topic_obstacles_expired_ = false;
      topicObstaclesChanged();
    }
  }
  source_errors_[source] = error;
  return error;
}

void CollisionMonitor::sourceMessageRefused(std::size_t source, const std::string& why) {
  if (source < source_errors_.size()) source_errors_[source] = why;
}

GateDecision CollisionMonitor::gateCommand(const VelocityCommand& command, double now_s,
                                           const TransformLookup& latest,
                                           const TransformAtLookup& at) {
  if (auto screened = gate_.screen(command, now_s)) {
    recordDecision(now_s, *screened, nullptr);
    return std::move(*screened);
  }
  const CheckOutcome& outcome = fullCheck(now_s, latest, at, StatePublishing::OnChange, "");
  const GateView view = gateView(outcome, now_s, latest);
  GateDecision decision = gate_.decide(command, view);
  recordDecision(now_s, decision, &view);
  return decision;
}

std::optional<GateDecision> CollisionMonitor::gateWatchdog(double now_s) {
  std::optional<GateDecision> decision = gate_.watchdog(now_s);
  if (decision) recordDecision(now_s, *decision, nullptr);
  return decision;
}

void CollisionMonitor::recordDecision(double now_s, const GateDecision& decision,
                                      const GateView* view) {
  if (!recorder_.settings().enabled) return;
  DecisionScene scene;
  for (const SourceFreshness::Stats& source : freshness_.stats(now_s)) {
    scene.source_ages.emplace_back(source.name, source.age_s);
  }
  if (view && view->outcome && view->outcome->error.empty() && view->robot.ok) {
    scene.outcome = view->outcome;
    scene.robot = planarPose(view->robot.fixed_from_frame);
    scene.motions = &view->obstacle_motions;
    if (gate_.lastMemory()) scene.memory = &*gate_.lastMemory();
  }
  recorder_.record(now_s, decision, &scene);
}

GateView CollisionMonitor::gateView(const CheckOutcome& outcome, double now_s,
                                    const TransformLookup& latest) const {
  GateView view;
  view.outcome = &outcome;
  view.fixed_frame = settings_.check.fixed_frame;
  view.freshness = Freshness{settings_.check.max_transform_age_s, now_s};
  view.allowed = &settings_.check.rules.allowed;
  view.world_revision = registry_.revision();
  if (!outcome.error.empty()) return view;
  const std::string& robot_frame = gate_.config().robot_frame;
  const auto known = outcome.frames.find(robot_frame);
  view.robot = known != outcome.frames.end() ? known->second : latest(robot_frame);
  view.silent_sources = outcome.silent_sources;
  if (topic_obstacles_expired_) view.silent_sources.push_back(expiredTopicNote());
  // Obstacles move by their own velocity only: one attached to a moving frame (a scan in the
  // sensor's frame) is where that frame puts it now and does not travel with the robot.
  // Listed by index, the moving ones only: a list of every entry cost a tenth of a command at
  // 100,000 obstacles.
  const core::Scene& placed = outcome.placed;
  const std::set<std::string>& moving = registry_.movingNames();
  if (moving.empty()) return view;
  const auto add = [&](std::size_t i) {
    const StoredEllipse& stored = registry_.entries().at(placed.name(i));
    const auto frame = outcome.frames.find(stored.spec.frame_id);
    if (frame == outcome.frames.end()) return;
    // A topic obstacle was where its message put it at the message's stamp; a stamp ahead of
    // the clock (another computer's clock) advances it by nothing.
    double since_s = 0.0;
    if (stored.source == EllipseSource::TopicObstacle) {
      const double stamp_s = registry_.topicStamp(stored.topic_source);
      if (stamp_s > 0.0 && now_s > stamp_s) since_s = now_s - stamp_s;
    }
    view.obstacle_motions.push_back(
        {i, ownMotion(stored.spec, frame->second.fixed_from_frame), since_s});
  };
  // A check that placed every stored ellipse placed them in the cache's order, whose moving
  // positions are kept per registry revision; otherwise every placed name is looked up.
  const auto& order = placement_cache_.placingOrder();
  const auto& positions = placement_cache_.ownMotionPositions();
  const bool in_order = placed.size() == order.size() &&
                        std::all_of(positions.begin(), positions.end(), [&](std::size_t p) {
                          return placed.name(p) == order[p].entry->first;
                        });
  if (in_order) {
    for (const std::size_t p : positions) add(p);
    return view;
  }
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (placed.role(i) == core::EllipseRole::Obstacle && moving.count(placed.name(i))) add(i);
  }
  return view;
}

CollisionMonitor::Health CollisionMonitor::health(double now_s) const {
  Health report;
  CheckHealthInputs inputs;
  inputs.outcome = state_.valid ? &state_.outcome : nullptr;
  inputs.check_failure = state_.failure;
  for (const auto& [frame, since] : missing_since_) {
    inputs.missing_for_s.emplace_back(frame, now_s - since);
  }
  inputs.obstacles_error = source_errors_[0];
  for (std::size_t i = 1; i < source_errors_.size(); ++i) {
    if (!source_errors_[i].empty()) {
      inputs.source_errors.push_back("source '" + settings_.sources[i - 1].name +
                                     "': " + source_errors_[i]);
    }
  }
  inputs.store_error = persistence_->lastError();
  report.health = assessCheckHealth(inputs);

  const CheckOutcome& outcome = state_.outcome;
  auto& values = report.values;
  const auto count = [&](EllipseSource source) { return std::to_string(registry_.count(source)); };
  values.emplace_back("links", count(EllipseSource::ConfiguredLink));
  values.emplace_back("obstacles (configured)", count(EllipseSource::ConfiguredObstacle));
  values.emplace_back("obstacles (service)", count(EllipseSource::ServiceObstacle));
  values.emplace_back("obstacles (topic)", count(EllipseSource::TopicObstacle));
  values.emplace_back("unavailable frames", joinText(outcome.unavailable_frames, ", "));
  values.emplace_back("collisions", std::to_string(outcome.collisions.size()));
  values.emplace_back("warnings", std::to_string(outcome.warnings.size()));
  values.emplace_back("full checks", std::to_string(full_checks_));
  values.emplace_back("last check duration [ms]", core::formatNumber(1e3 * state_.duration_s));
  values.emplace_back("complete", state_.valid && outcome.complete ? "true" : "false");
  values.emplace_back("stale frames", joinText(outcome.stale_frames, ", "));
  values.emplace_back("missing for [s]", joinText(report.health.missing_for, ", "));
  values.emplace_back("dropped obstacles (obstacle_timeout)", std::to_string(dropped_obstacles_));
  values.emplace_back("time jumps back", std::to_string(time_jumps_));
  values.emplace_back("prediction horizon [s]", core::formatNumber(settings_.prediction_horizon_s));
  values.emplace_back("smallest time to contact [s]",
                      outcome.predicted.empty() ? std::string("none")
                                                : core::formatNumber(outcome.predicted.front().time));
  values.emplace_back("predicted contacts", std::to_string(outcome.predicted.size()));
  values.emplace_back("prediction notes", joinText(outcome.prediction_notes, "; "));
  values.emplace_back("silent sources", joinText(outcome.silent_sources, "; "));
  for (const SourceFreshness::Stats& source : freshness_.stats(now_s)) {
    const std::string key = "source '" + source.name + "' ";
    values.emplace_back(key + "rate [Hz]",
                        core::formatNumber(std::round(source.rate_hz * 10) / 10));
    values.emplace_back(key + "age [s]",
                        source.age_s < 0.0
                            ? std::string("no message yet")
                            : core::formatNumber(std::round(source.age_s * 100) / 100));
    values.emplace_back(key + "obstacles", std::to_string(source.obstacles));
  }
  for (auto& value : gate_.healthValues()) values.push_back(std::move(value));
  return report;
}

TunableSettings CollisionMonitor::tunable() const {
  TunableSettings tunable;
  tunable.rate_hz = settings_.rate_hz;
  tunable.padding_m = settings_.check.global_padding_m;
  tunable.warning_distance_m = settings_.check.rules.warning_distance;
  tunable.prediction_horizon_s = settings_.prediction_horizon_s;
  tunable.max_transform_age_s = settings_.check.max_transform_age_s;
  tunable.obstacle_timeout_s = settings_.obstacle_timeout_s;
  tunable.gate = gate_.config();
  return tunable;
}

std::optional<FieldError> CollisionMonitor::retune(const TunableSettings& tunable) {
  if (auto invalid = findInvalidTunable(tunable)) return invalid;
  if (tunable.gate.robot_frame != gate_.config().robot_frame) {
    return FieldError{"gate/robot_frame",
                      "'" + gate_.config().robot_frame + "' (set at start-up only)",
                      "'" + tunable.gate.robot_frame + "'"};
  }
  for (const auto& [name, stored] : registry_.entries()) {
    if (const auto invalid = findInvalidPaddedField(stored.spec, tunable.padding_m)) {
      return FieldError{"padding",
                        "a padding under which every stored ellipse stays valid (" +
                            describeFieldError("'" + name + "'", *invalid) + ")",
                        core::formatNumber(tunable.padding_m)};
    }
  }
  settings_.rate_hz = tunable.rate_hz;
  settings_.check.global_padding_m = tunable.padding_m;
  settings_.check.rules.warning_distance = tunable.warning_distance_m;
  settings_.prediction_horizon_s = tunable.prediction_horizon_s;
  settings_.check.max_transform_age_s = tunable.max_transform_age_s;
  settings_.obstacle_timeout_s = tunable.obstacle_timeout_s;
  gate_.configure(tunable.gate);
  return std::nullopt;
}

}  // namespace ellipse_collision::app

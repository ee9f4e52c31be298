#include "ellipse_collision/app/incident_recorder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace ellipse_collision::app {
namespace {

constexpr double kBytesPerMegabyte = 1e6;

bool sameEllipse(const core::Ellipse& a, const core::Ellipse& b) {
  return a.center == b.center && a.radius_x == b.radius_x && a.radius_y == b.radius_y &&
         a.angle == b.angle;
}

}  // namespace

std::optional<FieldError> findInvalidIncidentSetting(const IncidentSettings& settings) {
  if (auto e = findOutsideRange("incident/before", settings.before_s, 0.0, kMaxIncidentWindowS,
                                /*min_excluded=*/true)) {
    return e;
  }
  if (auto e = findOutsideRange("incident/after", settings.after_s, 0.0, kMaxIncidentWindowS)) {
    return e;
  }
  if (auto e = findOutsideRange("incident/min_interval", settings.min_interval_s, 0.0,
                                kMaxIncidentIntervalS)) {
    return e;
  }
  if (auto e = findOutsideRange("incident/max_files", static_cast<double>(settings.max_files), 1.0,
                                kMaxIncidentFiles)) {
    return e;
  }
  if (auto e = findOutsideRange("incident/max_megabytes", settings.max_megabytes, 0.0,
                                kMaxIncidentMegabytes, /*min_excluded=*/true)) {
    return e;
  }
  if (settings.actions.empty()) {
    return FieldError{"incident/actions", "a non-empty list of gate actions", "[]"};
  }
  for (std::size_t i = 0; i < settings.actions.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (settings.actions[i] == settings.actions[j]) {
        return FieldError{"incident/actions", "each action once",
                          std::string(core::toString(settings.actions[i])) + " twice"};
      }
    }
  }
  return std::nullopt;
}

std::optional<FieldError> parseIncidentActions(const std::vector<std::string>& names,
                                               std::vector<core::GateAction>* actions) {
  static const core::GateAction kAll[] = {core::GateAction::Pass,    core::GateAction::Slow,
                                          core::GateAction::Stop,    core::GateAction::Escape,
                                          core::GateAction::Timeout, core::GateAction::Incomplete,
                                          core::GateAction::Disabled};
  std::vector<core::GateAction> parsed;
  for (const std::string& name : names) {
    const auto* found = std::find_if(std::begin(kAll), std::end(kAll),
                                     [&](core::GateAction a) { return name == core::toString(a); });
    if (found == std::end(kAll)) {
      return FieldError{
          "incident/actions",
          "gate actions among PASS, SLOW, STOP, ESCAPE, TIMEOUT, INCOMPLETE, DISABLED",
          "'" + name + "'"};
    }
    if (std::find(parsed.begin(), parsed.end(), *found) != parsed.end()) {
      return FieldError{"incident/actions", "each action once", "'" + name + "' twice"};
    }
    parsed.push_back(*found);
  }
  if (parsed.empty())
    return FieldError{"incident/actions", "a non-empty list of gate actions", "[]"};
  *actions = std::move(parsed);
  return std::nullopt;
}

IncidentRecorder::IncidentRecorder(IncidentSettings settings) : settings_(std::move(settings)) {}

bool IncidentRecorder::triggers(core::GateAction action) const {
  return std::find(settings_.actions.begin(), settings_.actions.end(), action) !=
         settings_.actions.end();
}

std::shared_ptr<const ObstacleSnapshot> IncidentRecorder::snapshotOf(const CheckOutcome& outcome,
                                                                     std::size_t first_obstacle) {
  const core::Scene& placed = outcome.placed;
  // The same grid is the same obstacles (StandingObstacles): no need to look at them.
  if (last_snapshot_ && outcome.standing && outcome.standing == last_standing_) {
    return last_snapshot_;
  }
  const std::size_t count = placed.size() - first_obstacle;
  bool same = last_snapshot_ && last_snapshot_->obstacles.size() == count;
  for (std::size_t i = 0; same && i < count; ++i) {
    const core::NamedEllipse& kept = last_snapshot_->obstacles[i];
    same = sameEllipse(kept.ellipse, placed.ellipse(first_obstacle + i)) &&
           kept.name == placed.name(first_obstacle + i);
  }
  last_standing_ = outcome.standing;
  if (same) return last_snapshot_;
  auto snapshot = std::make_shared<ObstacleSnapshot>();
  snapshot->id = next_snapshot_id_++;
  snapshot->obstacles.reserve(count);
  for (std::size_t i = first_obstacle; i < placed.size(); ++i) {
    snapshot->obstacles.push_back(placed.entry(i));
  }
  last_snapshot_ = std::move(snapshot);
  return last_snapshot_;
}

void IncidentRecorder::record(double now_s, const GateDecision& decision,
                              const DecisionScene* scene) {
  if (!settings_.enabled) return;
  finishPending(now_s);
  // ROS time went back (a looping bag, a simulator reset): what was recorded is of another run.
  if (!buffer_.empty() && now_s < buffer_.back().stamp_s) {
    buffer_.clear();
    last_trigger_s_.reset();
  }
  RecordedDecision recorded;
  recorded.stamp_s = now_s;
  recorded.decision = decision;
  if (scene && scene->outcome && scene->outcome->error.empty()) {
    const CheckOutcome& outcome = *scene->outcome;
    const core::Scene& placed = outcome.placed;
    recorded.judged_scene = true;
    recorded.complete = outcome.complete;
    recorded.robot = scene->robot;
    std::size_t first_obstacle = 0;
    while (first_obstacle < placed.size() &&
           placed.role(first_obstacle) != core::EllipseRole::Obstacle) {
      recorded.links.push_back(placed.entry(first_obstacle));
      ++first_obstacle;
    }
    recorded.obstacles = snapshotOf(outcome, first_obstacle);
    if (scene->motions) {
      for (const PlacedMotion& m : *scene->motions) {
        if (m.index >= first_obstacle)
          recorded.motions.push_back({m.index - first_obstacle, m.motion, m.since_s});
      }
    }
    recorded.source_ages = scene->source_ages;
    if (scene->memory) recorded.memory = *scene->memory;
    for (const auto& [frame, transform] : outcome.frames) {
      recorded.frame_ages.emplace_back(frame, !transform.ok ? -1.0
                                              : transform.stamp_s == 0.0
                                                  ? 0.0
                                                  : now_s - transform.stamp_s);
    }
  } else {
    // Decided without a scene: the last obstacles stay the ones that apply.
    static const auto kNone = std::make_shared<const ObstacleSnapshot>();
    recorded.obstacles = last_snapshot_ ? last_snapshot_ : kNone;
    if (scene) recorded.source_ages = scene->source_ages;
  }
  buffer_.push_back(std::move(recorded));
  if (pending_) pending_->decisions.push_back(buffer_.back());
  trim(now_s);

  if (!triggers(decision.action)) return;
  if (pending_) return;  // the incident under way covers it
  if (last_trigger_s_ && now_s - *last_trigger_s_ < settings_.min_interval_s) {
    ++suppressed_;
    return;
  }
  last_trigger_s_ = now_s;
  ++triggered_;
  pending_ = Incident{core::toString(decision.action), now_s,
                      std::vector<RecordedDecision>(buffer_.begin(), buffer_.end())};
  if (settings_.after_s == 0.0) {
    finished_.push_back(std::move(*pending_));
    pending_.reset();
  }
}

void IncidentRecorder::trim(double now_s) {
  while (!buffer_.empty() && buffer_.front().stamp_s < now_s - settings_.before_s) {
    buffer_.pop_front();
  }
}

bool IncidentRecorder::request(double now_s) {
  if (!settings_.enabled) return false;
  trim(now_s);
  finished_.push_back(
      Incident{"REQUESTED", now_s, std::vector<RecordedDecision>(buffer_.begin(), buffer_.end())});
  return true;
}

void IncidentRecorder::finishPending(double now_s) {
  // Finished once a decision could come after its window; a jump back in time ends it too.
  if (pending_ &&
      (now_s > pending_->trigger_s + settings_.after_s || now_s < pending_->trigger_s)) {
    finished_.push_back(std::move(*pending_));
    pending_.reset();
  }
}

std::vector<Incident> IncidentRecorder::takeFinished(double now_s) {
  finishPending(now_s);
  std::vector<Incident> taken = std::move(finished_);
  finished_.clear();
  return taken;
}

std::size_t IncidentRecorder::storedObstacles() const {
  std::size_t count = 0;
  const ObstacleSnapshot* previous = nullptr;
  for (const RecordedDecision& d : buffer_) {
    if (d.obstacles.get() != previous) count += d.obstacles->obstacles.size();
    previous = d.obstacles.get();
  }
  return count;
}

std::vector<std::string> incidentFilesToRemove(std::vector<IncidentFile> files,
                                               std::size_t max_files, double max_megabytes) {
  std::sort(files.begin(), files.end(),
            [](const IncidentFile& a, const IncidentFile& b) { return a.name < b.name; });
  double total = 0.0;
  for (const IncidentFile& f : files) total += static_cast<double>(f.bytes);
  const double budget = max_megabytes * kBytesPerMegabyte;
  std::vector<std::string> removed;
  std::size_t kept = files.size();
  for (std::size_t i = 0; i + 1 < files.size(); ++i) {
    if (kept <= max_files && total <= budget) break;
    removed.push_back(files[i].name);
    total -= static_cast<double>(files[i].bytes);
    --kept;
  }
  return removed;
}

std::string incidentFileName(double wall_s, const std::string& trigger) {
  const double whole = std::floor(wall_s);
  const std::time_t seconds = static_cast<std::time_t>(whole);
  const int millis = std::min(999, static_cast<int>((wall_s - whole) * 1000.0));
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char stamp[64];
  std::snprintf(stamp, sizeof(stamp), "%04d%02d%02dT%02d%02d%02d.%03dZ", utc.tm_year + 1900,
                utc.tm_mon + 1, utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec, millis);
  return "incident_" + std::string(stamp) + "_" + trigger + ".bag";
}

}  // namespace ellipse_collision::app

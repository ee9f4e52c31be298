#include "ellipse_collision/app/incident_replay.h"

#include <cstdint>
#include <cstring>

#include "ellipse_collision/core/number_format.h"

namespace ellipse_collision::app {
namespace {

/// Bit for bit: a replay either reproduces a number or it does not (-0 and 0 differ, as do two
/// NaNs of different payloads; the gate's numbers are never NaN).
bool sameBits(double a, double b) {
  std::uint64_t x = 0;
  std::uint64_t y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

class Comparison {
 public:
  Comparison(const GateDecision& recorded, const GateDecision& replayed)
      : recorded_(recorded), replayed_(replayed) {}

  void number(const char* field, double GateDecision::*member) {
    number(field, recorded_.*member, replayed_.*member);
  }
  void number(const char* field, double recorded, double replayed) {
    if (!difference_ && !sameBits(recorded, replayed)) {
      difference_ =
          DecisionDifference{field, core::formatNumber(recorded), core::formatNumber(replayed)};
    }
  }
  void text(const char* field, const std::string& recorded, const std::string& replayed) {
    if (!difference_ && recorded != replayed) {
      difference_ = DecisionDifference{field, "'" + recorded + "'", "'" + replayed + "'"};
    }
  }
  void flag(const char* field, bool recorded, bool replayed) {
    if (!difference_ && recorded != replayed) {
      difference_ =
          DecisionDifference{field, recorded ? "true" : "false", replayed ? "true" : "false"};
    }
  }
  void twist(const std::string& field, const VelocityCommand& recorded,
             const VelocityCommand& replayed) {
    static const char* const kAxes[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      number((field + ".linear." + kAxes[i]).c_str(), recorded.linear[i], replayed.linear[i]);
    }
    for (int i = 0; i < 3; ++i) {
      number((field + ".angular." + kAxes[i]).c_str(), recorded.angular[i], replayed.angular[i]);
    }
  }
  std::optional<DecisionDifference> result() const { return difference_; }

 private:
  const GateDecision& recorded_;
  const GateDecision& replayed_;
  std::optional<DecisionDifference> difference_;
};

}  // namespace

std::optional<DecisionDifference> firstDifference(const GateDecision& recorded,
                                                  const GateDecision& replayed) {
  Comparison c(recorded, replayed);
  c.text("action", toString(recorded.action), toString(replayed.action));
  c.number("scale", &GateDecision::scale);
  c.twist("output", recorded.output, replayed.output);
  c.flag("contact_predicted", recorded.contact_predicted, replayed.contact_predicted);
  // ~gate_state shows the time and point of a predicted contact only.
  if (recorded.contact_predicted && replayed.contact_predicted) {
    c.number("time_to_contact", &GateDecision::time_to_contact_s);
  }
  c.text("link", recorded.link, replayed.link);
  c.text("obstacle", recorded.obstacle, replayed.obstacle);
  if (recorded.contact_predicted && replayed.contact_predicted) {
    c.number("contact_point.x", recorded.contact_point.x(), replayed.contact_point.x());
    c.number("contact_point.y", recorded.contact_point.y(), replayed.contact_point.y());
  }
  c.number("braking_distance", &GateDecision::braking_distance_m);
  c.number("free_distance", &GateDecision::free_distance_m);
  c.flag("unavoidable", recorded.unavoidable, replayed.unavoidable);
  c.number("impact_speed", &GateDecision::impact_speed);
  return c.result();
}

GateDecision replayDecision(const RecordedDecision& recorded, const ReplaySettings& settings) {
  // The scene as the check placed it: the links first, then the obstacles (the recorder's order).
  core::Scene placed;
  const std::vector<core::NamedEllipse>& obstacles = recorded.obstacles->obstacles;
  placed.reserve(recorded.links.size() + obstacles.size());
  for (const core::NamedEllipse& link : recorded.links) {
    placed.push_back(link.name, core::EllipseRole::Link, link.ellipse);
  }
  for (const core::NamedEllipse& obstacle : obstacles) {
    placed.push_back(obstacle.name, core::EllipseRole::Obstacle, obstacle.ellipse);
  }
  std::vector<PlacedMotion> moving;
  moving.reserve(recorded.motions.size());
  for (const ObstacleMotion& m : recorded.motions) {
    moving.push_back({recorded.links.size() + m.index, m.motion, m.since_s});
  }
  // The base's dynamics are the settings' (as the node's VelocityGate::baseAt() takes them).
  GateMemory memory = *recorded.memory;
  memory.base.dynamics = settings.gate.base;
  // The node looks the standing obstacles up in its grid; the answer is the same bit for bit as
  // a scan of all of them (gateOnScene()), which the replay does.
  return judgeOnScene(recorded.decision.input, placed, moving, recorded.robot, settings.allowed,
                      settings.gate, memory);
}

ReplayReport replayIncident(const std::vector<RecordedDecision>& decisions,
                            const ReplaySettings& settings) {
  ReplayReport report;
  report.decisions = decisions.size();
  for (std::size_t i = 0; i < decisions.size(); ++i) {
    const RecordedDecision& recorded = decisions[i];
    if (!recorded.judged_scene || !recorded.memory) continue;
    ++report.replayed;
    const GateDecision replayed = replayDecision(recorded, settings);
    if (auto difference = firstDifference(recorded.decision, replayed)) {
      report.mismatches.push_back({i, recorded.stamp_s, std::move(*difference)});
    }
  }
  return report;
}

std::string describeMismatch(const ReplayMismatch& mismatch) {
  const DecisionDifference& d = mismatch.difference;
  return "decision " + std::to_string(mismatch.index) + " at " +
         core::formatNumber(mismatch.stamp_s) + " s: " + d.field + " recorded " + d.recorded +
         ", replayed " + d.replayed;
}

std::string replaySummary(const ReplayReport& report) {
  const std::size_t before_rules = report.decisions - report.replayed;
  if (report.replayed == 0) {
    return "replay: no decision judged by the gate's rules in " + std::to_string(report.decisions) +
           " decisions: nothing to reproduce";
  }
  std::string summary = "replay: " + std::to_string(report.replayed - report.mismatches.size()) +
                        " of " + std::to_string(report.replayed) + " decisions reproduced";
  if (before_rules > 0) {
    summary +=
        " (" + std::to_string(before_rules) + " decided before the gate's rules, not replayed)";
  }
  return summary;
}

}  // namespace ellipse_collision::app

// The incident replay (app::replayIncident()): the decisions a monitor recorded while braking
// toward obstacles, one of them coming, are judged again from the record alone and reproduced bit
// for bit; a tampered decision is reported naming the field and both values; the recorded base
// velocity and hold state are what makes them reproducible.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "ellipse_collision/app/incident_replay.h"
#include "ellipse_collision/core/number_format.h"
#include "frame_table.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

using test::circle;

VelocityCommand forward(double vx, double wz = 0.0) {
  VelocityCommand command;
  command.linear.x() = vx;
  command.angular.z() = wz;
  return command;
}

/// A braking base driving at a wall in map, a box coming toward it, commands at 10 Hz with
/// odometry lagging behind the output, silence at the end (a TIMEOUT): the recorded incident.
struct Drive {
  MonitorSettings settings;
  std::vector<RecordedDecision> decisions;

  Drive() {
    settings.check.fixed_frame = "map";
    settings.check.max_transform_age_s = 0.5;
    settings.gate.enabled = true;
    settings.gate.timing.horizon = 3.0;
    settings.gate.timing.time_before_collision = 1.0;
    settings.gate.timing.stop_time = 0.3;
    settings.gate.cmd_vel_timeout_s = 0.5;
    settings.gate.base.reaction_time = 0.2;
    settings.gate.base.linear_deceleration = 0.8;
    settings.gate.base.angular_deceleration = 2.0;
    settings.incident.before_s = 600.0;
    settings.incident.actions = {GateAction::Disabled};  // only the one requested at the end
    CollisionMonitor monitor(
        settings,
        {circle("body", "base_link", 0, 0, 0.3), circle("nose", "base_link", 0.3, 0, 0.1)},
        {circle("wall", "map", 3.0, 0.0, 0.3), circle("pillar", "map", 2.0, -1.2, 0.2)}, {}, {});
    std::map<std::string, int> lookups;
    test::FrameTable frames{{{"map", Eigen::Isometry3d::Identity()}}, {}, &lookups};
    const TransformLookup latest = [&](const std::string& f) { return frames(f); };
    const TransformAtLookup at = [&](const std::string& f, double) { return frames(f); };
    // A box on ~obstacles coming toward the robot, seen at 0.01 s (the gate advances it from
    // there), gone after 1.5 s (then the world stands).
    EllipseSpec coming = circle("box", "map", 4.0, 0.4, 0.2);
    coming.vx = -0.5;
    EXPECT_EQ(monitor.replaceTopicObstacles({coming}, 0.01, latest), "");
    double x = 0.0, yaw = 0.0, speed = 0.0;
    for (int i = 0; i < 40; ++i) {
      const double now = 0.1 * i;
      frames.poses["base_link"] = test::yawedPose(x, 0.02 * x, yaw);
      if (i == 15) {
        EXPECT_EQ(monitor.replaceTopicObstacles({}, now, latest), "");
      }
      if (i % 3 == 0) monitor.gateOdometry(forward(speed), now - 0.05);
      // The same input over and over: the no-stop-and-go rule holds the scale while it stands.
      const GateDecision d =
          monitor.gateCommand(forward(i < 30 ? 1.0 : 0.6, 0.05), now, latest, at);
      speed = d.output.linear.x();
      x += 0.1 * speed;
      yaw += 0.1 * d.output.angular.z();
    }
    EXPECT_TRUE(monitor.gateWatchdog(4.5));
    EXPECT_TRUE(monitor.requestIncident(4.5));
    const std::vector<Incident> incidents = monitor.takeIncidents(4.5);
    EXPECT_EQ(incidents.size(), 1u);
    if (!incidents.empty()) decisions = incidents[0].decisions;
  }
  ReplaySettings replaySettings() const { return {settings.gate, settings.check.rules.allowed}; }
};

TEST(IncidentReplay, RecordedDecisionsOfABrakingBaseAreReproduced) {
  const Drive drive;
  ASSERT_EQ(drive.decisions.size(), 41u);
  // The drive covers what a replay needs: braking from a measured velocity, a held scale, a
  // moving obstacle, slow-downs, and a decision made before the rules.
  int slowed = 0, held = 0, moving = 0;
  for (const RecordedDecision& d : drive.decisions) {
    slowed += d.decision.action == GateAction::Slow || d.decision.action == GateAction::Stop;
    held += d.memory && d.memory->hold && d.decision.reason.find("held at") != std::string::npos;
    moving += !d.motions.empty();
  }
  EXPECT_GT(slowed, 5);
  EXPECT_GT(held, 0);
  EXPECT_GT(moving, 0);
  EXPECT_EQ(drive.decisions.back().decision.action, GateAction::Timeout);
  EXPECT_FALSE(drive.decisions.back().memory);

  const ReplayReport report = replayIncident(drive.decisions, drive.replaySettings());
  EXPECT_EQ(report.decisions, 41u);
  EXPECT_EQ(report.replayed, 40u);
  for (const ReplayMismatch& m : report.mismatches) ADD_FAILURE() << describeMismatch(m);
  EXPECT_TRUE(report.reproduced());
  EXPECT_EQ(replaySummary(report),
            "replay: 40 of 40 decisions reproduced (1 decided before the gate's rules, not "
            "replayed)");
}

TEST(IncidentReplay, ATamperedDecisionIsReportedNamingTheFieldAndBothValues) {
  const Drive drive;
  std::size_t slow = 0;
  while (slow + 1 < drive.decisions.size() &&
         drive.decisions[slow].decision.action != GateAction::Slow) {
    ++slow;
  }
  ASSERT_EQ(drive.decisions[slow].decision.action, GateAction::Slow);
  const double recorded_scale = drive.decisions[slow].decision.scale;

  std::vector<RecordedDecision> tampered = drive.decisions;
  tampered[slow].decision.scale = std::nextafter(recorded_scale, 2.0);  // one bit
  tampered[slow].decision.output.linear.x() += 0.25;                    // reported after scale
  tampered[slow + 1].decision.link = "elbow";
  ReplayReport report = replayIncident(tampered, drive.replaySettings());
  ASSERT_EQ(report.mismatches.size(), 2u);
  EXPECT_FALSE(report.reproduced());
  EXPECT_EQ(report.mismatches[0].index, slow);
  EXPECT_EQ(report.mismatches[0].difference.field, "scale");
  EXPECT_EQ(report.mismatches[0].difference.replayed, core::formatNumber(recorded_scale));
  EXPECT_EQ(describeMismatch(report.mismatches[0]),
            "decision " + std::to_string(slow) + " at " +
                core::formatNumber(drive.decisions[slow].stamp_s) + " s: scale recorded " +
                core::formatNumber(std::nextafter(recorded_scale, 2.0)) + ", replayed " +
                core::formatNumber(recorded_scale));
  EXPECT_EQ(report.mismatches[1].difference.field, "link");
  EXPECT_EQ(report.mismatches[1].difference.recorded, "'elbow'");
  EXPECT_EQ(replaySummary(report),
            "replay: 38 of 40 decisions reproduced (1 decided before the gate's rules, not "
            "replayed)");

  // Every field is compared: each one changed alone is the one named.
  const std::vector<std::pair<std::string, void (*)(GateDecision&)>> changes = {
      {"action", [](GateDecision& d) { d.action = GateAction::Escape; }},
      {"output.angular.z", [](GateDecision& d) { d.output.angular.z() = -1.0; }},
      {"contact_predicted", [](GateDecision& d) { d.contact_predicted = !d.contact_predicted; }},
      {"time_to_contact", [](GateDecision& d) { d.time_to_contact_s += 1e-12; }},
      {"obstacle", [](GateDecision& d) { d.obstacle += "_"; }},
      {"contact_point.y", [](GateDecision& d) { d.contact_point.y() += 1e-9; }},
      {"braking_distance", [](GateDecision& d) { d.braking_distance_m *= 1.5; }},
      {"free_distance", [](GateDecision& d) { d.free_distance_m += 0.5; }},
      {"unavoidable", [](GateDecision& d) { d.unavoidable = !d.unavoidable; }},
      {"impact_speed", [](GateDecision& d) { d.impact_speed += 1.0; }}};
  for (const auto& [field, change] : changes) {
    GateDecision changed = drive.decisions[slow].decision;
    change(changed);
    const auto difference = firstDifference(changed, drive.decisions[slow].decision);
    ASSERT_TRUE(difference) << field;
    EXPECT_EQ(difference->field, field);
  }
  EXPECT_FALSE(firstDifference(drive.decisions[slow].decision, drive.decisions[slow].decision));
}

TEST(IncidentReplay, TheBaseVelocityTheHoldAndTheObstaclesAgesAreWhatMakesItReproducible) {
  const Drive drive;
  // Judged with the moving box where its message put it, not where it had come since, some
  // decisions come out otherwise.
  std::vector<RecordedDecision> unaged = drive.decisions;
  int aged = 0;
  for (RecordedDecision& d : unaged) {
    for (ObstacleMotion& m : d.motions) {
      aged += m.since_s > 0.0;
      m.since_s = 0.0;
    }
  }
  EXPECT_GT(aged, 10);
  EXPECT_FALSE(replayIncident(unaged, drive.replaySettings()).mismatches.empty());
  // Judged as if the base stood still, or without the hold, some decisions come out otherwise.
  for (const bool drop_hold : {false, true}) {
    std::vector<RecordedDecision> forgotten = drive.decisions;
    for (RecordedDecision& d : forgotten) {
      if (!d.memory) continue;
      if (drop_hold) {
        d.memory->hold.reset();
      } else {
        d.memory->base.velocity = core::Twist{};
      }
    }
    EXPECT_FALSE(replayIncident(forgotten, drive.replaySettings()).mismatches.empty())
        << (drop_hold ? "without the hold" : "with the base at rest");
  }
}

TEST(IncidentReplay, AnIncidentWithoutADecisionByTheRulesReproducesNothing) {
  Drive drive;
  std::vector<RecordedDecision> timeouts{drive.decisions.back()};
  const ReplayReport report = replayIncident(timeouts, drive.replaySettings());
  EXPECT_EQ(report.replayed, 0u);
  EXPECT_FALSE(report.reproduced()) << "nothing judged again proves nothing";
  EXPECT_EQ(replaySummary(report),
            "replay: no decision judged by the gate's rules in 1 decisions: nothing to reproduce");
}

}  // namespace
}  // namespace ellipse_collision::app

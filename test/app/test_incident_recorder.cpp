// The incident recorder's rules without ROS: the ring buffer by time, obstacles stored once per
// change, the trigger rule with min_interval and the after window, and the disk budget.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ellipse_collision/app/incident_recorder.h"

namespace ellipse_collision::app {
namespace {

using core::GateAction;

GateDecision decisionOf(GateAction action) {
  GateDecision decision;
  decision.action = action;
  decision.reason = toString(action);
  return decision;
}

/// A check of one link and `count` obstacles, the i-th at x = i + shift.
CheckOutcome outcomeWith(std::size_t count, double shift = 0.0) {
  CheckOutcome outcome;
  outcome.placed.push_back("body", core::EllipseRole::Link,
                           core::Ellipse{{0.0, 0.0}, 0.5, 0.3, 0.0});
  for (std::size_t i = 0; i < count; ++i) {
    outcome.placed.push_back("o" + std::to_string(i), core::EllipseRole::Obstacle,
                             core::Ellipse{{static_cast<double>(i) + shift, 2.0}, 0.1, 0.1, 0.0});
  }
  outcome.complete = true;
  return outcome;
}

IncidentSettings settingsOf(double before_s, double after_s, double min_interval_s) {
  IncidentSettings settings;
  settings.before_s = before_s;
  settings.after_s = after_s;
  settings.min_interval_s = min_interval_s;
  return settings;
}

/// Records `action` at `now_s` on `outcome`.
void recordOn(IncidentRecorder& recorder, double now_s, GateAction action,
              const CheckOutcome& outcome) {
  DecisionScene scene;
  scene.outcome = &outcome;
  scene.robot.position = {now_s, 0.0};
  scene.source_ages = {{"obstacles", 0.25}};
  recorder.record(now_s, decisionOf(action), &scene);
}

TEST(IncidentRecorder, BufferKeepsOnlyTheLastBeforeSeconds) {
  IncidentRecorder recorder(settingsOf(1.0, 0.0, 0.0));
  const CheckOutcome outcome = outcomeWith(3);
  for (int i = 0; i <= 30; ++i) recordOn(recorder, 0.1 * i, GateAction::Pass, outcome);
  // At 3.0 s the buffer holds 2.0 s (kept: not older than 1 s) .. 3.0 s.
  EXPECT_GE(recorder.bufferedDecisions(), 10u);
  EXPECT_LE(recorder.bufferedDecisions(), 11u);
  ASSERT_TRUE(recorder.request(3.0));
  const std::vector<Incident> incidents = recorder.takeFinished(3.0);
  ASSERT_EQ(incidents.size(), 1u);
  const Incident& incident = incidents[0];
  EXPECT_EQ(incident.trigger, "REQUESTED");
  ASSERT_FALSE(incident.decisions.empty());
  EXPECT_GE(incident.decisions.front().stamp_s, 2.0 - 1e-9);
  EXPECT_DOUBLE_EQ(incident.decisions.back().stamp_s, 3.0);
  // What each judged: the link, the obstacles, the robot, the sources.
  const RecordedDecision& last = incident.decisions.back();
  EXPECT_TRUE(last.judged_scene);
  ASSERT_EQ(last.links.size(), 1u);
  EXPECT_EQ(last.links[0].name, "body");
  ASSERT_EQ(last.obstacles->obstacles.size(), 3u);
  EXPECT_EQ(last.obstacles->obstacles[2].name, "o2");
  EXPECT_DOUBLE_EQ(last.robot.position.x(), 3.0);
  ASSERT_EQ(last.source_ages.size(), 1u);
  EXPECT_DOUBLE_EQ(last.source_ages[0].second, 0.25);
}

TEST(IncidentRecorder, StillObstaclesAreStoredOncePerChange) {
  IncidentRecorder recorder(settingsOf(10.0, 0.0, 0.0));
  const CheckOutcome still = outcomeWith(1000);
  for (int i = 0; i < 50; ++i) recordOn(recorder, 0.05 * i, GateAction::Pass, still);
  EXPECT_EQ(recorder.bufferedDecisions(), 50u);
  EXPECT_EQ(recorder.storedObstacles(), 1000u);  // not 50,000
  const CheckOutcome moved = outcomeWith(1000, 0.5);
  for (int i = 50; i < 60; ++i) recordOn(recorder, 0.05 * i, GateAction::Pass, moved);
  EXPECT_EQ(recorder.storedObstacles(), 2000u);
  // A changed name with the same geometry is a change too.
  CheckOutcome renamed = outcomeWith(0);
  for (std::size_t i = 0; i < 1000; ++i) {
    renamed.placed.push_back(i == 999 ? "other" : "o" + std::to_string(i),
                             core::EllipseRole::Obstacle,
                             core::Ellipse{{static_cast<double>(i) + 0.5, 2.0}, 0.1, 0.1, 0.0});
  }
  recordOn(recorder, 3.0, GateAction::Pass, renamed);
  EXPECT_EQ(recorder.storedObstacles(), 3000u);

  ASSERT_TRUE(recorder.request(3.0));
  const std::vector<Incident> incidents = recorder.takeFinished(3.0);
  ASSERT_EQ(incidents.size(), 1u);
  const std::vector<RecordedDecision>& d = incidents[0].decisions;
  ASSERT_EQ(d.size(), 61u);
  EXPECT_EQ(d[0].obstacles, d[49].obstacles);  // shared, the same snapshot
  EXPECT_NE(d[49].obstacles->id, d[50].obstacles->id);
  EXPECT_EQ(d[50].obstacles, d[59].obstacles);
  EXPECT_DOUBLE_EQ(d[50].obstacles->obstacles[0].ellipse.center.x(), 0.5);
  EXPECT_EQ(d[60].obstacles->obstacles[999].name, "other");
}

TEST(IncidentRecorder, TheSameStandingGridIsTheSameObstacles) {
  IncidentRecorder recorder(settingsOf(10.0, 0.0, 0.0));
  CheckOutcome first = outcomeWith(10);
  first.standing = std::make_shared<const core::IndexedObstacles>();
  recordOn(recorder, 0.0, GateAction::Pass, first);
  // A grid is built from exactly its check's obstacles: the same grid is not compared again.
  CheckOutcome second = outcomeWith(10, 1.0);
  second.standing = first.standing;
  recordOn(recorder, 0.1, GateAction::Pass, second);
  EXPECT_EQ(recorder.storedObstacles(), 10u);
  // A new grid is compared, and its obstacles differ.
  second.standing = std::make_shared<const core::IndexedObstacles>();
  recordOn(recorder, 0.2, GateAction::Pass, second);
  EXPECT_EQ(recorder.storedObstacles(), 20u);
}

TEST(IncidentRecorder, ListedActionTriggersWithTheWindowAfterIt) {
  IncidentRecorder recorder(settingsOf(1.0, 0.5, 0.0));
  const CheckOutcome outcome = outcomeWith(2);
  for (int i = 0; i < 20; ++i) recordOn(recorder, 0.1 * i, GateAction::Pass, outcome);
  EXPECT_TRUE(recorder.takeFinished(1.9).empty());  // PASS and SLOW are not listed
  recordOn(recorder, 2.0, GateAction::Stop, outcome);
  recordOn(recorder, 2.2, GateAction::Stop, outcome);
  EXPECT_TRUE(recorder.takeFinished(2.3).empty());  // its after window still open
  recordOn(recorder, 2.4, GateAction::Pass, outcome);
  recordOn(recorder, 2.6, GateAction::Pass, outcome);  // past the window: not in it
  const std::vector<Incident> incidents = recorder.takeFinished(2.6);
  ASSERT_EQ(incidents.size(), 1u);
  EXPECT_EQ(incidents[0].trigger, "STOP");
  EXPECT_DOUBLE_EQ(incidents[0].trigger_s, 2.0);
  const std::vector<RecordedDecision>& d = incidents[0].decisions;
  EXPECT_GE(d.front().stamp_s, 1.0 - 1e-9);
  EXPECT_DOUBLE_EQ(d.back().stamp_s, 2.4);
  EXPECT_EQ(recorder.triggered(), 1u);
}

TEST(IncidentRecorder, TheWindowEndsWithoutFurtherDecisions) {
  IncidentRecorder recorder(settingsOf(1.0, 0.5, 0.0));
  const CheckOutcome outcome = outcomeWith(2);
  recordOn(recorder, 1.0, GateAction::Incomplete, outcome);
  EXPECT_TRUE(recorder.takeFinished(1.5).empty());
  EXPECT_EQ(recorder.takeFinished(1.51).size(), 1u);
}

TEST(IncidentRecorder, MinIntervalHoldsBackTriggersButNotRequests) {
  IncidentRecorder recorder(settingsOf(1.0, 0.0, 10.0));
  const CheckOutcome outcome = outcomeWith(2);
  recordOn(recorder, 0.0, GateAction::Stop, outcome);
  recordOn(recorder, 5.0, GateAction::Escape, outcome);
  recordOn(recorder, 9.9, GateAction::Timeout, outcome);
  EXPECT_EQ(recorder.takeFinished(9.9).size(), 1u);
  EXPECT_EQ(recorder.suppressed(), 2u);
  EXPECT_TRUE(recorder.request(9.95));
  EXPECT_EQ(recorder.takeFinished(9.95).size(), 1u);
  recordOn(recorder, 10.0, GateAction::Stop, outcome);
  EXPECT_EQ(recorder.takeFinished(10.0).size(), 1u);
  EXPECT_EQ(recorder.triggered(), 2u);
}

TEST(IncidentRecorder, ConfiguredActionsAloneTrigger) {
  IncidentSettings settings = settingsOf(1.0, 0.0, 0.0);
  settings.actions = {GateAction::Slow};
  IncidentRecorder recorder(settings);
  const CheckOutcome outcome = outcomeWith(2);
  recordOn(recorder, 0.0, GateAction::Stop, outcome);
  EXPECT_TRUE(recorder.takeFinished(0.0).empty());
  recordOn(recorder, 0.1, GateAction::Slow, outcome);
  const std::vector<Incident> incidents = recorder.takeFinished(0.1);
  ASSERT_EQ(incidents.size(), 1u);
  EXPECT_EQ(incidents[0].trigger, "SLOW");
}

TEST(IncidentRecorder, DecisionsWithoutASceneKeepTheLastObstacles) {
  IncidentRecorder recorder(settingsOf(1.0, 0.0, 0.0));
  const CheckOutcome outcome = outcomeWith(4);
  recordOn(recorder, 0.0, GateAction::Pass, outcome);
  recorder.record(0.5, decisionOf(GateAction::Timeout), nullptr);
  const std::vector<Incident> incidents = recorder.takeFinished(0.5);
  ASSERT_EQ(incidents.size(), 1u);
  const RecordedDecision& timeout = incidents[0].decisions.back();
  EXPECT_FALSE(timeout.judged_scene);
  EXPECT_TRUE(timeout.links.empty());
  EXPECT_EQ(timeout.obstacles, incidents[0].decisions.front().obstacles);
}

TEST(IncidentRecorder, DisabledRecordsNothing) {
  IncidentSettings settings = settingsOf(1.0, 0.0, 0.0);
  settings.enabled = false;
  IncidentRecorder recorder(settings);
  const CheckOutcome outcome = outcomeWith(2);
  recordOn(recorder, 0.0, GateAction::Stop, outcome);
  EXPECT_EQ(recorder.bufferedDecisions(), 0u);
  EXPECT_FALSE(recorder.request(0.0));
  EXPECT_TRUE(recorder.takeFinished(1.0).empty());
}

TEST(IncidentRecorder, TimeGoingBackForgetsTheBuffer) {
  IncidentRecorder recorder(settingsOf(10.0, 0.0, 100.0));
  const CheckOutcome outcome = outcomeWith(2);
  recordOn(recorder, 50.0, GateAction::Stop, outcome);
  EXPECT_EQ(recorder.takeFinished(50.0).size(), 1u);
  recordOn(recorder, 1.0, GateAction::Pass, outcome);
  EXPECT_EQ(recorder.bufferedDecisions(), 1u);
  // min_interval counts in the new run's time.
  recordOn(recorder, 2.0, GateAction::Stop, outcome);
  EXPECT_EQ(recorder.takeFinished(2.0).size(), 1u);
}

TEST(IncidentSettings, RangesAndActionsAreChecked) {
  EXPECT_FALSE(findInvalidIncidentSetting(IncidentSettings{}));
  IncidentSettings s;
  s.before_s = 0.0;
  EXPECT_EQ(findInvalidIncidentSetting(s)->key, "incident/before");
  s = {};
  s.after_s = std::nan("");
  EXPECT_EQ(findInvalidIncidentSetting(s)->key, "incident/after");
  s = {};
  s.min_interval_s = -1.0;
  EXPECT_EQ(findInvalidIncidentSetting(s)->key, "incident/min_interval");
  s = {};
  s.max_files = 0;
  EXPECT_EQ(findInvalidIncidentSetting(s)->key, "incident/max_files");
  s = {};
  s.max_megabytes = 0.0;
  EXPECT_EQ(findInvalidIncidentSetting(s)->key, "incident/max_megabytes");

  std::vector<GateAction> actions;
  EXPECT_FALSE(parseIncidentActions({"STOP", "SLOW"}, &actions));
  EXPECT_EQ(actions, (std::vector<GateAction>{GateAction::Stop, GateAction::Slow}));
  const auto unknown = parseIncidentActions({"STOP", "halt"}, &actions);
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->actual, "'halt'");
  const auto twice = parseIncidentActions({"STOP", "STOP"}, &actions);
  ASSERT_TRUE(twice);
  EXPECT_EQ(twice->actual, "'STOP' twice");
  EXPECT_TRUE(parseIncidentActions({}, &actions));
}

TEST(IncidentFiles, OldestAreRemovedFirstWithinCountAndSize) {
  const std::vector<IncidentFile> files = {{"incident_3.bag", 1000000},
                                           {"incident_1.bag", 1000000},
                                           {"incident_2.bag", 1000000},
                                           {"incident_4.bag", 1000000}};
  EXPECT_TRUE(incidentFilesToRemove(files, 4, 4.0).empty());
  EXPECT_EQ(incidentFilesToRemove(files, 2, 100.0),
            (std::vector<std::string>{"incident_1.bag", "incident_2.bag"}));
  EXPECT_EQ(incidentFilesToRemove(files, 10, 2.5),
            (std::vector<std::string>{"incident_1.bag", "incident_2.bag"}));
  // The newest is kept even when it alone is over the budget.
  EXPECT_EQ(incidentFilesToRemove(files, 1, 0.5),
            (std::vector<std::string>{"incident_1.bag", "incident_2.bag", "incident_3.bag"}));
}

TEST(IncidentFiles, NamesSortByTime) {
  EXPECT_EQ(incidentFileName(0.25, "STOP"), "incident_19700101T000000.250Z_STOP.bag");
  EXPECT_LT(incidentFileName(1795000000.0, "STOP"), incidentFileName(1795000000.5, "ESCAPE"));
  EXPECT_LT(incidentFileName(1795000009.9, "STOP"), incidentFileName(1795000010.0, "STOP"));
}

}  // namespace
}  // namespace ellipse_collision::app

// Several obstacle sources without a master: the source list's rules (src/app/obstacle_source.cpp),
// each source's messages replacing only its own obstacles in the registry, and the freshness rule
// in the monitor (a silent source makes answers incomplete and the gate INCOMPLETE, naming it; the
// rule on its own: test_source_freshness.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "ellipse_collision/app/obstacle_source.h"
#include "ellipse_collision/app/source_freshness.h"
#include "spec_builders.h"

namespace ellipse_collision::app {
namespace {

using test::circle;

SourceSpec source(const std::string& name, SourceType type, const std::string& topic,
                  double timeout_s) {
  SourceSpec spec;
  spec.name = name;
  spec.type = type;
  spec.topic = topic;
  spec.timeout_s = timeout_s;
  return spec;
}

/// "key = actual" of the first violation, or "" when the list is accepted.
std::string refusal(const std::vector<SourceSpec>& sources) {
  const auto invalid = findInvalidSources(sources);
  return invalid ? invalid->key + " = " + invalid->actual : "";
}

TEST(SourceList, EachViolationNamesTheEntryTheKeyAndTheValue) {
  const SourceSpec front = source("front_scan", SourceType::Scan, "front/scan", 0.5);
  const SourceSpec rear = source("rear_scan", SourceType::Scan, "rear/scan", 0.5);
  EXPECT_EQ(refusal({}), "");
  EXPECT_EQ(refusal({front, rear}), "");

  SourceSpec twin = rear;
  twin.name = "front_scan";
  EXPECT_EQ(refusal({front, twin}), "sources[1].name = 'front_scan', the name of sources[0]");
  SourceSpec same_topic = rear;
  same_topic.topic = "front/scan";
  EXPECT_EQ(refusal({front, same_topic}),
            "sources[1].topic = 'front/scan', the topic of sources[0]");
  SourceSpec default_name = rear;
  default_name.name = kDefaultSourceName;
  EXPECT_NE(refusal({default_name}).find("sources[0].name = 'obstacles'"), std::string::npos);
  SourceSpec default_topic = rear;
  default_topic.topic = "~obstacles";
  EXPECT_NE(refusal({default_topic}).find("sources[0].topic = '~obstacles'"), std::string::npos);

  const auto changed = [&](void (*change)(SourceSpec&)) {
    SourceSpec spec = front;
    change(spec);
    return refusal({spec});
  };
  EXPECT_EQ(changed([](SourceSpec& s) { s.name = ""; }), "sources[0].name = ''");
  EXPECT_EQ(changed([](SourceSpec& s) { s.name = "front/scan"; }),
            "sources[0].name = 'front/scan'");
  EXPECT_EQ(changed([](SourceSpec& s) { s.topic = ""; }), "sources[0].topic = ''");
  EXPECT_EQ(changed([](SourceSpec& s) { s.timeout_s = NAN; }), "sources[0].timeout = nan");
  EXPECT_EQ(changed([](SourceSpec& s) { s.timeout_s = INFINITY; }), "sources[0].timeout = inf");
  EXPECT_EQ(changed([](SourceSpec& s) { s.timeout_s = -0.1; }), "sources[0].timeout = -0.1");
  EXPECT_EQ(changed([](SourceSpec& s) { s.timeout_s = 0.0; }), "") << "0 = no watchdog";
  EXPECT_EQ(changed([](SourceSpec& s) { s.scan.min_radius = -1.0; }), "sources[0].min_radius = -1");
  EXPECT_EQ(changed([](SourceSpec& s) {
              s.type = SourceType::Ellipses;
              s.scan.min_radius = -1.0;
            }),
            "")
      << "scan settings are not an ellipses source's";
  for (const SourceType type : {SourceType::Cloud, SourceType::Range}) {
    SourceSpec spec = front;
    spec.type = type;
    spec.scan.min_radius = 0.0;
    EXPECT_EQ(refusal({spec}), "sources[0].min_radius = 0") << toString(type);
  }

  SourceType type = SourceType::Ellipses;
  for (const SourceType each :
       {SourceType::Ellipses, SourceType::Scan, SourceType::Cloud, SourceType::Range}) {
    EXPECT_FALSE(parseSourceType(toString(each), "sources[0].type", &type));
    EXPECT_EQ(type, each);
  }
  const auto unknown = parseSourceType("sonar", "sources[0].type", &type);
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->key, "sources[0].type");
  EXPECT_EQ(unknown->actual, "'sonar'");
}

TEST(SourceList, ObstacleNamesCarryTheSourceAndOnlyRequiredRobotsAreWatched) {
  EXPECT_EQ(sourceObstacleName("front_scan", "scan_0"), "front_scan/scan_0");
  EXPECT_NE(sourceObstacleName("front_scan", "scan_0"), sourceObstacleName("rear_scan", "scan_0"));
  SourceSpec robots = source("fleet", SourceType::Robots, "/fleet/footprints", 1.0);
  EXPECT_FALSE(watchesSilence(robots));
  robots.required = true;
  EXPECT_TRUE(watchesSilence(robots));
  for (const SourceType type :
       {SourceType::Ellipses, SourceType::Scan, SourceType::Cloud, SourceType::Range}) {
    EXPECT_TRUE(watchesSilence(source("s", type, "t", 0.0))) << toString(type);
  }
  robots.timeout_s = 0.0;
  EXPECT_EQ(refusal({robots}), "sources[0].timeout = 0")
      << "a robot without a timeout never leaves";
  SourceSpec tracked = source("front_scan", SourceType::Scan, "front/scan", 0.5);
  tracked.tracking.max_speed = NAN;
  EXPECT_EQ(refusal({tracked}), "sources[0].tracking/max_speed = nan");
  tracked.type = SourceType::Range;
  EXPECT_EQ(refusal({tracked}), "") << "a range source is not tracked";
}

TEST(SourceList, AMonitorRefusesAListThatBreaksTheRules) {
  MonitorSettings settings;
  settings.sources = {source("a", SourceType::Ellipses, "x", 0.0),
                      source("b", SourceType::Ellipses, "x", 0.0)};
  EXPECT_THROW(CollisionMonitor(settings, {}, {}, {}, {}), std::invalid_argument);
}

TEST(SourceRegistry, AMessageReplacesOnlyItsOwnSourcesObstacles) {
  EllipseRegistry registry({circle("base", "map", 0, 0, 0.1)}, {});
  ASSERT_EQ(registry.replaceTopicObstacles(
                {circle("a/1", "map", 1, 0, 0.1), circle("a/2", "map", 2, 0, 0.1)}, "a", 1.0, 1),
            "");
  ASSERT_EQ(registry.replaceTopicObstacles({circle("b/1", "map", 0, 1, 0.1)}, "b", 1.0, 2), "");
  ASSERT_EQ(registry.replaceTopicObstacles({circle("rock", "map", 5, 0, 0.1)}, "ellipses", 1.0),
            "");
  // Source a's next message has one obstacle: its second goes, b's and ~obstacles' stay.
  ASSERT_EQ(registry.replaceTopicObstacles({circle("a/1", "map", 1.5, 0, 0.1)}, "a", 2.0, 1), "");
  EXPECT_FALSE(registry.contains("a/2"));
  EXPECT_TRUE(registry.contains("b/1"));
  EXPECT_TRUE(registry.contains("rock"));
  EXPECT_DOUBLE_EQ(registry.entries().at("a/1").spec.x, 1.5);
  EXPECT_EQ(registry.topicCount(0), 1u);
  EXPECT_EQ(registry.topicCount(1), 1u);
  EXPECT_EQ(registry.topicCount(2), 1u);
  EXPECT_EQ(registry.count(EllipseSource::TopicObstacle), 3u);
  // An empty message of b clears b alone.
  ASSERT_EQ(registry.replaceTopicObstacles({}, "b", 3.0, 2), "");
  EXPECT_FALSE(registry.contains("b/1"));
  EXPECT_TRUE(registry.contains("a/1"));
  EXPECT_EQ(registry.topicCount(2), 0u);

  // A name of another source is refused whole, naming it; nothing changes.
  const std::string error =
      registry.replaceTopicObstacles({circle("a/1", "map", 9, 9, 0.1)}, "b", 4.0, 2);
  EXPECT_NE(error.find("b[0].name = 'a/1'"), std::string::npos) << error;
  EXPECT_NE(error.find("another source"), std::string::npos) << error;
  EXPECT_DOUBLE_EQ(registry.entries().at("a/1").spec.x, 1.5);

  // Only ~obstacles (source 0) is stored and expires by obstacle_timeout.
  const StoredObstacles stored = registry.runtimeObstacles();
  ASSERT_EQ(stored.topic.size(), 1u);
  EXPECT_EQ(stored.topic[0].name, "rock");
  EXPECT_EQ(registry.dropExpiredTopicObstacles(100.0, 1.0), 1u);
  EXPECT_FALSE(registry.contains("rock"));
  EXPECT_TRUE(registry.contains("a/1"));
}

TEST(SourceRegistry, TheLimitCountsEverySourcesObstacles) {
  RegistryLimits limits;
  limits.max_obstacles = 3;
  EllipseRegistry registry({}, {}, limits);
  ASSERT_EQ(registry.replaceTopicObstacles(
                {circle("a/1", "map", 1, 0, 0.1), circle("a/2", "map", 2, 0, 0.1)}, "a", 1.0, 1),
            "");
  EXPECT_NE(registry.replaceTopicObstacles(
                {circle("b/1", "map", 0, 1, 0.1), circle("b/2", "map", 0, 2, 0.1)}, "b", 1.0, 2),
            "");
  EXPECT_EQ(registry.replaceTopicObstacles({circle("b/1", "map", 0, 1, 0.1)}, "b", 1.0, 2), "");
  EXPECT_EQ(registry.replaceTopicObstacles(
                {circle("a/1", "map", 1, 0, 0.1), circle("a/2", "map", 2, 0, 0.1)}, "a", 2.0, 1),
            "")
      << "a's own obstacles are replaced, not added to";
}

MonitorSettings twoSources() {
  MonitorSettings settings;
  settings.check.fixed_frame = "map";
  settings.gate.enabled = true;
  settings.gate.timing.horizon = 3.0;
  settings.gate.timing.time_before_collision = 1.0;
  settings.gate.timing.stop_time = 0.3;
  settings.sources = {source("front_scan", SourceType::Scan, "front/scan", 0.5),
                      source("rear_scan", SourceType::Scan, "rear/scan", 0.5)};
  return settings;
}

TransformLookup everyFrameAtOrigin() {
  return [](const std::string&) {
    FrameTransform t;
    t.ok = true;
    return t;
  };
}

TransformAtLookup everyFrameAtOriginAt() {
  return [](const std::string&, double) {
    FrameTransform t;
    t.ok = true;
    return t;
  };
}

TEST(SourceFreshness, ASilentSourceMakesAnswersIncompleteAndTheGateIncompleteNamingIt) {
  CollisionMonitor monitor(twoSources(), {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
  const TransformLookup frames = everyFrameAtOrigin();
  const auto send = [&](std::size_t source, double now_s, double x) {
    return monitor.replaceSourceObstacles(source, {circle("scan_0", "map", x, 3.0, 0.1)}, now_s,
                                          now_s, frames);
  };
  VelocityCommand forward;
  forward.linear.x() = 0.2;
  for (double t = 1.0; t < 1.45; t += 0.1) {
    ASSERT_EQ(send(1, t, 1.0), "");
    ASSERT_EQ(send(2, t, -1.0), "");
  }
  const CheckOutcome& fresh = monitor.serviceCheck({}, 0.0, 1.5, frames, everyFrameAtOriginAt());
  EXPECT_TRUE(fresh.complete);
  EXPECT_TRUE(fresh.silent_sources.empty());
  EXPECT_TRUE(monitor.registry().contains("front_scan/scan_0"));
  EXPECT_TRUE(monitor.registry().contains("rear_scan/scan_0"));
  EXPECT_EQ(monitor.gateCommand(forward, 1.5, frames, everyFrameAtOriginAt()).action,
            GateAction::Pass);

  // The rear scanner stops; the front one goes on, and its obstacle moves.
  for (double t = 1.5; t < 2.25; t += 0.1) ASSERT_EQ(send(1, t, 1.0 + t), "");
  const CheckOutcome& blind = monitor.serviceCheck({}, 0.0, 2.2, frames, everyFrameAtOriginAt());
  EXPECT_FALSE(blind.complete);
  ASSERT_EQ(blind.silent_sources.size(), 1u);
  EXPECT_EQ(blind.silent_sources[0], "source 'rear_scan' silent for 0.8 s (timeout 0.5 s)");
  EXPECT_NEAR(monitor.registry().entries().at("front_scan/scan_0").spec.x, 3.2, 1e-9);
  EXPECT_TRUE(monitor.registry().contains("rear_scan/scan_0")) << "kept, not dropped";
  const GateDecision stopped = monitor.gateCommand(forward, 2.2, frames, everyFrameAtOriginAt());
  EXPECT_EQ(stopped.action, GateAction::Incomplete);
  EXPECT_NE(stopped.reason.find("source 'rear_scan' silent for 0.8 s"), std::string::npos)
      << stopped.reason;
  // ~check_path says so too: checked without what the rear scanner would have seen.
  PathCheckRequest path;
  path.poses.resize(2);
  path.poses[1].x = 0.5;
  const auto lookup_to = [&](const std::string&) { return frames; };
  const PathCheckOutcome blind_path = monitor.checkPath(path, 2.2, lookup_to);
  ASSERT_EQ(blind_path.error, "");
  EXPECT_FALSE(blind_path.complete());
  EXPECT_EQ(blind_path.silent_sources, blind.silent_sources);
  const CollisionMonitor::Health health = monitor.health(2.2);
  EXPECT_EQ(health.health.level, CheckHealth::Level::Error);
  const std::map<std::string, std::string> values(health.values.begin(), health.values.end());
  EXPECT_EQ(values.at("source 'rear_scan' age [s]"), "0.8");
  EXPECT_EQ(values.at("source 'front_scan' obstacles"), "1");
  EXPECT_EQ(values.at("source 'front_scan' rate [Hz]"), "10");
  EXPECT_EQ(values.at("source 'obstacles' age [s]"), "no message yet");

  // A partial check is incomplete too; the next rear message makes everything fresh again.
  CheckRequest partial;
  partial.names = {"body"};
  EXPECT_FALSE(monitor.serviceCheck(partial, 0.0, 2.2, frames, everyFrameAtOriginAt()).complete);
  ASSERT_EQ(send(2, 2.3, -1.0), "");
  EXPECT_TRUE(monitor.serviceCheck({}, 0.0, 2.3, frames, everyFrameAtOriginAt()).complete);
  EXPECT_EQ(monitor.gateCommand(forward, 2.3, frames, everyFrameAtOriginAt()).action,
            GateAction::Pass);
  EXPECT_TRUE(monitor.checkPath(path, 2.3, lookup_to).complete());
}

TEST(SourceFreshness, ARefusedMessageIsNotFreshAndIsReportedForItsSource) {
  CollisionMonitor monitor(twoSources(), {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
  const TransformLookup frames = everyFrameAtOrigin();
  app::EllipseSpec bad = circle("scan_0", "map", 1, 0, 0.1);
  bad.radius_x = NAN;
  const std::string error = monitor.replaceSourceObstacles(1, {bad}, 1.0, 1.0, frames);
  EXPECT_NE(error.find("source 'front_scan' ellipses[0].radius_x"), std::string::npos) << error;
  EXPECT_EQ(monitor.sourceFreshness().stats(1.0)[1].messages, 0u);
  monitor.periodicCheck(1.0, frames, everyFrameAtOriginAt());
  const std::string message = monitor.health(1.0).health.message;
  EXPECT_NE(message.find("last message refused: source 'front_scan'"), std::string::npos)
      << message;
  EXPECT_NE(monitor.replaceSourceObstacles(3, {}, 1.0, 1.0, frames), "") << "no such source";
}

TEST(RobotsSource, OtherRobotsKeepTheirNamesAndComeAndGoWithoutMakingAnswersIncomplete) {
  MonitorSettings settings = twoSources();
  settings.sources.push_back(source("robots", SourceType::Robots, "/fleet/footprints", 1.0));
  CollisionMonitor monitor(settings, {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
  const TransformLookup frames = everyFrameAtOrigin();
  for (std::size_t scanner : {1u, 2u}) {
    ASSERT_EQ(monitor.replaceSourceObstacles(scanner, {}, 5.0, 5.0, frames), "");
  }
  // Another robot's link 1.2 m ahead: standing, 0.5 m/s forward reaches it in 2.4 s (PASS).
  app::EllipseSpec other = circle("r2/front", "map", 1.8, 0.0, 0.3);
  ASSERT_EQ(monitor.replaceSourceObstacles(3, {other}, 1.0, 1.0, frames), "");
  EXPECT_TRUE(monitor.registry().contains("r2/front")) << "named as published, no source prefix";
  EXPECT_FALSE(monitor.registry().contains("robots/r2/front"));
  VelocityCommand forward;
  forward.linear.x() = 0.5;
  EXPECT_EQ(monitor.gateCommand(forward, 5.0, frames, everyFrameAtOriginAt()).action,
            GateAction::Pass);
  // Coming at the robot at 1 m/s, seen 0.1 s ago: contact in 0.73 s, sooner than
  // time_before_collision.
  other.vx = -1.0;
  ASSERT_EQ(monitor.replaceSourceObstacles(3, {other}, 4.9, 4.9, frames), "");
  const GateDecision decision = monitor.gateCommand(forward, 5.0, frames, everyFrameAtOriginAt());
  EXPECT_NE(decision.action, GateAction::Pass) << decision.reason;
  EXPECT_NE(decision.reason.find("r2/front"), std::string::npos) << decision.reason;
  // Four seconds without a footprint: the robots source is not silent, the answers complete.
  const CheckOutcome& later = monitor.serviceCheck({}, 0.0, 5.0, frames, everyFrameAtOriginAt());
  EXPECT_TRUE(later.complete) << (later.silent_sources.empty() ? "" : later.silent_sources[0]);
  // The roster dropped r2: its links go, and that drop is no message heard.
  ASSERT_EQ(monitor.replaceSourceObstacles(3, {}, 5.0, 5.0, frames, /*heard=*/false), "");
  EXPECT_FALSE(monitor.registry().contains("r2/front"));
  EXPECT_EQ(monitor.sourceFreshness().stats(5.0)[3].messages, 2u);
}

TEST(RobotsSource, AMovingFootprintIsJudgedWhereItsVelocityHasTakenItSinceItsStamp) {
  // The gate decides for now: another robot's link seen at its message's stamp has moved on by
  // its velocity since. A footprint 0.5 s old coming at 1 m/s from 2.313 m is judged as a fresh
  // one from 1.813 m (slowed to keep time_before_collision), and unlike a fresh one from 2.313 m.
  MonitorSettings settings = twoSources();
  settings.sources = {source("robots", SourceType::Robots, "/fleet/footprints", 1.0)};
  const TransformLookup frames = everyFrameAtOrigin();
  VelocityCommand forward;
  forward.linear.x() = 0.5;
  const auto decide = [&](double x, double stamp_s, double now_s) {
    CollisionMonitor monitor(settings, {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
    app::EllipseSpec other = circle("r2/front", "map", x, 0.0, 0.3);
    other.vx = -1.0;
    EXPECT_EQ(monitor.replaceSourceObstacles(1, {other}, stamp_s, stamp_s, frames), "");
    return monitor.gateCommand(forward, now_s, frames, everyFrameAtOriginAt());
  };
  const GateDecision old_footprint = decide(2.313, 9.5, 10.0);
  const GateDecision fresh_nearer = decide(1.813, 10.0, 10.0);
  const GateDecision fresh_same = decide(2.313, 10.0, 10.0);
  EXPECT_EQ(old_footprint.action, GateAction::Slow) << old_footprint.reason;
  EXPECT_EQ(old_footprint.action, fresh_nearer.action);
  EXPECT_EQ(old_footprint.scale, fresh_nearer.scale);
  EXPECT_NEAR(old_footprint.time_to_contact_s, fresh_nearer.time_to_contact_s, 1e-9);
  // Closing at 1 + 0.5 k m/s over 1.213 m keeps 1 s for k up to 0.426: 0.42 on the grid.
  EXPECT_NEAR(old_footprint.scale, 0.42, 1e-12);
  EXPECT_GT(fresh_same.scale, old_footprint.scale + 0.3) << fresh_same.reason;
  // A stamp ahead of the clock (another computer's) advances it by nothing.
  const GateDecision ahead = decide(2.313, 10.5, 10.0);
  EXPECT_EQ(ahead.scale, fresh_same.scale);
  EXPECT_EQ(ahead.time_to_contact_s, fresh_same.time_to_contact_s);
}

TEST(RobotsSource, ItsPaddingGrowsEveryOtherRobotsLinkForEveryCheckAndTheGate) {
  // Room for the other robot to stray from its straight line: a link of radius 0.3 m padded by
  // 0.2 m is judged as one of 0.5 m, by the check and the gate alike.
  MonitorSettings settings = twoSources();
  SourceSpec robots = source("robots", SourceType::Robots, "/fleet/footprints", 1.0);
  robots.padding_m = 0.2;
  settings.sources = {robots};
  CollisionMonitor monitor(settings, {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
  const TransformLookup frames = everyFrameAtOrigin();
  ASSERT_EQ(monitor.replaceSourceObstacles(1, {circle("r2/front", "map", 0.75, 0.0, 0.3)}, 10.0,
                                           10.0, frames),
            "");
  EXPECT_EQ(monitor.registry().entries().at("r2/front").spec.padding, 0.2);
  const CheckOutcome& outcome = monitor.serviceCheck({}, 0.0, 10.0, frames, everyFrameAtOriginAt());
  ASSERT_EQ(outcome.collisions.size(), 1u) << "0.75 m apart, 0.6 m of radii, 0.2 m of padding";
  VelocityCommand forward;
  forward.linear.x() = 0.2;
  EXPECT_EQ(monitor.gateCommand(forward, 10.0, frames, everyFrameAtOriginAt()).action,
            GateAction::Stop);
  // Without the padding the two stand 0.15 m apart.
  settings.sources[0].padding_m = 0.0;
  CollisionMonitor unpadded(settings, {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
  ASSERT_EQ(unpadded.replaceSourceObstacles(1, {circle("r2/front", "map", 0.75, 0.0, 0.3)}, 10.0,
                                            10.0, frames),
            "");
  EXPECT_TRUE(
      unpadded.serviceCheck({}, 0.0, 10.0, frames, everyFrameAtOriginAt()).collisions.empty());
}

TEST(RobotsSource, RequiredMakesItsSilenceIncomplete) {
  MonitorSettings settings;
  settings.check.fixed_frame = "map";
  SourceSpec robots = source("robots", SourceType::Robots, "/fleet/footprints", 1.0);
  robots.required = true;
  settings.sources = {robots};
  CollisionMonitor monitor(settings, {circle("body", "base_link", 0, 0, 0.3)}, {}, {}, {});
  const TransformLookup frames = everyFrameAtOrigin();
  ASSERT_EQ(monitor.replaceSourceObstacles(1, {circle("r2/front", "map", 3.0, 0.0, 0.3)}, 1.0, 1.0,
                                           frames),
            "");
  EXPECT_TRUE(monitor.serviceCheck({}, 0.0, 1.5, frames, everyFrameAtOriginAt()).complete);
  // Dropping the silent robot does not count as hearing from the fleet.
  ASSERT_EQ(monitor.replaceSourceObstacles(1, {}, 2.1, 2.1, frames, /*heard=*/false), "");
  const CheckOutcome& silent = monitor.serviceCheck({}, 0.0, 2.2, frames, everyFrameAtOriginAt());
  EXPECT_FALSE(silent.complete);
  ASSERT_EQ(silent.silent_sources.size(), 1u);
  EXPECT_EQ(silent.silent_sources[0], "source 'robots' silent for 1.2 s (timeout 1 s)");
}

TEST(RobotsSource, TheListsRulesForRobots) {
  SourceSpec robots = source("robots", SourceType::Robots, "/fleet/footprints", 0.0);
  EXPECT_EQ(refusal({robots}), "sources[0].timeout = 0") << "a robot must be able to leave";
  robots.timeout_s = 1.0;
  EXPECT_EQ(refusal({robots}), "");
  SourceSpec scan = source("front_scan", SourceType::Scan, "front/scan", 0.5);
  scan.required = true;
  EXPECT_EQ(refusal({robots, scan}), "sources[1].required = true");
  robots.padding_m = -0.01;
  EXPECT_EQ(refusal({robots}), "sources[0].padding = -0.01");
  robots.padding_m = 10.5;
  EXPECT_EQ(refusal({robots}), "sources[0].padding = 10.5");
  robots.padding_m = 0.1;
  EXPECT_EQ(refusal({robots}), "");
  scan.required = false;
  scan.padding_m = 0.1;
  EXPECT_EQ(refusal({robots, scan}), "sources[1].padding = 0.1") << "type robots only";
  SourceType type;
  EXPECT_FALSE(parseSourceType("robots", "type", &type));
  EXPECT_EQ(type, SourceType::Robots);
  EXPECT_STREQ(toString(SourceType::Robots), "robots");
}

}  // namespace
}  // namespace ellipse_collision::app

// app::CollisionMonitor without a master: the node's rules (which check is full, when the state is
// published, time jumps and expiry, the store's gate and its refusal to write over a user's file,
// typed errors, one transform lookup per frame per check) driven with transforms from a table.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "ellipse_collision/app/obstacle_store.h"
#include "spec_builders.h"
#include "temporary_store.h"

namespace ellipse_collision::app {
namespace {

using test::circle;

/// Frames translated in the plane, with their stamps; each lookup is counted per frame.
struct FrameTable {
  std::map<std::string, Eigen::Vector2d> offsets{{"map", {0, 0}}};
  std::map<std::string, double> stamps;
  mutable std::map<std::string, int> lookups;
  mutable std::map<std::string, int> lookups_at;

  FrameTransform get(const std::string& frame, Eigen::Vector2d shift = {0, 0}) const {
    FrameTransform t;
    const auto found = offsets.find(frame);
    if (found == offsets.end()) {
      t.error = "frame '" + frame + "' does not exist";
      return t;
    }
    t.ok = true;
    t.fixed_from_frame.translation() << found->second + shift, 0.0;
    const auto stamp = stamps.find(frame);
    if (stamp != stamps.end()) t.stamp_s = stamp->second;
    return t;
  }
  TransformLookup latest() const {
    return [this](const std::string& frame) {
      ++lookups[frame];
      return get(frame);
    };
  }
  /// 0.1 s earlier a stamped frame stood 0.1 m further back along x (1 m/s).
  TransformAtLookup at() const {
    return [this](const std::string& frame, double time_s) {
      ++lookups_at[frame];
      FrameTransform t = get(frame);
      const auto stamp = stamps.find(frame);
      if (t.ok && stamp != stamps.end()) {
        t = get(frame, {time_s - stamp->second, 0.0});
        t.stamp_s = time_s;
      }
      return t;
    };
  }
};

MonitorSettings mapSettings() {
  MonitorSettings settings;
  settings.check.fixed_frame = "map";
  return settings;
}

class MonitorStore : public test::TemporaryStore {
 protected:
  MonitorStore() : TemporaryStore("store") {}
  StoreOptions store() const { return {path_, "launch"}; }
  static std::string read(const std::string& path) {
    std::string text, error;
    bool missing = false;
    return readWholeFile(path, text, missing, error) ? text : "<missing>";
  }
};

TEST_F(MonitorStore, AStoreFileBreakingAFieldRuleIsRefusedNamingFileLineAndField) {
  StoredObstacles stored;
  stored.session = "launch";
  stored.service = {circle("box", "map", 1.0, 0.0, 0.2), circle("bad", "map", 2.0, 0.0, 0.2)};
  std::string text = serializeObstacles(stored);
  // A hand edit: bad's radius_x (the 4th number) becomes nan.
  const std::size_t at = text.find("service 3:bad 3:map 2 0 0 0.2");
  ASSERT_NE(at, std::string::npos) << text;
  text.replace(text.find("0.2", at), 3, "nan");
  ASSERT_EQ(writeFileAtomically(path_, text), "");

  CollisionMonitor monitor(mapSettings(), {circle("base", "map", 0.0, 0.0, 0.1)}, {}, {}, store());
  EXPECT_EQ(monitor.registry().count(EllipseSource::ServiceObstacle), 0u) << "nothing restored";
  bool named = false;
  for (const StartupNote& note : monitor.startupNotes()) {
    if (note.level == StartupNote::Level::Error && note.text.find(path_) != std::string::npos &&
        note.text.find("line 6") != std::string::npos &&
        note.text.find("service obstacle 'bad'.radius_x = nan") != std::string::npos) {
      named = true;
    }
  }
  EXPECT_TRUE(named) << "the note names the file, the line and the field";
  FrameTable frames;
  const CheckOutcome& outcome = monitor.periodicCheck(1.0, frames.latest(), frames.at());
  EXPECT_TRUE(outcome.complete) << "no degenerate obstacle skipped at every check";
}

TEST_F(MonitorStore, AStoreFileThatFitsNoPaddingIsRefusedAtRestore) {
  // Valid alone, but the launch's global padding takes the radius past the core's limit.
  StoredObstacles stored;
  stored.session = "launch";
  stored.service = {circle("huge", "map", 0.0, 0.0, core::kMaxRadius)};
  ASSERT_EQ(writeFileAtomically(path_, serializeObstacles(stored)), "");
  MonitorSettings settings = mapSettings();
  settings.check.global_padding_m = 1.0;
  CollisionMonitor monitor(settings, {}, {}, {}, store());
  EXPECT_EQ(monitor.registry().count(EllipseSource::ServiceObstacle), 0u);
  ASSERT_FALSE(monitor.startupNotes().empty());
  EXPECT_NE(monitor.startupNotes().back().text.find("service obstacle 'huge'.radius_x"),
            std::string::npos)
      << monitor.startupNotes().back().text;
}

TEST_F(MonitorStore, AFileThatIsNotAStoreIsNeverWrittenOver) {
  const std::string user_file = "my robot's calibration, not an obstacle store\n";
  ASSERT_EQ(writeFileAtomically(path_, user_file), "");
  CollisionMonitor monitor(mapSettings(), {circle("base", "map", 0.0, 0.0, 0.1)}, {}, {}, store());
  EXPECT_FALSE(monitor.storeEnabled());
  ASSERT_FALSE(monitor.startupNotes().empty());
  FrameTable frames;
  const ChangeAnswer added =
      monitor.addObstacles({circle("box", "map", 2.0, 0.0, 0.2)}, frames.latest());
  EXPECT_EQ(added.error_kind, ErrorKind::NotPersisted);
  EXPECT_NE(added.message.find("is not an obstacle store"), std::string::npos) << added.message;
  EXPECT_TRUE(monitor.registry().contains("box")) << "it serves on, in memory";
  monitor.replaceTopicObstacles({circle("rock", "map", 3.0, 0.0, 0.2)}, 1.0, frames.latest());
  monitor.writeStoreIfBehind();
  const ChangeAnswer removed = monitor.removeObstacles({"rock"});
  EXPECT_EQ(removed.error_kind, ErrorKind::NotPersisted);
  monitor.flushStore();
  EXPECT_EQ(read(path_), user_file);
  EXPECT_EQ(read(serviceRecordPath(path_)), "<missing>");
  // /diagnostics says so.
  const CollisionMonitor::Health health = monitor.health(2.0);
  EXPECT_NE(health.health.message.find("not an obstacle store"), std::string::npos)
      << health.health.message;
  EXPECT_NE(health.health.level, CheckHealth::Level::Ok);
}

TEST_F(MonitorStore, AServiceRecordThatIsNotOursIsNotWrittenOverEither) {
  const std::string user_file = "{\"json\": true}";
  ASSERT_EQ(writeFileAtomically(serviceRecordPath(path_), user_file), "");
  CollisionMonitor monitor(mapSettings(), {}, {}, {}, store());
  FrameTable frames;
  EXPECT_EQ(monitor.addObstacles({circle("box", "map", 2.0, 0.0, 0.2)}, frames.latest()).error_kind,
            ErrorKind::NotPersisted);
  monitor.flushStore();
  EXPECT_EQ(read(serviceRecordPath(path_)), user_file);
  EXPECT_EQ(read(path_), "<missing>");
}

TEST_F(MonitorStore, AnAcceptedAddIsDurableAndRestoredByTheNextMonitor) {
  FrameTable frames;
  {
    CollisionMonitor monitor(mapSettings(), {}, {}, {}, store());
    const ChangeAnswer added =
        monitor.addObstacles({circle("box", "map", 2.0, 0.0, 0.2)}, frames.latest());
    EXPECT_TRUE(added.success()) << added.message;
    EXPECT_EQ(added.message, "added 1 obstacle(s)");
  }
  CollisionMonitor restarted(mapSettings(), {}, {}, {}, store());
  EXPECT_TRUE(restarted.registry().contains("box"));
  ASSERT_FALSE(restarted.startupNotes().empty());
  EXPECT_EQ(restarted.startupNotes().back().level, StartupNote::Level::Warn);
}

TEST(CollisionMonitor, ErrorsCarryTheirKind) {
  CollisionMonitor monitor(mapSettings(), {circle("base", "map", 0.0, 0.0, 0.1)}, {}, {}, {});
  FrameTable frames;
  CheckRequest unknown_name;
  unknown_name.names = {"nobody"};
  EXPECT_EQ(monitor.serviceCheck(unknown_name, 0.0, 1.0, frames.latest(), frames.at()).error_kind,
            ErrorKind::InvalidRequest);
  CheckRequest unknown_frame;
  unknown_frame.query = {circle("probe", "nowhere", 0.0, 0.0, 0.1)};
  const CheckOutcome& outcome =
      monitor.serviceCheck(unknown_frame, 0.0, 1.0, frames.latest(), frames.at());
  EXPECT_EQ(outcome.error_kind, ErrorKind::FrameUnavailable);
  EXPECT_NE(outcome.error.find("query[0].frame_id = 'nowhere'"), std::string::npos);
  CheckRequest fine;
  fine.query = {circle("probe", "map", 0.15, 0.0, 0.1)};
  const CheckOutcome& answered = monitor.serviceCheck(fine, 0.0, 1.0, frames.latest(), frames.at());
  EXPECT_EQ(answered.error_kind, ErrorKind::None);
  EXPECT_EQ(answered.collisions.size(), 1u);
  EXPECT_EQ(monitor.addObstacles({circle("base", "map", 0, 0, 0.1)}, frames.latest()).error_kind,
            ErrorKind::InvalidRequest)
      << "a link's name";
  EXPECT_EQ(monitor.removeObstacles({"base"}).error_kind, ErrorKind::InvalidRequest);
  PathCheckRequest path;
  path.moving_frame = "nowhere";
  path.poses.resize(1);
  EXPECT_EQ(monitor.checkPath(path, 1.0, [&](const std::string&) { return frames.latest(); })
                .error_kind,
            ErrorKind::FrameUnavailable);
}

TEST(CollisionMonitor, OnlyAFullCheckIsRecordedAndItsPublishingFollowsTheRate) {
  FrameTable frames;
  for (const bool periodic : {true, false}) {
    MonitorSettings settings = mapSettings();
    settings.rate_hz = periodic ? 10.0 : 0.0;
    CollisionMonitor monitor(settings, {circle("base", "map", 0.0, 0.0, 0.1)},
                             {circle("post", "map", 0.15, 0.0, 0.1)}, {}, {});
    monitor.periodicCheck(1.0, frames.latest(), frames.at());
    EXPECT_TRUE(monitor.stateUpdated());
    EXPECT_EQ(monitor.statePublishing(), StatePublishing::Always);
    EXPECT_EQ(monitor.state().stamp_s, 1.0);

    CheckRequest partial;
    partial.names = {"post"};
    monitor.serviceCheck(partial, 0.0, 2.0, frames.latest(), frames.at());
    EXPECT_FALSE(monitor.stateUpdated()) << "a partial check is not the state";
    EXPECT_EQ(monitor.state().stamp_s, 1.0);
    monitor.serviceCheck({}, 1.5, 2.0, frames.latest(), frames.at());
    EXPECT_FALSE(monitor.stateUpdated()) << "nor a check at a stamp";

    const CheckOutcome& full = monitor.serviceCheck({}, 0.0, 3.0, frames.latest(), frames.at());
    EXPECT_TRUE(monitor.stateUpdated());
    EXPECT_EQ(&full, &monitor.state().outcome);
    EXPECT_EQ(monitor.state().stamp_s, 3.0);
    EXPECT_EQ(monitor.statePublishing(),
              periodic ? StatePublishing::OnChange : StatePublishing::Always)
        << periodic;
  }
}

TEST(CollisionMonitor, RetunedSettingsPassTheStartUpRulesAndTakeEffectAtTheNextCheck) {
  FrameTable frames;
  // base and post 0.1 m apart (circles of 0.1 m at x = 0 and 0.3).
  CollisionMonitor monitor(mapSettings(), {circle("base", "map", 0.0, 0.0, 0.1)},
                           {circle("post", "map", 0.3, 0.0, 0.1)}, {}, {});
  EXPECT_TRUE(monitor.periodicCheck(1.0, frames.latest(), frames.at()).warnings.empty());

  TunableSettings tunable = monitor.tunable();
  EXPECT_EQ(tunable.rate_hz, 10.0);
  tunable.warning_distance_m = 0.15;
  EXPECT_FALSE(monitor.retune(tunable));
  const CheckOutcome& warned = monitor.periodicCheck(2.0, frames.latest(), frames.at());
  ASSERT_EQ(warned.warnings.size(), 1u);
  EXPECT_NEAR(warned.warnings[0].distance, 0.1, 1e-12);
  tunable.padding_m = 0.06;  // 0.1 + 0.06 on each side: overlapping
  EXPECT_FALSE(monitor.retune(tunable));
  EXPECT_EQ(monitor.periodicCheck(3.0, frames.latest(), frames.at()).collisions.size(), 1u)
      << "a new padding re-projects the ellipses the cache held";

  // Refused whole, naming the key, as at start-up; nothing changes.
  const TunableSettings kept = monitor.tunable();
  const auto refuse = [&](TunableSettings bad, const std::string& key, const std::string& actual) {
    const std::optional<FieldError> error = monitor.retune(bad);
    ASSERT_TRUE(error) << key;
    EXPECT_EQ(error->key, key);
    EXPECT_EQ(error->actual, actual);
    EXPECT_EQ(describeTunable(monitor.tunable()), describeTunable(kept));
  };
  TunableSettings bad = kept;
  bad.rate_hz = -1.0;
  bad.warning_distance_m = 0.2;  // a good change beside a bad one is not taken either
  refuse(bad, "rate", "-1");
  bad = kept;
  bad.rate_hz = 5000.0;
  refuse(bad, "rate", "5000");
  bad = kept;
  bad.prediction_horizon_s = std::nan("");
  refuse(bad, "prediction_horizon", "nan");
  bad = kept;
  bad.gate.timing.stop_time = 2.0;  // above time_before_collision
  refuse(bad, "gate/stop_time", "2");
  bad = kept;
  bad.gate.robot_frame = "odom";
  refuse(bad, "gate/robot_frame", "'odom'");
  bad = kept;
  bad.padding_m = core::kMaxRadius;  // base's radius would leave the core's range
  refuse(bad, "padding", "1e+09");

  // The messages the node logs.
  TunableSettings changed = kept;
  changed.rate_hz = 2.0;
  changed.gate.enabled = true;
  EXPECT_EQ(describeTunableChanges(kept, changed), "rate 10 -> 2 Hz; gate/enabled false -> true");
  EXPECT_EQ(describeTunableChanges(kept, kept), "");
  EXPECT_FALSE(monitor.retune(changed));
  EXPECT_TRUE(monitor.gateEnabled());
  EXPECT_EQ(monitor.settings().rate_hz, 2.0);
}

TEST(CollisionMonitor, ATimeJumpBackIsPassedOnAndExpiredObstaclesDropped) {
  MonitorSettings settings = mapSettings();
  settings.obstacle_timeout_s = 0.5;
  std::vector<double> jumps;
  std::vector<std::size_t> expired;
  MonitorHooks hooks;
  hooks.time_jumped_back = [&](double seconds) { jumps.push_back(seconds); };
  hooks.obstacles_expired = [&](std::size_t count, double) { expired.push_back(count); };
  CollisionMonitor monitor(settings, {circle("base", "map", 0.0, 0.0, 0.1)}, {}, {}, {}, hooks);
  FrameTable frames;
  ASSERT_EQ(monitor.replaceTopicObstacles({circle("rock", "map", 3.0, 0.0, 0.2)}, 10.0,
                                          frames.latest()),
            "");
  monitor.periodicCheck(10.2, frames.latest(), frames.at());
  EXPECT_TRUE(monitor.registry().contains("rock"));
  monitor.periodicCheck(10.6, frames.latest(), frames.at());
  EXPECT_FALSE(monitor.registry().contains("rock"));
  EXPECT_EQ(expired, std::vector<std::size_t>{1});
  monitor.periodicCheck(4.0, frames.latest(), frames.at());
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_DOUBLE_EQ(jumps[0], 6.6);
  const CollisionMonitor::Health health = monitor.health(4.0);
  std::map<std::string, std::string> values(health.values.begin(), health.values.end());
  EXPECT_EQ(values["time jumps back"], "1");
  EXPECT_EQ(values["dropped obstacles (obstacle_timeout)"], "1");
  EXPECT_EQ(values["full checks"], "3");
  EXPECT_EQ(values["complete"], "true");
}

TEST(CollisionMonitor, AFrameMissingLongerThanASecondIsAnError) {
  CollisionMonitor monitor(mapSettings(), {circle("hand", "arm", 0.0, 0.0, 0.1)}, {}, {}, {});
  FrameTable frames;  // no "arm"
  monitor.periodicCheck(1.0, frames.latest(), frames.at());
  EXPECT_EQ(monitor.health(1.5).health.level, CheckHealth::Level::Warn);
  EXPECT_EQ(monitor.health(2.5).health.level, CheckHealth::Level::Error);
  frames.offsets["arm"] = {0, 0};
  monitor.periodicCheck(3.0, frames.latest(), frames.at());
  EXPECT_EQ(monitor.health(3.5).health.level, CheckHealth::Level::Ok);
}

TEST(CollisionMonitor, PredictionReusesTheCheckTransformsOneLookupPerFramePerCheck) {
  MonitorSettings settings = mapSettings();
  settings.prediction_horizon_s = 2.0;
  FrameTable frames;
  frames.offsets["arm"] = {0, 0};
  frames.stamps["arm"] = 10.0;
  // The arm moves at 1 m/s along x: hand and post 1.2 m apart (1.0 m of gap): contact in 1 s.
  CollisionMonitor monitor(settings, {circle("hand", "arm", 0.0, 0.0, 0.1)},
                           {circle("post", "map", 1.2, 0.0, 0.1),
                            circle("far", "map", 0.0, 5.0, 0.1)},
                           {}, {});
  for (int check = 0; check < 3; ++check) {
    frames.lookups.clear();
    frames.lookups_at.clear();
    const CheckOutcome& outcome = monitor.periodicCheck(10.0, frames.latest(), frames.at());
    ASSERT_EQ(outcome.predicted.size(), 1u);
    EXPECT_NEAR(outcome.predicted[0].time, 1.0, 1e-9);
    EXPECT_EQ(frames.lookups["arm"], 1) << "check " << check;
    EXPECT_EQ(frames.lookups["map"], check == 0 ? 1 : frames.lookups["map"]);
    EXPECT_LE(frames.lookups["map"], 1);
    EXPECT_EQ(frames.lookups_at["arm"], 1) << "the earlier pose, once per moving frame";
    EXPECT_EQ(frames.lookups_at["map"], 0) << "no earlier pose of a timeless frame";
  }
}

}  // namespace
}  // namespace ellipse_collision::app

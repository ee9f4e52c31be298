// The obstacle store a restarted node reads back (app/obstacle_store.h): exact round trips, refused
// corrupt text, atomic writes; and the registry's side (runtimeObstacles / restore). No master.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/obstacle_persistence.h"
#include "ellipse_collision/app/obstacle_store.h"
#include "temporary_store.h"

namespace ellipse_collision::app {
namespace {

EllipseSpec spec(const std::string& name, const std::string& frame, double x) {
  EllipseSpec s;
  s.name = name;
  s.frame_id = frame;
  s.x = x;
  s.y = -1.0 / 3.0;
  s.angle = 0.1;
  s.radius_x = 0.3;
  s.radius_y = 1e-9;
  s.padding = 0.05;
  s.vx = 0.25;
  s.vy = -1.0 / 7.0;
  s.angular_velocity = 3e-5;
  return s;
}

/// `s` as an ellipsoid (a point-cloud cluster standing on its side): numbers that need all 17
/// digits, and a roll of a quarter turn.
EllipseSpec tilted(EllipseSpec s) {
  s.ellipsoid = EllipsoidPart{0.7 / 3.0, 1.5707963267948966, -1.0 / 9.0, 0.45};
  return s;
}

bool same(const EllipseSpec& a, const EllipseSpec& b) {
  const bool same_part =
      a.ellipsoid.has_value() == b.ellipsoid.has_value() &&
      (!a.ellipsoid || (a.ellipsoid->z == b.ellipsoid->z && a.ellipsoid->roll == b.ellipsoid->roll &&
                        a.ellipsoid->pitch == b.ellipsoid->pitch &&
                        a.ellipsoid->radius_z == b.ellipsoid->radius_z));
  return a.name == b.name && a.frame_id == b.frame_id && a.x == b.x && a.y == b.y &&
         a.angle == b.angle && a.radius_x == b.radius_x && a.radius_y == b.radius_y &&
         a.padding == b.padding && a.vx == b.vx && a.vy == b.vy &&
         a.angular_velocity == b.angular_velocity && same_part;
}

TEST(ObstacleStore, RoundTripIsExactEvenForNamesWithSpacesColonsAndNewlines) {
  StoredObstacles stored;
  stored.session = "run 1:2";
  stored.service = {spec("a b:c", "map", 0.1), spec("line\nbreak\n", "odom", -999999999.87654321)};
  stored.topic = {spec("rock", "base_link", -2.5)};
  stored.topic_stamp_s = 1795404665.586293518;
  StoredObstacles back;
  ASSERT_EQ(parseObstacles(serializeObstacles(stored), back), "");
  EXPECT_EQ(back.session, stored.session);
  ASSERT_EQ(back.service.size(), 2u);
  EXPECT_TRUE(same(back.service[0], stored.service[0]));
  EXPECT_TRUE(same(back.service[1], stored.service[1]));
  ASSERT_EQ(back.topic.size(), 1u);
  EXPECT_TRUE(same(back.topic[0], stored.topic[0]));
  EXPECT_EQ(back.topic_stamp_s, stored.topic_stamp_s);
}

TEST(ObstacleStore, EllipsoidRoundTripsAndAPlanarRecordIsWrittenAsBefore) {
  StoredObstacles stored;
  stored.session = "launch";
  stored.service = {spec("a", "map", 0.1), tilted(spec("slab", "odom", 2.0))};
  stored.topic = {tilted(spec("cluster", "base_link", -1.0))};
  const std::string text = serializeObstacles(stored);
  // The planar record is the very line written before ellipsoids; the ellipsoid's four follow
  // its velocities, shortest round-trip numbers too.
  EXPECT_NE(text.find("service 1:a 3:map 0.1 -0.3333333333333333 0.1 0.3 1e-09 0.05 0.25 "
                      "-0.14285714285714285 3e-05\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("service 4:slab 4:odom 2 -0.3333333333333333 0.1 0.3 1e-09 0.05 0.25 "
                      "-0.14285714285714285 3e-05 0.2333333333333333 1.5707963267948966 "
                      "-0.1111111111111111 0.45\n"),
            std::string::npos)
      << text;
  StoredObstacles back;
  ASSERT_EQ(parseObstacles(text, back), "");
  ASSERT_EQ(back.service.size(), 2u);
  EXPECT_FALSE(back.service[0].ellipsoid);
  ASSERT_TRUE(back.service[1].ellipsoid);
  EXPECT_TRUE(same(back.service[0], stored.service[0]));
  EXPECT_TRUE(same(back.service[1], stored.service[1]));
  ASSERT_EQ(back.topic.size(), 1u);
  EXPECT_TRUE(same(back.topic[0], stored.topic[0]));
  EXPECT_EQ(serializeObstacles(back), text);
}

TEST(ObstacleStore, AnEllipsoidRecordBreakingTheFieldRulesRefusesTheFile) {
  StoredObstacles out;
  const std::string head = "ellipse_collision obstacle store 1\nsession 1:s\n";
  // A roll without radius_z, and a negative radius_z: named as the services name them.
  EXPECT_EQ(parseObstacles(head + "service 1:a 3:map 1 2 0 0.5 0.5 0 0 0 0 0 1 0 0\nend\n", out),
            "record 3 (line 3): service obstacle 'a'.roll = 1: expected 0 when radius_z = 0 (a "
            "planar ellipse); z, roll and pitch describe an ellipsoid, which needs radius_z > 0");
  EXPECT_EQ(parseObstacles(head + "topic 1:a 3:map 1 2 0 0.5 0.5 0 0 0 0 0 0 0 -1\nend\n", out),
            "record 3 (line 3): topic obstacle 'a'.radius_z = -1: expected a finite number > 0");
  // Ten to twelve numbers are neither record.
  EXPECT_EQ(parseObstacles(head + "service 1:a 3:map 1 2 0 0.5 0.5 0 0 0 0 0.1\nend\n", out)
                .rfind("record 3: expected service <name> <frame>", 0),
            0u);
}

TEST(ObstacleStore, NumbersAreWrittenShortestAndStoresWithSeventeenDigitsStillRead) {
  StoredObstacles stored;
  stored.service = {spec("a", "map", 0.1)};
  const std::string text = serializeObstacles(stored);
  EXPECT_NE(text.find(" 0.1 -0.3333333333333333 0.1 0.3 1e-09 0.05 0.25 -0.14285714285714285 3e-05\n"),
            std::string::npos)
      << text;
  // The form written before (printf's %.17g) reads back to the very same doubles.
  StoredObstacles back;
  ASSERT_EQ(parseObstacles("ellipse_collision obstacle store 1\nsession 0:\n"
                           "topic_stamp 1795404665.5862935\n"
                           "service 1:a 3:map 0.10000000000000001 -0.33333333333333331 "
                           "0.10000000000000001 0.29999999999999999 1.0000000000000001e-09 "
                           "0.050000000000000003 0.25 -0.14285714285714285 3.0000000000000001e-05\n"
                           "end\n",
                           back),
            "");
  ASSERT_EQ(back.service.size(), 1u);
  EXPECT_TRUE(same(back.service[0], stored.service[0]));
  EXPECT_EQ(back.topic_stamp_s, 1795404665.5862935);
}

// Version 1 is what a node from before ellipsoid obstacles reads: a store without ellipsoids keeps
// it, so that such a node still reads the store after a downgrade; one with an ellipsoid is 2, so
// that such a node refuses it at the header and not at a record it cannot read.
TEST(ObstacleStore, TheHeaderNamesVersionTwoOnlyWhenAnEllipsoidIsStored) {
  StoredObstacles planar;
  planar.session = "launch";
  planar.service = {spec("a", "map", 0.1)};
  planar.topic = {spec("b", "odom", 0.2)};
  EXPECT_EQ(serializeObstacles(planar).rfind("ellipse_collision obstacle store 1\n", 0), 0u);
  for (const bool in_topic : {false, true}) {
    StoredObstacles mixed = planar;
    (in_topic ? mixed.topic : mixed.service).push_back(tilted(spec("slab", "odom", 2.0)));
    const std::string text = serializeObstacles(mixed);
    EXPECT_EQ(text.rfind("ellipse_collision obstacle store 2\n", 0), 0u) << text;
    StoredObstacles back;
    ASSERT_EQ(parseObstacles(text, back), "");
    EXPECT_EQ(serializeObstacles(back), text);
    // A store written with ellipsoids under the version-1 header (this package did so before the
    // header told them apart) reads the same.
    StoredObstacles old_header;
    ASSERT_EQ(parseObstacles("ellipse_collision obstacle store 1" + text.substr(text.find('\n')),
                             old_header),
              "");
    EXPECT_EQ(serializeObstacles(old_header), text);
  }
  StoredObstacles out;
  EXPECT_EQ(parseObstacles("ellipse_collision obstacle store 3\nsession 1:s\nend\n", out),
            "record 1: 'ellipse_collision obstacle store 3' is a version this node does not read "
            "(it reads versions 1 to 2): written by a newer ellipse_collision?");
}

TEST(ObstacleStore, CorruptTextIsRefusedWithTheLine) {
  StoredObstacles out;
  out.session = "kept";
  EXPECT_EQ(parseObstacles("", out), "empty file");
  EXPECT_EQ(parseObstacles("garbage\n", out),
            "record 1: expected 'ellipse_collision obstacle store 1' or "
            "'ellipse_collision obstacle store 2'");
  const std::string good = serializeObstacles({"s", {spec("a", "map", 1.0)}, {}, 0.0});
  EXPECT_EQ(parseObstacles(good.substr(0, good.size() - 4), out), "truncated: no 'end' record");
  // Cut inside the obstacle's record.
  EXPECT_EQ(parseObstacles(good.substr(0, good.find("service 1:a") + 15), out).rfind("record", 0),
            0u);
  EXPECT_EQ(parseObstacles("ellipse_collision obstacle store 1\nservice 9:a map 1\nend\n", out),
            "record 2: expected service <name> <frame> x y angle radius_x radius_y padding "
            "[vx vy angular_velocity [z roll pitch radius_z]]");
  // A store written before the velocities: the obstacle stands still.
  StoredObstacles old_store;
  ASSERT_EQ(
      parseObstacles("ellipse_collision obstacle store 1\nservice 1:a 3:map 1 2 0 0.5 0.5 0\nend\n",
                     old_store),
      "");
  ASSERT_EQ(old_store.service.size(), 1u);
  EXPECT_EQ(old_store.service[0].vx, 0.0);
  EXPECT_EQ(old_store.service[0].radius_x, 0.5);
  EXPECT_NE(parseObstacles(
                "ellipse_collision obstacle store 1\nservice 1:a 3:map 1 2 0 0.5 0.5 0 1\nend\n",
                old_store),
            "")
      << "velocities are all three or none";
  EXPECT_EQ(parseObstacles("ellipse_collision obstacle store 1\nfoo\nend\n", out),
            "record 2: unknown entry 'foo'");
  EXPECT_EQ(parseObstacles(good + "x", out), "record 6: expected nothing after 'end'");
  for (const char* revision : {"-1", "1.5", "x", "", "12345678901234567890"}) {
    EXPECT_EQ(parseObstacles("ellipse_collision obstacle store 1\nservice_revision " +
                                 std::string(revision) + "\nend\n",
                             out),
              "record 2: expected service_revision <count>")
        << revision;
  }
  EXPECT_EQ(out.session, "kept") << "left untouched on failure";
}

TEST(ObstacleStore, ServiceRevisionRoundTripsAndOlderStoresReadZero) {
  StoredObstacles stored;
  stored.session = "s";
  stored.service_revision = 18446744073709551ull;
  StoredObstacles back;
  ASSERT_EQ(parseObstacles(serializeObstacles(stored), back), "");
  EXPECT_EQ(back.service_revision, stored.service_revision);
  ASSERT_EQ(parseObstacles("ellipse_collision obstacle store 1\nsession 1:s\nend\n", back), "");
  EXPECT_EQ(back.service_revision, 0u) << "a store written before the service record";
}

TEST(ObstacleStore, ANewerServiceRecordOfTheSameLaunchReplacesTheServiceObstacles) {
  StoredObstacles store;
  store.session = "launch";
  store.service_revision = 4;
  store.service = {spec("old", "map", 1.0)};
  store.topic = {spec("rock", "map", 2.0), spec("reused", "map", 3.0)};
  store.topic_stamp_s = 9.0;
  StoredObstacles record;
  record.session = "launch";
  record.service_revision = 5;
  record.service = {spec("new", "map", 4.0), spec("reused", "odom", 5.0)};

  StoredObstacles applied = store;
  ASSERT_TRUE(applyNewerServiceRecord(applied, record));
  ASSERT_EQ(applied.service.size(), 2u);
  EXPECT_TRUE(same(applied.service[0], record.service[0]));
  EXPECT_TRUE(same(applied.service[1], record.service[1]));
  // The topic obstacle under a name the service took later was gone when the record was made.
  ASSERT_EQ(applied.topic.size(), 1u);
  EXPECT_EQ(applied.topic[0].name, "rock");
  EXPECT_EQ(applied.topic_stamp_s, 9.0);
  EXPECT_EQ(applied.service_revision, 5u);

  for (const auto& [session, revision] :
       std::vector<std::pair<std::string, std::uint64_t>>{{"launch", 4}, {"launch", 3}, {"other", 9}}) {
    StoredObstacles kept = store;
    record.session = session;
    record.service_revision = revision;
    EXPECT_FALSE(applyNewerServiceRecord(kept, record)) << session << " " << revision;
    ASSERT_EQ(kept.service.size(), 1u);
    EXPECT_EQ(kept.service[0].name, "old");
    EXPECT_EQ(kept.topic.size(), 2u);
  }
}

/// A store in a directory of its own, removed with what is in it.
class StoreDirectory : public test::TemporaryStore {
 protected:
  StoreDirectory() : TemporaryStore("store") {}
  void write(const std::string& path, const StoredObstacles& stored) {
    ASSERT_EQ(writeFileAtomically(path, serializeObstacles(stored)), "");
  }
};

TEST_F(StoreDirectory, LoadUsesEachFileOfThisLaunchAndSaysWhyAnotherIsLeftOut) {
  LoadedStore nothing = loadObstacleStore(path_, "launch");
  EXPECT_FALSE(nothing.found);
  EXPECT_TRUE(nothing.notes.empty()) << "missing files are no news";

  StoredObstacles store;
  store.session = "launch";
  store.service_revision = 2;
  store.service = {spec("old", "map", 1.0)};
  store.topic = {spec("rock", "map", 2.0)};
  StoredObstacles record;
  record.session = "launch";
  record.service_revision = 3;
  record.service = {spec("new", "map", 4.0)};

  // The record alone (no periodic write yet in this launch).
  write(serviceRecordPath(path_), record);
  LoadedStore alone = loadObstacleStore(path_, "launch");
  ASSERT_TRUE(alone.found);
  ASSERT_EQ(alone.obstacles.service.size(), 1u);
  EXPECT_EQ(alone.obstacles.service[0].name, "new");
  EXPECT_EQ(alone.obstacles.service_revision, 3u);

  // Both: the newer record's service obstacles over the store's topic obstacles.
  write(path_, store);
  LoadedStore both = loadObstacleStore(path_, "launch");
  ASSERT_TRUE(both.found);
  ASSERT_EQ(both.obstacles.service.size(), 1u);
  EXPECT_EQ(both.obstacles.service[0].name, "new");
  ASSERT_EQ(both.obstacles.topic.size(), 1u);
  EXPECT_TRUE(both.notes.empty());

  // A store written after the record holds the service obstacles itself.
  store.service_revision = 3;
  write(path_, store);
  LoadedStore newer_store = loadObstacleStore(path_, "launch");
  ASSERT_EQ(newer_store.obstacles.service.size(), 1u);
  EXPECT_EQ(newer_store.obstacles.service[0].name, "old");

  // A store of another launch is left out (not an error), the record still counts.
  store.session = "earlier";
  write(path_, store);
  LoadedStore foreign = loadObstacleStore(path_, "launch");
  ASSERT_TRUE(foreign.found);
  EXPECT_TRUE(foreign.obstacles.topic.empty());
  ASSERT_EQ(foreign.notes.size(), 1u);
  EXPECT_FALSE(foreign.notes[0].failed);
  EXPECT_NE(foreign.notes[0].text.find("run_id 'earlier'"), std::string::npos);

  // A corrupt record is an error, and the store is used alone.
  store.session = "launch";
  write(path_, store);
  ASSERT_EQ(writeFileAtomically(serviceRecordPath(path_), "ellipse_collision obstacle store 1\n"),
            "");
  LoadedStore corrupt = loadObstacleStore(path_, "launch");
  ASSERT_TRUE(corrupt.found);
  EXPECT_EQ(corrupt.obstacles.service[0].name, "old");
  ASSERT_EQ(corrupt.notes.size(), 1u);
  EXPECT_TRUE(corrupt.notes[0].failed);
  EXPECT_NE(corrupt.notes[0].text.find("is corrupt"), std::string::npos);
}

/// The node's way of keeping the store (app::ObstaclePersistence, as CollisionNode uses it),
/// against a live registry: service calls that change only service obstacles write the record,
/// one that removes a topic obstacle writes the whole store, topic messages write the whole store
/// some time later (or not before the crash). At any crash the registry restored from the files
/// has exactly the live service obstacles, and the topic obstacles of the last whole store
/// written, less those the service took over since.
TEST_F(StoreDirectory, WhatIsRestoredAfterAnyCrashIsEveryAcknowledgedServiceChange) {
  std::mt19937 rng(16);
  const auto name = [&rng](const char* prefix) {
    return std::string(prefix) + std::to_string(std::uniform_int_distribution<int>(0, 7)(rng));
  };
  for (int trial = 0; trial < 200; ++trial) {
    std::remove(path_.c_str());
    std::remove(serviceRecordPath(path_).c_str());
    EllipseRegistry live({spec("arm", "map", 0.0)}, {});
    ObstaclePersistence persistence(path_, "launch", 0);
    StoredObstacles last_store;  // the topic obstacles of the last whole store, as documented
    const int steps = std::uniform_int_distribution<int>(1, 30)(rng);
    for (int step = 0; step < steps; ++step) {
      const int action = std::uniform_int_distribution<int>(0, 3)(rng);
      if (action == 0) {  // ~add_obstacles
        const std::string added = name(rng() % 2 == 0 ? "t" : "s");
        if (live.addObstacles({spec(added, "map", step)}, "o") != "") continue;
        ASSERT_EQ(persistence.afterServiceCall(live, false), "");
      } else if (action == 1) {  // ~remove_obstacles
        std::vector<std::string> names = {name(rng() % 2 == 0 ? "t" : "s")};
        if (rng() % 3 == 0) names.push_back(name("s"));  // a topic and a service obstacle at once
        const bool removes_topic_obstacle = live.anyTopicObstacle(names);
        if (live.removeObstacles(names, "n") != "") continue;
        if (removes_topic_obstacle) last_store = live.runtimeObstacles();
        ASSERT_EQ(persistence.afterServiceCall(live, removes_topic_obstacle), "");
      } else if (action == 2) {  // an ~obstacles message
        std::vector<EllipseSpec> topic;
        for (int k = std::uniform_int_distribution<int>(0, 3)(rng); k > 0; --k) {
          topic.push_back(spec(name("t"), "map", k));
        }
        std::sort(topic.begin(), topic.end(),
                  [](const EllipseSpec& a, const EllipseSpec& b) { return a.name < b.name; });
        topic.erase(std::unique(topic.begin(), topic.end(),
                                [](const EllipseSpec& a, const EllipseSpec& b) {
                                  return a.name == b.name;
                                }),
                    topic.end());
        if (live.replaceTopicObstacles(topic, "e", step) == "") persistence.topicChanged();
      } else {  // the periodic write
        if (persistence.behind()) last_store = live.runtimeObstacles();
        persistence.writeIfBehind(live);
        persistence.flush();
        ASSERT_FALSE(persistence.behind());
        ASSERT_EQ(persistence.lastError(), "");
      }
    }

    // The crash: a new registry restores what is on disk.
    const LoadedStore loaded = loadObstacleStore(path_, "launch");
    EllipseRegistry restarted({spec("arm", "map", 0.0)}, {});
    if (loaded.found) {
      ASSERT_EQ(restarted.restore(loaded.obstacles), "") << "trial " << trial;
    }
    const StoredObstacles expected_service = live.serviceObstacles();
    const StoredObstacles restored = restarted.runtimeObstacles();
    ASSERT_EQ(restored.service.size(), expected_service.service.size()) << "trial " << trial;
    for (std::size_t i = 0; i < restored.service.size(); ++i) {
      EXPECT_TRUE(same(restored.service[i], expected_service.service[i])) << "trial " << trial;
    }
    std::vector<std::string> expected_topic;
    for (const EllipseSpec& topic : last_store.topic) {
      if (!live.contains(topic.name) ||
          live.entries().at(topic.name).source != EllipseSource::ServiceObstacle) {
        expected_topic.push_back(topic.name);
      }
    }
    std::vector<std::string> restored_topic;
    for (const EllipseSpec& topic : restored.topic) restored_topic.push_back(topic.name);
    EXPECT_EQ(restored_topic, expected_topic) << "trial " << trial;
  }
}

TEST_F(StoreDirectory, EllipsoidObstaclesComeBackAfterARestartAndArePlacedAsBefore) {
  // A service and a topic obstacle, both ellipsoids, written as the node writes them and read as
  // a restarted node reads them: the restored registry places them exactly where the live one
  // did, through a frame tilted 60 degrees where a planar reading would differ.
  EllipseRegistry live({spec("arm", "map", 0.0)}, {});
  ObstaclePersistence persistence(path_, "launch", 0);
  ASSERT_EQ(live.replaceTopicObstacles({tilted(spec("cluster", "map", 3.0))}, "e", 5.0), "");
  persistence.topicChanged();
  persistence.writeIfBehind(live);
  persistence.flush();
  ASSERT_EQ(live.addObstacles({tilted(spec("slab", "map", 1.0))}, "o"), "");
  ASSERT_EQ(persistence.afterServiceCall(live, false), "");

  const LoadedStore loaded = loadObstacleStore(path_, "launch");
  ASSERT_TRUE(loaded.found);
  EllipseRegistry restarted({spec("arm", "map", 0.0)}, {});
  ASSERT_EQ(restarted.restore(loaded.obstacles), "");
  Eigen::Isometry3d tilt = Eigen::Isometry3d::Identity();
  tilt.linear() = Eigen::AngleAxisd(1.0471975511965976, Eigen::Vector3d::UnitX()).toRotationMatrix();
  for (const char* name : {"slab", "cluster"}) {
    SCOPED_TRACE(name);
    const EllipseSpec& before = live.entries().at(name).spec;
    const EllipseSpec& after = restarted.entries().at(name).spec;
    EXPECT_EQ(restarted.entries().at(name).source, live.entries().at(name).source);
    ASSERT_TRUE(after.ellipsoid);
    EXPECT_TRUE(same(after, before));
    const core::ProjectionResult was = placeInPlane(before, 0.02, tilt);
    const core::ProjectionResult is = placeInPlane(after, 0.02, tilt);
    ASSERT_TRUE(was.ok() && is.ok()) << was.error << is.error;
    EXPECT_EQ(is.ellipse.center, was.ellipse.center);
    EXPECT_EQ(is.ellipse.radius_x, was.ellipse.radius_x);
    EXPECT_EQ(is.ellipse.radius_y, was.ellipse.radius_y);
    EXPECT_EQ(is.ellipse.angle, was.ellipse.angle);
    EllipseSpec planar = before;
    planar.ellipsoid.reset();
    EXPECT_NE(placeInPlane(planar, 0.02, tilt).ellipse.radius_y, is.ellipse.radius_y);
  }
}

TEST_F(StoreDirectory, AtomicWriteReplacesTheFile) {
  const std::string& path = path_;
  std::string text, error;
  bool missing = false;
  EXPECT_FALSE(readWholeFile(path, text, missing, error));
  EXPECT_TRUE(missing);
  ASSERT_EQ(writeFileAtomically(path, "one"), "");
  ASSERT_EQ(writeFileAtomically(path, "two"), "");
  ASSERT_TRUE(readWholeFile(path, text, missing, error));
  EXPECT_EQ(text, "two");
  EXPECT_NE(writeFileAtomically(std::string(directory_) + "/no/such/dir/store", "x").find("cannot create"),
            std::string::npos);
}

TEST(ObstacleStore, RegistryRestoresItsRuntimeObstacles) {
  EllipseRegistry registry({spec("arm", "map", 0.0)}, {spec("table", "map", 0.0)});
  ASSERT_EQ(registry.addObstacles({spec("box", "map", 1.0), spec("table", "map", 2.0)}, "o"), "");
  ASSERT_EQ(registry.replaceTopicObstacles({spec("rock", "map", 3.0)}, "e", 42.0), "");
  const StoredObstacles stored = registry.runtimeObstacles();
  EXPECT_EQ(stored.service.size(), 2u);  // box, and the configured table replaced by the service
  EXPECT_EQ(stored.topic.size(), 1u);
  EXPECT_EQ(stored.topic_stamp_s, 42.0);

  EllipseRegistry restarted({spec("arm", "map", 0.0)}, {spec("table", "map", 0.0)});
  ASSERT_EQ(restarted.restore(stored), "");
  EXPECT_EQ(restarted.count(EllipseSource::ServiceObstacle), 2u);
  EXPECT_EQ(restarted.entries().at("table").spec.x, 2.0);
  EXPECT_EQ(restarted.count(EllipseSource::TopicObstacle), 1u);
  EXPECT_EQ(restarted.topicStamp(), 42.0);

  // A store that clashes with the new configuration (a link now called box) is refused whole.
  EllipseRegistry changed({spec("box", "map", 0.0)}, {});
  EXPECT_NE(changed.restore(stored), "");
  EXPECT_EQ(changed.count(EllipseSource::ServiceObstacle), 0u);
  EXPECT_EQ(changed.count(EllipseSource::TopicObstacle), 0u);
}

}  // namespace
}  // namespace ellipse_collision::app

// The obstacle store a restarted node reads back (app/obstacle_store.h): exact round trips, refused
// corrupt text, atomic writes; and the registry's side (runtimeObstacles / restore). No master.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/obstacle_store.h"

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

bool same(const EllipseSpec& a, const EllipseSpec& b) {
  return a.name == b.name && a.frame_id == b.frame_id && a.x == b.x && a.y == b.y &&
         a.angle == b.angle && a.radius_x == b.radius_x && a.radius_y == b.radius_y &&
         a.padding == b.padding && a.vx == b.vx && a.vy == b.vy &&
         a.angular_velocity == b.angular_velocity;
}

TEST(ObstacleStore, RoundTripIsExactEvenForNamesWithSpacesColonsAndNewlines) {
  StoredObstacles stored;
  stored.session = "run 1:2";
  stored.service = {spec("a b:c", "map", 0.1), spec("line\nbreak\n", "odom", 1e300)};
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

TEST(ObstacleStore, CorruptTextIsRefusedWithTheLine) {
  StoredObstacles out;
  out.session = "kept";
  EXPECT_EQ(parseObstacles("", out), "empty file");
  EXPECT_EQ(parseObstacles("garbage\n", out),
            "record 1: expected 'ellipse_collision obstacle store 1'");
  const std::string good = serializeObstacles({"s", {spec("a", "map", 1.0)}, {}, 0.0});
  EXPECT_EQ(parseObstacles(good.substr(0, good.size() - 4), out), "truncated: no 'end' record");
  EXPECT_EQ(parseObstacles(good.substr(0, good.size() / 2), out).rfind("record", 0), 0u);
  EXPECT_EQ(parseObstacles("ellipse_collision obstacle store 1\nservice 9:a map 1\nend\n", out),
            "record 2: expected service <name> <frame> x y angle radius_x radius_y padding "
            "[vx vy angular_velocity]");
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
  EXPECT_EQ(parseObstacles(good + "x", out), "record 5: expected nothing after 'end'");
  EXPECT_EQ(out.session, "kept") << "left untouched on failure";
}

TEST(ObstacleStore, AtomicWriteReplacesTheFile) {
  char directory[] = "/tmp/obstacle_store_XXXXXX";
  ASSERT_NE(mkdtemp(directory), nullptr);
  const std::string path = std::string(directory) + "/store";
  std::string text, error;
  bool missing = false;
  EXPECT_FALSE(readWholeFile(path, text, missing, error));
  EXPECT_TRUE(missing);
  ASSERT_EQ(writeFileAtomically(path, "one"), "");
  ASSERT_EQ(writeFileAtomically(path, "two"), "");
  ASSERT_TRUE(readWholeFile(path, text, missing, error));
  EXPECT_EQ(text, "two");
  EXPECT_NE(writeFileAtomically(std::string(directory) + "/no/such/dir/store", "x").find("cannot create"),
            std::string::npos);
  std::remove(path.c_str());
  rmdir(directory);
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

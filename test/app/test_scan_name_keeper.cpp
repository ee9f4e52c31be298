// Names of one sensor's obstacle ellipses carried from message to message
// (app/scan_name_keeper.h): matched by shared keys on the ring of beams, greedily, most shared
// first; names that went away come back within kRememberedMessages; clashes get "_2", "_3".
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/scan_name_keeper.h"

namespace ellipse_collision::app {
namespace {

TEST(ScanNameKeeper, ASplitKeepsTheNameWhereMostBeamsStayAndWrapsRoundTheScanStart) {
  EXPECT_EQ(sharedKeys({100, 150}, {120, 200}, 720), 31u);
  EXPECT_EQ(sharedKeys({700, 20}, {0, 10}, 720), 11u);   // across the scan's start
  EXPECT_EQ(sharedKeys({700, 20}, {710, 5}, 720), 16u);  // both across it
  EXPECT_EQ(sharedKeys({100, 150}, {151, 200}, 720), 0u);

  const auto obstacles = [](std::vector<std::pair<std::string, KeySpan>> named) {
    SensorObstacles o;
    o.key_ring = 720;
    for (const auto& [name, span] : named) {
      EllipseSpec spec;
      spec.name = name;
      spec.frame_id = "laser";
      o.ellipses.push_back(spec);
      o.spans.push_back(span);
    }
    return o;
  };
  ScanNameKeeper keeper;
  SensorObstacles first = obstacles({{"scan_100", {100, 150}}, {"scan_700", {700, 20}}});
  keeper.rename(first);
  EXPECT_EQ(first.ellipses[0].name, "scan_100");
  // The stretch 100-150 is split, the scan-start contour's first beam moves to 702.
  SensorObstacles second =
      obstacles({{"scan_100", {100, 119}}, {"scan_120", {120, 150}}, {"scan_702", {702, 21}}});
  keeper.rename(second);
  EXPECT_EQ(second.ellipses[0].name, "scan_100_2");  // its first-beam name is held by 120-150
  EXPECT_EQ(second.ellipses[1].name, "scan_100");    // most of the old stretch's beams
  EXPECT_EQ(second.ellipses[2].name, "scan_700");
  EXPECT_EQ(keeper.namesDropped(), 0u);
  // Far from anything it was: a new name; the old ones are gone.
  SensorObstacles third = obstacles({{"scan_300", {300, 310}}});
  keeper.rename(third);
  EXPECT_EQ(third.ellipses[0].name, "scan_300");
  EXPECT_EQ(keeper.namesDropped(), 3u);
  // Another beam count is another sensor: no name is carried over.
  SensorObstacles other = obstacles({{"scan_300", {301, 310}}});
  other.key_ring = 360;
  keeper.rename(other);
  EXPECT_EQ(other.ellipses[0].name, "scan_300");
  other = obstacles({{"scan_5", {0, 30}}});
  other.key_ring = 360;
  keeper.rename(other);
  EXPECT_EQ(other.ellipses[0].name, "scan_5");  // 301-310 shares nothing with 0-30
}

/// A message of ellipses named by first key, on a ring of `ring` keys in `frame`.
SensorObstacles message(const std::vector<std::pair<std::string, KeySpan>>& named,
                        std::size_t ring = 720, const std::string& frame = "laser") {
  SensorObstacles o;
  o.key_ring = ring;
  for (const auto& [name, span] : named) {
    EllipseSpec spec;
    spec.name = name;
    spec.frame_id = frame;
    spec.x = static_cast<double>(span.first);
    o.ellipses.push_back(spec);
    o.spans.push_back(span);
  }
  return o;
}

std::vector<std::string> names(const SensorObstacles& o) {
  std::vector<std::string> out;
  for (const EllipseSpec& e : o.ellipses) out.push_back(e.name);
  return out;
}

TEST(SharedKeys, CountsAgainstEnumeratingTheRing) {
  // Every pair of spans on a ring of 12 keys, wrapped or not, against counting key by key.
  const std::size_t ring = 12;
  const auto covers = [ring](const KeySpan& s, std::size_t key) {
    return s.first <= s.last ? key >= s.first && key <= s.last : key >= s.first || key <= s.last;
  };
  for (std::size_t a0 = 0; a0 < ring; ++a0) {
    for (std::size_t a1 = 0; a1 < ring; ++a1) {
      for (std::size_t b0 = 0; b0 < ring; ++b0) {
        for (std::size_t b1 = 0; b1 < ring; ++b1) {
          const KeySpan a{a0, a1}, b{b0, b1};
          std::size_t expected = 0;
          for (std::size_t key = 0; key < ring; ++key) expected += covers(a, key) && covers(b, key);
          ASSERT_EQ(sharedKeys(a, b, ring), expected)
              << "[" << a0 << ", " << a1 << "] and [" << b0 << ", " << b1 << "]";
        }
      }
    }
  }
}

TEST(ScanNameKeeper, OnlyMoreThanHalfOfTheShorterSpanMatches) {
  ScanNameKeeper keeper;
  SensorObstacles first = message({{"scan_100", {100, 109}}});
  keeper.rename(first);
  SensorObstacles half = message({{"scan_105", {105, 114}}});  // shares 5 of 10: not more
  keeper.rename(half);
  EXPECT_EQ(names(half), std::vector<std::string>{"scan_105"});
  ScanNameKeeper other;
  first = message({{"scan_100", {100, 109}}});
  other.rename(first);
  SensorObstacles more = message({{"scan_104", {104, 113}}});  // shares 6 of 10
  other.rename(more);
  EXPECT_EQ(names(more), std::vector<std::string>{"scan_100"});
}

TEST(ScanNameKeeper, MostSharedKeysWinAndEachOldNameIsGivenOnce) {
  ScanNameKeeper keeper;
  SensorObstacles first = message({{"scan_0", {0, 99}}});
  keeper.rename(first);
  // Both halves share more than half of their own (shorter) span with 0-99; the larger wins.
  SensorObstacles split = message({{"scan_0", {0, 39}}, {"scan_40", {40, 99}}});
  keeper.rename(split);
  EXPECT_EQ(names(split), (std::vector<std::string>{"scan_0_2", "scan_0"}));
  EXPECT_EQ(keeper.namesDropped(), 0u);
}

TEST(ScanNameKeeper, ANameThatWentAwayComesBackWithinTheRememberedMessages) {
  // Away for kRememberedMessages messages it comes back on the next; one message more, it does not.
  for (const std::size_t absent : {std::size_t{1}, ScanNameKeeper::kRememberedMessages,
                                   ScanNameKeeper::kRememberedMessages + 1}) {
    ScanNameKeeper keeper;
    SensorObstacles first = message({{"scan_10", {10, 30}}, {"scan_200", {200, 260}}});
    keeper.rename(first);
    for (std::size_t k = 0; k < absent; ++k) {
      SensorObstacles without = message({{"scan_200", {200, 260}}});
      keeper.rename(without);
      ASSERT_EQ(names(without), std::vector<std::string>{"scan_200"});
    }
    // Back with its first beam moved: the remembered name, while it is remembered.
    SensorObstacles back = message({{"scan_12", {12, 30}}, {"scan_200", {200, 260}}});
    keeper.rename(back);
    const bool remembered = absent <= ScanNameKeeper::kRememberedMessages;
    EXPECT_EQ(back.ellipses[0].name, remembered ? "scan_10" : "scan_12") << absent << " away";
    EXPECT_EQ(back.ellipses[1].name, "scan_200");
  }
}

TEST(ScanNameKeeper, AnotherFrameStartsAfreshAndOnlyNamesChange) {
  ScanNameKeeper keeper;
  SensorObstacles first = message({{"scan_100", {100, 150}}});
  keeper.rename(first);
  SensorObstacles moved = message({{"scan_101", {101, 150}}}, 720, "laser_rear");
  keeper.rename(moved);
  EXPECT_EQ(names(moved), std::vector<std::string>{"scan_101"});
  EXPECT_EQ(moved.ellipses[0].x, 101.0) << "the geometry is untouched";
  EXPECT_EQ(moved.ellipses[0].frame_id, "laser_rear");
}

TEST(ScanNameKeeper, ClashingFirstKeyNamesGetTheNextFreeSuffix) {
  ScanNameKeeper keeper;
  SensorObstacles first = message({{"scan_5", {5, 50}}, {"scan_5_2", {300, 310}}});
  keeper.rename(first);
  // A new ellipse at 60-70 whose first-key name is held by the match of 5-50; "_2" is held too.
  SensorObstacles second =
      message({{"scan_5", {60, 70}}, {"scan_6", {6, 50}}, {"scan_300", {300, 310}}});
  keeper.rename(second);
  EXPECT_EQ(names(second), (std::vector<std::string>{"scan_5_3", "scan_5", "scan_5_2"}));
}

TEST(ScanNameKeeper, AnEmptyMessageDropsEveryName) {
  ScanNameKeeper keeper;
  SensorObstacles first = message({{"scan_1", {1, 5}}, {"scan_9", {9, 20}}});
  keeper.rename(first);
  SensorObstacles empty = message({});
  keeper.rename(empty);
  EXPECT_TRUE(empty.ellipses.empty());
  EXPECT_EQ(keeper.namesDropped(), 2u);
  SensorObstacles again = message({{"scan_2", {2, 5}}});
  keeper.rename(again);
  EXPECT_EQ(names(again), std::vector<std::string>{"scan_1"}) << "remembered through the gap";
}

}  // namespace
}  // namespace ellipse_collision::app

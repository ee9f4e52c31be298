// The per-source freshness rule (src/app/source_freshness.cpp): silent past the timeout or never
// heard from, the message naming the source and its age, the rate over the last receipts, ages
// and counts, and a clock that jumps back.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "ellipse_collision/app/source_freshness.h"

namespace ellipse_collision::app {
namespace {

TEST(SourceFreshness, ASourceIsSilentOnlyPastItsTimeout) {
  SourceFreshness freshness({{"obstacles", 0.0}, {"front", 0.5}, {"rear", 0.5}});
  EXPECT_EQ(freshness.silent(0.0),
            (std::vector<std::string>{"source 'front' silent: no message yet",
                                      "source 'rear' silent: no message yet"}));
  for (int i = 0; i <= 10; ++i) {
    freshness.received(1, 1.0 + 0.1 * i, 4);
    freshness.received(2, 1.0 + 0.1 * i, 2);
  }
  EXPECT_TRUE(freshness.silent(2.5).empty()) << "0.5 s after the last message is not past 0.5 s";
  freshness.received(1, 2.8, 5);
  EXPECT_EQ(freshness.silent(2.8),
            std::vector<std::string>{"source 'rear' silent for 0.8 s (timeout 0.5 s)"});
  const std::vector<SourceFreshness::Stats> stats = freshness.stats(2.8);
  ASSERT_EQ(stats.size(), 3u);
  EXPECT_EQ(stats[0].age_s, -1.0) << "~obstacles: no message";
  EXPECT_EQ(stats[1].obstacles, 5u);
  EXPECT_EQ(stats[2].obstacles, 2u);
  EXPECT_NEAR(stats[2].rate_hz, 10.0, 1e-9) << "9 intervals of 0.1 s";
  EXPECT_NEAR(stats[2].age_s, 0.8, 1e-9);
  EXPECT_EQ(stats[2].messages, 11u);
  EXPECT_TRUE(freshness.silent(1e9).size() == 2u) << "~obstacles has no watchdog";
}

TEST(SourceFreshness, TheRateSpansTheLastReceiptsOnly) {
  SourceFreshness freshness({{"front", 1.0}});
  freshness.received(0, 0.0, 1);
  EXPECT_EQ(freshness.stats(0.0)[0].rate_hz, 0.0) << "one message: no rate";
  // 1 Hz for 20 s, then 20 Hz: the rate follows the last kRateWindow receipts.
  for (int i = 1; i <= 20; ++i) freshness.received(0, i, 1);
  EXPECT_NEAR(freshness.stats(20.0)[0].rate_hz, 1.0, 1e-12);
  for (int i = 1; i <= static_cast<int>(SourceFreshness::kRateWindow) - 1; ++i) {
    freshness.received(0, 20.0 + 0.05 * i, 1);
  }
  EXPECT_NEAR(freshness.stats(21.0)[0].rate_hz, 20.0, 1e-9);
  EXPECT_EQ(freshness.stats(21.0)[0].messages, 21u + SourceFreshness::kRateWindow - 1);
  EXPECT_NEAR(freshness.stats(21.0)[0].age_s, 1.0 - 0.05 * 9, 1e-12);
}

TEST(SourceFreshness, AgesAreRoundedToATenthInTheMessageButNotInTheStats) {
  SourceFreshness freshness({{"rear_scan", 0.25}});
  freshness.received(0, 10.0, 3);
  EXPECT_TRUE(freshness.silent(10.25).empty()) << "at the timeout is not past it";
  EXPECT_EQ(freshness.silent(10.26),
            std::vector<std::string>{"source 'rear_scan' silent for 0.3 s (timeout 0.25 s)"});
  EXPECT_EQ(freshness.silent(12.34),
            std::vector<std::string>{"source 'rear_scan' silent for 2.3 s (timeout 0.25 s)"});
  EXPECT_NEAR(freshness.stats(12.34)[0].age_s, 2.34, 1e-12);
}

TEST(SourceFreshness, AClockThatJumpsBackCountsReceiptsFromTheFutureAsNow) {
  SourceFreshness freshness({{"front", 0.5}});
  for (int i = 0; i < 5; ++i) freshness.received(0, 100.0 + 0.1 * i, 2);
  // A simulation restarted at 5 s: the receipts at 100 s are in the future.
  EXPECT_TRUE(freshness.silent(5.0).empty());
  EXPECT_EQ(freshness.stats(5.0)[0].age_s, 0.0);
  freshness.received(0, 5.0, 2);
  freshness.received(0, 5.1, 2);
  EXPECT_NEAR(freshness.stats(5.1)[0].rate_hz, 10.0, 1e-9)
      << "the rate from the receipts after the jump only";
  EXPECT_EQ(freshness.silent(5.7),
            std::vector<std::string>{"source 'front' silent for 0.6 s (timeout 0.5 s)"});
}

TEST(SourceFreshness, ASourceWithoutTimeoutIsNeverSilent) {
  SourceFreshness freshness({{"obstacles", 0.0}, {"people", 0.0}});
  EXPECT_EQ(freshness.size(), 2u);
  EXPECT_TRUE(freshness.silent(1e9).empty());
  EXPECT_THROW(freshness.received(2, 0.0, 1), std::out_of_range);
}

}  // namespace
}  // namespace ellipse_collision::app

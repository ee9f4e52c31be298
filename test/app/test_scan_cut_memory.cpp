// Where one laser's last scans cut their contours (app/scan_cut_memory.h): a cut is offered again
// where the two beams around it read the same within the noise and as the same kind of reading,
// and let go once it was not needed in kUnneededMessages scans in a row.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ellipse_collision/app/scan_cut_memory.h"

namespace ellipse_collision::app {
namespace {

constexpr float kNoReturn = std::numeric_limits<float>::infinity();
constexpr double kSigma = 0.01;  // [m]

/// A scan's result cut at `cuts` (ascending first beams of its contours) on `beams` beams.
SensorObstacles cutAt(const std::vector<std::size_t>& cuts, std::size_t beams,
                      const std::vector<std::size_t>& unneeded = {},
                      const std::string& frame = "laser") {
  SensorObstacles o;
  o.key_ring = beams;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    EllipseSpec spec;
    spec.name = "scan_" + std::to_string(cuts[i]);
    spec.frame_id = frame;
    o.ellipses.push_back(spec);
    o.spans.push_back({cuts[i], (i + 1 < cuts.size() ? cuts[i + 1] : cuts.front() + beams) - 1});
    o.spans.back().last %= beams;
  }
  o.unneeded_hints = unneeded;
  return o;
}

using Hints = std::vector<std::size_t>;

TEST(ScanCutMemory, NoHintsWithoutAnEarlierScanOfTheSameSensor) {
  ScanCutMemory memory;
  const std::vector<float> ranges(30, 2.0f);
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), Hints{});
  memory.update(cutAt({0, 10, 20}, 30), ranges);
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), (Hints{0, 10, 20}));
  EXPECT_EQ(memory.hints(ranges, "laser_rear", kSigma), Hints{}) << "another frame";
  EXPECT_EQ(memory.hints(std::vector<float>(31, 2.0f), "laser", kSigma), Hints{})
      << "another beam count";
  EXPECT_EQ(memory.hints({}, "laser", kSigma), Hints{});
}

TEST(ScanCutMemory, ACutStaysWhereBothBeamsAroundItReadTheSameWithinTheNoise) {
  std::vector<float> ranges(30, 2.0f);
  ScanCutMemory memory;
  memory.update(cutAt({0, 10, 20}, 30), ranges);
  const double tolerance = ScanCutMemory::kSameRangeSigmas * kSigma;  // 0.0424 m
  // Beam 9 (before the cut at 10) moved within the tolerance, beam 20 beyond it, and beam 29
  // (before the cut at 0, round the scan's start) beyond it too.
  std::vector<float> next = ranges;
  next[9] = static_cast<float>(2.0 + 0.9 * tolerance);
  EXPECT_EQ(memory.hints(next, "laser", kSigma), (Hints{0, 10, 20}));
  next[20] = static_cast<float>(2.0 - 1.1 * tolerance);
  EXPECT_EQ(memory.hints(next, "laser", kSigma), (Hints{0, 10}));
  next[29] = static_cast<float>(2.0 + 1.1 * tolerance);
  EXPECT_EQ(memory.hints(next, "laser", kSigma), Hints{10});
  // With no noise assumed only the very same ranges count.
  EXPECT_EQ(memory.hints(next, "laser", 0.0), Hints{});
  EXPECT_EQ(memory.hints(ranges, "laser", 0.0), (Hints{0, 10, 20}));
}

TEST(ScanCutMemory, AReadingOfAnotherKindIsAChange) {
  std::vector<float> ranges(30, 2.0f);
  ranges[9] = kNoReturn;
  ranges[19] = std::numeric_limits<float>::quiet_NaN();
  ranges[29] = -1.0f;  // unknown like NaN
  ScanCutMemory memory;
  memory.update(cutAt({0, 10, 20}, 30), ranges);
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), (Hints{0, 10, 20}))
      << "no return again and unknown again are the same";
  std::vector<float> next = ranges;
  next[9] = 9.0f;                                      // a return where there was none
  next[19] = -std::numeric_limits<float>::infinity();  // unknown, as NaN was
  next[29] = std::numeric_limits<float>::quiet_NaN();  // unknown, as -1 was
  EXPECT_EQ(memory.hints(next, "laser", 1e3), (Hints{0, 20}));
  next[0] = kNoReturn;  // the beam of the cut itself
  EXPECT_EQ(memory.hints(next, "laser", 1e3), Hints{20});
}

TEST(ScanCutMemory, ACutIsLetGoAfterItWasNotNeededInARow) {
  static_assert(ScanCutMemory::kUnneededMessages == 2, "the sequence below counts to two");
  const std::vector<float> ranges(30, 2.0f);
  ScanCutMemory memory;
  memory.update(cutAt({0, 10, 20}, 30), ranges);
  memory.update(cutAt({0, 10, 20}, 30, {10}), ranges);  // not needed once: still offered
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), (Hints{0, 10, 20}));
  memory.update(cutAt({0, 10, 20}, 30), ranges);  // needed again: the count starts over
  memory.update(cutAt({0, 10, 20}, 30, {10}), ranges);
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), (Hints{0, 10, 20}));
  memory.update(cutAt({0, 10, 20}, 30, {20, 10}), ranges);  // twice in a row: let go
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), (Hints{0, 20}));
}

TEST(ScanCutMemory, OnlyTheLastScansCutsAreOffered) {
  const std::vector<float> ranges(30, 2.0f);
  ScanCutMemory memory;
  memory.update(cutAt({0, 10, 20}, 30), ranges);
  memory.update(cutAt({5, 25}, 30), ranges);
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), (Hints{5, 25}));
  // A scan without ellipses has no cuts.
  memory.update(SensorObstacles{}, ranges);
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), Hints{});
  memory.update(cutAt({3}, 30), ranges);
  EXPECT_EQ(memory.hints(ranges, "laser", kSigma), Hints{3});
}

}  // namespace
}  // namespace ellipse_collision::app

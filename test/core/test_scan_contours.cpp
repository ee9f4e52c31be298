// The scan pipeline's first steps in the core (src/core/scan_contours.cpp), by hand: what a beam
// says (readBeam()), a LaserScan as returns and free space (scanView()), the breakpoint rule
// (sameContour()) and the contours it cuts (breakContours()). The ellipses a whole pipeline fits,
// on ray-cast scenes against an oracle of their own, are test/app/test_scan_contours.cpp's.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "ellipse_collision/core/ellipse.h"
#include "ellipse_collision/core/scan_contours.h"

namespace ellipse_collision::core {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

TEST(ScanContours, EachBeamIsAReturnNoReturnOrUnknownAsDocumented) {
  EXPECT_EQ(readBeam(1.0, 0.1, 10.0), BeamReading::Return);
  EXPECT_EQ(readBeam(0.1, 0.1, 10.0), BeamReading::Return) << "range_min itself";
  EXPECT_EQ(readBeam(10.0, 0.1, 10.0), BeamReading::Return) << "range_max itself";
  EXPECT_EQ(readBeam(10.5, 0.1, 10.0), BeamReading::NoReturn);
  EXPECT_EQ(readBeam(kInf, 0.1, 10.0), BeamReading::NoReturn);
  EXPECT_EQ(readBeam(kNaN, 0.1, 10.0), BeamReading::Unknown) << "a failed measurement";
  EXPECT_EQ(readBeam(0.05, 0.1, 10.0), BeamReading::Unknown) << "too near to measure";
  EXPECT_EQ(readBeam(-kInf, 0.1, 10.0), BeamReading::Unknown);
  EXPECT_EQ(readBeam(0.0, -1.0, 10.0), BeamReading::Return) << "range_min below 0 counts as 0";
  EXPECT_EQ(readBeam(-0.5, -1.0, 10.0), BeamReading::Unknown);
  EXPECT_EQ(readBeam(1.0, kNaN, 10.0), BeamReading::Unknown) << "a NaN limit";
  EXPECT_EQ(readBeam(1.0, 0.1, kNaN), BeamReading::Unknown);
  EXPECT_EQ(readBeam(1.0, 2.0, 0.5), BeamReading::Unknown) << "range_max below range_min";
  EXPECT_EQ(readBeam(2 * kMaxCoordinate, 0.0, kInf), BeamReading::Unknown)
      << "beyond the coordinates the core accepts";
}

TEST(ScanContours, AScanViewHoldsEachReturnAtItsAngleKeyedByItsBeam) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  // Beams at 0, 90, 180 and 270 degrees: a return, nothing, a NaN, a return.
  const SensorView view = scanView({2.0f, inf, nan, 0.5f}, 0.0, kPi / 2, 0.1, 10.0, 0.05);
  ASSERT_EQ(view.returns.size(), 2u);
  EXPECT_EQ(view.returns[0].key, 0u);
  EXPECT_NEAR(view.returns[0].point.x(), 2.0, 1e-15);
  EXPECT_NEAR(view.returns[0].point.y(), 0.0, 1e-15);
  EXPECT_EQ(view.returns[1].key, 3u);
  EXPECT_NEAR(view.returns[1].point.x(), 0.0, 1e-15);
  EXPECT_NEAR(view.returns[1].point.y(), -0.5, 1e-15);
  EXPECT_TRUE(view.full_turn) << "4 beams of 90 degrees";
  // Free space: along beam 0 up to 2 - 0.05 m, along beam 1 to range_max, beam 2 not at all.
  const Ellipse on_beam_0{{1.5, 0.0}, 0.1, 0.1, 0.0};
  const Ellipse beyond_return_0{{2.5, 0.0}, 0.1, 0.1, 0.0};
  const Ellipse on_beam_1{{0.0, 9.0}, 0.1, 0.1, 0.0};
  const Ellipse on_beam_2{{-5.0, 0.0}, 0.1, 0.1, 0.0};
  EXPECT_TRUE(view.free_space.entered(on_beam_0));
  EXPECT_FALSE(view.free_space.entered(beyond_return_0));
  EXPECT_TRUE(view.free_space.entered(on_beam_1));
  EXPECT_FALSE(view.free_space.entered(on_beam_2)) << "a NaN beam is not a clear view";

  EXPECT_FALSE(scanView({1.0f, 1.0f, 1.0f}, 0.0, 0.01, 0.1, 10.0, 0.05).full_turn);
  EXPECT_TRUE(scanView({1.0f, 1.0f, 1.0f}, kNaN, 0.01, 0.1, 10.0, 0.05).returns.empty())
      << "beams without a finite angle are skipped";
  EXPECT_TRUE(scanView({1.0f, 1.0f}, 0.0, 0.01, kNaN, 10.0, 0.05).returns.empty())
      << "a NaN limit makes every beam unknown";
}

TEST(ScanContours, TheBreakpointRuleJoinsWhatASteepSurfaceLeavesAndBreaksAtTenDegrees) {
  // Two returns 1 degree apart at 2 m: the rule's bound is 2 sin(1 deg) / sin(9 deg) + 3 sigma.
  const double dphi = kPi / 180.0;
  const Eigen::Vector2d p(2.0, 0.0);
  const double bound = 2.0 * std::sin(dphi) / std::sin(kBreakpointAngle - dphi);
  const Eigen::Vector2d direction(std::cos(dphi), std::sin(dphi));
  const Eigen::Vector2d near = (2.0 + 0.5 * bound) * direction;  // 0.12 m from p, bound 0.22 m
  const Eigen::Vector2d far = (2.0 + 1.2 * bound) * direction;   // 0.27 m from p
  EXPECT_TRUE(sameContour(p, near, 0.0, 0.0));
  EXPECT_FALSE(sameContour(p, far, 0.0, 0.0));
  EXPECT_TRUE(sameContour(p, far, (far - p).norm() / 3.0, 0.0)) << "3 sigma of range noise";
  EXPECT_TRUE(sameContour(p, far, 0.0, (far - p).norm() * 1.01)) << "closer than join_distance";
  const Eigen::Vector2d wide = 2.0 * Eigen::Vector2d(std::cos(0.2), std::sin(0.2));
  EXPECT_FALSE(sameContour(p, wide, 1.0, 0.0)) << "11.5 degrees apart: always a break";
  EXPECT_TRUE(sameContour(p, wide, 1.0, 1.0)) << "unless closer than join_distance";
}

TEST(ScanContours, ContoursAreCutAtBreaksJoinedAcrossAFullTurnAndSmallOnesDropped) {
  // 30 beams round, 12 degrees apart (beyond the breakpoint angle): a ring at 1 m on beams 0-4
  // and 25-29 (one object across the scan's start), a lone return at 3 m on beam 15, nothing
  // elsewhere.
  std::vector<float> ranges(30, std::numeric_limits<float>::infinity());
  for (int i : {0, 1, 2, 3, 4, 25, 26, 27, 28, 29}) ranges[i] = 1.0f;
  ranges[15] = 3.0f;
  const SensorView view = scanView(ranges, 0.0, 2 * kPi / 30, 0.1, 10.0, 0.05);
  ASSERT_TRUE(view.full_turn);
  // The ring's neighbours are 0.209 m apart: joined by join_distance 0.25 m, not by 0.1 m.
  const auto contours = breakContours(view, 0.0, 0.25, 1);
  ASSERT_EQ(contours.size(), 2u);
  ASSERT_EQ(contours[0].size(), 1u);
  EXPECT_EQ(contours[0][0].key, 15u);
  ASSERT_EQ(contours[1].size(), 10u);
  EXPECT_EQ(contours[1].front().key, 25u) << "the contour across the start, in beam order";
  EXPECT_EQ(contours[1].back().key, 4u);
  const auto without_lone = breakContours(view, 0.0, 0.25, 2);
  ASSERT_EQ(without_lone.size(), 1u);
  EXPECT_EQ(without_lone[0].size(), 10u);
  EXPECT_EQ(breakContours(view, 0.0, 0.25, 0).size(), 2u) << "0 counts as 1";
  EXPECT_EQ(breakContours(view, 0.0, 0.1, 1).size(), 11u) << "every return alone";
  // Not a full turn: the two ends of the ring stay two contours.
  std::vector<float> half(ranges.begin(), ranges.end() - 1);
  EXPECT_EQ(breakContours(scanView(half, 0.0, 2 * kPi / 30, 0.1, 10.0, 0.05), 0.0, 0.25, 1).size(),
            3u);
}

}  // namespace
}  // namespace ellipse_collision::core

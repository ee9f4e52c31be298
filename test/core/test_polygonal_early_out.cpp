// The polygonal test may give up (Unknown) but must never give a wrong answer; on clear pairs it
// must decide within the default iteration cap.

#include <gtest/gtest.h>
#include <quadmath.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "contact_scale_oracle.h"
#include "ellipse_builders.h"
#include "ellipse_collision/core/polygonal_early_out.h"

namespace ellipse_collision::core {
namespace test {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Pair {
  Ellipse a;
  Ellipse b;
};

using ellipse_collision::test::makeEllipse;

/// Seeded pairs with axis ratios up to `max_ratio`, b placed from a at the contact scale drawn by
/// `target`; the result is rounded, so callers that need t* re-measure it with the oracle.
template <typename TargetFn>
std::vector<Pair> placedPairs(std::uint64_t seed, int count, double max_ratio, TargetFn target) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto ellipse = [&](double cx, double cy) {
    const double major = 0.3 + 3.0 * unit(rng);
    const double minor = major / std::exp(std::log(max_ratio) * unit(rng));
    const bool x_is_major = unit(rng) < 0.5;
    return makeEllipse(cx, cy, x_is_major ? major : minor, x_is_major ? minor : major,
                       2.0 * kPi * unit(rng));
  };
  std::vector<Pair> pairs;
  for (int i = 0; i < count; ++i) {
    const Ellipse a = ellipse(10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0);
    Ellipse b = ellipse(0.0, 0.0);
    const double phi = 2.0 * kPi * unit(rng);
    b.center = a.center + 5.0 * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    pairs.push_back({a, placeAtContactScale(a, b, target(rng))});
  }
  return pairs;
}

// ------------------------------------------------------------------ clear pairs are decided

TEST(PolygonalTest, ClearlyOverlappingHandPairsAreProvenOverlapping) {
  const Pair pairs[] = {
      {makeEllipse(0, 0, 1, 1), makeEllipse(1, 0, 1, 1)},                     // circles, t* = 0.5
      {makeEllipse(0, 0, 5, 0.5), makeEllipse(0.5, 0.5, 5, 0.5, kPi / 2.0)},  // thin X crossing
      {makeEllipse(0, 0, 3, 1), makeEllipse(0, 1.5, 1, 1)},                   // circle on a side
      {makeEllipse(0, 0, 2, 1, 0.7), makeEllipse(1.5, 1, 1.5, 0.5, -0.4)},    // generic
  };
  for (const Pair& p : pairs) {
    ASSERT_LT(static_cast<double>(oracleContactScale(p.a, p.b).quad), 0.8)
        << describePair(p.a, p.b);
    EXPECT_EQ(polygonalTest(p.a, p.b), PolygonalResult::Overlap) << describePair(p.a, p.b);
    EXPECT_EQ(polygonalTest(p.b, p.a), PolygonalResult::Overlap) << describePair(p.a, p.b);
  }
}

TEST(PolygonalTest, ClearlySeparateHandPairsAreProvenSeparate) {
  const Pair pairs[] = {
      {makeEllipse(0, 0, 1, 1), makeEllipse(3, 0, 1, 1)},                 // circles, t* = 1.5
      {makeEllipse(0, 0, 5, 0.5), makeEllipse(0, 2, 5, 0.5)},             // parallel thin
      {makeEllipse(0, 0, 3, 1), makeEllipse(5, 3, 1, 1)},                 // circle off a tip
      {makeEllipse(0, 0, 2, 1, 0.7), makeEllipse(4, 3, 1.5, 0.5, -0.4)},  // generic
  };
  for (const Pair& p : pairs) {
    ASSERT_GT(static_cast<double>(oracleContactScale(p.a, p.b).quad), 1.25)
        << describePair(p.a, p.b);
    EXPECT_EQ(polygonalTest(p.a, p.b), PolygonalResult::Separate) << describePair(p.a, p.b);
    EXPECT_EQ(polygonalTest(p.b, p.a), PolygonalResult::Separate) << describePair(p.a, p.b);
  }
}

TEST(PolygonalTest, RandomClearPairsAreDecidedWithinTheDefaultIterations) {
  std::uniform_real_distribution<double> overlapping(0.2, 0.8), separate(1.25, 4.0);
  for (const bool overlap_side : {true, false}) {
    const auto pairs = placedPairs(31 + overlap_side, 500, 5.0, [&](std::mt19937_64& rng) {
      return overlap_side ? overlapping(rng) : separate(rng);
    });
    const PolygonalResult expected =
        overlap_side ? PolygonalResult::Overlap : PolygonalResult::Separate;
    int wrong = 0;
    for (const Pair& p : pairs) {
      for (const PolygonalResult got : {polygonalTest(p.a, p.b), polygonalTest(p.b, p.a)}) {
        if (got != expected && ++wrong <= 5) {
          ADD_FAILURE() << "polygonalTest = " << ellipse_collision::core::toString(got)
                        << ", oracle t* = " << toString(oracleContactScale(p.a, p.b).quad) << "\n  "
                        << describePair(p.a, p.b);
        }
      }
    }
    EXPECT_EQ(wrong, 0) << "expected " << ellipse_collision::core::toString(expected);
  }
}

// ------------------------------------------------------------------ near tangency: never lies

// Two levels of bisection leave chords and tangent triangles far coarser than 1e-9 of the size,
// so neither proof can succeed: the answer has to be Unknown, and above all not Separate.
TEST(PolygonalTest, OverlapBy1em9CappedAtTwoIterationsIsUnknownNeverSeparate) {
  const auto pairs = placedPairs(33, 20, 5.0, [](std::mt19937_64&) { return 1.0 - 1e-9; });
  for (const Pair& p : pairs) {
    ASSERT_TRUE(oracleContactScale(p.a, p.b).quad < 1 - 5e-10) << describePair(p.a, p.b);
    EXPECT_EQ(polygonalTest(p.a, p.b, 2), PolygonalResult::Unknown) << describePair(p.a, p.b);
    EXPECT_EQ(polygonalTest(p.b, p.a, 2), PolygonalResult::Unknown) << describePair(p.a, p.b);
  }
}

TEST(PolygonalTest, SeparateBy1em9CappedAtTwoIterationsIsUnknownNeverOverlap) {
  const auto pairs = placedPairs(34, 20, 5.0, [](std::mt19937_64&) { return 1.0 + 1e-9; });
  for (const Pair& p : pairs) {
    ASSERT_TRUE(oracleContactScale(p.a, p.b).quad > 1 + 5e-10) << describePair(p.a, p.b);
    EXPECT_EQ(polygonalTest(p.a, p.b, 2), PolygonalResult::Unknown) << describePair(p.a, p.b);
    EXPECT_EQ(polygonalTest(p.b, p.a, 2), PolygonalResult::Unknown) << describePair(p.a, p.b);
  }
}

// ------------------------------------------------------------------ containment

TEST(PolygonalTest, EllipseContainedNearTheRimIsOverlap) {
  // Homothetic inner copy (k = 0.3) shifted to 1e-6 (normalised) short of the outer rim: the
  // two rims run almost parallel there, yet containment is a collision.
  const Ellipse outer = makeEllipse(1, -2, 4, 2, 0.5);
  for (const double phi : {0.0, 0.9, 2.0, -2.7}) {
    const double k = 0.3, reach = (1.0 - k) * (1.0 - 1e-6);
    const Eigen::Vector2d local(reach * outer.radius_x * std::cos(phi),
                                reach * outer.radius_y * std::sin(phi));
    const Ellipse inner = makeEllipse(0, 0, k * outer.radius_x, k * outer.radius_y, outer.angle);
    Ellipse moved = inner;
    moved.center = outer.center + Eigen::Rotation2Dd(outer.angle) * local;
    for (const int iterations : {0, 2, kDefaultPolygonalIterations}) {
      EXPECT_EQ(polygonalTest(outer, moved, iterations), PolygonalResult::Overlap)
          << describePair(outer, moved);
      EXPECT_EQ(polygonalTest(moved, outer, iterations), PolygonalResult::Overlap)
          << describePair(outer, moved);
    }
  }
  // A thin ellipse lying along the inside of a big circle's rim.
  const Ellipse circle = makeEllipse(0, 0, 10, 10);
  const Ellipse thin = makeEllipse(0, 9.5 - 1e-6, 2, 0.5);  // top at y = 10 - 1e-6
  EXPECT_EQ(polygonalTest(circle, thin), PolygonalResult::Overlap);
  EXPECT_EQ(polygonalTest(thin, circle), PolygonalResult::Overlap);
}

// ------------------------------------------------------------------ zero iterations

TEST(PolygonalTest, ZeroIterationsNeverGivesAWrongAnswer) {
  std::uniform_real_distribution<double> clear(0.3, 3.0);
  const double near[] = {1.0 - 1e-3, 1.0 + 1e-3, 1.0 - 1e-9, 1.0 + 1e-9};
  int decided = 0, wrong = 0;
  std::uint64_t seed = 35;
  for (const double max_ratio : {1.0 + 1e-12, 5.0, 1e3}) {  // near-circles, moderate, thin
    const auto pairs = placedPairs(seed++, 400, max_ratio, [&](std::mt19937_64& rng) {
      return std::uniform_int_distribution<int>(0, 1)(rng) ? clear(rng) : near[rng() % 4];
    });
    for (const Pair& p : pairs) {
      const bool truth = oracleOverlap(p.a, p.b);
      for (const PolygonalResult got : {polygonalTest(p.a, p.b, 0), polygonalTest(p.b, p.a, 0)}) {
        if (got == PolygonalResult::Unknown) continue;
        ++decided;
        if ((got == PolygonalResult::Overlap) != truth && ++wrong <= 5) {
          ADD_FAILURE() << "polygonalTest(.., 0) = " << ellipse_collision::core::toString(got)
                        << ", oracle t* = " << toString(oracleContactScale(p.a, p.b).quad) << "\n  "
                        << describePair(p.a, p.b);
        }
      }
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(decided, 0);  // otherwise the test would check nothing
  std::printf("[ info     ] zero iterations decided %d of %d calls\n", decided, 2 * 3 * 400);
}

TEST(PolygonalTest, ZeroIterationsStillDecidesObviousPairs) {
  const Ellipse a = makeEllipse(0, 0, 2, 1, 0.3);
  EXPECT_EQ(polygonalTest(a, makeEllipse(0, 0, 0.5, 3, -0.2), 0), PolygonalResult::Overlap);
  EXPECT_EQ(polygonalTest(a, makeEllipse(100, -50, 0.5, 3, -0.2), 0), PolygonalResult::Separate);
}

// Fuzzer findings: pictures too large or needles too thin for polygons in double precision must
// be left to the eigenvalue test, never decided wrongly.
TEST(PolygonalTest, UnresolvablePicturesAreNeverDecidedWrongly) {
  const std::pair<Ellipse, Ellipse> pairs[] = {
      // 200 m needles, 2 nm thick, 90 m apart: the margin of the picture exceeded the unit circle.
      {Ellipse{{0.0, 0.0}, 100.0, 1e-9, 0.0}, Ellipse{{0.0, 90.0}, 100.0, 1e-9, 1.0}},
      // A circle against a 1e9 m needle: from 9 iterations on it was certified separate.
      {Ellipse{{1e9, 3.0000000000000004}, 3.0000000000000004, 2.9999999999999987, 1.0},
       Ellipse{{20.371089100837708, 6.111326733559963e-08}, 1e9, 1e-9, -2.4983353906949635e-127}},
  };
  for (const auto& [a, b] : pairs) {
    const bool truth = oracleOverlap(a, b);
    for (int iterations : {0, 2, 6, 9, 12, 20, 30}) {
      const PolygonalResult result = polygonalTest(a, b, iterations);
      if (result != PolygonalResult::Unknown) {
        EXPECT_EQ(result == PolygonalResult::Overlap, truth)
            << describePair(a, b) << " at " << iterations << " iterations";
      }
    }
  }
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

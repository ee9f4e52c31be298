// The free parts of a sensor's beams and the tests an obstacle ellipse must pass
// (core/free_space.h), against oracles in long double written here: the normalised form along a
// beam minimised by ternary search (not the closed form), segment crossings by orientation
// predicates, clearances by brute force over every segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ellipse_collision/core/free_space.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace {

using Long = long double;
constexpr double kPi = 3.14159265358979323846;

FreeSegment beam(double angle, double from, double to) {
  return {Eigen::Vector2d(std::cos(angle), std::sin(angle)), from, to};
}

/// The normalised form of `e` at (x, y): the point mapped into the frame where `e` is the unit
/// circle, its squared length.
Long form(const Ellipse& e, Long x, Long y) {
  const Long c = std::cos(Long(e.angle)), s = std::sin(Long(e.angle));
  const Long dx = x - e.center.x(), dy = y - e.center.y();
  const Long u = (c * dx + s * dy) / e.radius_x, v = (-s * dx + c * dy) / e.radius_y;
  return u * u + v * v;
}

/// The least form over the open beam segment, by ternary search (the form is convex along it).
Long leastFormOn(const Ellipse& e, const FreeSegment& f) {
  Long lo = f.from, hi = f.to;
  const auto at = [&](Long t) { return form(e, t * f.direction.x(), t * f.direction.y()); };
  for (int i = 0; i < 300; ++i) {
    const Long m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (at(m1) < at(m2)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  return at((lo + hi) / 2);
}

std::vector<FreeSegment> randomBeams(test::RandomSource& random, int count) {
  std::vector<FreeSegment> beams;
  for (int i = 0; i < count; ++i) {
    const double from = random.uniform(0.0, 1.0);
    beams.push_back(beam(random.uniform(-kPi, kPi), from, from + random.uniform(0.1, 8.0)));
  }
  return beams;
}

Ellipse randomEllipse(test::RandomSource& random) {
  Ellipse e;
  e.center = {random.uniform(-6.0, 6.0), random.uniform(-6.0, 6.0)};
  e.radius_x = random.uniform(0.05, 1.5);
  e.radius_y = random.uniform(0.05, 1.5);
  e.angle = random.uniform(-kPi, kPi);
  return e;
}

TEST(FreeSpace, EmptyOrReversedSegmentsAreDroppedAndTheRestSortedByAngle) {
  const FreeSpace space({beam(2.0, 0.0, 1.0), beam(-3.0, 0.5, 0.5), beam(-1.0, 0.0, 2.0),
                         beam(0.5, 2.0, 1.0), FreeSegment{{NAN, 0.0}, 0.0, 1.0},
                         FreeSegment{{1.0, INFINITY}, 0.0, 1.0}, beam(kPi, 0.0, 1.0)});
  ASSERT_EQ(space.segments().size(), 3u);
  EXPECT_NEAR(std::atan2(space.segments()[0].direction.y(), space.segments()[0].direction.x()),
              -1.0, 1e-15);
  EXPECT_EQ(space.segments()[1].to, 1.0);
  EXPECT_EQ(space.segments()[2].to, 1.0);
  EXPECT_NEAR(space.segments()[2].direction.x(), -1.0, 1e-15);
}

TEST(FreeSpace, AnEllipseHoldingTheSensorOriginIsEnteredEvenWithoutBeams) {
  const FreeSpace none;
  Eigen::Vector2d where(5.0, 5.0);
  EXPECT_TRUE(none.entered(Ellipse{{0.3, 0.0}, 0.5, 0.2, 0.0}, &where));
  EXPECT_EQ(where, Eigen::Vector2d::Zero());
  EXPECT_FALSE(none.entered(Ellipse{{3.0, 0.0}, 0.5, 0.2, 0.0}));
  EXPECT_TRUE(none.crossed({-1.0, 0.0}, {1.0, 0.0}, &where)) << "through the origin";
  EXPECT_EQ(where, Eigen::Vector2d::Zero());
  EXPECT_EQ(none.clearance({3.0, 4.0}, 10.0), 5.0) << "the origin is 5 m away";
  EXPECT_EQ(none.clearance({3.0, 4.0}, 2.0), 2.0);
}

TEST(FreeSpace, ABeamStoppingShortOfACircleOrStartingBehindItDoesNotEnterIt) {
  // A circle of radius 1 at (5, 0): the beam along x meets it from t = 4 to t = 6.
  const Ellipse circle{{5.0, 0.0}, 1.0, 1.0, 0.0};
  EXPECT_FALSE(FreeSpace({beam(0.0, 0.0, 3.999)}).entered(circle));
  EXPECT_TRUE(FreeSpace({beam(0.0, 0.0, 4.001)}).entered(circle));
  EXPECT_FALSE(FreeSpace({beam(0.0, 6.001, 9.0)}).entered(circle));
  EXPECT_TRUE(FreeSpace({beam(0.0, 4.5, 4.6)}).entered(circle)) << "wholly inside";
  // A beam passing at 1.001 m of the centre misses; at 0.999 m it enters; the direction told.
  const double miss = std::asin(1.001 / 5.0), hit = std::asin(0.999 / 5.0);
  EXPECT_FALSE(FreeSpace({beam(miss, 0.0, 10.0)}).entered(circle));
  Eigen::Vector2d where;
  EXPECT_TRUE(FreeSpace({beam(miss, 0.0, 10.0), beam(hit, 0.0, 10.0)}).entered(circle, &where));
  EXPECT_NEAR(where.y(), std::sin(hit), 1e-15);
}

TEST(FreeSpace, EnteredAgreesWithTheLeastFormOnEveryBeam) {
  test::RandomSource random(41);
  int entered = 0, checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<FreeSegment> beams = randomBeams(random, 60);
    const FreeSpace space(beams);
    const Ellipse e = randomEllipse(random);
    Long least = form(e, 0.0L, 0.0L);
    for (const FreeSegment& f : beams) least = std::min(least, leastFormOn(e, f));
    const Long threshold = 1.0L + kFreeSpaceMargin;
    if (std::fabs(least - threshold) < 1e-12L) continue;  // too close to call either way
    ++checked;
    Eigen::Vector2d where;
    const bool is_entered = space.entered(e, &where);
    EXPECT_EQ(is_entered, least < threshold)
        << "trial " << trial << ", least form " << double(least);
    if (is_entered && where != Eigen::Vector2d::Zero()) {
      // The reported beam itself enters.
      const auto found = std::find_if(beams.begin(), beams.end(),
                                      [&](const FreeSegment& f) { return f.direction == where; });
      ASSERT_NE(found, beams.end());
      EXPECT_LT(leastFormOn(e, *found), threshold + 1e-12L);
    }
    entered += is_entered;
  }
  EXPECT_GT(checked, 290);
  EXPECT_GT(entered, 30) << "the comparison must see both answers";
  EXPECT_LT(entered, checked - 30);
}

TEST(FreeSpace, BeamsAcrossTheAngleSeamAreFound) {
  // Beams at +-pi and an ellipse behind the sensor straddling the seam of atan2.
  const Ellipse behind{{-4.0, 0.0}, 0.3, 0.6, 0.2};
  for (const double angle : {kPi, -kPi, kPi - 0.05, -kPi + 0.05}) {
    EXPECT_TRUE(FreeSpace({beam(0.0, 0.0, 10.0), beam(angle, 0.0, 10.0)}).entered(behind)) << angle;
  }
  EXPECT_TRUE(FreeSpace({beam(kPi - 0.05, 0.0, 10.0)}).crossed({-4.0, -1.0}, {-4.0, 1.0}));
  EXPECT_NEAR(FreeSpace({beam(-kPi + 0.01, 0.0, 10.0)}).clearance({-4.0, 0.5}, 1.0),
              std::fabs(4.0 * std::sin(-0.01) - 0.5 * std::cos(0.01)), 1e-12);
}

Eigen::Vector2d towards(double angle) { return {std::cos(angle), std::sin(angle)}; }

TEST(FreeSpace, BesideFindsTheNearestBeamOutsideARunOnEachSideAcrossTheSeam) {
  // Beams every 0.1 rad; a run's own first and last beams are not beside it.
  std::vector<FreeSegment> beams;
  for (int i = -31; i <= 31; ++i) beams.push_back(beam(0.1 * i, 0.0, 1.0 + i * 0.01));
  const FreeSpace space(beams);
  const auto [lo, hi] = space.beside(towards(0.2), towards(0.5));
  ASSERT_TRUE(lo && hi);
  EXPECT_NEAR(std::atan2(lo->direction.y(), lo->direction.x()), 0.1, 1e-12);
  EXPECT_NEAR(std::atan2(hi->direction.y(), hi->direction.x()), 0.6, 1e-12);
  EXPECT_DOUBLE_EQ(lo->to, 1.01);
  // Across the seam of atan2: from 3.05 to -3.05 counter-clockwise (a run behind the sensor).
  const auto [behind_lo, behind_hi] = space.beside(towards(3.05), towards(-3.05));
  ASSERT_TRUE(behind_lo && behind_hi);
  EXPECT_NEAR(std::atan2(behind_lo->direction.y(), behind_lo->direction.x()), 3.0, 1e-12);
  EXPECT_NEAR(std::atan2(behind_hi->direction.y(), behind_hi->direction.x()), -3.0, 1e-12);
  // The run's first beam is the last of the array: the next clockwise wraps to the first.
  const auto [wrap_lo, wrap_hi] = space.beside(towards(-3.1), towards(-2.9));
  ASSERT_TRUE(wrap_lo && wrap_hi);
  EXPECT_NEAR(std::atan2(wrap_lo->direction.y(), wrap_lo->direction.x()), 3.1, 1e-12);
  EXPECT_NEAR(std::atan2(wrap_hi->direction.y(), wrap_hi->direction.x()), -2.8, 1e-12);
  // Nothing beside: no beams, or the only beam inside the run.
  EXPECT_FALSE(FreeSpace().beside(towards(0.0), towards(0.1)).first);
  const FreeSpace inside({beam(0.05, 0.0, 1.0)});
  EXPECT_FALSE(inside.beside(towards(0.0), towards(0.1)).first);
  EXPECT_FALSE(inside.beside(towards(0.0), towards(0.1)).second);
  // One beam a little more than half a turn clockwise of the run's start: not beside it on
  // that side, but less than half a turn counter-clockwise of its end, so beside it there.
  const FreeSpace opposite({beam(kPi - 0.01, 0.0, 1.0)});
  EXPECT_FALSE(opposite.beside(towards(0.0), towards(0.1)).first);
  EXPECT_TRUE(opposite.beside(towards(0.0), towards(0.1)).second);
}

/// Whether the closed segment [a, b] and the open segment from p to q cross (orientation
/// predicates in long double; general position assumed).
bool segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p,
                   const Eigen::Vector2d& q) {
  const auto orient = [](const Eigen::Vector2d& o, const Eigen::Vector2d& u,
                         const Eigen::Vector2d& v) {
    return (Long(u.x()) - o.x()) * (Long(v.y()) - o.y()) -
           (Long(u.y()) - o.y()) * (Long(v.x()) - o.x());
  };
  return (orient(a, b, p) > 0) != (orient(a, b, q) > 0) &&
         (orient(p, q, a) > 0) != (orient(p, q, b) > 0);
}

TEST(FreeSpace, CrossedAndClearanceAgreeWithBruteForce) {
  test::RandomSource random(42);
  int crossed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<FreeSegment> beams = randomBeams(random, 40);
    const FreeSpace space(beams);
    const Eigen::Vector2d a(random.uniform(-6, 6), random.uniform(-6, 6));
    const Eigen::Vector2d b = a + Eigen::Vector2d(random.uniform(-1, 1), random.uniform(-1, 1));
    bool expected = false;
    for (const FreeSegment& f : beams) {
      expected = expected || segmentsCross(a, b, f.from * f.direction, f.to * f.direction);
    }
    EXPECT_EQ(space.crossed(a, b), expected) << "trial " << trial;
    crossed += expected;
    // Clearance: every segment and the origin, by brute force in long double.
    const double radius = random.uniform(0.1, 3.0);
    Long nearest = std::min<Long>(radius, std::hypot(Long(a.x()), Long(a.y())));
    for (const FreeSegment& f : beams) {
      const Long t = std::clamp<Long>(Long(a.x()) * f.direction.x() + Long(a.y()) * f.direction.y(),
                                      f.from, f.to);
      nearest =
          std::min(nearest, std::hypot(a.x() - t * f.direction.x(), a.y() - t * f.direction.y()));
    }
    EXPECT_NEAR(space.clearance(a, radius), double(nearest), 1e-12) << "trial " << trial;
  }
  EXPECT_GT(crossed, 20);
  EXPECT_LT(crossed, 280);
}

}  // namespace
}  // namespace ellipse_collision::core

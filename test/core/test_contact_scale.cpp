// Hand-checkable cases for eigenvalueOverlap() and contactScale(); the random families are in
// test_overlap_accuracy.cpp.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "contact_scale_oracle.h"
#include "ellipse_builders.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/overlap.h"

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Hand values below are exact, so contactScale() is only allowed rounding-level error.
constexpr double kRelTolerance = 1e-12;

using ellipse_collision::test::makeEllipse;

Ellipse makeCircle(double cx, double cy, double r) { return makeEllipse(cx, cy, r, r); }

void expectRelNear(double value, double expected, double rel_tolerance = kRelTolerance) {
  EXPECT_NEAR(value, expected, rel_tolerance * std::fabs(expected))
      << "value " << value << " expected " << expected;
}

/// Random pairs with moderate shapes and separations, seeded so failures repeat.
std::vector<std::pair<Ellipse, Ellipse>> randomPairs(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> position(-5.0, 5.0), radius(0.2, 3.0), angle(-kPi, kPi);
  std::vector<std::pair<Ellipse, Ellipse>> pairs;
  for (int i = 0; i < count; ++i) {
    const Ellipse a =
        makeEllipse(position(rng), position(rng), radius(rng), radius(rng), angle(rng));
    const Ellipse b =
        makeEllipse(position(rng), position(rng), radius(rng), radius(rng), angle(rng));
    pairs.emplace_back(a, b);
  }
  return pairs;
}

Ellipse scaled(const Ellipse& e, double k) {
  return makeEllipse(k * e.center.x(), k * e.center.y(), k * e.radius_x, k * e.radius_y, e.angle);
}

// ------------------------------------------------------------------ circles

TEST(ContactScale, CirclesGiveCentreDistanceOverRadiusSum) {
  expectRelNear(contactScale(makeCircle(0, 0, 1), makeCircle(3, 4, 2)), 5.0 / 3.0);
  expectRelNear(contactScale(makeCircle(0, 0, 1), makeCircle(2, 0, 1)), 1.0);
  expectRelNear(contactScale(makeCircle(-1, 2, 0.5), makeCircle(-1, 2.25, 0.5)), 0.25);
  expectRelNear(contactScale(makeCircle(10, 10, 3), makeCircle(-20, -30, 7)), 5.0);
}

TEST(EigenvalueOverlap, CirclesJustApartAreSeparateAndJustCloserOverlap) {
  const Ellipse a = makeCircle(0, 0, 1);
  EXPECT_FALSE(eigenvalueOverlap(a, makeCircle(2.0 * (1 + 1e-6), 0, 1)));
  EXPECT_TRUE(eigenvalueOverlap(a, makeCircle(2.0 * (1 - 1e-6), 0, 1)));
  EXPECT_FALSE(eigenvalueOverlap(a, makeCircle(0, 3.1, 2)));
  EXPECT_TRUE(eigenvalueOverlap(a, makeCircle(0, 2.9, 2)));
}

// Fuzzer finding: equal shapes turned by 1.7e-158 and -1e-300 make M the identity up to an
// off-diagonal 1.6e-158, whose eigenvector's squared length was subnormal: the offsets along it
// came out 2.3e-9 (relative) off, enough to flip the decision of eigenvalueOverlap() and of
// overlap() this close to tangency.
TEST(EigenvalueOverlap, NearlyEqualShapesWithTinyAnglesKeepTheirOffsets) {
  const Ellipse a = makeEllipse(4, 68, 1, 1.5707963267948966, 1.7325062590226989e-158);
  const Ellipse b = makeEllipse(1e-9, 1e9, 1, 1.5707963267948966, -1e-300);
  for (const double target : {1.0 - 1e-10, 1.0 + 1e-10, 2.0, 1e8}) {
    const Ellipse placed = test::placeAtContactScale(a, b, target);
    const test::OracleContactScale truth = test::oracleContactScale(a, placed);
    EXPECT_EQ(eigenvalueOverlap(a, placed), truth.value <= 1.0) << target;
    EXPECT_EQ(overlap(a, placed), truth.value <= 1.0) << target;
    EXPECT_NEAR(contactScale(a, placed) / truth.value, 1.0, 1e-14) << target;
  }
}

// ------------------------------------------------------------------ ellipses touching

TEST(ContactScale, AxisAlignedEllipsesTouchingTipToTipGiveOne) {
  const Ellipse a = makeEllipse(0, 0, 3, 1);
  expectRelNear(contactScale(a, makeEllipse(5, 0, 2, 0.5)), 1.0);     // along x: 5 = 3 + 2
  expectRelNear(contactScale(a, makeEllipse(0, -1.5, 2, 0.5)), 1.0);  // along y: 1.5 = 1 + 0.5
  expectRelNear(contactScale(a, makeEllipse(10, 0, 2, 0.5)), 2.0);
}

TEST(ContactScale, RotatedTipTouchingTheOtherEllipsesSideGivesOne) {
  // b stands upright on a's flat side: its tip at y = 1 meets a's side.
  const Ellipse a = makeEllipse(0, 0, 3, 1);
  expectRelNear(contactScale(a, makeEllipse(0, 3, 2, 0.5, kPi / 2.0)), 1.0);
  // Both turned by a quarter turn: a tip-to-tip contact along y.
  expectRelNear(
      contactScale(makeEllipse(0, 0, 3, 1, kPi / 2.0), makeEllipse(0, 5, 2, 0.5, kPi / 2.0)), 1.0);
}

TEST(ContactScale, ThinEllipseOfAxisRatio1e3TouchingACircleGivesOne) {
  const Ellipse thin = makeEllipse(0, 0, 1000, 1);
  expectRelNear(contactScale(thin, makeCircle(0, 2, 1)), 1.0);     // on the long flat side
  expectRelNear(contactScale(thin, makeCircle(1001, 0, 1)), 1.0);  // at the sharp tip
  expectRelNear(contactScale(thin, makeCircle(0, 4, 1)), 2.0);
}

TEST(EigenvalueOverlap, TipToTipJustApartIsSeparateAndJustCloserOverlaps) {
  const Ellipse a = makeEllipse(0, 0, 3, 1, 0.0);
  EXPECT_FALSE(eigenvalueOverlap(a, makeEllipse(5.0 * (1 + 1e-9), 0, 2, 0.5)));
  EXPECT_TRUE(eigenvalueOverlap(a, makeEllipse(5.0 * (1 - 1e-9), 0, 2, 0.5)));
  const Ellipse thin = makeEllipse(0, 0, 1000, 1);
  EXPECT_FALSE(eigenvalueOverlap(thin, makeCircle(1001.0 * (1 + 1e-9), 0, 1)));
  EXPECT_TRUE(eigenvalueOverlap(thin, makeCircle(1001.0 * (1 - 1e-9), 0, 1)));
  EXPECT_FALSE(eigenvalueOverlap(thin, makeCircle(0, 2.0 * (1 + 1e-9), 1)));
  EXPECT_TRUE(eigenvalueOverlap(thin, makeCircle(0, 2.0 * (1 - 1e-9), 1)));
}

// ------------------------------------------------------------------ containment and concentric

TEST(EigenvalueOverlap, EllipseContainedInAnotherOverlaps) {
  const Ellipse outer = makeEllipse(1, 2, 5, 3, 0.3);
  const Ellipse inner = makeCircle(2, 3, 0.5);
  EXPECT_TRUE(eigenvalueOverlap(outer, inner));
  EXPECT_TRUE(eigenvalueOverlap(inner, outer));
  // d = (1, 1) lies inside `outer`, so t* is below its normalised radius there.
  const double c = std::cos(0.3), s = std::sin(0.3);
  const double local_x = c * 1.0 + s * 1.0, local_y = -s * 1.0 + c * 1.0;
  const double inside = std::sqrt(local_x * local_x / 25.0 + local_y * local_y / 9.0);
  const double t = contactScale(outer, inner);
  EXPECT_GT(t, 0.0);
  EXPECT_LT(t, inside);
}

TEST(ContactScale, ConcentricEllipsesGiveZeroAndOverlap) {
  const Ellipse a = makeEllipse(1.5, -2.5, 4, 0.5, 0.7);
  const Ellipse b = makeEllipse(1.5, -2.5, 0.1, 3, -1.2);
  EXPECT_EQ(contactScale(a, b), 0.0);
  EXPECT_EQ(contactScale(a, a), 0.0);
  EXPECT_TRUE(eigenvalueOverlap(a, b));
  EXPECT_TRUE(eigenvalueOverlap(a, a));
  const Ellipse far_a = makeEllipse(1e6, -1e6, 4, 0.5, 0.7);
  const Ellipse far_b = makeEllipse(1e6, -1e6, 1e-3, 2, 0.1);
  EXPECT_EQ(contactScale(far_a, far_b), 0.0);
  EXPECT_TRUE(eigenvalueOverlap(far_a, far_b));
}

// ------------------------------------------------------------------ invariances

TEST(ContactScale, IsSymmetricInThePair) {
  for (const auto& [a, b] : randomPairs(21, 500)) {
    expectRelNear(contactScale(b, a), contactScale(a, b));
    EXPECT_EQ(eigenvalueOverlap(a, b), eigenvalueOverlap(b, a));
  }
}

TEST(ContactScale, ScalingAllLengthsLeavesItUnchanged) {
  for (const auto& [a, b] : randomPairs(22, 300)) {
    const double t = contactScale(a, b);
    for (const double k : {1e-4, 0.37, 3.0, 1e4}) {
      expectRelNear(contactScale(scaled(a, k), scaled(b, k)), t);
    }
  }
}

TEST(ContactScale, TranslatingBothCentresBy1e6LeavesItUnchanged) {
  // Centres with few binary digits so that the translated inputs are exact.
  const Ellipse a = makeEllipse(0.5, 0.25, 2.0, 0.75, 0.4);
  const Ellipse b = makeEllipse(2.75, -1.125, 1.5, 0.25, -1.1);
  const double t = contactScale(a, b);
  for (const Eigen::Vector2d& shift :
       {Eigen::Vector2d(1e6, 0), Eigen::Vector2d(-1e6, 1e6), Eigen::Vector2d(0, -1e6)}) {
    Ellipse a_far = a, b_far = b;
    a_far.center += shift;
    b_far.center += shift;
    expectRelNear(contactScale(a_far, b_far), t);
    EXPECT_EQ(eigenvalueOverlap(a_far, b_far), eigenvalueOverlap(a, b));
  }
}

TEST(ContactScale, AnglePlusPiOrQuarterTurnWithSwappedRadiiIsTheSameEllipse) {
  for (const auto& [a, b] : randomPairs(23, 300)) {
    const double t = contactScale(a, b);
    Ellipse half_turn = a;
    half_turn.angle += kPi;
    expectRelNear(contactScale(half_turn, b), t);
    Ellipse quarter_turn = a;
    quarter_turn.angle += kPi / 2.0;
    std::swap(quarter_turn.radius_x, quarter_turn.radius_y);
    expectRelNear(contactScale(quarter_turn, b), t);
  }
}

TEST(EigenvalueOverlap, AgreesWithContactScaleAwayFromTangency) {
  int overlapping = 0;
  for (const auto& [a, b] : randomPairs(24, 1000)) {
    const double t = contactScale(a, b);
    if (std::fabs(t - 1.0) < 1e-6) continue;  // the accuracy families cover near-tangent pairs
    EXPECT_EQ(eigenvalueOverlap(a, b), t <= 1.0) << "t* = " << t;
    overlapping += t <= 1.0 ? 1 : 0;
  }
  EXPECT_GT(overlapping, 50);  // both answers must be exercised
  EXPECT_LT(overlapping, 950);
}

// Fuzzer finding: an offset so small that its squared components underflow is still an offset.
TEST(ContactScale, TinyCentreOffsetDoesNotUnderflowToCoincidentCentres) {
  const Ellipse a{{0.0, 0.0}, 1e-9, 1e9, 0.0};
  const Ellipse b{{-2.237502219360062e-154, 7.9989294464120617e-315}, 1e9, 1.030517578125, 0.5};
  const double t = contactScale(a, b);
  EXPECT_GT(t, 0.0);
  EXPECT_TRUE(overlap(a, b));
  EXPECT_TRUE(eigenvalueOverlap(a, b));
  // t* is homogeneous in the offset: doubling it doubles t*, exactly as far as rounding allows.
  Ellipse b2 = b;
  b2.center *= 2.0;
  EXPECT_NEAR(contactScale(a, b2) / t, 2.0, 1e-12);
}

}  // namespace
}  // namespace ellipse_collision::core

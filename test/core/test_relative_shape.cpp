// One ellipse seen in the frame where the other is the unit circle (src/core/relative_shape.h),
// against the frame change written out in long double with trigonometry of the two angles
// separately; the principal axes against the eigenvalues of [p q][p q]^T in closed form; the
// canonical frame the same bits whichever way round the pair is given.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "random_source.h"
#include "relative_shape.h"

namespace ellipse_collision::core::detail {
namespace {

using Long = long double;

Ellipse randomEllipse(test::RandomSource& random, double scale) {
  return {{random.uniform(-1, 1) * scale, random.uniform(-1, 1) * scale},
          random.logUniform(1e-3, 1.0) * scale,
          random.logUniform(1e-3, 1.0) * scale,
          random.uniform(-10.0, 10.0)};
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(RelativeShape, IsTheOtherEllipseMappedIntoTheUnitCirclesFrame) {
  test::RandomSource random(21);
  for (int i = 0; i < 2000; ++i) {
    const double scale = random.logUniform(1e-3, 1e3);
    const Ellipse unit = randomEllipse(random, scale), other = randomEllipse(random, scale);
    const SinCosPair trig = sinCosPair(unit.angle, other.angle);
    const RelativeShape shape = relativeShape(unit, frameFactors(unit, trig.first), other,
                                              trig.second.cos, trig.second.sin);
    // x -> diag(1/rx, 1/ry) R(-unit.angle) (x - unit.center), in long double.
    const Long cu = std::cos(Long(unit.angle)), su = std::sin(Long(unit.angle));
    const Long co = std::cos(Long(other.angle)), so = std::sin(Long(other.angle));
    const auto map = [&](Long x, Long y, Long* u, Long* v) {
      *u = (cu * x + su * y) / unit.radius_x;
      *v = (-su * x + cu * y) / unit.radius_y;
    };
    Long cx, cy, px, py, qx, qy;
    map(Long(other.center.x()) - unit.center.x(), Long(other.center.y()) - unit.center.y(), &cx,
        &cy);
    map(co * other.radius_x, so * other.radius_x, &px, &py);
    map(-so * other.radius_y, co * other.radius_y, &qx, &qy);
    const Long size = std::fabs(cx) + std::fabs(cy) + 1;
    const Long axes = std::fabs(px) + std::fabs(py) + std::fabs(qx) + std::fabs(qy);
    EXPECT_NEAR(shape.center_x, double(cx), 1e-13 * double(size)) << i;
    EXPECT_NEAR(shape.center_y, double(cy), 1e-13 * double(size)) << i;
    EXPECT_NEAR(shape.p_x, double(px), 1e-14 * double(axes)) << i;
    EXPECT_NEAR(shape.p_y, double(py), 1e-14 * double(axes)) << i;
    EXPECT_NEAR(shape.q_x, double(qx), 1e-14 * double(axes)) << i;
    EXPECT_NEAR(shape.q_y, double(qy), 1e-14 * double(axes)) << i;
    EXPECT_NEAR(shape.determinant, double(px * qy - py * qx), 1e-14 * double(px * qy - py * qx));
  }
}

TEST(RelativeShape, EqualAnglesGiveAnExactlyZeroRelativeTurn) {
  const Ellipse unit{{1.0, 2.0}, 2.0, 0.5, 0.7}, other{{4.0, -1.0}, 0.25, 1.0, 0.7};
  const RelativeShape shape = canonicalRelativeShape(unit, other);
  EXPECT_EQ(shape.p_y, 0.0);
  EXPECT_EQ(shape.q_x, 0.0);
  EXPECT_EQ(shape.determinant, (0.25 / 2.0) * (1.0 / 0.5));
}

TEST(RelativeShape, TheLargerAreaIsTheUnitAndEitherOrderGivesTheSameBits) {
  test::RandomSource random(22);
  for (int i = 0; i < 2000; ++i) {
    const Ellipse a = randomEllipse(random, 5.0);
    Ellipse b = randomEllipse(random, 5.0);
    if (i % 4 == 0) {  // equal areas: the tie order decides
      b.radius_x = a.radius_y;
      b.radius_y = a.radius_x;
    }
    const RelativeShape ab = canonicalRelativeShape(a, b), ba = canonicalRelativeShape(b, a);
    EXPECT_TRUE(sameBits(ab.center_x, ba.center_x) && sameBits(ab.center_y, ba.center_y) &&
                sameBits(ab.p_x, ba.p_x) && sameBits(ab.q_y, ba.q_y) &&
                sameBits(ab.determinant, ba.determinant))
        << i;
    // The other is never larger than the unit (on equal areas the ratios' product may round up).
    EXPECT_LE(ab.determinant, 1.0 + 4 * std::numeric_limits<double>::epsilon());
    const bool identical = a.radius_x == b.radius_x && a.radius_y == b.radius_y &&
                           a.angle == b.angle && a.center == b.center;
    if (!identical) {
      EXPECT_NE(precedesAsUnit(a, b), precedesAsUnit(b, a)) << "one unit per pair";
    }
  }
  const Ellipse same{{0.0, 0.0}, 1.0, 0.5, 0.0};
  EXPECT_TRUE(precedesAsUnit(same, same)) << "ties of identical ellipses still pick one";
}

TEST(PrincipalShape, AxesAndOffsetsAgainstTheClosedFormEigenDecomposition) {
  test::RandomSource random(23);
  for (int i = 0; i < 2000; ++i) {
    const Ellipse a = randomEllipse(random, 1.0), b = randomEllipse(random, 1.0);
    const RelativeShape s = canonicalRelativeShape(a, b);
    const PrincipalShape principal = principalShape(s);
    // M = [p q][p q]^T; its eigenvalues and the angle of its first eigenvector, in long double.
    const Long m00 = Long(s.p_x) * s.p_x + Long(s.q_x) * s.q_x;
    const Long m01 = Long(s.p_x) * s.p_y + Long(s.q_x) * s.q_y;
    const Long m11 = Long(s.p_y) * s.p_y + Long(s.q_y) * s.q_y;
    const Long mean = (m00 + m11) / 2, half = std::hypot((m00 - m11) / 2, m01);
    const Long big = mean + half, small = (m00 * m11 - m01 * m01) / big;
    const Long theta = std::atan2(2 * m01, m00 - m11) / 2;
    const Long along = std::fabs(std::cos(theta) * s.center_x + std::sin(theta) * s.center_y);
    const Long across = std::fabs(-std::sin(theta) * s.center_x + std::cos(theta) * s.center_y);
    EXPECT_NEAR(principal.lambda[0], double(big), 1e-14 * double(big)) << i;
    EXPECT_NEAR(principal.lambda[1], double(small), 1e-12 * double(small)) << i;
    EXPECT_GE(principal.lambda[0], principal.lambda[1]);
    EXPECT_NEAR(principal.semi_axis[0], double(std::sqrt(big)), 1e-14 * double(std::sqrt(big)));
    EXPECT_NEAR(principal.semi_axis[0] * principal.semi_axis[1], s.determinant,
                1e-14 * s.determinant);
    const Long offset = std::hypot(Long(s.center_x), Long(s.center_y));
    // The eigenvector's direction is ill-conditioned when the eigenvalues nearly coincide.
    if (half > 1e-6L * big) {
      EXPECT_NEAR(principal.offset[0], double(along), 1e-9 * double(offset) + 1e-300) << i;
      EXPECT_NEAR(principal.offset[1], double(across), 1e-9 * double(offset) + 1e-300) << i;
    }
    EXPECT_NEAR(std::hypot(principal.offset[0], principal.offset[1]), double(offset),
                1e-14 * double(offset));
  }
}

TEST(PrincipalShape, AMultipleOfTheIdentityAndTinyOrHugeEigenvectorsKeepTheOffset) {
  // Concentric circles of the unit frame: M = k I, any axes; the offset keeps its length.
  RelativeShape circle{3.0, -4.0, 0.5, 0.0, 0.0, 0.5, 0.25};
  PrincipalShape p = principalShape(circle);
  EXPECT_EQ(p.lambda[0], 0.25);
  EXPECT_EQ(p.semi_axis[1], 0.5);
  EXPECT_NEAR(std::hypot(p.offset[0], p.offset[1]), 5.0, 1e-15);
  // Off-diagonal 1e-158 (a subnormal square) and offsets of 1e-290: still resolved.
  RelativeShape tiny{1e-290, 2e-290, 1.0, 1e-158, 0.0, 1.0, 1.0};
  p = principalShape(tiny);
  EXPECT_GT(p.offset[0] + p.offset[1], 0.0) << "the centres are not taken to coincide";
  EXPECT_NEAR(std::hypot(p.offset[0], p.offset[1]), std::hypot(1e-290, 2e-290), 1e-300);
}

}  // namespace
}  // namespace ellipse_collision::core::detail

// overlap() on pairs whose answer is exact in binary arithmetic (core/overlap.h): closed ellipses
// touching at one point collide, and 1e-9 further apart (the band the accuracy tests hold it to)
// they do not; the inline bounding-circle rejection and the exact stages agree on every pair
// whose circles meet; symmetry bit for bit. (Accuracy against the quad-precision oracle over many
// families: test_overlap_accuracy.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "ellipse_collision/core/overlap.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace {

TEST(Overlap, CirclesTouchingAtOnePointCollideAndOnesJustApartDoNot) {
  // Radii 0.5 and 1.5: touching at centres exactly 2 apart, on an axis and on a 3-4-5 diagonal.
  const Ellipse a{{0.0, 0.0}, 0.5, 0.5, 0.0};
  EXPECT_TRUE(overlap(a, Ellipse{{2.0, 0.0}, 1.5, 1.5, 0.0}));
  EXPECT_FALSE(overlap(a, Ellipse{{2.0 * (1 + 1e-9), 0.0}, 1.5, 1.5, 0.0}));
  EXPECT_TRUE(overlap(Ellipse{{0.0, 0.0}, 2.0, 2.0, 0.0}, Ellipse{{3.0, 4.0}, 3.0, 3.0, 0.0}));
  EXPECT_FALSE(
      overlap(Ellipse{{0.0, 0.0}, 2.0, 2.0, 0.0}, Ellipse{{3.0, 4.0 * (1 + 1e-9)}, 3.0, 3.0, 0.0}));
}

TEST(Overlap, EllipsesTipToTipAndSideToSideTouchAtTheirAxes) {
  // Axis-aligned: tips along x at 0.75 + 0.25 = 1, flat sides along y at 0.125 + 0.375 = 0.5.
  const Ellipse a{{0.0, 0.0}, 0.75, 0.125, 0.0};
  EXPECT_TRUE(overlap(a, Ellipse{{1.0, 0.0}, 0.25, 0.0625, 0.0}));
  EXPECT_FALSE(overlap(a, Ellipse{{1.0 + 1e-9, 0.0}, 0.25, 0.0625, 0.0}));
  EXPECT_TRUE(overlap(a, Ellipse{{0.0, 0.5}, 2.0, 0.375, 0.0}));
  EXPECT_FALSE(overlap(a, Ellipse{{0.0, 0.5 * (1 + 1e-9)}, 2.0, 0.375, 0.0}));
  // Crossed like a plus sign: each holds the other's centre.
  EXPECT_TRUE(overlap(Ellipse{{0.0, 0.0}, 5.0, 0.01, 0.0}, Ellipse{{0.0, 0.0}, 5.0, 0.01, 1.5}));
}

TEST(Overlap, ContainmentIsACollision) {
  EXPECT_TRUE(overlap(Ellipse{{0.0, 0.0}, 10.0, 4.0, 0.3}, Ellipse{{1.0, 0.5}, 0.01, 0.02, -1.0}));
  EXPECT_TRUE(overlap(Ellipse{{5.0, 5.0}, 1.0, 1.0, 0.0}, Ellipse{{5.0, 5.0}, 1.0, 1.0, 0.0}));
}

TEST(Overlap, IsSymmetricAndTheCircleRejectionNeverContradictsTheExactStages) {
  test::RandomSource random(71);
  int collisions = 0;
  for (int i = 0; i < 20000; ++i) {
    const Ellipse a{{random.uniform(-2, 2), random.uniform(-2, 2)},
                    random.logUniform(0.01, 1.5),
                    random.logUniform(0.01, 1.5),
                    random.uniform(-4, 4)};
    const Ellipse b{{random.uniform(-2, 2), random.uniform(-2, 2)},
                    random.logUniform(0.01, 1.5),
                    random.logUniform(0.01, 1.5),
                    random.uniform(-4, 4)};
    const bool ab = overlap(a, b);
    EXPECT_EQ(ab, overlap(b, a)) << i;
    if (detail::circlesApart(a.center, b.center, boundingRadius(a) + boundingRadius(b))) {
      EXPECT_FALSE(ab);
      // The exact stages, asked anyway, agree: the rejection only saves their work.
      EXPECT_FALSE(detail::overlapOfNearPair(a, b)) << i;
    } else {
      EXPECT_EQ(ab, detail::overlapOfNearPair(a, b)) << i;
    }
    collisions += ab;
  }
  EXPECT_GT(collisions, 500);
  EXPECT_LT(collisions, 19000);
}

}  // namespace
}  // namespace ellipse_collision::core

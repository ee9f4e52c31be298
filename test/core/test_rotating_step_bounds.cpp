// The bounds the rotating contact steps rest on (src/core/rotating_step_bounds.h): the worst
// curvature in time of a turning ellipse's support function, against second differences of that
// function in long double over every direction and pose sampled, and reached where the closed
// form says; which ellipses count as turning.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "random_source.h"
#include "rotating_step_bounds.h"

namespace ellipse_collision::core::detail {
namespace {

using Long = long double;

/// The support function of an ellipse of radii (rx, ry) turned to `angle` along direction `phi`.
Long support(Long rx, Long ry, Long angle, Long phi) {
  const Long along = std::cos(phi - angle), across = std::sin(phi - angle);
  return std::sqrt(rx * rx * along * along + ry * ry * across * across);
}

TEST(RotatingStepBounds, SweepCurvatureBoundsTheSecondTimeDerivativeOfTheSupport) {
  test::RandomSource random(61);
  for (int i = 0; i < 300; ++i) {
    const Ellipse e{
        {0.0, 0.0}, random.uniform(0.01, 2.0), random.uniform(0.01, 2.0), random.uniform(-3, 3)};
    const double omega = random.uniform(-5, 5);
    const double bound = sweepCurvature(e, omega);
    Long worst = 0;
    const Long h = 1e-4L;
    // From the normal of the flat side (along the short axis), where the curvature peaks.
    const Long flat_normal = e.angle + (e.radius_x >= e.radius_y ? 1.5707963267948966L : 0.0L);
    for (int k = 0; k < 400; ++k) {
      const Long phi = flat_normal + 2 * 3.14159265358979323846L * k / 400;
      const auto at = [&](Long t) {
        return support(e.radius_x, e.radius_y, e.angle + omega * t, phi);
      };
      const Long second = (at(h) - 2 * at(0) + at(-h)) / (h * h);
      worst = std::max(worst, std::fabs(second));
      ASSERT_LE(std::fabs(second), bound * (1 + 1e-6) + 1e-9) << i << " phi " << double(phi);
    }
    // Reached at the flat side's normal: omega^2 (R^2 / r - r) exactly there, so the bound is
    // tight to the sampling.
    const Long big = std::max(e.radius_x, e.radius_y), small = std::min(e.radius_x, e.radius_y);
    EXPECT_NEAR(bound, double(Long(omega) * omega * (big * big / small - small)), 1e-12 * bound);
    EXPECT_GE(worst, 0.9L * bound) << i;
  }
}

TEST(RotatingStepBounds, CirclesAndStillEllipsesDoNotTurn) {
  const Ellipse circle{{0.0, 0.0}, 0.5, 0.5, 1.0}, ellipse{{0.0, 0.0}, 0.5, 0.25, 1.0};
  EXPECT_FALSE(turns(circle, 3.0));
  EXPECT_FALSE(turns(ellipse, 0.0));
  EXPECT_TRUE(turns(ellipse, -1e-300));
  EXPECT_EQ(sweepCurvature(circle, 3.0), 0.0);
  EXPECT_EQ(sweepCurvature(ellipse, 0.0), 0.0);
  EXPECT_EQ(sweepCurvature(ellipse, 2.0), 4.0 * (0.5 * 2.0 - 0.25));
}

}  // namespace
}  // namespace ellipse_collision::core::detail

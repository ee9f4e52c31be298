#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ellipse_collision/ellipse_collision.h"

namespace ellipse_collision::core {
namespace {

Ellipse valid() { return Ellipse{{1.0, 2.0}, 0.5, 0.25, 0.3}; }

TEST(InvalidReason, ValidEllipseHasNoReason) { EXPECT_EQ(invalidReason(valid()), ""); }

TEST(InvalidReason, NamesNonFiniteFieldAndValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Ellipse e = valid();
  e.center.x() = nan;
  EXPECT_EQ(invalidReason(e), "center.x = nan is not finite");
  e = valid();
  e.center.y() = -inf;
  EXPECT_EQ(invalidReason(e), "center.y = -inf is not finite");
  e = valid();
  e.angle = inf;
  EXPECT_EQ(invalidReason(e), "angle = inf is not finite");
  e = valid();
  e.radius_y = nan;
  EXPECT_EQ(invalidReason(e), "radius_y = nan is not finite");
}

TEST(InvalidReason, RejectsZeroAndNegativeRadiiWithTheirValue) {
  Ellipse e = valid();
  e.radius_x = 0.0;
  EXPECT_EQ(invalidReason(e), "radius_x = 0 must be > 0");
  e = valid();
  e.radius_y = -1.5;
  EXPECT_EQ(invalidReason(e), "radius_y = -1.5 must be > 0");
  e = valid();
  e.radius_x = -0.0;
  EXPECT_EQ(invalidReason(e), "radius_x = -0 must be > 0");
}

TEST(InvalidReason, ValueIsPrintedExactlyEnoughToReadBack) {
  Ellipse e = valid();
  e.radius_x = -0.1;
  EXPECT_EQ(invalidReason(e), "radius_x = -0.1 must be > 0");
  e.radius_x = -1e-300;
  EXPECT_EQ(invalidReason(e), "radius_x = -1e-300 must be > 0");
}

TEST(InvalidReason, AcceptsTheWholeDocumentedRange) {
  Ellipse e = valid();
  e.radius_x = kMinRadius;
  e.radius_y = kMaxRadius;
  e.center = {-kMaxCoordinate, kMaxCoordinate};
  EXPECT_EQ(invalidReason(e), "");
}

TEST(InvalidReason, RejectsLengthsOutsideTheRangeTheTestsAreExactIn) {
  Ellipse e = valid();
  e.radius_x = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(invalidReason(e), "radius_x = 5e-324 is outside [1e-09, 1e+09] m");
  e = valid();
  e.radius_y = 1e300;
  EXPECT_EQ(invalidReason(e), "radius_y = 1e+300 is outside [1e-09, 1e+09] m");
  e = valid();
  e.center.y() = -2e9;
  EXPECT_EQ(invalidReason(e), "center.y = -2e+09 is outside [-1e+09, 1e+09] m");
}

TEST(BoundingRadii, AreTheLargerAndSmallerSemiAxis) {
  const Ellipse e{{0.0, 0.0}, 0.5, 2.0, 1.0};
  EXPECT_EQ(boundingRadius(e), 2.0);
  EXPECT_EQ(inscribedRadius(e), 0.5);
}

}  // namespace
}  // namespace ellipse_collision::core

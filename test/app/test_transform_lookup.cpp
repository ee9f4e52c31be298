// The freshness rule of transforms (app/transform_lookup.h): which found transforms are too old
// for a check, and how old they are.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "ellipse_collision/app/transform_lookup.h"

namespace ellipse_collision::app {
namespace {

TEST(Freshness, OnlyStampedTransformsOlderThanTheMaximumAreStale) {
  FrameTransform transform;
  transform.ok = true;
  transform.stamp_s = 100.0;
  EXPECT_FALSE(isStale(transform, {0.5, 100.5})) << "exactly max_transform_age old is fresh";
  EXPECT_TRUE(isStale(transform, {0.5, 100.6}));
  EXPECT_NEAR(ageOf(transform, {0.5, 100.6}), 0.6, 1e-9);
  EXPECT_FALSE(isStale(transform, {0.0, 1e6})) << "max_transform_age 0 is off";
  EXPECT_FALSE(isStale(transform, {0.5, 99.0})) << "a transform from the future is not old";
  transform.stamp_s = 0.0;
  EXPECT_FALSE(isStale(transform, {0.5, 1e6})) << "static chains (stamp 0) never go stale";
  EXPECT_EQ(ageOf(transform, {0.5, 1e6}), 0.0);
  transform.ok = false;
  transform.stamp_s = 1.0;
  EXPECT_FALSE(isStale(transform, {0.5, 1e6})) << "unavailable is not stale";
}

TEST(Freshness, AgeIsTheReferenceMinusTheStampWhateverTheMaximum) {
  FrameTransform transform;
  transform.ok = true;
  transform.stamp_s = 12.25;
  // Binary fractions, so that the differences are exact.
  EXPECT_EQ(ageOf(transform, {0.0, 20.5}), 8.25) << "the age does not depend on the rule";
  EXPECT_EQ(ageOf(transform, {3.0, 10.0}), -2.25) << "a transform from the future is younger";
  EXPECT_EQ(ageOf(transform, {3.0, 12.25}), 0.0);
  transform.ok = false;
  EXPECT_EQ(ageOf(transform, {3.0, 20.5}), 8.25) << "an unavailable transform still has an age";
}

TEST(Freshness, TheMaximumIsExclusiveAtTheLastRepresentableStep) {
  FrameTransform transform;
  transform.ok = true;
  transform.stamp_s = 1.0;
  const double max_age = 0.5;
  const double limit = 1.5;  // stamp + max_age, exact
  EXPECT_FALSE(isStale(transform, {max_age, limit}));
  EXPECT_TRUE(isStale(transform, {max_age, std::nextafter(limit, 2.0)}));
  EXPECT_TRUE(isStale(transform, {max_age, std::numeric_limits<double>::infinity()}));
  EXPECT_FALSE(isStale(transform, {-1.0, 1e6})) << "a negative maximum is off like 0";
}

TEST(Freshness, ADefaultTransformIsUnavailableTimelessAndNeverStale) {
  const FrameTransform transform;
  EXPECT_FALSE(transform.ok);
  EXPECT_EQ(transform.stamp_s, 0.0);
  EXPECT_TRUE(transform.fixed_from_frame.matrix().isIdentity(0.0));
  EXPECT_FALSE(isStale(transform, {0.5, 1e6}));
  EXPECT_EQ(ageOf(transform, {0.5, 1e6}), 0.0);
}

}  // namespace
}  // namespace ellipse_collision::app

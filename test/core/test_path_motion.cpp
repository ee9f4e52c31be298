// The rigid motion of a frame between two path poses (core/path_motion.h): the shortest turn,
// poses and moves against closed forms, swept boxes holding the exact extents of the moving
// ellipse at every sampled time (long double), and segmentContact() against closed-form contact
// times of circles on a line and on an arc.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ellipse_collision/core/path_motion.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace {

using Long = long double;
constexpr Long kPiL = 3.141592653589793238462643383279502884L;
constexpr double kPi = 3.14159265358979323846;

TEST(PathMotion, ShortestRotationIsTheDifferenceWrappedIntoPlusMinusPi) {
  EXPECT_EQ(shortestRotation(0.0, 0.5), 0.5);
  EXPECT_EQ(shortestRotation(0.5, 0.0), -0.5);
  EXPECT_NEAR(shortestRotation(3.0, -3.0), 2 * kPi - 6.0, 1e-15) << "across the seam";
  EXPECT_NEAR(shortestRotation(0.0, 1.5 * kPi), -0.5 * kPi, 1e-15);
  EXPECT_NEAR(shortestRotation(-20.0, 20.0), static_cast<double>(40.0L - 6 * 2 * kPiL), 1e-13);
  test::RandomSource random(7);
  for (int i = 0; i < 1000; ++i) {
    const double from = random.uniform(-50.0, 50.0), to = random.uniform(-50.0, 50.0);
    const double turn = shortestRotation(from, to);
    EXPECT_LE(std::fabs(turn), kPi);
    // A whole number of turns apart from the plain difference, in long double.
    const Long turns = (Long(to) - from - turn) / (2 * kPiL);
    EXPECT_NEAR(static_cast<double>(turns), std::round(static_cast<double>(turns)), 1e-12);
  }
}

TEST(PathMotion, SegmentMotionIsUniformInTau) {
  const SegmentMotion m = segmentMotion({1.0, 2.0, 3.0, 0.0}, {4.0, -2.0, -3.0, 5.0}, 2.0);
  EXPECT_EQ(m.start, Eigen::Vector2d(1.0, 2.0));
  EXPECT_EQ(m.velocity, Eigen::Vector2d(1.5, -2.0));
  EXPECT_EQ(m.start_yaw, 3.0);
  EXPECT_NEAR(m.yaw_rate, (2 * kPi - 6.0) / 2.0, 1e-15);
  EXPECT_EQ(m.duration, 2.0);
}

TEST(PathMotion, PlaceAtTurnsAboutTheFrameOriginAndMovedByMovesTheCentre) {
  const Ellipse link{{1.0, 0.5}, 0.4, 0.2, 0.25};
  const Ellipse placed = placeAt(link, {10.0, -1.0}, 0.5);
  const Long c = std::cos(0.5L), s = std::sin(0.5L);
  EXPECT_NEAR(placed.center.x(), static_cast<double>(10.0L + c * 1.0L - s * 0.5L), 1e-14);
  EXPECT_NEAR(placed.center.y(), static_cast<double>(-1.0L + s * 1.0L + c * 0.5L), 1e-14);
  EXPECT_EQ(placed.angle, 0.75);
  EXPECT_EQ(placed.radius_x, 0.4);
  const Ellipse moved = movedBy(link, Motion{{2.0, -4.0}, 0.5}, 0.25);
  EXPECT_EQ(moved.center, Eigen::Vector2d(1.5, -0.5));
  EXPECT_EQ(moved.angle, 0.375);
  EXPECT_EQ(moved.radius_y, 0.2);
}

/// The exact half-extents of `e` along x and y.
void extents(const Ellipse& e, Long angle, Long* half_x, Long* half_y) {
  const Long c = std::cos(angle), s = std::sin(angle);
  *half_x =
      std::sqrt(Long(e.radius_x) * e.radius_x * c * c + Long(e.radius_y) * e.radius_y * s * s);
  *half_y =
      std::sqrt(Long(e.radius_x) * e.radius_x * s * s + Long(e.radius_y) * e.radius_y * c * c);
}

bool holds(const BoundingBox& box, Long cx, Long cy, Long half_x, Long half_y) {
  return box.min_x <= cx - half_x && cx + half_x <= box.max_x && box.min_y <= cy - half_y &&
         cy + half_y <= box.max_y;
}

TEST(PathMotion, SweptBoxHoldsTheEllipseAtEveryTime) {
  test::RandomSource random(8);
  for (int trial = 0; trial < 200; ++trial) {
    const Ellipse e{{random.uniform(-100, 100), random.uniform(-100, 100)},
                    random.uniform(0.01, 2.0),
                    random.uniform(0.01, 2.0),
                    random.uniform(-3, 3)};
    const Motion motion{{random.uniform(-3, 3), random.uniform(-3, 3)}, random.uniform(-2, 2)};
    const double horizon = random.uniform(0.1, 5.0);
    const BoundingBox box = sweptBox(e, motion, horizon);
    for (int k = 0; k <= 200; ++k) {
      const Long t = Long(horizon) * k / 200;
      Long hx, hy;
      extents(e, e.angle + motion.angular_velocity * t, &hx, &hy);
      ASSERT_TRUE(holds(box, e.center.x() + motion.velocity.x() * t,
                        e.center.y() + motion.velocity.y() * t, hx, hy))
          << "trial " << trial << " t " << double(t);
    }
  }
}

TEST(PathMotion, SweptLinkBoxHoldsTheLinkOnItsArcAndIsNotMuchLarger) {
  test::RandomSource random(9);
  for (int trial = 0; trial < 200; ++trial) {
    const Ellipse link{{random.uniform(-2, 2), random.uniform(-2, 2)},
                       random.uniform(0.01, 0.5),
                       random.uniform(0.01, 0.5),
                       random.uniform(-3, 3)};
    const PathPose from{random.uniform(-50, 50), random.uniform(-50, 50), random.uniform(-3, 3), 0};
    const PathPose to{from.x + random.uniform(-1, 1), from.y + random.uniform(-1, 1),
                      random.uniform(-3, 3), 0};
    const SegmentMotion m = segmentMotion(from, to, 1.0);
    const BoundingBox box = sweptLinkBox(link, m);
    Long low_x = 1e300L, high_x = -1e300L;
    for (int k = 0; k <= 400; ++k) {
      const Long tau = Long(k) / 400;
      const Long yaw = Long(m.start_yaw) + Long(m.yaw_rate) * tau;
      const Long c = std::cos(yaw), s = std::sin(yaw);
      const Long cx =
          m.start.x() + m.velocity.x() * tau + c * link.center.x() - s * link.center.y();
      const Long cy =
          m.start.y() + m.velocity.y() * tau + s * link.center.x() + c * link.center.y();
      Long hx, hy;
      extents(link, Long(link.angle) + yaw, &hx, &hy);
      ASSERT_TRUE(holds(box, cx, cy, hx, hy)) << "trial " << trial << " tau " << double(tau);
      low_x = std::min(low_x, cx - hx);
      high_x = std::max(high_x, cx + hx);
    }
    // Wider than the sweep only by the bounding circle and the sagitta on either side.
    const double sagitta = link.center.norm() * (1.0 - std::cos(0.5 * m.yaw_rate * m.duration));
    const double slack = std::max(link.radius_x, link.radius_y) + sagitta + 1e-9;
    EXPECT_LE(box.max_x - box.min_x, double(high_x - low_x) + 2 * slack) << "trial " << trial;
  }
}

TEST(PathMotion, ACentredLinkOnALineTouchesWhenTheGapIsCovered) {
  // Circles of radii 0.3 and 0.2, 5 m apart along x, the link at 3 m per unit of tau for 2.
  const SegmentMotion m = segmentMotion({0.0, 0.0, 0.0, 0.0}, {6.0, 0.0, 0.7, 0.0}, 2.0);
  const Ellipse link{{0.0, 0.0}, 0.3, 0.3, 0.0};
  const Ellipse obstacle{{5.0, 0.0}, 0.2, 0.2, 0.0};
  const FirstContact contact = segmentContact(link, m, obstacle, Motion{});
  ASSERT_TRUE(contact.contact);
  EXPECT_NEAR(contact.time, (5.0 - 0.5) / 3.0, 1e-12);
  EXPECT_FALSE(segmentContact(link, m, Ellipse{{5.0, 0.51}, 0.2, 0.2, 0.0}, Motion{}).contact);
  EXPECT_FALSE(segmentContact(link, m, Ellipse{{6.6, 0.0}, 0.2, 0.2, 0.0}, Motion{}).contact)
      << "beyond the segment's end";
  // An obstacle coming the other way at 0.5 per unit of tau: the gap closes at 3.5.
  const FirstContact head_on = segmentContact(link, m, obstacle, Motion{{-0.5, 0.0}, 0.0});
  ASSERT_TRUE(head_on.contact);
  EXPECT_NEAR(head_on.time, 4.5 / 3.5, 1e-12);
}

TEST(PathMotion, AnOffsetLinkOfATurningFrameTouchesWhereItsArcMeetsTheObstacle) {
  // The frame turns a quarter turn in place; a circle of radius 0.1 at (1, 0) of it sweeps the
  // unit circle towards an obstacle circle of radius 0.15 at (0, 1): the centres are
  // 2 sin((pi/2 - theta) / 2) apart at angle theta, touching at 0.25 of it.
  const SegmentMotion m = segmentMotion({0.0, 0.0, 0.0, 0.0}, {0.0, 0.0, kPi / 2, 0.0}, 1.0);
  const Ellipse link{{1.0, 0.0}, 0.1, 0.1, 0.0};
  const Ellipse obstacle{{0.0, 1.0}, 0.15, 0.15, 0.0};
  const Long theta = kPiL / 2 - 2 * std::asin(0.25L / 2);
  const double exact = static_cast<double>(theta / (kPiL / 2));
  const FirstContact contact = segmentContact(link, m, obstacle, Motion{});
  ASSERT_TRUE(contact.contact);
  EXPECT_LE(contact.time, exact + 1e-15) << "never late";
  EXPECT_GE(contact.time, exact - 2.5e-10) << "within the documented resolution";
  // Placed already touching at tau = 0: contact at 0.
  EXPECT_EQ(segmentContact(link, m, Ellipse{{1.0, 0.2}, 0.15, 0.15, 0.0}, Motion{}).time, 0.0);
  // A smaller turn stops short of it.
  const SegmentMotion short_turn =
      segmentMotion({0.0, 0.0, 0.0, 0.0}, {0.0, 0.0, 0.9 * static_cast<double>(theta), 0.0}, 1.0);
  EXPECT_FALSE(segmentContact(link, short_turn, obstacle, Motion{}).contact);
}

TEST(PathMotion, InvalidSegmentReasonNamesTheObstaclesMotionLimits) {
  const Ellipse obstacle{{0.0, 0.0}, 0.2, 0.2, 0.0};
  EXPECT_EQ(invalidSegmentReason(obstacle, Motion{{1.0, 0.0}, 0.5}, 3.0), "");
  EXPECT_NE(invalidSegmentReason(obstacle, Motion{{2e9, 0.0}, 0.0}, 1.0), "");
  EXPECT_NE(invalidSegmentReason(obstacle, Motion{{NAN, 0.0}, 0.0}, 1.0), "");
  EXPECT_NE(invalidSegmentReason(obstacle, Motion{{0.0, 0.0}, 50.0}, 3.0), "")
      << "150 rad is beyond kMaxTurn";
}

}  // namespace
}  // namespace ellipse_collision::core

// The pair the rotating contact search steps (src/core/rotating_pair.h): b's pose relative to a's
// centre at any t against the two motions written out in long double (lines, turns and the arc
// of a link offset in a turning frame), with what rounding left out kept in the low parts.
#include <gtest/gtest.h>

#include <cmath>

#include "ellipse_collision/core/path_motion.h"
#include "random_source.h"
#include "rotating_pair.h"

namespace ellipse_collision::core::detail {
namespace {

using Long = long double;

TEST(RotatingPair, BIsPlacedRelativeToACentreAndTheLowPartsCompleteIt) {
  test::RandomSource random(31);
  for (int i = 0; i < 1000; ++i) {
    const double out = random.logUniform(1.0, 1e6);
    const Ellipse a{{random.uniform(-1, 1) * out, random.uniform(-1, 1) * out}, 0.5, 0.2, 0.3};
    const Ellipse b{{a.center.x() + random.uniform(-3, 3), a.center.y() + random.uniform(-3, 3)},
                    0.4,
                    0.1,
                    -1.0};
    const Eigen::Vector2d va(random.uniform(-2, 2), random.uniform(-2, 2));
    const Motion mb{{random.uniform(-2, 2), random.uniform(-2, 2)}, random.uniform(-1, 1)};
    const double wa = random.uniform(-1, 1);
    const RotatingPair p = rotatingPair(a, va, Eigen::Vector2d::Zero(), wa, b, mb);
    EXPECT_EQ(p.a.center, Eigen::Vector2d::Zero());
    EXPECT_EQ(p.wa, wa);
    EXPECT_EQ(p.wb, mb.angular_velocity);
    EXPECT_FALSE(p.hasArc());
    for (int k = 0; k < 2; ++k) {
      // high + low is the difference to long double precision.
      const Long centre = Long(b.center[k]) - a.center[k], w = Long(mb.velocity[k]) - va[k];
      EXPECT_LE(std::fabs(Long(p.b.center[k]) + p.low.b_center[k] - centre),
                1e-19L * std::fabs(centre));
      EXPECT_LE(std::fabs(Long(p.w[k]) + p.low.w[k] - w), 1e-19L * std::fabs(w));
      EXPECT_FALSE(p.low.b_center[k] == 0.0 && centre != Long(p.b.center[k]))
          << "what rounding left out is kept";
    }
    const double t = random.uniform(0.0, 2.0);
    const Ellipse bt = p.bAt(t), at = p.aAt(t);
    for (int k = 0; k < 2; ++k) {
      // The centres' difference first: exact in long double, where 1e6 m out a sum would round.
      const Long exact =
          (Long(b.center[k]) - a.center[k]) + (Long(mb.velocity[k]) - va[k]) * Long(t);
      EXPECT_NEAR(bt.center[k], double(exact), 1e-14 * (1 + std::fabs(double(exact))));
    }
    EXPECT_NEAR(bt.angle, b.angle + mb.angular_velocity * t, 1e-15);
    EXPECT_NEAR(at.angle, a.angle + wa * t, 1e-15);
    EXPECT_EQ(p.centreVelocityAt(t), p.w);
  }
}

TEST(RotatingPair, AnOffsetLinkOfATurningSegmentMovesOnItsArc) {
  test::RandomSource random(32);
  for (int i = 0; i < 500; ++i) {
    const Ellipse link{
        {random.uniform(-2, 2), random.uniform(-2, 2)}, 0.3, 0.1, random.uniform(-3, 3)};
    const PathPose from{random.uniform(-100, 100), random.uniform(-100, 100), random.uniform(-3, 3),
                        0};
    const PathPose to{from.x + random.uniform(-1, 1), from.y + random.uniform(-1, 1),
                      from.yaw + random.uniform(-2, 2), 0};
    const SegmentMotion m = segmentMotion(from, to, random.uniform(0.5, 2.0));
    const Ellipse obstacle{
        {from.x + random.uniform(-3, 3), from.y + random.uniform(-3, 3)}, 0.2, 0.2, 0.0};
    const Motion om{{random.uniform(-1, 1), random.uniform(-1, 1)}, random.uniform(-1, 1)};
    const RotatingPair p = segmentPair(link, m, obstacle, om);
    ASSERT_TRUE(p.hasArc() || (link.center.isZero() || m.yaw_rate == 0.0));
    for (int k = 0; k <= 8; ++k) {
      const Long tau = Long(m.duration) * k / 8;
      // The link's centre: the frame's origin on the line plus R(yaw(tau)) c; the obstacle's on
      // its line. b's centre in the pair is their difference.
      const Long yaw = Long(m.start_yaw) + Long(m.yaw_rate) * tau;
      const Long c = std::cos(yaw), s = std::sin(yaw);
      const Long lx =
          m.start.x() + m.velocity.x() * tau + c * link.center.x() - s * link.center.y();
      const Long ly =
          m.start.y() + m.velocity.y() * tau + s * link.center.x() + c * link.center.y();
      const Long ox = obstacle.center.x() + om.velocity.x() * tau;
      const Long oy = obstacle.center.y() + om.velocity.y() * tau;
      const Ellipse bt = p.bAt(double(tau)), at = p.aAt(double(tau));
      EXPECT_NEAR(bt.center.x(), double(ox - lx), 1e-12) << i << " tau " << double(tau);
      EXPECT_NEAR(bt.center.y(), double(oy - ly), 1e-12) << i << " tau " << double(tau);
      EXPECT_NEAR(at.angle, double(Long(link.angle) + yaw), 1e-13);
      EXPECT_NEAR(bt.angle, obstacle.angle + om.angular_velocity * double(tau), 1e-14);
      // The centre's velocity against a central difference of the exact path.
      const Long h = 1e-6L;
      const auto lxAt = [&](Long t) {
        const Long y = Long(m.start_yaw) + Long(m.yaw_rate) * t;
        return Long(m.velocity.x()) * t + std::cos(y) * link.center.x() -
               std::sin(y) * link.center.y();
      };
      const Long dlx = (lxAt(tau + h) - lxAt(tau - h)) / (2 * h);
      EXPECT_NEAR(p.centreVelocityAt(double(tau)).x(), double(om.velocity.x() - dlx), 1e-8);
    }
  }
}

}  // namespace
}  // namespace ellipse_collision::core::detail

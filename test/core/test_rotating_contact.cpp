// detail::rotatingContact() (src/core/rotating_contact.*) on its own, against an oracle that
// shares none of its code: the pair's poses at t evaluated in long double from the motion (a's
// centre on its arc integrated in closed form), overlap judged by the quad-precision contact scale
// (contact_scale_oracle.h), the first contact found by dense sampling, golden-section search of
// the sampled minima near 1 and bisection. Transversal crossings only (a pair whose minimum comes
// within 1e-6 of touching is left to the grazing families of test_first_contact,
// test_path_check and test_velocity_gate): the answer must never be late and at most the
// resolution early. Also largestCentreSpeed() against dense sampling.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "contact_scale_oracle.h"
#include "ellipse_collision/core/ellipse.h"
#include "random_source.h"
#include "rotating_contact.h"

namespace ellipse_collision::core {
namespace {

using Long = long double;
using detail::RotatingPair;

// Samples of the oracle over the horizon, and the bisection steps on the first crossing.
constexpr int kSamples = 500;
constexpr int kBisections = 60;
// A sampled local minimum of the contact scale below this, before the first crossing, may hide a
// contact between the samples: it is refined.
constexpr double kGrazingMargin = 1.1;
// The oracle's poses are rounded to double: its crossing time is exact to about this [horizon].
constexpr double kOracleSlack = 1e-12;

// The pose of `e` after turning by `angle` with its centre at (x, y).
Ellipse posed(const Ellipse& e, Long x, Long y, Long angle) {
  Ellipse out = e;
  out.center = {static_cast<double>(x), static_cast<double>(y)};
  out.angle = static_cast<double>(angle);
  return out;
}

// The contact scale of the pair at t, its poses from the motion in long double: a turns at wa
// about its centre, which moves by the integral of R(wa s) v_arc; b's centre moves at w (both in
// the frame of a's centre at t = 0) and b turns at wb.
double scaleAt(const RotatingPair& p, Long t) {
  const auto exact = [](double high, double low) { return Long(high) + Long(low); };
  const Long vx = exact(p.a_arc_velocity.x(), p.low.a_arc_velocity.x());
  const Long vy = exact(p.a_arc_velocity.y(), p.low.a_arc_velocity.y());
  Long arc_x = vx * t, arc_y = vy * t;
  if (p.wa != 0.0) {
    const Long turn = Long(p.wa) * t;
    const Long s = std::sin(turn), one_minus_c = 2 * std::sin(turn / 2) * std::sin(turn / 2);
    arc_x = (s * vx - one_minus_c * vy) / Long(p.wa);
    arc_y = (one_minus_c * vx + s * vy) / Long(p.wa);
  }
  const Long bx = exact(p.b.center.x(), p.low.b_center.x()) + exact(p.w.x(), p.low.w.x()) * t;
  const Long by = exact(p.b.center.y(), p.low.b_center.y()) + exact(p.w.y(), p.low.w.y()) * t;
  // b relative to a's moving centre: a stays at the origin.
  const Ellipse a = posed(p.a, 0, 0, exact(p.a.angle, p.low.a_angle) + Long(p.wa) * t);
  const Ellipse b = posed(p.b, bx - arc_x, by - arc_y, Long(p.b.angle) + Long(p.wb) * t);
  return test::oracleContactScale(a, b).value;
}

struct OracleAnswer {
  bool judged{false};  // false: the pair comes too close to grazing to be judged by samples
  bool contact{false};
  double time{0.0};  // the first crossing of scale 1 [s]
};

// The first t in [lo, hi] where the scale is <= 1, given it is > 1 at lo and <= 1 at hi.
Long firstCrossing(const RotatingPair& p, Long lo, Long hi) {
  for (int i = 0; i < kBisections; ++i) {
    const Long mid = (lo + hi) / 2;
    (scaleAt(p, mid) <= 1.0 ? hi : lo) = mid;
  }
  return hi;
}

OracleAnswer oracleFirstContact(const RotatingPair& p, double horizon) {
  OracleAnswer answer;
  const auto timeOf = [horizon](int k) { return Long(horizon) * k / kSamples; };
  const auto contactAt = [&](Long lo, Long hi) {
    answer.contact = true;
    answer.time = static_cast<double>(firstCrossing(p, lo, hi));
    // Transversal: overlapping by a percent of the scale a hundredth of the horizon later (or
    // at the horizon).
    const Long deeper = std::min(Long(answer.time) + Long(horizon) / 100, Long(horizon));
    answer.judged = deeper == Long(answer.time) || scaleAt(p, deeper) < 0.99;
    return answer;
  };
  double before = scaleAt(p, 0.0), previous = before;
  if (!(before > kGrazingMargin)) return answer;  // apart at t = 0 with room to spare
  for (int k = 1; k <= kSamples; ++k) {
    const double scale = scaleAt(p, timeOf(k));
    if (scale <= 1.0) return contactAt(timeOf(k - 1), timeOf(k));
    // A sampled local minimum near 1 may hide a contact between the samples: the minimum is
    // refined by golden-section search between the neighbours of sample k - 1.
    if (k >= 2 && scale > previous && previous < before && previous < kGrazingMargin) {
      Long lo = timeOf(k - 2), hi = timeOf(k);
      const Long golden = (std::sqrt(Long(5)) - 1) / 2;
      Long x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
      double f1 = scaleAt(p, x1), f2 = scaleAt(p, x2);
      for (int i = 0; i < kBisections && f1 > 1.0 && f2 > 1.0; ++i) {
        if (f1 < f2) {
          hi = x2, x2 = x1, f2 = f1, x1 = hi - golden * (hi - lo), f1 = scaleAt(p, x1);
        } else {
          lo = x1, x1 = x2, f1 = f2, x2 = lo + golden * (hi - lo), f2 = scaleAt(p, x2);
        }
      }
      if (f1 <= 1.0) return contactAt(timeOf(k - 2), x1);
      if (f2 <= 1.0) return contactAt(timeOf(k - 2), x2);
      if (std::min(f1, f2) < 1.0 + 1e-6) return answer;  // a tangency: not judged here
    }
    before = previous;
    previous = scale;
  }
  // No crossing: judged unless the scale ends near 1 and still falling.
  answer.judged = !(previous < kGrazingMargin && previous < before);
  return answer;
}

std::string describe(const RotatingPair& p, double horizon) {
  char text[512];
  std::snprintf(text, sizeof text,
                "a = {%.17g, %.17g, %.17g} wa = %.17g arc v = (%.17g, %.17g); b = {%.17g, %.17g, "
                "%.17g, %.17g, %.17g} w = (%.17g, %.17g) wb = %.17g; horizon %.17g",
                p.a.radius_x, p.a.radius_y, p.a.angle, p.wa, p.a_arc_velocity.x(),
                p.a_arc_velocity.y(), p.b.center.x(), p.b.center.y(), p.b.radius_x, p.b.radius_y,
                p.b.angle, p.w.x(), p.w.y(), p.wb, horizon);
  return text;
}

RotatingPair pairOf(const Ellipse& a, double wa, const Eigen::Vector2d& a_arc_velocity,
                    const Ellipse& b, const Motion& motion_b) {
  return detail::rotatingPair(a, Eigen::Vector2d::Zero(), a_arc_velocity, wa, b, motion_b);
}

// Checks the answer against the oracle's (not judged: nothing to check).
void expectAgreesWithOracle(const RotatingPair& p, double horizon, const OracleAnswer& oracle) {
  if (!oracle.judged) return;
  detail::RotationWork work;
  const FirstContact found = detail::rotatingContact(p, horizon, &work);
  EXPECT_FALSE(work.capped) << describe(p, horizon);
  EXPECT_GT(work.distance_calls, 0) << describe(p, horizon);
  EXPECT_EQ(found.contact, oracle.contact) << describe(p, horizon);
  if (!found.contact || !oracle.contact) return;
  // Never late, at most one resolution early.
  EXPECT_LE(found.time, oracle.time + kOracleSlack * horizon) << describe(p, horizon);
  EXPECT_GE(found.time, oracle.time - (detail::kRotationResolution + kOracleSlack) * horizon)
      << describe(p, horizon);
}

TEST(RotatingContact, TwoTurningEllipsesMeetNeverLateWithinResolution) {
  const RotatingPair p = pairOf({{0.0, 0.0}, 1.0, 0.3, 0.0}, 2.0, {0.0, 0.0},
                                {{3.0, 0.2}, 0.8, 0.2, 0.5}, Motion{{-1.0, 0.0}, -3.0});
  const OracleAnswer oracle = oracleFirstContact(p, 3.0);
  ASSERT_TRUE(oracle.judged && oracle.contact) << describe(p, 3.0);
  expectAgreesWithOracle(p, 3.0, oracle);
}

TEST(RotatingContact, TurningNeedleSweepsIntoDisc) {
  // The needle's tip sweeps the disc about 0.31 s in: a fixed direction sees its flat side curve
  // at omega^2 R^2 / r, the turning direction does not.
  const RotatingPair p =
      pairOf({{0.0, 0.0}, 2.0, 0.01, 0.0}, 1.5, {0.0, 0.0}, {{1.5, 1.0}, 0.2, 0.2, 0.0}, Motion{});
  const OracleAnswer oracle = oracleFirstContact(p, 2.0);
  ASSERT_TRUE(oracle.judged && oracle.contact) << describe(p, 2.0);
  EXPECT_NEAR(oracle.time, 0.31, 0.05);
  expectAgreesWithOracle(p, 2.0, oracle);
}

TEST(RotatingContact, LinkOnAnArcMeetsApproachingObstacle) {
  // a's centre on an arc of radius 1 about (-1, 0), as a link of a turning frame; they meet about
  // 1.1 s in.
  const RotatingPair p = pairOf({{0.0, 0.0}, 0.5, 0.2, 0.3}, 1.0, {0.0, 1.0},
                                {{2.0, 0.5}, 0.3, 0.3, 0.0}, Motion{{-2.0, 0.0}, 0.0});
  ASSERT_TRUE(p.hasArc());
  const OracleAnswer oracle = oracleFirstContact(p, 2.0);
  ASSERT_TRUE(oracle.judged && oracle.contact) << describe(p, 2.0);
  EXPECT_NEAR(oracle.time, 1.1, 0.2);
  expectAgreesWithOracle(p, 2.0, oracle);
}

TEST(RotatingContact, ClearPassIsClear) {
  // b passes 0.5 m beyond the reach of a's turning tips.
  const RotatingPair p = pairOf({{0.0, 0.0}, 1.0, 0.1, 0.0}, 3.0, {0.0, 0.0},
                                {{-4.0, 1.7}, 0.2, 0.1, 0.0}, Motion{{2.0, 0.0}, 1.0});
  const OracleAnswer oracle = oracleFirstContact(p, 4.0);
  ASSERT_TRUE(oracle.judged && !oracle.contact) << describe(p, 4.0);
  expectAgreesWithOracle(p, 4.0, oracle);
}

TEST(RotatingContact, RandomTurningPairsAgreeWithOracle) {
  ellipse_collision::test::RandomSource random(40);
  int judged = 0, contacts = 0;
  const int pairs = 12;
  for (int i = 0; i < pairs; ++i) {
    const double radius_a = random.uniform(0.2, 1.0), radius_b = random.uniform(0.1, 0.8);
    const Ellipse a{
        {0.0, 0.0}, radius_a, radius_a * random.logUniform(0.02, 1.0), random.uniform(-3.0, 3.0)};
    const double bearing = random.uniform(-3.0, 3.0), range = random.uniform(2.0, 4.0);
    const Ellipse b{{range * std::cos(bearing), range * std::sin(bearing)},
                    radius_b,
                    radius_b * random.logUniform(0.05, 1.0),
                    random.uniform(-3.0, 3.0)};
    // b heads roughly towards a, missing by up to its own reach.
    const double heading = bearing + 3.14159265358979323846 + random.uniform(-0.5, 0.5);
    const double speed = random.uniform(0.5, 2.0);
    const Motion motion_b{{speed * std::cos(heading), speed * std::sin(heading)},
                          random.uniform(-4.0, 4.0)};
    const double wa = random.uniform(-4.0, 4.0);
    const Eigen::Vector2d arc =
        random.coin() ? Eigen::Vector2d(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0))
                      : Eigen::Vector2d::Zero();
    const RotatingPair p = pairOf(a, wa, arc, b, motion_b);
    const double horizon = 3.0;
    const OracleAnswer oracle = oracleFirstContact(p, horizon);
    expectAgreesWithOracle(p, horizon, oracle);
    judged += oracle.judged ? 1 : 0;
    contacts += oracle.judged && oracle.contact ? 1 : 0;
  }
  std::printf("random turning pairs: %d of %d judged, %d in contact\n", judged, pairs, contacts);
  // Enough of both kinds for the family to mean something.
  EXPECT_GE(judged, pairs / 2);
  EXPECT_GE(contacts, 3);
  EXPECT_GE(judged - contacts, 2);
}

TEST(RotatingContact, UntilStopsBeforeALaterContactAndKeepsAnEarlierOne) {
  const RotatingPair p = pairOf({{0.0, 0.0}, 1.0, 0.3, 0.0}, 2.0, {0.0, 0.0},
                                {{3.0, 0.2}, 0.8, 0.2, 0.5}, Motion{{-1.0, 0.0}, -3.0});
  const double horizon = 3.0;
  const FirstContact full = detail::rotatingContact(p, horizon);
  ASSERT_TRUE(full.contact);
  ASSERT_GT(full.time, 0.1);
  EXPECT_FALSE(detail::rotatingContact(p, horizon, nullptr, 0.5 * full.time).contact);
  const FirstContact later =
      detail::rotatingContact(p, horizon, nullptr, full.time + 0.25 * (horizon - full.time));
  EXPECT_TRUE(later.contact);
  EXPECT_EQ(later.time, full.time);
}

TEST(RotatingContact, LargestCentreSpeedBoundsSampledSpeedTightly) {
  ellipse_collision::test::RandomSource random(41);
  for (int i = 0; i < 12; ++i) {
    const Eigen::Vector2d w(random.uniform(-2.0, 2.0), random.uniform(-2.0, 2.0));
    const Eigen::Vector2d v(random.uniform(-2.0, 2.0), random.uniform(-2.0, 2.0));
    const double turn = random.uniform(-7.0, 7.0);
    Long sampled = 0;
    constexpr int kSpeedSamples = 20000;
    for (int k = 0; k <= kSpeedSamples; ++k) {
      const Long s = Long(turn) * k / kSpeedSamples, c = std::cos(s), sn = std::sin(s);
      const Long x = w.x() - (c * v.x() - sn * v.y()), y = w.y() - (sn * v.x() + c * v.y());
      sampled = std::max(sampled, std::sqrt(x * x + y * y));
    }
    const double bound = detail::largestCentreSpeed(w, v, turn);
    EXPECT_GE(bound, static_cast<double>(sampled)) << i;
    // The samples miss the maximum by at most |w| |v| step^2 / 2 (step <= 3.5e-4 rad) over it.
    EXPECT_LE(bound, static_cast<double>(sampled) * (1.0 + 1e-6)) << i;
  }
}

}  // namespace
}  // namespace ellipse_collision::core

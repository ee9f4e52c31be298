// Motion under a held twist (core/twist_motion.h): poses against the arc about the instantaneous
// centre in quad precision, twistContact() against the quad translation oracle and a dense
// overlap() scan of the exact arc.
#include <gtest/gtest.h>
#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/twist_motion.h"
#include "first_contact_oracle.h"
#include "grazing_tally.h"
#include "random_source.h"
#include "rotating_contact.h"
#include "scene_test_helpers.h"
#include "twist_motion_detail.h"
#include "twist_oracle.h"

namespace ellipse_collision::core {
namespace {

using scene_test::ellipse;
using namespace twist_oracle;

NamedEllipse link(const std::string& name, const Ellipse& e) {
  return {name, EllipseRole::Link, e};
}

// ---- poses ----------------------------------------------------------------------------------

TEST(TwistPose, MatchesTheArcAboutTheInstantaneousCentreForEveryTurnRate) {
  // Mutation tried: across = (1 - cos(wz t)) / wz -> fails at the tiny turn rates (cancellation).
  const Ellipse origin_link = ellipse(0.0, 0.0, 0.1, 0.1);
  for (double wz : {2.0, -0.3, 1e-3, 1e-6, -1e-9, 1e-12, 1e-15}) {
    const Twist twist{0.7, -0.4, wz};
    for (double t : {0.01, 0.5, 3.0}) {
      const PathPose pose = poseAfter(twist, t);
      const Ellipse oracle = oracleLinkAt(origin_link, twist, t);
      const double scale = std::hypot(twist.vx, twist.vy) * t;
      EXPECT_NEAR(pose.x, oracle.center.x(), 4e-16 * scale) << wz << " " << t;
      EXPECT_NEAR(pose.y, oracle.center.y(), 4e-16 * scale) << wz << " " << t;
      EXPECT_EQ(pose.yaw, wz * t);
      EXPECT_EQ(pose.time, t);
    }
  }
  // A turn rate too small for the quad oracle's centre (1e300 m out): the line.
  const PathPose tiny = poseAfter({0.7, -0.4, 1e-300}, 3.0);
  EXPECT_EQ(tiny.x, 0.7 * 3.0);
  EXPECT_EQ(tiny.y, -0.4 * 3.0);
  // No turn: exactly the line.
  const PathPose line = poseAfter({1.5, -2.0, 0.0}, 2.0);
  EXPECT_EQ(line.x, 3.0);
  EXPECT_EQ(line.y, -4.0);
}

TEST(TwistPose, LinksAtTimeKeepNamesAndPlaceEachLinkOnItsArc) {
  // Mutation tried: linksAtTime() turning the links by -yaw -> fails.
  const std::vector<NamedEllipse> links = {link("front", ellipse(0.5, 0.0, 0.2, 0.1, 0.3)),
                                           link("rear", ellipse(-0.5, 0.2, 0.3, 0.1))};
  const Twist twist{0.4, 0.1, 0.8};
  const std::vector<NamedEllipse> placed = linksAtTime(links, twist, 1.3);
  ASSERT_EQ(placed.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(placed[i].name, links[i].name);
    const Ellipse oracle = oracleLinkAt(links[i].ellipse, twist, 1.3);
    EXPECT_NEAR(placed[i].ellipse.center.x(), oracle.center.x(), 1e-15);
    EXPECT_NEAR(placed[i].ellipse.center.y(), oracle.center.y(), 1e-15);
    EXPECT_NEAR(placed[i].ellipse.angle, oracle.angle, 1e-15);
    EXPECT_EQ(placed[i].ellipse.radius_x, links[i].ellipse.radius_x);
  }
}

// ---- twistContact ---------------------------------------------------------------------------

struct RandomPair {
  Ellipse link;
  Twist twist;
  Ellipse obstacle;
  Motion motion;
  double horizon;
};

RandomPair randomPair(ellipse_collision::test::RandomSource& rng, bool turning,
                      bool obstacle_moves) {
  RandomPair p;
  p.link = ellipse(rng.uniform(-0.6, 0.6), rng.uniform(-0.4, 0.4), rng.logUniform(0.05, 0.5),
                   rng.logUniform(0.02, 0.5), rng.uniform(-3.0, 3.0));
  const double heading = rng.uniform(-3.2, 3.2), speed = rng.logUniform(0.05, 3.0);
  p.twist = {speed * std::cos(heading), speed * std::sin(heading), 0.0};
  if (turning) {
    const int kind = rng.index(3);  // large, ordinary, tiny turn rates
    const double magnitude = kind == 0   ? rng.logUniform(2.0, 20.0)
                             : kind == 1 ? rng.logUniform(0.05, 2.0)
                                         : rng.logUniform(1e-12, 1e-4);
    p.twist.wz = rng.coin() ? magnitude : -magnitude;
  }
  // Mostly ahead of the motion, so that about half the pairs meet.
  const double angle = heading + rng.uniform(-1.2, 1.2), range = rng.uniform(0.5, 4.0);
  p.obstacle = ellipse(range * std::cos(angle), range * std::sin(angle), rng.logUniform(0.01, 1.0),
                       rng.logUniform(0.01, 1.0), rng.uniform(-3.0, 3.0));
  if (obstacle_moves) {
    p.motion.velocity = Eigen::Vector2d(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5));
    p.motion.angular_velocity = turning && rng.coin() ? rng.uniform(-2.0, 2.0) : 0.0;
  }
  p.horizon = 3.0;
  return p;
}

TEST(TwistContact, TranslationIsExactAgainstTheQuadOracle) {
  // Mutation tried: the link given Motion{1.001 v, 0} -> fails (times off by 0.1 %).
  ellipse_collision::test::RandomSource rng(71);
  int contacts = 0;
  double worst = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const RandomPair p = randomPair(rng, false, rng.coin());
    ASSERT_EQ(invalidTwistContactReason(p.link, p.twist, p.obstacle, p.motion, p.horizon), "");
    const FirstContact got = twistContact(p.link, p.twist, p.obstacle, p.motion, p.horizon);
    const test::OracleFirstContact want = test::oracleFirstContact(
        p.link, Motion{{p.twist.vx, p.twist.vy}, 0.0}, p.obstacle, p.motion, p.horizon);
    // A pair whose path grazes within the 1e-9 band of the contact scale may go either way.
    if (got.contact != want.contact &&
        std::fabs(static_cast<double>(want.min_scale) - 1.0) < 1e-8) {
      continue;
    }
    ASSERT_EQ(got.contact, want.contact) << i;
    if (!got.contact) continue;
    ++contacts;
    const double error = got.time - static_cast<double>(want.time);
    worst = std::max(worst, std::fabs(error));
    EXPECT_LE(error, 1e-9) << i << ": late";
    EXPECT_GE(error, -1e-6) << i << ": far too early";
  }
  EXPECT_GT(contacts, 150);
  RecordProperty("worst_translation_error_s", formatNumber(worst));
}

TEST(TwistContact, TurningIsNeverLateAndCloseToTheScannedArc) {
  // Mutations tried: dropping |wz| (R_l - r_l) from the approach bound -> late contacts; the
  // frame's speed |v| for the link centre's |v_c| -> late contacts.
  ellipse_collision::test::RandomSource rng(72);
  int contacts = 0, within_1e6 = 0, claimed_without_scan = 0;
  double worst_early = 0.0;
  for (int i = 0; i < 2500; ++i) {
    const RandomPair p = randomPair(rng, true, rng.coin());
    ASSERT_EQ(invalidTwistContactReason(p.link, p.twist, p.obstacle, p.motion, p.horizon), "");
    const FirstContact got = twistContact(p.link, p.twist, p.obstacle, p.motion, p.horizon);
    const double scanned = scannedContact(p.link, p.twist, p.obstacle, p.motion, p.horizon);
    if (scanned >= 0.0) {
      ASSERT_TRUE(got.contact) << i << ": missed the contact at " << scanned;
      EXPECT_LE(got.time, scanned + 1e-9) << i << ": late, wz " << p.twist.wz;
      ++contacts;
      const double early = scanned - got.time;
      worst_early = std::max(worst_early, early);
      within_1e6 += early <= 1e-6 ? 1 : 0;
    } else if (got.contact) {
      // Claimed where the scan saw nothing: a contact shorter than the scan's step, or a graze
      // reported early by design; the pair must really come within a hair of touching.
      ++claimed_without_scan;
      const Clearance c = distance(oracleLinkAt(p.link, p.twist, got.time),
                                   obstacleAt(p.obstacle, p.motion, got.time));
      EXPECT_LE(c.distance, 1e-6) << i;
    }
  }
  EXPECT_GT(contacts, 150);
  // Conservative advancement stops within 5e-10 relative of touching: all but grazing arrivals
  // come within 1e-6 s of the true time.
  EXPECT_GE(within_1e6, contacts * 98 / 100) << "worst " << worst_early;
  EXPECT_LE(claimed_without_scan, 25);
  RecordProperty("turning_within_1e-6_s",
                 std::to_string(within_1e6) + "/" + std::to_string(contacts));
  RecordProperty("turning_worst_early_s", formatNumber(worst_early));
}

TEST(TwistContact, EccentricLinkGrazingWhileTurningIsFoundWithinTheResolution) {
  // An eccentric link (axis ratio 3..30) offset from the frame's origin, so that its centre moves
  // on an arc, passes an eccentric obstacle that translates and turns; the pair is made to graze
  // at depths 1e-8, 1e-10, 1e-12 either side of touching (drawTwistPass()). The plain
  // conservative advancement before stopped at its 20000-step cap on 83 of the 90 passes or in
  // its 5e-10 band: all 45 touching passes early by more than 1e-9 of the horizon (up to 2.4e-4),
  // 10 of the 15 passes clear by 1e-8 reported in contact.
  ellipse_collision::test::RandomSource rng(74);
  test::GrazingTally tally("twist: eccentric link grazing");
  test::checkGrazingPasses(
      tally, rng, test::drawTwistPass,
      [](const test::TurningPass& p) {
        EXPECT_EQ(invalidTwistContactReason(p.a, p.twist, p.b, p.motion_b, p.horizon), "")
            << p.text;
        return twistContact(p.a, p.twist, p.b, p.motion_b, p.horizon);
      },
      [](const test::TurningPass& p, detail::RotationWork* work) {
        return detail::rotatingContact(detail::twistPair(p.a, p.twist, p.b, p.motion_b), p.horizon,
                                       work);
      });
}

TEST(TwistContact, TinyTurnRateAgreesWithTheLineAndAFarCentreLosesNothing) {
  // wz = 1e-12: the instantaneous centre is 1e12 m away; the arc is the line to within
  // |v| wz t^2 / 2 ~ 1e-12 m, so the contact time is the translation's to within ~1e-9 s.
  // Mutation tried: the translation's velocity scaled by 1.001 -> fails.
  const Ellipse link_e = ellipse(0.4, 0.1, 0.3, 0.1, 0.2);
  const Ellipse wall = ellipse(3.0, 0.0, 0.05, 2.0);
  const FirstContact line = twistContact(link_e, {1.0, 0.0, 0.0}, wall, {}, 5.0);
  ASSERT_TRUE(line.contact);
  for (double wz : {1e-12, -1e-9, 1e-15}) {
    const FirstContact arc = twistContact(link_e, {1.0, 0.0, wz}, wall, {}, 5.0);
    ASSERT_TRUE(arc.contact) << wz;
    EXPECT_NEAR(arc.time, line.time, 1e-8) << wz;
    EXPECT_LE(arc.time, line.time + 1e-8) << wz;
  }
}

TEST(TwistContact, LargeTurnRateOfAnOffsetLinkIsCaughtMidTurn) {
  // Spinning in place at 20 rad/s, a link 1 m out sweeps a circle; an obstacle on that circle a
  // quarter turn ahead is hit at (pi / 2 - its half-width angle) / 20 s, not missed between
  // steps. Mutation tried: ignoring the link offset in the bound (|v_c| -> |v|) -> contact missed.
  const Ellipse arm = ellipse(1.0, 0.0, 0.05, 0.05);
  const Ellipse post = ellipse(0.0, 1.0, 0.05, 0.05);
  const FirstContact c = twistContact(arm, {0.0, 0.0, 20.0}, post, {}, 1.0);
  ASSERT_TRUE(c.contact);
  const double scanned = scannedContact(arm, {0.0, 0.0, 20.0}, post, {}, 1.0, 20000);
  EXPECT_LE(c.time, scanned);
  EXPECT_NEAR(c.time, scanned, 1e-7);
  EXPECT_NEAR(c.time, (M_PI / 2.0 - 2.0 * std::asin(0.05)) / 20.0, 1e-7);
}

TEST(TwistContact, OverlapNowIsTimeZeroAndApartNowNeverIs) {
  // Mutation tried: no "just after 0" for a graze found at 0 -> the second pair gets time 0.
  const Ellipse a = ellipse(0.0, 0.0, 0.5, 0.2);
  EXPECT_EQ(twistContact(a, {1.0, 0.0, 1.0}, ellipse(0.6, 0.0, 0.2, 0.2), {}, 1.0).time, 0.0);
  const FirstContact touching_soon =
      twistContact(a, {1.0, 0.0, 1.0}, ellipse(0.7 + 1e-13, 0.0, 0.2, 0.2), {}, 1.0);
  ASSERT_TRUE(touching_soon.contact);
  EXPECT_GT(touching_soon.time, 0.0);
}

TEST(TwistContact, InvalidInputsAreNamedWithTheirValue) {
  // Mutation tried: twist.vy named twist.vx -> fails.
  const Ellipse good = ellipse(0.0, 0.0, 0.5, 0.2), far = ellipse(3.0, 0.0, 0.5, 0.2);
  EXPECT_EQ(invalidTwistContactReason(good, {1.0, 0.0, 0.5}, far, {}, 2.0), "");
  EXPECT_EQ(invalidTwistContactReason(good, {NAN, 0.0, 0.5}, far, {}, 2.0),
            "twist.vx = nan must be finite");
  EXPECT_EQ(invalidTwistContactReason(good, {0.0, 2e9, 0.5}, far, {}, 2.0),
            "twist.vy = 2e+09 is outside [-1e+09, 1e+09] m/s");
  EXPECT_EQ(invalidTwistContactReason(good, {0.0, 0.0, INFINITY}, far, {}, 2.0),
            "twist.wz = inf must be finite");
  EXPECT_EQ(invalidTwistContactReason(good, {0.0, 0.0, 60.0}, far, {}, 2.0),
            "twist.wz = 60 turns more than 100 rad within horizon = 2 s");
  EXPECT_EQ(invalidTwistContactReason(ellipse(0, 0, 0, 1), {}, far, {}, 2.0),
            "link: radius_x = 0 must be > 0");
  EXPECT_EQ(invalidTwistContactReason(good, {}, far, Motion{{0.0, NAN}, 0.0}, 2.0),
            "obstacle: velocity.y = nan must be finite");
  EXPECT_EQ(invalidTwistContactReason(good, {}, far, {}, -1.0), "horizon = -1 must be >= 0");
  EXPECT_NE(invalidTwistContactReason(good, {6e8, 0.0, 0.0}, far, {}, 2.0).find("link: reaches"),
            std::string::npos);
}

}  // namespace
}  // namespace ellipse_collision::core

// Continuous path checks (core/path_check.h, core/path_motion.h) against the quad-precision
// first-contact oracle and against brute force over every pair.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/path_check.h"
#include "first_contact_oracle.h"
#include "grazing_tally.h"
#include "random_source.h"
#include "rotating_contact.h"
#include "scene_test_helpers.h"

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

using scene_test::ellipse;

NamedEllipse named(const std::string& name, EllipseRole role, const Ellipse& e) {
  return NamedEllipse{name, role, e};
}

PathScene oneLinkOneObstacle(const Ellipse& link, const Ellipse& obstacle, Motion motion = {}) {
  PathScene scene;
  scene.links.push_back(named("link", EllipseRole::Link, link));
  scene.obstacles.push_back(named("obstacle", EllipseRole::Obstacle, obstacle));
  scene.obstacle_motions.push_back(motion);
  return scene;
}

// Independent of segmentContact(): the link's exact rigid pose at tau, the contact scale of the
// standing pair in quad precision, scanned densely and the first crossing bisected.
double oracleRigidContact(const Ellipse& link_in_moving, const SegmentMotion& m,
                          const Ellipse& obstacle, int samples = 300) {
  const auto scale = [&](double tau) {
    const Ellipse link =
        placeAt(link_in_moving, m.start + m.velocity * tau, m.start_yaw + m.yaw_rate * tau);
    return static_cast<double>(test::oracleScaleAt(link, Motion{}, obstacle, Motion{}, 0));
  };
  double prev = 0.0;
  if (scale(0.0) <= 1.0) return 0.0;
  for (int i = 1; i <= samples; ++i) {
    const double tau = m.duration * i / samples;
    if (scale(tau) <= 1.0) {
      double lo = prev, hi = tau;
      for (int k = 0; k < 60; ++k) {
        const double mid = 0.5 * (lo + hi);
        (scale(mid) <= 1.0 ? hi : lo) = mid;
      }
      return hi;
    }
    prev = tau;
  }
  return -1.0;  // no contact
}

TEST(PathMotion, ShortestRotationWrapsIntoMinusPiToPi) {
  EXPECT_NEAR(shortestRotation(0.1, -0.1), -0.2, 1e-15);
  EXPECT_NEAR(shortestRotation(3.0, -3.0), 2.0 * kPi - 6.0, 1e-12);
  EXPECT_NEAR(shortestRotation(-3.0, 3.0), -(2.0 * kPi - 6.0), 1e-12);
  EXPECT_NEAR(shortestRotation(0.0, 4.0 * kPi + 0.5), 0.5, 1e-12);
}

TEST(PathMotion, LinkSweptBoxContainsTheLinkAtEveryPoseOfTheSegment) {
  const Ellipse link = ellipse(0.8, -0.3, 0.4, 0.1, 0.3);
  const SegmentMotion m = segmentMotion({1.0, 2.0, 0.2, 0.0}, {1.5, 1.0, 2.9, 0.0}, 1.0);
  const BoundingBox box = sweptLinkBox(link, m);
  for (int i = 0; i <= 1000; ++i) {
    const double tau = i / 1000.0;
    const BoundingBox at =
        boundingBox(placeAt(link, m.start + m.velocity * tau, m.start_yaw + m.yaw_rate * tau));
    ASSERT_LE(box.min_x, at.min_x) << tau;
    ASSERT_LE(box.min_y, at.min_y) << tau;
    ASSERT_GE(box.max_x, at.max_x) << tau;
    ASSERT_GE(box.max_y, at.max_y) << tau;
  }
}

TEST(PathCheck, ThinObstacleBetweenTwoPosesIsFoundWherePoseChecksMissIt) {
  // A 2 cm wall halfway along a 10 m segment: both poses are clear, the segment is not.
  const Ellipse link = ellipse(0.0, 0.0, 0.3, 0.3);
  const Ellipse wall = ellipse(5.0, 0.0, 0.01, 1.0);
  const PathScene scene = oneLinkOneObstacle(link, wall);
  const std::vector<PathPose> poses = {{0, 0, 0, 0}, {10, 0, 0, 0}};
  EXPECT_FALSE(overlap(placeAt(link, {0, 0}, 0), wall));
  EXPECT_FALSE(overlap(placeAt(link, {10, 0}, 0), wall));
  const PathCheckResult r = checkPath(scene, poses, false);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_FALSE(r.collision_free);
  EXPECT_EQ(r.segment, 0u);
  EXPECT_EQ(r.link, "link");
  EXPECT_EQ(r.obstacle, "obstacle");
  const test::OracleFirstContact oracle =
      test::oracleFirstContact(link, Motion{{10.0, 0.0}, 0.0}, wall, Motion{}, 1.0);
  ASSERT_TRUE(oracle.contact);
  EXPECT_NEAR(r.fraction, static_cast<double>(oracle.time), 1e-12);
  EXPECT_NEAR(r.fraction, 0.469, 1e-12);  // by hand: (5 - 0.01 - 0.3) / 10
  // Clearance only at the pose before the contact: the link 4.69 m from the wall.
  ASSERT_TRUE(r.has_clearance);
  EXPECT_EQ(r.min_clearance_pose, 0u);
  EXPECT_NEAR(r.min_clearance, 4.69, 1e-12);
}

TEST(PathCheck, TurningOffsetLinkMatchesTheRigidMotionOracleAndIsNeverLate) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int contacts = 0;
  double worst = 0.0;
  for (int trial = 0; trial < 16; ++trial) {
    // The link sweeps an arc of radius ~0.8 m about the frame's origin; the obstacle sits on it.
    const Ellipse link = ellipse(0.8 + 0.1 * u(rng), 0.1 * u(rng), 0.2 + 0.05 * u(rng),
                                 0.08 + 0.02 * u(rng), u(rng));
    const double at = 0.9 + 0.2 * u(rng);
    const Ellipse obstacle = ellipse(0.8 * std::cos(at), 0.8 * std::sin(at), 0.1 + 0.03 * u(rng),
                                     0.05 + 0.02 * u(rng), u(rng));
    const PathPose from{0.0, 0.0, 0.0, 0.0};
    const PathPose to{0.1 * u(rng), 0.1 * u(rng), 1.8 + 0.3 * u(rng), 0.0};
    const SegmentMotion m = segmentMotion(from, to, 1.0);
    if (overlap(placeAt(link, m.start, m.start_yaw), obstacle)) continue;
    const FirstContact got = segmentContact(link, m, obstacle, Motion{});
    const double oracle = oracleRigidContact(link, m, obstacle);
    if (oracle < 0.0) {
      // No crossing on the oracle's grid: a contact may only be a graze the grid missed.
      if (got.contact) {
        const Ellipse at =
            placeAt(link, m.start + m.velocity * got.time, m.start_yaw + m.yaw_rate * got.time);
        EXPECT_LT(distance(at, obstacle).distance, 1e-8) << trial;
      }
      continue;
    }
    ++contacts;
    ASSERT_TRUE(got.contact) << trial;
    EXPECT_LE(got.time, oracle + 1e-12) << "late, trial " << trial;
    EXPECT_NEAR(got.time, oracle, 1e-6) << trial;
    worst = std::max(worst, std::fabs(got.time - oracle));
  }
  std::printf("turning offset links: %d contacts, largest |time - oracle| = %.3g\n", contacts,
              worst);
  EXPECT_GT(contacts, 8);
}

TEST(PathCheck, EccentricOffsetLinkGrazingWhileTurningIsFoundWithinTheResolution) {
  // An eccentric link (axis ratio 3..30) offset from the moving frame's origin, the frame up to
  // 100 m out driving up to 2 m per unit of tau and turning by up to 3 rad over the segment,
  // passes an eccentric obstacle that translates and turns; the pair is made to graze at depths
  // 1e-8, 1e-10, 1e-12 either side of touching (drawSegmentPass()). The plain conservative
  // advancement before stopped at its 20000-step cap on 80 of the 90 passes or in its 5e-10
  // band: all 45 touching passes early by more than 1e-9 of the horizon (up to 2.7e-4), 12 of the
  // 15 passes clear by 1e-8 reported in contact.
  ellipse_collision::test::RandomSource rng(15);
  test::GrazingTally tally("segment: eccentric link grazing");
  test::checkGrazingPasses(
      tally, rng, test::drawSegmentPass,
      [](const test::TurningPass& p) {
        EXPECT_EQ(invalidSegmentReason(p.b, p.motion_b, p.horizon), "") << p.text;
        return segmentContact(p.a, p.segment, p.b, p.motion_b);
      },
      [](const test::TurningPass& p, detail::RotationWork* work) {
        return detail::rotatingContact(detail::segmentPair(p.a, p.segment, p.b, p.motion_b),
                                       p.horizon, work);
      });
}

TEST(PathCheck, TimedPathMeetsAMovingObstacleAtTheOracleTime) {
  // The robot drives along x at 1 m/s for 4 s; an obstacle crosses its way along y at 1 m/s.
  const Ellipse link = ellipse(0.0, 0.0, 0.4, 0.2);
  const Ellipse obstacle = ellipse(2.5, -3.0, 0.2, 0.2);
  const Motion motion{{0.0, 1.0}, 0.0};
  const PathScene scene = oneLinkOneObstacle(link, obstacle, motion);
  const std::vector<PathPose> poses = {
      {0, 0, 0, 0}, {1, 0, 0, 1}, {2, 0, 0, 2}, {3, 0, 0, 3}, {4, 0, 0, 4}};
  const PathCheckResult timed = checkPath(scene, poses, true);
  ASSERT_TRUE(timed.ok()) << timed.error;
  ASSERT_FALSE(timed.collision_free);
  const test::OracleFirstContact oracle =
      test::oracleFirstContact(link, Motion{{1.0, 0.0}, 0.0}, obstacle, motion, 4.0);
  ASSERT_TRUE(oracle.contact);
  EXPECT_NEAR(timed.time, static_cast<double>(oracle.time), 1e-9);
  EXPECT_EQ(timed.segment, static_cast<std::size_t>(std::floor(static_cast<double>(oracle.time))));
  EXPECT_NEAR(timed.segment + timed.fraction, static_cast<double>(oracle.time), 1e-9);
  // The same poses without times: a geometric path, the obstacle stands at y = -3, clear.
  std::vector<PathPose> geometric = poses;
  for (PathPose& p : geometric) p.time = 0.0;
  const PathCheckResult still = checkPath(scene, geometric, false);
  ASSERT_TRUE(still.ok());
  EXPECT_TRUE(still.collision_free);
}

// Brute force: every pair of every segment through segmentContact(), every pair at every pose
// through distance().
PathCheckResult bruteForce(const PathScene& scene, const std::vector<PathPose>& poses, bool timed) {
  PathCheckResult r;
  std::size_t last = poses.size() - 1;
  for (std::size_t s = 0; s + 1 < poses.size() && r.collision_free; ++s) {
    const double duration = timed ? poses[s + 1].time - poses[s].time : 1.0;
    const SegmentMotion m = segmentMotion(poses[s], poses[s + 1], duration);
    double best = 2.0 * duration;
    for (std::size_t l = 0; l < scene.links.size(); ++l) {
      for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
        if (scene.allowed.contains(scene.links[l].name, scene.obstacles[o].name)) continue;
        const Motion motion = timed ? scene.obstacle_motions[o] : Motion{};
        const FirstContact c =
            segmentContact(scene.links[l].ellipse, m,
                           movedBy(scene.obstacles[o].ellipse, motion, poses[s].time), motion);
        if (c.contact &&
            (c.time < best ||
             (c.time == best && std::make_pair(scene.links[l].name, scene.obstacles[o].name) <
                                    std::make_pair(r.link, r.obstacle)))) {
          best = c.time;
          r.collision_free = false;
          r.segment = s;
          r.fraction = std::clamp(c.time / duration, 0.0, 1.0);
          r.link = scene.links[l].name;
          r.obstacle = scene.obstacles[o].name;
          last = s;
        }
      }
    }
  }
  for (std::size_t p = 0; p <= last; ++p) {
    for (std::size_t l = 0; l < scene.links.size(); ++l) {
      const Ellipse link = placeAt(scene.links[l].ellipse, {poses[p].x, poses[p].y}, poses[p].yaw);
      for (std::size_t o = 0; o < scene.obstacles.size(); ++o) {
        if (scene.allowed.contains(scene.links[l].name, scene.obstacles[o].name)) continue;
        const Motion motion = timed ? scene.obstacle_motions[o] : Motion{};
        const Clearance c =
            distance(link, movedBy(scene.obstacles[o].ellipse, motion, poses[p].time));
        const double d = c.separated ? c.distance : 0.0;
        if (!r.has_clearance || d < r.min_clearance) {
          r.has_clearance = true;
          r.min_clearance = d;
          r.min_clearance_pose = p;
          r.clearance_link = scene.links[l].name;
          r.clearance_obstacle = scene.obstacles[o].name;
        }
      }
    }
  }
  return r;
}

TEST(PathCheck, BroadphaseAnswersExactlyAsBruteForce) {
  std::mt19937 rng(1414);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int with_contact = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const bool timed = trial % 2 == 1;
    PathScene scene;
    for (int l = 0; l < 4; ++l) {
      scene.links.push_back(named(
          "l" + std::to_string(l), EllipseRole::Link,
          ellipse(0.4 * u(rng), 0.3 * u(rng), 0.15 + 0.1 * u(rng), 0.08 + 0.03 * u(rng), u(rng))));
    }
    for (int o = 0; o < 30; ++o) {
      scene.obstacles.push_back(named("o" + std::to_string(o), EllipseRole::Obstacle,
                                      ellipse(10.0 * u(rng), 10.0 * u(rng), 0.1 + 0.05 * u(rng),
                                              0.05 + 0.02 * u(rng), u(rng))));
      scene.obstacle_motions.push_back(
          o % 3 == 0 ? Motion{{0.3 * u(rng), 0.3 * u(rng)}, 0.5 * u(rng)} : Motion{});
    }
    scene.allowed.add("l0", "o7");
    std::vector<PathPose> poses;
    PathPose p{-8.0, 2.0 * u(rng), u(rng), 0.0};
    for (int k = 0; k < 30; ++k) {
      poses.push_back(p);
      p.x += 0.55 + 0.1 * u(rng);
      p.y += 0.2 * u(rng);
      p.yaw += 0.3 * u(rng);
      if (timed) p.time += 0.5 + 0.2 * u(rng);
    }
    const PathCheckResult fast = checkPath(scene, poses, timed);
    const PathCheckResult slow = bruteForce(scene, poses, timed);
    ASSERT_TRUE(fast.ok()) << fast.error;
    ASSERT_EQ(fast.collision_free, slow.collision_free) << trial;
    with_contact += !fast.collision_free;
    EXPECT_EQ(fast.segment, slow.segment) << trial;
    EXPECT_EQ(fast.fraction, slow.fraction) << trial;
    EXPECT_EQ(fast.link, slow.link) << trial;
    EXPECT_EQ(fast.obstacle, slow.obstacle) << trial;
    EXPECT_EQ(fast.min_clearance, slow.min_clearance) << trial;
    EXPECT_EQ(fast.min_clearance_pose, slow.min_clearance_pose) << trial;
    EXPECT_EQ(fast.clearance_link, slow.clearance_link) << trial;
    EXPECT_EQ(fast.clearance_obstacle, slow.clearance_obstacle) << trial;
  }
  std::printf("broadphase vs brute force: 40 paths, %d with a contact\n", with_contact);
  EXPECT_GT(with_contact, 5);
  EXPECT_LT(with_contact, 40);
}

}  // namespace
}  // namespace ellipse_collision::core

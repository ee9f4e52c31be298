// The braking model (core/base_braking.h): the scale profile against its own numerical integral,
// the shedding rate, and brakingContact() never late against a dense scan of the exact motion
// (the quad-precision arc at the numerically integrated twist-time).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "ellipse_collision/core/base_braking.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "random_source.h"
#include "scene_test_helpers.h"
#include "twist_oracle.h"

namespace ellipse_collision::core {
namespace {

using scene_test::ellipse;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// sigma(t) by the midpoint rule on scaleAt() in steps of 2e-6 s, kept as a running sum:
/// independent of sigmaAt(), good to 2e-6 of the largest jump of the scale (a rise at once falls
/// inside one step) and far better elsewhere (the scale is piecewise linear).
class IntegratedSigma {
 public:
  IntegratedSigma(const ScaleProfile& p, double until) {
    const std::size_t steps = static_cast<std::size_t>(std::ceil(until / kStep)) + 1;
    sums_.resize(steps + 1, 0.0);
    for (std::size_t i = 0; i < steps; ++i) {
      sums_[i + 1] = sums_[i] + kStep * p.scaleAt((static_cast<double>(i) + 0.5) * kStep);
    }
  }
  double operator()(double t) const {
    const double cells = t / kStep;
    const std::size_t i = std::min(static_cast<std::size_t>(cells), sums_.size() - 2);
    const double share = cells - static_cast<double>(i);
    return sums_[i] + share * (sums_[i + 1] - sums_[i]);
  }

 private:
  static constexpr double kStep = 2e-6;
  std::vector<double> sums_;
};

TEST(ScaleProfile, SigmaIsTheIntegralOfTheScaleOnEveryShape) {
  struct Case {
    double from, to, reaction, hold, rate;
  };
  const Case cases[] = {{1.0, 1.0, 0.1, 0.05, 0.5},    // cruising, then braking
                        {1.0, 0.2, 0.1, 0.05, 0.5},    // the ramp down outlasts the hold
                        {1.0, 0.9, 0.2, 0.5, 2.0},     // reaches the output, holds it, brakes
                        {0.3, 1.0, 0.1, 0.05, 1.0},    // a rise is at once
                        {0.0, 0.5, 0.0, 0.05, 4.0},    // from rest
                        {1.0, 0.0, 0.05, 0.05, 1.0}};  // stopping now
  for (const Case& c : cases) {
    const ScaleProfile p(c.from, c.to, c.reaction, c.hold, c.rate);
    const IntegratedSigma integrated(p, 3.0);
    for (double t : {0.0, 0.03, 0.1, 0.12, 0.3, 0.7, 1.5, 3.0}) {
      EXPECT_NEAR(p.sigmaAt(t), integrated(t), 2e-6) << c.from << " " << c.to << " " << t;
    }
    EXPECT_EQ(p.scaleAt(p.stopTime() + 1e-9), 0.0);
    EXPECT_GT(p.scaleAt(p.stopTime() * (1.0 - 1e-6)) + (p.stopTime() == 0.0), 0.0);
    // timeAtSigma() inverts sigmaAt() up to the stop, and is infinite beyond it.
    for (double share : {0.0, 0.1, 0.5, 0.9, 1.0}) {
      const double sigma = share * p.stopSigma();
      EXPECT_NEAR(p.sigmaAt(p.timeAtSigma(sigma)), sigma, 1e-12);
    }
    EXPECT_EQ(p.timeAtSigma(p.stopSigma() * 1.001 + 1e-9), kInf);
  }
}

TEST(ScaleProfile, ClosedFormsOfABaseBrakingFromCruise) {
  // 1.5 m/s, 0.8 m/s^2: the scale sheds at 0.8 / 1.5 per second; reaction 0.1 s, period 0.05 s.
  const double rate = 0.8 / 1.5;
  const ScaleProfile p(1.0, 0.0, 0.1, 0.05, rate);
  // Stopping from the moment the command is sent: 0.1 s at full speed, then braking.
  EXPECT_NEAR(p.stopTime(), 0.1 + 1.0 / rate, 1e-12);
  EXPECT_NEAR(1.5 * p.stopSigma(), 1.5 * 0.1 + 1.5 * 1.5 / (2.0 * 0.8), 1e-12);
  // An infinite rate stops at once after the reaction and the output's period.
  const ScaleProfile at_once(1.0, 0.4, 0.1, 0.05, kInf);
  EXPECT_DOUBLE_EQ(at_once.stopTime(), 0.15);
  EXPECT_NEAR(at_once.stopSigma(), 0.1 + 0.4 * 0.05, 1e-15);
  EXPECT_EQ(at_once.maxScale(), 1.0);
}

TEST(BrakingRate, TheSlowerLimitOfTheMovingPartsKeepsTheArc) {
  const BaseDynamics dynamics{0.1, 0.8, 2.0};
  EXPECT_NEAR(brakingRate({1.5, 0.0, 0.0}, dynamics), 0.8 / 1.5, 1e-15);
  EXPECT_NEAR(brakingRate({0.0, 0.0, 1.2}, dynamics), 2.0 / 1.2, 1e-15);
  EXPECT_NEAR(brakingRate({1.5, 0.0, 1.2}, dynamics), std::min(0.8 / 1.5, 2.0 / 1.2), 1e-15);
  EXPECT_NEAR(brakingRate({0.6, 0.8, 0.0}, dynamics), 0.8, 1e-15);
  EXPECT_EQ(brakingRate({1.5, 0.0, 1.2}, BaseDynamics{0.1, 0.0, 0.0}), kInf);
  EXPECT_EQ(brakingRate({0.0, 0.0, 0.0}, dynamics), kInf);
  EXPECT_TRUE(BaseDynamics().ideal());
  EXPECT_FALSE(dynamics.ideal());
}

/// The first time the exact motion comes within `clearance` (dense scan, 2,000 samples, then
/// bisection): the link on the quad-precision arc at the integrated twist-time.
double scannedBrakingContact(const Ellipse& link, const Twist& twist, const ScaleProfile& p,
                             const IntegratedSigma& sigma, const Ellipse& obstacle,
                             const Motion& motion, double clearance) {
  const auto near = [&](double t) {
    const Ellipse a = twist_oracle::oracleLinkAt(link, twist, sigma(t));
    const Ellipse b = twist_oracle::obstacleAt(obstacle, motion, t);
    const Clearance c = distance(a, b);
    return !c.separated || c.distance <= clearance;
  };
  return twist_oracle::firstScanned(near, p.stopTime(), 2000, 40);
}

TEST(BrakingContact, NeverLateAgainstTheScannedMotionAndCloseWhenItClaims) {
  test::RandomSource random(41);
  int contacts = 0, clear = 0;
  for (int i = 0; i < 60; ++i) {
    const Ellipse link =
        ellipse(random.uniform(-0.3, 0.3), random.uniform(-0.2, 0.2), random.uniform(0.05, 0.4),
                random.uniform(0.05, 0.3), random.uniform(-3.0, 3.0));
    const Twist twist{random.uniform(0.2, 2.0), random.uniform(-0.3, 0.3),
                      random.uniform(-1.5, 1.5)};
    const Ellipse obstacle =
        ellipse(random.uniform(0.6, 2.0), random.uniform(-1.0, 1.0), random.uniform(0.05, 0.5),
                random.uniform(0.05, 0.5), random.uniform(-3.0, 3.0));
    const Motion motion{{random.uniform(-1.0, 0.3), random.uniform(-0.5, 0.5)},
                        random.uniform(-1.0, 1.0)};
    const ScaleProfile p(random.uniform(0.0, 1.0), random.uniform(0.0, 1.0),
                         random.uniform(0.0, 0.2), 0.05, random.uniform(0.3, 3.0));
    const double clearance = random.uniform(0.0, 0.1);
    const IntegratedSigma sigma(p, p.stopTime());
    const FirstContact claimed = brakingContact(link, twist, p, obstacle, motion, clearance);
    const double scanned =
        scannedBrakingContact(link, twist, p, sigma, obstacle, motion, clearance);
    if (scanned >= 0.0) {
      ASSERT_TRUE(claimed.contact) << i << ": missed a contact at " << scanned;
      // Late by no more than the oracle's own error (its twist-time is good to ~2e-6).
      EXPECT_LE(claimed.time, scanned + 1e-5) << i << ": late";
      ++contacts;
    }
    if (claimed.contact) {
      // Never absurdly early: at the claimed time the pair is within the clearance (or 1e-6 m).
      const Ellipse a = twist_oracle::oracleLinkAt(link, twist, sigma(claimed.time));
      const Ellipse b = twist_oracle::obstacleAt(obstacle, motion, claimed.time);
      const Clearance c = distance(a, b);
      EXPECT_TRUE(!c.separated || c.distance <= clearance + 1e-6) << i << ": " << c.distance;
    } else {
      ++clear;
    }
  }
  EXPECT_GT(contacts, 10);
  EXPECT_GT(clear, 10);
}

}  // namespace
}  // namespace ellipse_collision::core

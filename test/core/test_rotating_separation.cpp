// The separation of a rotating pair along a direction (src/core/rotating_separation.h): its value
// against the support functions written out in long double, its rates in time and in the
// direction's angle against central differences of that function, a lower bound of the distance
// of rim samples, never made worse by the direction steps; rim normals against the closed form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "random_source.h"
#include "rotating_separation.h"

namespace ellipse_collision::core::detail {
namespace {

using Long = long double;

/// The support function of `e` turned to `angle` along the direction of angle `phi`.
Long support(const Ellipse& e, Long angle, Long phi) {
  const Long along = std::cos(phi - angle), across = std::sin(phi - angle);
  return std::sqrt(Long(e.radius_x) * e.radius_x * along * along +
                   Long(e.radius_y) * e.radius_y * across * across);
}

struct Case {
  Ellipse a, b;
  Eigen::Vector2d velocity;
  double wa, wb, phi;
  /// f at time t along the direction of angle phi + dphi, in long double.
  Long f(Long t, Long dphi) const {
    const Long phi_now = phi + dphi;
    const Long px = Long(b.center.x()) - a.center.x() + velocity.x() * t;
    const Long py = Long(b.center.y()) - a.center.y() + velocity.y() * t;
    return std::cos(phi_now) * px + std::sin(phi_now) * py - support(a, a.angle + wa * t, phi_now) -
           support(b, b.angle + wb * t, phi_now);
  }
};

Case randomCase(test::RandomSource& random) {
  Case c;
  c.a = {{random.uniform(-5, 5), random.uniform(-5, 5)},
         random.uniform(0.05, 1.0),
         random.uniform(0.05, 1.0),
         random.uniform(-3, 3)};
  const double direction = random.uniform(-3.2, 3.2), gap = random.uniform(2.0, 4.0);
  c.b = {{c.a.center.x() + gap * std::cos(direction), c.a.center.y() + gap * std::sin(direction)},
         random.uniform(0.05, 0.9),
         random.uniform(0.05, 0.9),
         random.uniform(-3, 3)};
  c.velocity = {random.uniform(-2, 2), random.uniform(-2, 2)};
  c.wa = random.uniform(-2, 2);
  c.wb = random.uniform(-2, 2);
  c.phi = direction + random.uniform(-0.3, 0.3);
  return c;
}

/// The distance of the two rims sampled at 360 points each: never below the true distance.
Long sampledDistance(const Ellipse& a, const Ellipse& b) {
  const auto rim = [](const Ellipse& e) {
    std::vector<std::pair<Long, Long>> points;
    const Long c = std::cos(Long(e.angle)), sn = std::sin(Long(e.angle));
    for (int k = 0; k < 360; ++k) {
      const Long s = 2 * 3.14159265358979323846L * k / 360;
      const Long x = e.radius_x * std::cos(s), y = e.radius_y * std::sin(s);
      points.emplace_back(e.center.x() + c * x - sn * y, e.center.y() + sn * x + c * y);
    }
    return points;
  };
  Long best = 1e300L;
  const auto rim_b = rim(b);
  for (const auto& pa : rim(a)) {
    for (const auto& pb : rim_b) {
      const Long dx = pa.first - pb.first, dy = pa.second - pb.second;
      best = std::min(best, dx * dx + dy * dy);
    }
  }
  return std::sqrt(best);
}

TEST(RotatingSeparation, ValueAndRatesAgreeWithTheSupportFunctionsInLongDouble) {
  test::RandomSource random(51);
  for (int i = 0; i < 500; ++i) {
    const Case c = randomCase(random);
    const Eigen::Vector2d u(std::cos(c.phi), std::sin(c.phi));
    const SeparationAlong s =
        separationAlong(sinCosPair(c.a.angle, c.b.angle), c.a, c.b, c.velocity, c.wa, c.wb, u);
    EXPECT_LE(std::fabs(s.value - c.f(0, 0)), s.rounding + 1e-15L) << i;
    EXPECT_GT(s.rounding, 0.0);
    const Long h = 1e-5L;
    EXPECT_NEAR(s.rate, double((c.f(h, 0) - c.f(-h, 0)) / (2 * h)), 1e-8) << i;
    EXPECT_NEAR(s.slope, double((c.f(0, h) - c.f(0, -h)) / (2 * h)), 1e-8) << i;
    const Long k = 1e-5L;
    EXPECT_NEAR(s.curvature, double((c.f(0, k) - 2 * c.f(0, 0) + c.f(0, -k)) / (k * k)), 1e-6) << i;
    EXPECT_NEAR(s.centre_rate, u.dot(c.velocity), 1e-15);
  }
}

TEST(RotatingSeparation, TheBestSeparationIsALowerBoundNoWorseThanTheFirstDirection) {
  test::RandomSource random(52);
  for (int i = 0; i < 30; ++i) {
    const Case c = randomCase(random);
    const Eigen::Vector2d u(std::cos(c.phi), std::sin(c.phi));
    const SeparationAlong first =
        separationAlong(sinCosPair(c.a.angle, c.b.angle), c.a, c.b, c.velocity, c.wa, c.wb, u);
    const Separation best = bestSeparation(c.a, c.b, c.velocity, c.wa, c.wb, u);
    EXPECT_GE(best.best.value - best.best.rounding, first.value - first.rounding) << i;
    EXPECT_LE(best.best.value, double(sampledDistance(c.a, c.b)) + 1e-12) << i;
    EXPECT_NEAR(best.last_direction.norm(), 1.0, 1e-15);
  }
}

TEST(RotatingSeparation, RimNormalsAreTheGradientDirectionOfTheRim) {
  test::RandomSource random(53);
  for (int i = 0; i < 1000; ++i) {
    const Ellipse e{{random.uniform(-9, 9), random.uniform(-9, 9)},
                    random.uniform(0.01, 2.0),
                    random.uniform(0.01, 2.0),
                    random.uniform(-3, 3)};
    const Long s = random.uniform(-3.2, 3.2);
    const Long c = std::cos(Long(e.angle)), sn = std::sin(Long(e.angle));
    const Long lx = e.radius_x * std::cos(s), ly = e.radius_y * std::sin(s);
    const Eigen::Vector2d point(double(e.center.x() + c * lx - sn * ly),
                                double(e.center.y() + sn * lx + c * ly));
    // The normal at parameter s: R (cos s / r_x, sin s / r_y), normalised.
    const Long nx = std::cos(s) / e.radius_x, ny = std::sin(s) / e.radius_y;
    const Long wx = c * nx - sn * ny, wy = sn * nx + c * ny, length = std::hypot(wx, wy);
    Eigen::Vector2d normal;
    ASSERT_TRUE(rimNormal(e, point, &normal));
    EXPECT_NEAR(normal.x(), double(wx / length), 1e-9) << i;
    EXPECT_NEAR(normal.y(), double(wy / length), 1e-9) << i;
  }
  Eigen::Vector2d normal;
  const Ellipse e{{1.0, 2.0}, 1.0, 0.5, 0.0};
  EXPECT_FALSE(rimNormal(e, e.center, &normal)) << "no normal at the centre";
}

}  // namespace
}  // namespace ellipse_collision::core::detail

// The contact scale as the root of a quartic (contact_scale_quartic.h), which contactScale() and
// every scene check use: its coefficients against Q's own definition, its batch against the single
// pair (same bits), how often it needs the certified fallback, and its agreement with that
// certified maximisation of Q on pairs far harder than a robot scene. Accuracy against the
// quad-precision oracle is in test_overlap_accuracy.cpp.

#include <gtest/gtest.h>
#include <quadmath.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "contact_scale_oracle.h"
#include "contact_scale_quartic.h"
#include "contact_scale_detail.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "random_source.h"
#include "relative_shape.h"

namespace ellipse_collision::core {
namespace test {
namespace {

using quad = __float128;
using detail::RelativeShape;
using detail::ScaleProblem;

constexpr double kPi = 3.14159265358979323846;

class Generator : public ellipse_collision::test::RandomSource {
 public:
  using RandomSource::RandomSource;
  /// A pair with sizes over `size_range` decades and axis ratios up to max_ratio, centres within
  /// `spread` of each other (relative to the first's size).
  std::pair<Ellipse, Ellipse> pair(double max_ratio, double size_range, double spread) {
    const double size_a = logUniform(1e-2, 1e2);
    const Ellipse a = ellipse({uniform(-50, 50), uniform(-50, 50)}, size_a, max_ratio);
    const double size_b = size_a * logUniform(std::pow(10.0, -size_range),
                                              std::pow(10.0, size_range));
    const double distance = size_a * logUniform(1e-6, spread);
    const double direction = uniform(-kPi, kPi);
    const Ellipse b = ellipse(a.center + distance * Eigen::Vector2d(std::cos(direction),
                                                                      std::sin(direction)),
                              size_b, max_ratio);
    return {a, b};
  }

 private:
  Ellipse ellipse(const Eigen::Vector2d& center, double major, double max_ratio) {
    Ellipse e;
    e.center = center;
    e.radius_x = major;
    e.radius_y = major / logUniform(1.0, max_ratio);
    if (coin()) std::swap(e.radius_x, e.radius_y);
    e.angle = uniform(-kPi, kPi);
    return e;
  }
};

bool sameBits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

/// Q(s) = d^T (I / (1 - s) + M / s)^-1 d straight from its definition, in quad, with M = [p q]
/// [p q]^T and the 2x2 inverse written out: no adjugate identity, no eigenvectors.
quad qFromDefinition(const RelativeShape& r, quad s) {
  const quad m00 = (quad)r.p_x * r.p_x + (quad)r.q_x * r.q_x;
  const quad m01 = (quad)r.p_x * r.p_y + (quad)r.q_x * r.q_y;
  const quad m11 = (quad)r.p_y * r.p_y + (quad)r.q_y * r.q_y;
  const quad h00 = 1 / (1 - s) + m00 / s, h01 = m01 / s, h11 = 1 / (1 - s) + m11 / s;
  const quad det = h00 * h11 - h01 * h01;
  const quad dx = r.center_x, dy = r.center_y;
  return (h11 * dx * dx - 2 * h01 * dx * dy + h00 * dy * dy) / det;
}

TEST(ContactScaleQuartic, ItsPolynomialVanishesWhereQFromItsDefinitionIsStationary) {
  // P(t) = Q'(t) * denominator^2 with t = s / (1 - s): P changes sign exactly where a central
  // difference of the quad Q changes sign, and Q's maximum found by a quad search on that
  // difference equals max Q from the quartic's root.
  Generator gen(31);
  for (int i = 0; i < 200; ++i) {
    const auto [a, b] = gen.pair(20.0, 1.0, 3.0);
    const RelativeShape r = detail::canonicalRelativeShape(a, b);
    const ScaleProblem problem = detail::scaleProblem(r);
    ASSERT_FALSE(problem.fallback);
    // The maximiser of Q on (0, 1) by a quad ternary search on the definition.
    quad lo = 0, hi = 1;
    for (int k = 0; k < 200; ++k) {
      const quad m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      if (qFromDefinition(r, m1) < qFromDefinition(r, m2)) {
        lo = m1;
      } else {
        hi = m2;
      }
    }
    const quad s_star = (lo + hi) / 2;
    const quad t_star = s_star / (1 - s_star);
    // P in t from the stored coefficients (undo the reversal).
    const auto p_at = [&problem](quad t) {
      const double* k = problem.coefficient;
      quad x = problem.reversed ? 1 / t : t;
      quad value = 0;
      for (int j = 0; j < 5; ++j) value = value * x + k[j];
      return value;
    };
    // The sign of P on either side of the quad maximiser: + left of it, - right of it (in t; the
    // reversed polynomial at x = 1 / t is P(t) / t^4, of the same sign), checked 1e-6 of t* away,
    // far beyond the coefficients' rounding.
    EXPECT_GT((double)p_at(t_star * (1 - (quad)1e-6)), 0.0) << describePair(a, b);
    EXPECT_LT((double)p_at(t_star * (1 + (quad)1e-6)), 0.0) << describePair(a, b);
    const double t_scale = std::sqrt((double)qFromDefinition(r, s_star));
    EXPECT_NEAR(contactScale(a, b) / t_scale, 1.0, 1e-14) << describePair(a, b);
  }
}

TEST(ContactScaleQuartic, BatchGivesTheBitsOfEachPairAlone) {
  Generator gen(32);
  std::vector<ScaleProblem> problems;
  std::vector<double> alone;
  for (int i = 0; i < 3000; ++i) {
    // Round, thin (to 1e5), far, deep, nearly concentric, and identical pairs, interleaved.
    const double ratio = i % 3 == 0 ? 1e5 : (i % 3 == 1 ? 10.0 : 1.0);
    auto [a, b] = gen.pair(ratio, i % 2 == 0 ? 2.0 : 0.5, i % 5 == 0 ? 1e4 : 3.0);
    if (i % 97 == 0) b = a;
    const PreparedEllipse pa(a), pb(b);
    problems.push_back(detail::scaleProblem(detail::canonicalRelativeShape(pa, pb)));
    alone.push_back(contactScale(pa, pb));
    EXPECT_TRUE(sameBits(alone.back(), contactScale(a, b))) << describePair(a, b);
  }
  std::vector<double> batch(problems.size());
  detail::solveContactScales(problems.data(), problems.size(), batch.data());
  for (std::size_t i = 0; i < batch.size(); ++i) {
    ASSERT_TRUE(sameBits(batch[i], alone[i])) << i << ": " << batch[i] << " vs " << alone[i];
  }
}

/// Steps the problem to its end; returns the steps taken, or kMaxQuarticSteps + 1 for a pair that
/// takes the certified fallback.
int stepsOf(const Ellipse& a, const Ellipse& b) {
  return detail::quarticStepsOf(detail::canonicalRelativeShape(a, b));
}

TEST(ContactScaleQuartic, RobotLikePairsTakeFewStepsAndNoFallback) {
  // Shapes of links and obstacles (axis ratios to 10, sizes within 10x), overlapping: what every
  // scene check pays for. The fallback is 2x the cost; it must stay the exception.
  Generator gen(33);
  int pairs = 0, steps = 0, fallbacks = 0, worst = 0;
  while (pairs < 5000) {
    const auto [a, b] = gen.pair(10.0, 1.0, 2.0);
    if (!overlap(a, b)) continue;
    ++pairs;
    const int taken = stepsOf(a, b);
    fallbacks += taken > detail::kMaxQuarticSteps ? 1 : 0;
    worst = std::max(worst, taken);
    steps += taken;
  }
  std::printf("[ quartic  ] robot-like overlapping pairs: mean steps %.2f, worst %d, fallbacks %d "
              "of %d\n", static_cast<double>(steps) / pairs, worst, fallbacks, pairs);
  EXPECT_EQ(fallbacks, 0);
  EXPECT_LT(static_cast<double>(steps) / pairs, 4.5);
}

TEST(ContactScaleQuartic, AgreesWithTheCertifiedMaximisationOnHardPairs) {
  // Axis ratios to 1e5, sizes over 4 decades, centres from 1e-6 to 1e4 sizes apart. The rounding
  // firstContact() allows contactScale() is 2.5e-12; both answers are far closer than that.
  Generator gen(34);
  double worst = 0.0;
  int fallbacks = 0;
  constexpr int kPairs = 20000;
  for (int i = 0; i < kPairs; ++i) {
    const auto [a, b] = gen.pair(1e5, 2.0, i % 2 == 0 ? 1e4 : 3.0);
    const RelativeShape r = detail::canonicalRelativeShape(a, b);
    const double certified = detail::contactScalePrincipal(detail::principalShape(r));
    const double fast = detail::solveContactScale(r);
    const double relative = std::abs(fast - certified) / certified;
    worst = std::max(worst, relative);
    ASSERT_LE(relative, 1e-13) << describePair(a, b);
    fallbacks += stepsOf(a, b) > detail::kMaxQuarticSteps ? 1 : 0;
  }
  std::printf("[ quartic  ] hard pairs: worst difference from the certified maximisation %.3g, "
              "fallbacks %d of %d\n", worst, fallbacks, kPairs);
  EXPECT_LT(fallbacks, kPairs / 20);
}

TEST(ContactScaleQuartic, UnusableQuarticsTakeTheCertifiedPath) {
  // Squared shape terms beyond double range (radii ratios 1e160): the quartic overflows and the
  // problem says so at once instead of iterating on infinities.
  const Ellipse a{{0.0, 0.0}, 1e-160, 1e-160, 0.0};
  const Ellipse b{{1.0, 0.5}, 1e160, 1.0, 0.3};
  const RelativeShape r = detail::canonicalRelativeShape(a, b);
  EXPECT_TRUE(detail::scaleProblem(r).fallback);
  const double certified = detail::contactScalePrincipal(detail::principalShape(r));
  EXPECT_TRUE(sameBits(contactScale(a, b), certified));
  EXPECT_TRUE(std::isfinite(certified));
}

TEST(ContactScaleQuartic, NeedlesBeyondAxisRatio1e9TakeTheCertifiedPath) {
  // Fuzzer findings: needles of axis ratio 1e18 nearly along the centre offset. The relative
  // frame's cross products cancel some 17 digits for any method built on it; the quartic and the
  // certified maximisation were then 2e-9 to 3e-9 off the quad oracle on opposite sides, and
  // contactScale() contradicted overlap() outside the 1e-9 band. Beyond axis ratio 1e9 (in the
  // unit frame) the certified maximisation answers, with overlap()'s own rounding.
  struct Case {
    Ellipse a, b;
  };
  const Case cases[] = {
      {{{1000000000.0, 3.0000000000000004}, 3.0000000000000004, 2.9999999999990892, 1.0},
       {{22.371089100837708, 6.111326733559963e-08}, 1000000000.0, 1.0000000000000001e-09,
        -1.9762625833649862e-323}},
      {{{3.0, 3.0}, 2.9999999999999996, 2.9999999999999987, 3.0},
       {{1000000000.0, 9.9999999999999998e-13}, 1000000000.0, 1.0000000000000001e-09, 0.0}},
  };
  for (const Case& c : cases) {
    const RelativeShape r = detail::canonicalRelativeShape(c.a, c.b);
    EXPECT_TRUE(detail::scaleProblem(r).fallback) << describePair(c.a, c.b);
    const double certified = detail::contactScalePrincipal(detail::principalShape(r));
    EXPECT_TRUE(sameBits(contactScale(c.a, c.b), certified)) << describePair(c.a, c.b);
    EXPECT_EQ(overlap(c.a, c.b), contactScale(c.a, c.b) <= 1.0) << describePair(c.a, c.b);
  }
  // Shapes up to axis ratio 1e8 in the unit frame keep the quartic.
  const Ellipse circle{{0.0, 0.0}, 1.0, 1.0, 0.0};
  const Ellipse needle{{2.0, 0.5}, 1e4, 1e-4, 0.3};
  EXPECT_FALSE(detail::scaleProblem(detail::canonicalRelativeShape(circle, needle)).fallback);
}

TEST(ContactScaleQuartic, CertifiedMaximisationKeepsAnOffsetOf1e280) {
  // Fuzzer finding: equal shapes turned by 4.7e-62, centres 2e-283 apart. The eigenvector of
  // the certified path had length 1e-58, and its product with the offset underflowed: t* = 0,
  // "coincident centres", where the quartic finds 1.5e-280.
  const Ellipse a{{5.2413296049490307e-312, 0.0}, 2.0, 0.00068433284759521489, 0.0};
  const Ellipse b{{4.8381504034008209e-312, 2.0847106595282407e-283}, 2.0,
                  0.00068433284759521489, 4.6672614583958561e-62};
  const RelativeShape r = detail::canonicalRelativeShape(a, b);
  const double certified = detail::contactScalePrincipal(detail::principalShape(r));
  EXPECT_GT(certified, 1e-280);
  EXPECT_NEAR(contactScale(a, b) / certified, 1.0, 1e-12);
}

TEST(ContactScaleQuartic, ANaNOffsetIsNoAnswerRatherThanCoincidentCentres) {
  // Invalid input (the API requires valid ellipses), as a fuzz harness once fed it: the quartic
  // must not read a NaN offset as coincident centres (t* = 0, "collision"); like the certified
  // path, it answers NaN.
  const Ellipse a{{0.0, 0.0}, 1.0, 0.5, 0.3};
  const Ellipse b{{std::nan(""), 3.0}, 1.6875, 1.0, 0.0};
  EXPECT_TRUE(std::isnan(contactScale(a, b)));
  EXPECT_TRUE(std::isnan(contactScale(b, a)));
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

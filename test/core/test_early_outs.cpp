// The cheap certified stages in front of overlap()'s polygonal and eigenvalue tests: the
// centre-line test and the Perram-Wertheim one-point test, both fed with the coarse sines and
// cosines. Every decision they make is checked against the quad-precision oracle, on pairs placed
// at t* = 1 +- delta from far outside their margins down into the band no double-input method can
// decide, with axis ratios below and beyond their caps.

#include <gtest/gtest.h>
#include <quadmath.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "centre_line_test.h"
#include "contact_scale_oracle.h"
#include "ellipse_collision/core/ellipse.h"
#include "one_point_test.h"
#include "random_source.h"
#include "sin_cos.h"

namespace ellipse_collision::core {
namespace test {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Pairs closer to tangency than this (relative t*) cannot be decided from double inputs: a
// decision there means a margin that does not cover its rounding.
constexpr double kAmbiguousBand = 1e-12;

class Generator : public ellipse_collision::test::RandomSource {
 public:
  using RandomSource::RandomSource;
  Ellipse ellipse(double max_offset, double min_major, double max_major, double max_ratio) {
    Ellipse e;
    e.center = {uniform(-max_offset, max_offset), uniform(-max_offset, max_offset)};
    const double major = logUniform(min_major, max_major);
    const double minor = major / logUniform(1.0, max_ratio);
    const bool x_major = coin();
    e.radius_x = x_major ? major : minor;
    e.radius_y = x_major ? minor : major;
    e.angle = uniform(-4.0 * kPi, 4.0 * kPi);
    return e;
  }
};

struct Tally {
  int decided{0};
  int undecided{0};
  int wrong{0};
  int decided_in_band{0};
  std::string first_failure;
};

void record(Tally* tally, PolygonalResult verdict, const Ellipse& a, const Ellipse& b,
            const char* stage) {
  if (verdict == PolygonalResult::Unknown) {
    ++tally->undecided;
    return;
  }
  ++tally->decided;
  const __float128 t = oracleContactScale(a, b).quad;
  const __float128 off = t - 1;
  const bool in_band = (off < 0 ? -off : off) <= kAmbiguousBand;
  const bool oracle_overlap = t <= 1;
  const bool wrong = (verdict == PolygonalResult::Overlap) != oracle_overlap;
  if (in_band) ++tally->decided_in_band;
  if (!in_band && wrong) ++tally->wrong;
  if ((in_band || wrong) && tally->first_failure.empty()) {
    tally->first_failure = std::string(stage) + " said " + toString(verdict) + " at t* = " +
                           toString(t) + " for " + describePair(a, b);
  }
}

/// Both stages on one pair, with the coarse sines and cosines as overlap() feeds them, and the
/// one-point test also at other points of (0, 1): its certificates hold for every s.
void checkPair(Tally* centre_line, Tally* one_point, const Ellipse& a, const Ellipse& b) {
  const detail::SinCosPair trig = detail::sinCosPairCoarse(a.angle, b.angle);
  const detail::CentreLineResult line = detail::centreLineTest(a, trig.first, b, trig.second);
  record(centre_line, line.result, a, b, "centre line");
  for (const double s : {line.circle_guess, 0.1, 0.5, 0.9}) {
    record(one_point, detail::onePointTest(a, trig.first, b, trig.second, s), a, b, "one point");
  }
}

void expectSound(const Tally& tally, const char* name) {
  EXPECT_EQ(tally.wrong, 0) << name << ": " << tally.first_failure;
  EXPECT_EQ(tally.decided_in_band, 0) << name << ": " << tally.first_failure;
}

TEST(EarlyOuts, CoarseSinCosStaysWithinItsStatedError) {
  Generator gen(41);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double angle = i < 100000 ? gen.uniform(-8.0, 8.0) : gen.uniform(-1e5, 1e5);
    const detail::SinCosPair coarse = detail::sinCosPairCoarse(angle, -angle);
    const __float128 q = angle;
    const double exact_sin = static_cast<double>(sinq(q)), exact_cos = static_cast<double>(cosq(q));
    worst = std::max({worst, std::abs(coarse.first.sin - exact_sin),
                      std::abs(coarse.first.cos - exact_cos),
                      std::abs(coarse.second.sin + exact_sin),
                      std::abs(coarse.second.cos - exact_cos)});
  }
  std::printf("sinCosPairCoarse: worst error %.3g (bound %.3g)\n", worst,
              detail::kCoarseSinCosError);
  EXPECT_LE(worst, detail::kCoarseSinCosError);
  EXPECT_GT(worst, 1e-14);  // really the short series, not the long one
}

TEST(EarlyOuts, DecisionsNearTangencyMatchTheOracleAndNoneFallInTheAmbiguousBand) {
  Generator gen(42);
  for (const double max_ratio : {8.0, 30.0, 1e3, 1e5}) {
    for (const double delta : {0.3, 1e-2, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13}) {
      Tally centre_line, one_point;
      for (int i = 0; i < 300; ++i) {
        const Ellipse a = gen.ellipse(10.0, 0.05, 5.0, max_ratio);
        Ellipse b = gen.ellipse(0.0, 0.05, 5.0, max_ratio);
        b.center = a.center + Eigen::Vector2d(gen.uniform(-1.0, 1.0), gen.uniform(-1.0, 1.0));
        const double target = gen.coin() ? 1.0 - delta : 1.0 + delta;
        const Ellipse placed = placeAtContactScale(a, b, target);
        checkPair(&centre_line, &one_point, a, placed);
        checkPair(&centre_line, &one_point, placed, a);
      }
      char name[96];
      std::snprintf(name, sizeof name, "ratio %.0e, t* = 1 +- %.0e: centre line %d/%d, one point %d/%d",
                    max_ratio, delta, centre_line.decided,
                    centre_line.decided + centre_line.undecided, one_point.decided,
                    one_point.decided + one_point.undecided);
      std::printf("%s\n", name);
      expectSound(centre_line, name);
      expectSound(one_point, name);
      if (delta >= 0.3 && max_ratio <= 30.0) {
        // Clear pairs are what the stages are for: most must be decided, or overlap() pays for
        // nothing.
        EXPECT_GT(centre_line.decided + one_point.decided / 4, 300) << name;
      }
    }
  }
}

TEST(EarlyOuts, FarFromTheOriginTinyAndHugeEllipsesAreDecidedSoundly) {
  Generator gen(43);
  Tally centre_line, one_point;
  for (int i = 0; i < 1500; ++i) {
    const double size = gen.logUniform(1e-8, 1e8);
    Ellipse a = gen.ellipse(0.0, size, 4.0 * size, 20.0);
    a.center = {gen.uniform(-1e9, 1e9) * (gen.coin() ? 1.0 : 1e-6), gen.uniform(-1e9, 1e9)};
    a.center = a.center.cwiseMax(-kMaxCoordinate + 10.0 * size).cwiseMin(kMaxCoordinate - 10.0 * size);
    Ellipse b = gen.ellipse(0.0, size, 4.0 * size, 20.0);
    b.center = a.center + size * Eigen::Vector2d(gen.uniform(-1.0, 1.0), gen.uniform(-1.0, 1.0));
    if (b.center == a.center) continue;
    const double delta = gen.logUniform(1e-13, 1e-1);
    const Ellipse placed = placeAtContactScale(a, b, gen.coin() ? 1.0 - delta : 1.0 + delta);
    if (!invalidReason(placed).empty()) continue;
    checkPair(&centre_line, &one_point, a, placed);
  }
  expectSound(centre_line, "far/tiny/huge centre line");
  expectSound(one_point, "far/tiny/huge one point");
  EXPECT_GT(centre_line.decided, 30);  // the family reaches the decisions, not only Unknown
}

TEST(EarlyOuts, CoincidentAndNearlyCoincidentCentresAreOverlapOrUnknown) {
  Generator gen(44);
  for (int i = 0; i < 2000; ++i) {
    const Ellipse a = gen.ellipse(5.0, 1e-9, 1e9, 1e4);
    Ellipse b = gen.ellipse(0.0, 1e-9, 1e9, 1e4);
    b.center = a.center + Eigen::Vector2d(gen.uniform(-1e-300, 1e-300), 0.0) * (i % 2);
    const detail::SinCosPair trig = detail::sinCosPairCoarse(a.angle, b.angle);
    const detail::CentreLineResult line = detail::centreLineTest(a, trig.first, b, trig.second);
    EXPECT_NE(line.result, PolygonalResult::Separate) << describePair(a, b);
    EXPECT_NE(detail::onePointTest(a, trig.first, b, trig.second, 0.5), PolygonalResult::Separate)
        << describePair(a, b);
  }
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

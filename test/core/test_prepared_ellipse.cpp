// PreparedEllipse must cache the right per-ellipse quantities, and the prepared pair tests must
// answer bit for bit like the plain ones (which test_overlap_accuracy checks against the oracle).

#include <gtest/gtest.h>
#include <quadmath.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "contact_scale_oracle.h"
#include "ellipse_builders.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Pair {
  Ellipse a;
  Ellipse b;
};

class Random : public ellipse_collision::test::RandomSource {
 public:
  using RandomSource::RandomSource;

  Ellipse ellipse(double half_width, double min_major, double max_major, double max_ratio,
                  double max_angle = kPi) {
    return ellipse_collision::test::randomEllipse(*this, half_width, min_major, max_major,
                                                  max_ratio, max_angle);
  }

  /// `b` moved to contact scale 1 +- delta from `a`, delta log-uniform in [1e-9, 1e-3].
  Pair nearTangent(const Ellipse& a, Ellipse b) {
    const double phi = uniform(-kPi, kPi);
    b.center = a.center + Eigen::Vector2d(std::cos(phi), std::sin(phi));
    const double delta = logUniform(1e-9, 1e-3);
    return {a, test::placeAtContactScale(a, b, coin() ? 1.0 - delta : 1.0 + delta)};
  }
};

bool sameBits(double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; }

/// Checks both argument orders; returns how many of the pairs overlap.
int expectPreparedMatchesPlain(const std::vector<Pair>& pairs, const std::string& family) {
  int overlaps = 0;
  int reported = 0;
  for (const Pair& p : pairs) {
    const PreparedEllipse pa(p.a), pb(p.b);
    for (const bool swapped : {false, true}) {
      const Ellipse& a = swapped ? p.b : p.a;
      const Ellipse& b = swapped ? p.a : p.b;
      const PreparedEllipse& prepared_a = swapped ? pb : pa;
      const PreparedEllipse& prepared_b = swapped ? pa : pb;
      const bool plain = overlap(a, b);
      const double plain_scale = contactScale(a, b);
      const double prepared_scale = contactScale(prepared_a, prepared_b);
      overlaps += plain && !swapped ? 1 : 0;
      if ((overlap(prepared_a, prepared_b) != plain || !sameBits(plain_scale, prepared_scale)) &&
          ++reported <= 5) {
        ADD_FAILURE() << "[" << family << "] prepared and plain differ: overlap " << plain
                      << ", contactScale " << plain_scale << " vs " << prepared_scale << "\n  "
                      << test::describePair(a, b);
      }
    }
  }
  return overlaps;
}

TEST(PreparedEllipse, AnswersBitForBitLikeThePlainApi) {
  Random random(21);
  std::vector<Pair> scattered, tangent, far_away, huge_angles, equal_areas, concentric;
  for (int i = 0; i < 1500; ++i) {
    scattered.push_back({random.ellipse(2.0, 0.1, 3.0, 20.0), random.ellipse(2.0, 0.1, 3.0, 20.0)});
    tangent.push_back(random.nearTangent(random.ellipse(5.0, 0.05, 2.0, 50.0),
                                         random.ellipse(0.0, 0.05, 2.0, 50.0)));
    Ellipse a = random.ellipse(100.0, 0.1, 3.0, 10.0);
    a.center += Eigen::Vector2d(1e6, -1e6);
    far_away.push_back(random.nearTangent(a, random.ellipse(0.0, 0.1, 3.0, 10.0)));
    // Beyond the fast sine's range on one or both sides: the library takes over.
    huge_angles.push_back(random.nearTangent(random.ellipse(5.0, 0.1, 3.0, 10.0, 1e7),
                                             random.ellipse(0.0, 0.1, 3.0, 10.0, 2e5)));
    // Equal areas take the tie-breaking order; equal angles give an exact relative rotation.
    Ellipse c = random.ellipse(3.0, 0.2, 2.0, 5.0), d = c;
    d.center = {random.uniform(-3.0, 3.0), random.uniform(-3.0, 3.0)};
    if (random.coin()) std::swap(d.radius_x, d.radius_y);
    if (random.coin()) d.angle = random.uniform(-kPi, kPi);
    equal_areas.push_back({c, d});
    Ellipse e = random.ellipse(3.0, 0.01, 2.0, 100.0), f = random.ellipse(0.0, 0.01, 2.0, 100.0);
    f.center = e.center;
    concentric.push_back({e, random.coin() ? e : f});
  }
  const std::pair<const char*, const std::vector<Pair>*> families[] = {
      {"scattered", &scattered},     {"near tangency", &tangent},   {"1e6 m away", &far_away},
      {"huge angles", &huge_angles}, {"equal areas", &equal_areas}, {"concentric", &concentric}};
  for (const auto& [name, pairs] : families) {
    const int overlaps = expectPreparedMatchesPlain(*pairs, name);
    if (std::string(name) == "concentric") {
      EXPECT_EQ(overlaps, static_cast<int>(pairs->size()));
    } else {  // both answers must occur for the comparison to mean anything
      EXPECT_GT(overlaps, 100) << name;
      EXPECT_LT(overlaps, static_cast<int>(pairs->size()) - 100) << name;
    }
  }
}

TEST(PreparedEllipse, HugeAnglesAreClassifiedLikeTheOracle) {
  // test_overlap_accuracy keeps angles within +-2 pi; beyond 1e5 rad the sines come from the
  // library instead of the inline polynomial, and must be as good.
  Random random(22);
  int wrong = 0;
  for (int i = 0; i < 1000; ++i) {
    const Pair p = random.nearTangent(random.ellipse(5.0, 0.1, 3.0, 10.0, 1e8),
                                      random.ellipse(0.0, 0.1, 3.0, 10.0, 1e5 + 10.0));
    const __float128 t = test::oracleContactScale(p.a, p.b).quad;
    if (fabsq(t - 1) <= 1e-12) continue;
    if (overlap(PreparedEllipse(p.a), PreparedEllipse(p.b)) != (t <= 1) && ++wrong <= 5) {
      ADD_FAILURE() << "oracle t* = " << test::toString(t) << "\n  "
                    << test::describePair(p.a, p.b);
    }
  }
  EXPECT_EQ(wrong, 0);
}

TEST(PreparedEllipse, CachesCosAndSinToWithinTwoUlps) {
  Random random(23);
  std::vector<double> angles = {0.0,        -0.0,        kPi / 4, kPi / 2, kPi,
                                -kPi,       3 * kPi / 2, 1e5,     -1e5,    std::nextafter(1e5, 2e5),
                                123456.789, -9.87e15};
  for (int k = -40; k <= 40; ++k) {
    angles.push_back(k * kPi / 4);  // quadrant boundaries and the middles between them
    angles.push_back(std::nextafter(k * kPi / 4, 1e9));
  }
  for (int i = 0; i < 20000; ++i) angles.push_back(random.uniform(-1e5, 1e5));
  for (int i = 0; i < 2000; ++i) angles.push_back(random.uniform(-7.0, 7.0));
  constexpr double kTwoUlpsOfOne = 4.440892098500626e-16;
  for (const double angle : angles) {
    Ellipse e;
    e.angle = angle;
    const PreparedEllipse prepared(e);
    const double true_cos = static_cast<double>(cosq(static_cast<__float128>(angle)));
    const double true_sin = static_cast<double>(sinq(static_cast<__float128>(angle)));
    // Absolute error: these enter rotation matrices, where that is what counts.
    EXPECT_NEAR(prepared.cosAngle(), true_cos, kTwoUlpsOfOne) << "angle " << angle;
    EXPECT_NEAR(prepared.sinAngle(), true_sin, kTwoUlpsOfOne) << "angle " << angle;
  }
}

TEST(PreparedEllipse, AxisAlignedEllipseHasExactlyUnitCosAndZeroSin) {
  Ellipse e;
  e.angle = 0.0;
  const PreparedEllipse prepared(e);
  EXPECT_EQ(prepared.cosAngle(), 1.0);
  EXPECT_EQ(prepared.sinAngle(), 0.0);
}

TEST(PreparedEllipse, CachesRadiiAndTheBoundingBoxOfTheEllipse) {
  Random random(24);
  for (int i = 0; i < 500; ++i) {
    const Ellipse e = random.ellipse(1e3, 1e-3, 1e3, 1e3);
    const PreparedEllipse prepared(e);
    EXPECT_EQ(prepared.ellipse().center, e.center);
    EXPECT_EQ(prepared.ellipse().angle, e.angle);
    EXPECT_EQ(prepared.inverseRadiusX(), 1.0 / e.radius_x);
    EXPECT_EQ(prepared.inverseRadiusY(), 1.0 / e.radius_y);
    EXPECT_EQ(prepared.boundingRadius(), std::max(e.radius_x, e.radius_y));
    EXPECT_EQ(prepared.inscribedRadius(), std::min(e.radius_x, e.radius_y));
    const BoundingBox box = boundingBox(e);
    EXPECT_EQ(prepared.box().min_x, box.min_x);
    EXPECT_EQ(prepared.box().min_y, box.min_y);
    EXPECT_EQ(prepared.box().max_x, box.max_x);
    EXPECT_EQ(prepared.box().max_y, box.max_y);
  }
}

}  // namespace
}  // namespace ellipse_collision::core

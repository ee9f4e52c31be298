// Accuracy of distance() against the independent primal oracle of distance_oracle.h. Separated
// pairs are built from a contact normal n and a gap g in quad precision: b is placed so that its
// support point in -n lies g beyond a's support point in n, which makes g the exact distance
// before b's centre is rounded to double. The oracle must reproduce g too, which checks the oracle.
// Every family uses a fixed seed so that a failure repeats; failing pairs are printed with %.17g.

#include <gtest/gtest.h>
#include <quadmath.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "contact_scale_oracle.h"
#include "distance_oracle.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/overlap.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();

// distance() must match the oracle to this relative error.
constexpr double kRelTolerance = 1e-9;
// Witness points must lie this close to their rims, relative to the ellipse's size; a coordinate
// of magnitude |p| is also allowed its own rounding, eps |p|.
constexpr double kRimTolerance = 1e-9;
// The oracle must reproduce the constructed gap to this relative error, beyond the shift caused by
// rounding b's centre to double.
constexpr double kOracleTolerance = 1e-20;
constexpr int kMaxReportedFailures = 8;

std::string str(quad value) {
  char buffer[64];
  quadmath_snprintf(buffer, sizeof buffer, "%.25Qg", value);
  return buffer;
}

/// A separated pair and the distance it was built with.
struct Built {
  Ellipse a, b;
  quad gap;    ///< distance before b's centre was rounded [m]
  quad shift;  ///< how far rounding moved b's centre [m]; the true distance is gap +- shift
};

/// Offset from the centre to the support point of `e` in direction (nx, ny), in quad [m].
void supportOffset(const Ellipse& e, quad nx, quad ny, quad* ox, quad* oy) {
  const quad angle = e.angle;
  const quad c = cosq(angle), s = sinq(angle);
  const quad p = nx * c + ny * s, q = -nx * s + ny * c;
  const quad rx = e.radius_x, ry = e.radius_y;
  const quad h = sqrtq(rx * rx * p * p + ry * ry * q * q);
  const quad lx = rx * rx * p / h, ly = ry * ry * q / h;
  *ox = c * lx - s * ly;
  *oy = s * lx + c * ly;
}

/// Places b (its shape and angle kept) so that the pair's contact normal is at `normal_angle` and
/// the gap is `gap` [m]; a negative gap makes them overlap by that much along the normal.
Built place(const Ellipse& a, Ellipse b, double normal_angle, double gap) {
  const quad nx = cosq(static_cast<quad>(normal_angle)), ny = sinq(static_cast<quad>(normal_angle));
  quad ax, ay, bx, by;
  supportOffset(a, nx, ny, &ax, &ay);
  supportOffset(b, nx, ny, &bx, &by);
  const quad cx = static_cast<quad>(a.center.x()) + ax + gap * nx + bx;
  const quad cy = static_cast<quad>(a.center.y()) + ay + gap * ny + by;
  b.center = Eigen::Vector2d(static_cast<double>(cx), static_cast<double>(cy));
  const quad ex = static_cast<quad>(b.center.x()) - cx, ey = static_cast<quad>(b.center.y()) - cy;
  return {a, b, gap, sqrtq(ex * ex + ey * ey)};
}

using Random = ellipse_collision::test::RandomSource;

/// Ellipse at `center` with radius_x log-uniform in [size_lo, size_hi] and the axis ratio
/// log-uniform in [1, max_ratio] (radius_y the smaller one, or the larger one half the time).
Ellipse randomEllipse(Random& rng, Eigen::Vector2d center, double size_lo, double size_hi,
                      double max_ratio) {
  Ellipse e;
  e.center = center;
  const double major = rng.logUniform(size_lo, size_hi);
  const double minor = std::max(major / rng.logUniform(1.0, max_ratio), size_lo);
  const bool swap = rng.integer(0, 1) == 1;
  e.radius_x = swap ? minor : major;
  e.radius_y = swap ? major : minor;
  e.angle = rng.uniform(-kPi, kPi);
  return e;
}

double size(const Ellipse& e) { return std::max(e.radius_x, e.radius_y); }

/// Checks distance() on separated pairs against the oracle and records the worst errors.
class Checker {
 public:
  explicit Checker(std::string family) : family_(std::move(family)) {}

  ~Checker() {
    std::printf("[ %-22s ] %4d pairs, max rel. error %.3g, max rim offset/size %.3g\n",
                family_.c_str(), pairs_, max_rel_error_, max_rim_error_);
  }

  void check(const Built& built) { check(built.a, built.b, &built); }

  /// `built`, when given, is also used to check the oracle.
  void check(const Ellipse& a, const Ellipse& b, const Built* built = nullptr) {
    ++pairs_;
    const Clearance c = distance(a, b);
    const OracleDistance o = oracleDistance(a, b);
    const quad truth = o.distance;
    bool ok = c.separated && !overlap(a, b);

    if (built != nullptr) {
      const quad oracle_error = fabsq(truth - built->gap);
      if (oracle_error > built->shift + kOracleTolerance * built->gap) {
        report(a, b,
               "oracle misses the constructed gap " + str(built->gap) + " (shift " +
                   str(built->shift) + "): oracle " + str(truth));
      }
    }

    const double rel_error =
        static_cast<double>(fabsq(static_cast<quad>(c.distance) - truth) / truth);
    max_rel_error_ = std::max(max_rel_error_, rel_error);
    ok = ok && rel_error <= kRelTolerance;

    const double rim_a = rimError(a, c.point_a), rim_b = rimError(b, c.point_b);
    max_rim_error_ = std::max({max_rim_error_, rim_a, rim_b});
    ok = ok && rim_a <= kRimTolerance && rim_b <= kRimTolerance;

    // |p_b - p_a| is the distance, up to the rounding of four coordinates.
    const quad wx = static_cast<quad>(c.point_b.x()) - c.point_a.x();
    const quad wy = static_cast<quad>(c.point_b.y()) - c.point_a.y();
    const double gap = static_cast<double>(sqrtq(wx * wx + wy * wy));
    const double magnitude = std::max(
        {c.point_a.cwiseAbs().maxCoeff(), c.point_b.cwiseAbs().maxCoeff(), size(a), size(b)});
    ok = ok && std::abs(gap - c.distance) <= kRelTolerance * c.distance + 8 * kEps * magnitude;

    if (!ok) {
      char buffer[512];
      std::snprintf(buffer, sizeof buffer,
                    "separated %d, distance %.17g (rel. error %.3g), |p_b - p_a| %.17g, rim errors "
                    "%.3g %.3g, p_a (%.17g, %.17g), p_b (%.17g, %.17g)",
                    c.separated, c.distance, rel_error, gap, rim_a, rim_b, c.point_a.x(),
                    c.point_a.y(), c.point_b.x(), c.point_b.y());
      report(a, b, buffer + (", oracle " + str(truth)));
    }
  }

 private:
  /// Distance of p from e's rim over e's size, less the rounding allowance of p's coordinates.
  static double rimError(const Ellipse& e, const Eigen::Vector2d& p) {
    const double off = static_cast<double>(distanceToRim(e, p.x(), p.y()));
    return std::max(0.0, off - kEps * p.cwiseAbs().maxCoeff()) / size(e);
  }

  void report(const Ellipse& a, const Ellipse& b, const std::string& what) {
    if (++failures_ <= kMaxReportedFailures) {
      ADD_FAILURE() << family_ << ": " << describePair(a, b) << ": " << what;
    } else if (failures_ == kMaxReportedFailures + 1) {
      ADD_FAILURE() << family_ << ": further failures not shown";
    }
  }

  std::string family_;
  int pairs_{0};
  int failures_{0};
  double max_rel_error_{0.0};
  double max_rim_error_{0.0};
};

TEST(Distance, CirclesMatchTheClosedForm) {
  Random rng(11);
  double max_error = 0.0;
  for (int i = 0; i < 2000; ++i) {
    Ellipse a, b;
    a.center = {rng.uniform(-100, 100), rng.uniform(-100, 100)};
    b.center = {rng.uniform(-100, 100), rng.uniform(-100, 100)};
    a.radius_x = a.radius_y = rng.logUniform(1e-3, 50);
    b.radius_x = b.radius_y = rng.logUniform(1e-3, 50);
    a.angle = rng.uniform(-kPi, kPi);
    b.angle = rng.uniform(-kPi, kPi);
    const quad dx = static_cast<quad>(b.center.x()) - a.center.x();
    const quad dy = static_cast<quad>(b.center.y()) - a.center.y();
    const quad exact = sqrtq(dx * dx + dy * dy) - a.radius_x - b.radius_x;
    const Clearance c = distance(a, b);
    if (exact <= 0) {
      EXPECT_FALSE(c.separated) << describePair(a, b);
      continue;
    }
    ASSERT_TRUE(c.separated) << describePair(a, b);
    const double error = static_cast<double>(fabsq(c.distance - exact) / exact);
    max_error = std::max(max_error, error);
    ASSERT_LE(error, kRelTolerance) << describePair(a, b) << ": " << c.distance << " vs " << str(exact);
    // The witness points lie on the line of centres (coordinates are below 150 m).
    const Eigen::Vector2d d_hat = (b.center - a.center).normalized();
    EXPECT_NEAR((c.point_a - (a.center + a.radius_x * d_hat)).norm(), 0.0, 1e-10) << describePair(a, b);
    EXPECT_NEAR((c.point_b - (b.center - b.radius_x * d_hat)).norm(), 0.0, 1e-10) << describePair(a, b);
  }
  std::printf("[ circles                ] max rel. error %.3g\n", max_error);
}

TEST(Distance, RandomPairsMatchTheOracle) {
  Random rng(21);
  Checker checker("random");
  for (int i = 0; i < 300; ++i) {
    const Ellipse a =
        randomEllipse(rng, {rng.uniform(-10, 10), rng.uniform(-10, 10)}, 0.05, 5, 20);
    const Ellipse b = randomEllipse(rng, {0, 0}, 0.05, 5, 20);
    const double gap = rng.logUniform(1e-4, 3) * std::max(size(a), size(b));
    checker.check(place(a, b, rng.uniform(-kPi, kPi), gap));
  }
}

TEST(Distance, ThinCrossingPairsMatchTheOracle) {
  Random rng(31);
  Checker checker("thin crossing (1e3)");
  for (int i = 0; i < 300; ++i) {
    Ellipse a, b;
    a.radius_x = rng.logUniform(0.5, 2);
    a.radius_y = a.radius_x * 1e-3;
    b.radius_x = rng.logUniform(0.5, 2);
    b.radius_y = b.radius_x * 1e-3;
    a.center = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
    a.angle = rng.uniform(-kPi, kPi);
    b.angle = a.angle + kPi / 2 + rng.uniform(-0.3, 0.3);
    const double gap = rng.logUniform(1e-6, 1) * std::max(size(a), size(b));
    checker.check(place(a, b, rng.uniform(-kPi, kPi), gap));
  }
}

TEST(Distance, ThinParallelPairsMatchTheOracle) {
  Random rng(41);
  Checker checker("thin parallel (1e3)");
  for (int i = 0; i < 300; ++i) {
    Ellipse a, b;
    a.radius_x = rng.logUniform(0.5, 2);
    a.radius_y = a.radius_x * 1e-3;
    b.radius_x = rng.logUniform(0.5, 2);
    b.radius_y = b.radius_x * 1e-3;
    a.center = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
    a.angle = rng.uniform(-kPi, kPi);
    b.angle = i % 2 == 0 ? a.angle : a.angle + rng.uniform(-1e-3, 1e-3);
    // Stacked side by side (normal along the minor axes), nearly so, or at a random angle.
    const int kind = i % 3;
    const double normal = kind == 0   ? a.angle + kPi / 2
                          : kind == 1 ? a.angle + kPi / 2 + rng.uniform(-1e-3, 1e-3)
                                      : rng.uniform(-kPi, kPi);
    const double gap = rng.logUniform(1e-6, 1) * std::max(size(a), size(b));
    checker.check(place(a, b, normal, gap));
  }
}

TEST(Distance, NearTangentPairsMatchTheOracle) {
  for (const double relative_gap : {1e-3, 1e-6}) {
    Random rng(51);
    char family[32];
    std::snprintf(family, sizeof family, "near tangent, gap %g", relative_gap);
    Checker checker(family);
    for (int i = 0; i < 300; ++i) {
      const Ellipse a = randomEllipse(rng, {rng.uniform(-3, 3), rng.uniform(-3, 3)}, 0.1, 2, 1e3);
      const Ellipse b = randomEllipse(rng, {0, 0}, 0.1, 2, 1e3);
      const double gap = relative_gap * std::max(size(a), size(b));
      checker.check(place(a, b, rng.uniform(-kPi, kPi), gap));
    }
  }
}

TEST(Distance, PairsFarFromTheOriginMatchTheOracle) {
  Random rng(61);
  Checker checker("1e6 m from the origin");
  for (int i = 0; i < 200; ++i) {
    const double where = rng.uniform(-kPi, kPi);
    const Eigen::Vector2d center = 1e6 * Eigen::Vector2d(std::cos(where), std::sin(where));
    const Ellipse a = randomEllipse(rng, center, 0.1, 10, 100);
    const Ellipse b = randomEllipse(rng, center, 0.1, 10, 100);
    const double gap = rng.logUniform(1e-3, 1) * std::max(size(a), size(b));
    checker.check(place(a, b, rng.uniform(-kPi, kPi), gap));
  }
}

TEST(Distance, MixedSizesMatchTheOracle) {
  Random rng(71);
  Checker checker("sizes 1e-4..1e4 m");
  for (int i = 0; i < 300; ++i) {
    const Ellipse a = randomEllipse(rng, {0, 0}, 1e-4, 1e4, 1e3);
    const Ellipse b = randomEllipse(rng, {0, 0}, 1e-4, 1e4, 1e3);
    const double gap = rng.logUniform(1e-6, 1) * std::max(size(a), size(b));
    checker.check(place(a, b, rng.uniform(-kPi, kPi), gap));
  }
}

// With angle 0 the axes are exact, so nothing limits the accuracy but the evaluation itself: the
// gap, a tiny difference of large support values, must still come out to 1e-9.
TEST(Distance, AxisAlignedPairsStayExactAtTinyGaps) {
  Random rng(101);
  Checker checker("axis aligned, gap 1e-9");
  for (int i = 0; i < 200; ++i) {
    Ellipse a = randomEllipse(rng, {rng.uniform(-3, 3), rng.uniform(-3, 3)}, 0.1, 2, 1e3);
    Ellipse b = randomEllipse(rng, {0, 0}, 0.1, 2, 1e3);
    a.angle = b.angle = 0.0;
    const double gap = 1e-9 * std::max(size(a), size(b));
    checker.check(place(a, b, rng.uniform(-kPi, kPi), gap));
  }
}

// The line of centres need not separate the ellipses: here u = d/|d| sees them overlap, and a
// search that followed the dual objective there could stop in a negative local maximum.
TEST(Distance, NeedlesWhoseCentreLineDoesNotSeparateThemAreSolved) {
  Checker checker("staggered needles");
  for (const double gap : {1e-1, 1e-3, 1e-6, 1e-9}) {
    Ellipse a, b;
    a.radius_x = b.radius_x = 1.0;
    a.radius_y = b.radius_y = 1e-3;
    // A normal 3 mrad off the minor axes puts b's centre at about (1.9, 6e-4 + gap).
    const Built built = place(a, b, kPi / 2 - 3e-3, gap);
    const Eigen::Vector2d d = built.b.center - built.a.center;
    ASSERT_LT(d.norm(), 2.0) << "the centre line must see the needles overlap";
    checker.check(built);
  }
}

TEST(Distance, OverlappingPairsAreNotSeparatedAndHaveZeroDistance) {
  Random rng(81);
  std::vector<std::pair<Ellipse, Ellipse>> pairs;
  for (int i = 0; i < 300; ++i) {
    const Ellipse a = randomEllipse(rng, {rng.uniform(-3, 3), rng.uniform(-3, 3)}, 0.01, 2, 1e3);
    const Ellipse b = randomEllipse(rng, {0, 0}, 0.01, 2, 1e3);
    // b's support point in -n lies inside a by `depth` along n.
    const double depth = rng.logUniform(1e-6, 1) * std::min(size(a), size(b)) * 1e-3;
    pairs.emplace_back(a, place(a, b, rng.uniform(-kPi, kPi), -depth).b);
  }
  Ellipse big;
  big.radius_x = 3.0;
  big.radius_y = 1.0;
  big.angle = 0.4;
  Ellipse small = big;
  small.radius_x = 0.1;
  small.radius_y = 0.01;
  small.center = {0.5, 0.2};
  pairs.emplace_back(big, small);  // containment
  pairs.emplace_back(small, big);
  pairs.emplace_back(big, big);  // identical
  small.center = big.center;
  pairs.emplace_back(small, big);  // coincident centres
  for (const auto& [a, b] : pairs) {
    ASSERT_TRUE(overlap(a, b)) << describePair(a, b);
    const Clearance c = distance(a, b);
    EXPECT_FALSE(c.separated) << describePair(a, b);
    EXPECT_EQ(c.distance, 0.0) << describePair(a, b);
  }
}

TEST(Distance, SwappingTheEllipsesSwapsTheWitnessPoints) {
  Random rng(91);
  for (int i = 0; i < 200; ++i) {
    const Ellipse a = randomEllipse(rng, {rng.uniform(-3, 3), rng.uniform(-3, 3)}, 0.1, 2, 1e3);
    const Ellipse b = randomEllipse(rng, {0, 0}, 0.1, 2, 1e3);
    const Built built = place(a, b, rng.uniform(-kPi, kPi), rng.logUniform(1e-6, 1));
    const Clearance ab = distance(built.a, built.b);
    const Clearance ba = distance(built.b, built.a);
    ASSERT_TRUE(ab.separated && ba.separated) << describePair(built.a, built.b);
    const double scale = std::max(size(a), size(b));
    EXPECT_NEAR(ab.distance, ba.distance, 1e-9 * ab.distance) << describePair(built.a, built.b);
    EXPECT_NEAR((ab.point_a - ba.point_b).norm(), 0.0, 1e-9 * scale) << describePair(built.a, built.b);
    EXPECT_NEAR((ab.point_b - ba.point_a).norm(), 0.0, 1e-9 * scale) << describePair(built.a, built.b);
  }
}

}  // namespace
}  // namespace test
}  // namespace ellipse_collision::core

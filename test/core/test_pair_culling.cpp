// The circle tests of overlap() on columns of pairs (src/core/pair_culling.h): each kernel gives,
// pair by pair, what overlap()'s bounding-circle rejection and inscribed-circle acceptance give
// (the rule written out here from overlap.h), the survivors in increasing order, nothing written
// outside the range, and pairs clear of the margins classified as the circles in long double say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "overlap_detail.h"
#include "pair_culling.h"
#include "random_source.h"

namespace ellipse_collision::core::detail {
namespace {

struct Columns {
  std::vector<double> x, y, bounding, inscribed;
  CullColumns view() const { return {x.data(), y.data(), bounding.data(), inscribed.data()}; }
  void add(double cx, double cy, double rb, double ri) {
    x.push_back(cx);
    y.push_back(cy);
    bounding.push_back(rb);
    inscribed.push_back(ri);
  }
};

Columns randomColumns(test::RandomSource& random, std::size_t count, double spread) {
  Columns c;
  for (std::size_t k = 0; k < count; ++k) {
    const double r1 = random.uniform(0.01, 1.0), r2 = random.uniform(0.01, 1.0);
    c.add(random.uniform(-spread, spread), random.uniform(-spread, spread), std::max(r1, r2),
          std::min(r1, r2));
  }
  return c;
}

/// overlap()'s circle stages on pair k: 0 apart, 1 inscribed circles meet, 2 left open.
int expectedClass(const Columns& a, std::size_t ia, const Columns& b, std::size_t ib) {
  const Eigen::Vector2d ca(a.x[ia], a.y[ia]), cb(b.x[ib], b.y[ib]);
  if (circlesApart(ca, cb, a.bounding[ia] + b.bounding[ib])) return 0;
  const double inscribed_sum = a.inscribed[ia] + b.inscribed[ib];
  if ((cb - ca).squaredNorm() < inscribed_sum * inscribed_sum * (1.0 - kCircleMargin)) return 1;
  return 2;
}

std::vector<bool> kernels() {
  std::vector<bool> avx2{false};
  if (useAvx2(BatchKernel::Automatic)) avx2.push_back(true);
  return avx2;
}

TEST(PairCulling, EachKernelClassifiesEveryPairAsOverlapsCircleTests) {
  test::RandomSource random(11);
  for (const bool avx2 : kernels()) {
    int classes[3] = {0, 0, 0};
    for (int round = 0; round < 50; ++round) {
      const std::size_t n = 1 + random.index(static_cast<int>(kCullBlock));
      const Columns a = randomColumns(random, n, 3.0), b = randomColumns(random, n, 3.0);
      std::vector<std::uint8_t> out(n, 7);
      std::vector<std::size_t> survivors(n + kCullSurvivorSlack);
      const std::size_t kept =
          cullPairs(avx2, a.view(), b.view(), 0, n, out.data(), survivors.data());
      std::vector<std::size_t> expected_survivors;
      for (std::size_t k = 0; k < n; ++k) {
        const int c = expectedClass(a, k, b, k);
        ++classes[c];
        EXPECT_EQ(out[k], c == 1 ? 1 : 0) << "pair " << k << (avx2 ? " avx2" : "");
        if (c == 2) expected_survivors.push_back(k);
      }
      ASSERT_EQ(kept, expected_survivors.size());
      for (std::size_t i = 0; i < kept; ++i) EXPECT_EQ(survivors[i], expected_survivors[i]);
    }
    EXPECT_GT(classes[0], 500);
    EXPECT_GT(classes[1], 200);
    EXPECT_GT(classes[2], 500);
  }
}

TEST(PairCulling, ARangeIsCulledAloneAndOneAgainstManyIsAReplicatedColumn) {
  test::RandomSource random(12);
  const std::size_t n = 200, begin = 37, end = 151;
  const Columns b = randomColumns(random, n, 2.0);
  Columns one;
  one.add(0.1, -0.2, 0.9, 0.3);
  Columns replicated;
  for (std::size_t k = 0; k < n; ++k) replicated.add(0.1, -0.2, 0.9, 0.3);
  for (const bool avx2 : kernels()) {
    std::vector<std::uint8_t> out_one(n, 7), out_pairs(n, 7);
    std::vector<std::size_t> s_one(n + kCullSurvivorSlack), s_pairs(n + kCullSurvivorSlack);
    const std::size_t kept_one =
        cullOneAgainstMany(avx2, one.view(), b.view(), begin, end, out_one.data(), s_one.data());
    const std::size_t kept_pairs =
        cullPairs(avx2, replicated.view(), b.view(), begin, end, out_pairs.data(), s_pairs.data());
    ASSERT_EQ(kept_one, kept_pairs);
    for (std::size_t i = 0; i < kept_one; ++i) {
      EXPECT_EQ(s_one[i], s_pairs[i]);
      EXPECT_GE(s_one[i], begin);
      EXPECT_LT(s_one[i], end);
      if (i > 0) {
        EXPECT_GT(s_one[i], s_one[i - 1]);
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (k < begin || k >= end) {
        EXPECT_EQ(out_one[k], 7) << "written outside the range at " << k;
        EXPECT_EQ(out_pairs[k], 7) << "written outside the range at " << k;
      } else {
        EXPECT_EQ(out_one[k], out_pairs[k]) << k;
        EXPECT_EQ(out_one[k], expectedClass(one, 0, b, k) == 1 ? 1 : 0) << k;
      }
    }
  }
}

TEST(PairCulling, ClearCasesAgreeWithTheCirclesInLongDouble) {
  // Pairs 1e-6 of the radius sum away from either circle test's boundary, on both sides.
  Columns a, b;
  std::vector<int> truth;  // 0 apart, 1 inscribed circles meet, 2 between
  for (const double d : {1.7 * (1 + 1e-6), 1.7 * (1 - 1e-6), 0.5 * (1 + 1e-6), 0.5 * (1 - 1e-6)}) {
    a.add(1e6, -1e6, 1.0, 0.2);
    b.add(1e6 + d * 0.6, -1e6 + d * 0.8, 0.7, 0.3);
    const long double dx = (long double)b.x.back() - a.x.back();
    const long double dy = (long double)b.y.back() - a.y.back();
    const long double dist = std::sqrt(dx * dx + dy * dy);
    truth.push_back(dist > 1.7L ? 0 : dist < 0.5L ? 1 : 2);
  }
  for (const bool avx2 : kernels()) {
    std::vector<std::uint8_t> out(4, 7);
    std::vector<std::size_t> survivors(4 + kCullSurvivorSlack);
    const std::size_t kept =
        cullPairs(avx2, a.view(), b.view(), 0, 4, out.data(), survivors.data());
    EXPECT_EQ(kept, 2u);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(out[k], truth[k] == 1 ? 1 : 0) << k;
    EXPECT_EQ(survivors[0], 1u);
    EXPECT_EQ(survivors[1], 2u);
  }
}

}  // namespace
}  // namespace ellipse_collision::core::detail

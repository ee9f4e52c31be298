// The batch pair tests must answer every pair as overlap() does, with either culling kernel (the
// portable one and, where the processor has it, AVX2): on a scene-like mix, a near mix, pairs at
// the very edges of the two circle tests, near-tangent, contained, concentric and needle-thin
// pairs, in batches of every length around the kernels' steps. overlap() itself is checked
// against the quad-precision oracle in test_overlap_accuracy; here a sample is checked against
// the oracle too, so that a batch agreeing with a broken overlap() would still fail.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "contact_scale_oracle.h"
#include "ellipse_builders.h"
#include "ellipse_collision/core/batch_overlap.h"
#include "ellipse_collision/core/overlap.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;
using detail::BatchKernel;

struct Pair {
  Ellipse a;
  Ellipse b;
};

class Random : public ellipse_collision::test::RandomSource {
 public:
  using RandomSource::RandomSource;

  Ellipse ellipse(double half_width, double min_major, double max_major, double max_ratio) {
    return ellipse_collision::test::randomEllipse(*this, half_width, min_major, max_major,
                                                  max_ratio);
  }

  /// `b`'s centre at `scale` times the sum of the bounding radii from `a`'s, in a random
  /// direction.
  Pair atBoundingScale(const Ellipse& a, Ellipse b, double scale) {
    const double phi = uniform(-kPi, kPi);
    const double reach = boundingRadius(a) + boundingRadius(b);
    b.center = a.center + scale * reach * Eigen::Vector2d(std::cos(phi), std::sin(phi));
    return {a, b};
  }
};

/// 50 links against obstacles in a 10 m room, as a scene check pairs them: most far apart.
std::vector<Pair> sceneLikePairs(int count, std::uint64_t seed) {
  Random random(seed);
  std::vector<Pair> pairs;
  std::vector<Ellipse> links;
  for (int i = 0; i < 50; ++i) links.push_back(random.ellipse(5.0, 0.05, 0.5, 5.0));
  for (int k = 0; k < count; ++k) {
    pairs.push_back({links[k % links.size()], random.ellipse(5.0, 0.05, 0.5, 5.0)});
  }
  return pairs;
}

/// Centres within 1.5 times the sum of the bounding radii: about half the pairs pass the
/// bounding circles.
std::vector<Pair> nearPairs(int count, std::uint64_t seed) {
  Random random(seed);
  std::vector<Pair> pairs;
  for (int k = 0; k < count; ++k) {
    const Ellipse a = random.ellipse(5.0, 0.05, 2.0, 20.0);
    const Ellipse b = random.ellipse(5.0, 0.05, 2.0, 20.0);
    pairs.push_back(random.atBoundingScale(a, b, 1.5 * std::sqrt(random.uniform(0.0, 1.0))));
  }
  return pairs;
}

/// Pairs where the circle tests and the exact stages are hardest to agree on: centre distances a
/// few ulps either side of the bounding circles' and inscribed circles' thresholds (with and
/// without their margin), near-tangent pairs, one inside the other, concentric, needles of axis
/// ratio up to 1e6, circles touching, and tiny and huge ellipses.
std::vector<Pair> edgePairs(int count, std::uint64_t seed) {
  Random random(seed);
  std::vector<Pair> pairs;
  for (int k = 0; k < count; ++k) {
    const Ellipse a = random.ellipse(100.0, 1e-3, 10.0, random.coin() ? 3.0 : 1e6);
    Ellipse b = random.ellipse(100.0, 1e-3, 10.0, random.coin() ? 3.0 : 1e6);
    switch (k % 8) {
      case 0:  // the bounding circles' threshold, a few ulps either side
        pairs.push_back(random.atBoundingScale(
            a, b, std::sqrt(1.0 + detail::kCircleMargin) * (1.0 + random.integer(-8, 8) * 1e-16)));
        break;
      case 1:  // touching bounding circles, without the margin
        pairs.push_back(random.atBoundingScale(a, b, 1.0 + random.integer(-8, 8) * 1e-16));
        break;
      case 2: {  // the inscribed circles' threshold
        const double inner = inscribedRadius(a) + inscribedRadius(b);
        const double reach = boundingRadius(a) + boundingRadius(b);
        const double scale = std::sqrt(1.0 - detail::kCircleMargin) * inner / reach;
        pairs.push_back(
            random.atBoundingScale(a, b, scale * (1.0 + random.integer(-8, 8) * 1e-16)));
        break;
      }
      case 3: {  // near-tangent
        const double delta = random.logUniform(1e-12, 1e-3);
        b.center = a.center + Eigen::Vector2d(1.0, 0.5);
        pairs.push_back(
            {a, test::placeAtContactScale(a, b, random.coin() ? 1.0 - delta : 1.0 + delta)});
        break;
      }
      case 4:  // b small and inside a (or a small inside b, when the roles swap below)
        b.center = a.center;
        b.radius_x = std::max(kMinRadius, inscribedRadius(a) * random.uniform(0.01, 0.5));
        b.radius_y = std::max(kMinRadius, inscribedRadius(a) * random.uniform(0.01, 0.5));
        pairs.push_back(random.coin() ? Pair{a, b} : Pair{b, a});
        break;
      case 5:  // concentric
        b.center = a.center;
        pairs.push_back({a, b});
        break;
      case 6: {  // circles touching within a few ulps: there the circle tests are exact answers,
                 // and only their margins keep them from deciding a pair wrongly
        Ellipse circle_a = a, circle_b = b;
        circle_a.radius_y = circle_a.radius_x;
        circle_b.radius_y = circle_b.radius_x;
        pairs.push_back(
            random.atBoundingScale(circle_a, circle_b, 1.0 + random.integer(-8, 8) * 1e-16));
        break;
      }
      default:  // tiny against huge, anywhere near
        b.radius_x = random.logUniform(kMinRadius, 1e-6);
        b.radius_y = random.logUniform(kMinRadius, 1e-6);
        pairs.push_back(random.atBoundingScale(a, b, random.uniform(0.0, 1.2)));
        break;
    }
  }
  return pairs;
}

struct Batches {
  EllipseBatch a;
  EllipseBatch b;
};

Batches batchesOf(const std::vector<Pair>& pairs) {
  Batches batches;
  for (const Pair& pair : pairs) {
    // An ellipse refused would shift every later pair: the generators make valid ones only.
    EXPECT_EQ(batches.a.add(pair.a), "");
    EXPECT_EQ(batches.b.add(pair.b), "");
  }
  return batches;
}

std::vector<BatchKernel> kernels() {
  std::vector<BatchKernel> all{BatchKernel::Automatic, BatchKernel::Portable};
  if (detail::avx2Supported()) all.push_back(BatchKernel::Avx2);
  return all;
}

const char* nameOf(BatchKernel kernel) {
  switch (kernel) {
    case BatchKernel::Automatic:
      return "automatic";
    case BatchKernel::Portable:
      return "portable";
    case BatchKernel::Avx2:
      return "avx2";
  }
  return "?";
}

/// Every kernel, pairs i-i, against overlap() on each pair; returns how many overlap.
int expectBatchMatchesSingle(const std::vector<Pair>& pairs, const std::string& family) {
  const Batches batches = batchesOf(pairs);
  int overlapping = 0;
  for (const BatchKernel kernel : kernels()) {
    // Pre-filled with a value no answer has, so that a pair left unwritten fails.
    std::vector<std::uint8_t> out(pairs.size(), 7);
    detail::overlapBatchWith(kernel, batches.a, batches.b, out.data());
    int wrong = 0;
    overlapping = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const std::uint8_t single = overlap(pairs[k].a, pairs[k].b) ? 1 : 0;
      overlapping += single;
      if (out[k] != single && ++wrong <= 5) {
        ADD_FAILURE() << family << ", " << nameOf(kernel) << " kernel, pair " << k << ": batch "
                      << int(out[k]) << ", overlap() " << int(single) << ": "
                      << test::describePair(pairs[k].a, pairs[k].b);
      }
    }
    EXPECT_EQ(wrong, 0) << family << ", " << nameOf(kernel) << " kernel";
  }
  return overlapping;
}

TEST(OverlapBatch, SceneLikeMixAnswersAsOverlap) {
  const int overlapping = expectBatchMatchesSingle(sceneLikePairs(20000, 1), "scene-like");
  // Both answers occur, so agreement is not agreement on a constant.
  EXPECT_GT(overlapping, 20);
  EXPECT_LT(overlapping, 2000);
}

TEST(OverlapBatch, NearMixAnswersAsOverlap) {
  const int overlapping = expectBatchMatchesSingle(nearPairs(20000, 2), "near");
  EXPECT_GT(overlapping, 2000);
  EXPECT_LT(overlapping, 18000);
}

TEST(OverlapBatch, CircleThresholdsAndDegeneratePairsAnswerAsOverlap) {
  const int overlapping = expectBatchMatchesSingle(edgePairs(8000, 3), "edge");
  EXPECT_GT(overlapping, 500);
  EXPECT_LT(overlapping, 6500);
}

TEST(OverlapBatch, EveryLengthAroundTheKernelStepsAndBlocks) {
  // Lengths that leave 0-3 pairs for the scalar tail and cross the 256-pair blocks.
  const std::vector<Pair> pool = nearPairs(1100, 4);
  for (const std::size_t length : {0u, 1u, 2u, 3u, 4u, 5u, 7u, 8u, 255u, 256u, 257u, 259u, 1029u}) {
    const std::vector<Pair> pairs(pool.begin(), pool.begin() + length);
    expectBatchMatchesSingle(pairs, "length " + std::to_string(length));
  }
}

TEST(OverlapBatch, OneToManyAnswersAsOverlap) {
  Random random(5);
  EllipseBatch many;
  std::vector<Ellipse> obstacles;
  for (int k = 0; k < 3001; ++k) {
    obstacles.push_back(random.ellipse(3.0, 0.02, 1.0, 30.0));
    ASSERT_EQ(many.add(obstacles.back()), "");
  }
  for (int i = 0; i < 40; ++i) {
    const Ellipse link = random.ellipse(3.0, 0.05, 1.0, 10.0);
    const PreparedEllipse prepared(link);
    std::vector<std::uint8_t> expected(obstacles.size());
    for (std::size_t j = 0; j < obstacles.size(); ++j) expected[j] = overlap(link, obstacles[j]);
    for (const BatchKernel kernel : kernels()) {
      std::vector<std::uint8_t> out(obstacles.size(), 7);
      detail::overlapOneToManyWith(kernel, prepared, many, out.data());
      EXPECT_EQ(out, expected) << "link " << i << ", " << nameOf(kernel) << " kernel";
    }
    std::vector<std::uint8_t> out(obstacles.size(), 7);
    EXPECT_EQ(overlapOneToMany(link, many, out.data()), "");
    EXPECT_EQ(out, expected) << "link " << i << ", overlapOneToMany()";
  }
}

TEST(OverlapBatch, AgreesWithTheQuadOracleOnASample) {
  // Independent of overlap(): a sample of the near and edge families, decided by the oracle where
  // it is clear of tangency (|t* - 1| > 1e-9, where overlap() is certified).
  std::vector<Pair> pairs = nearPairs(300, 6);
  const std::vector<Pair> edges = edgePairs(300, 7);
  pairs.insert(pairs.end(), edges.begin(), edges.end());
  const Batches batches = batchesOf(pairs);
  std::vector<std::uint8_t> out(pairs.size(), 7);
  ASSERT_EQ(overlapBatch(batches.a, batches.b, out.data()), "");
  int judged = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const test::OracleContactScale oracle = test::oracleContactScale(pairs[k].a, pairs[k].b);
    const double t = static_cast<double>(oracle.value);
    if (std::fabs(t - 1.0) <= 1e-9) continue;
    ++judged;
    EXPECT_EQ(out[k] == 1, t <= 1.0)
        << "pair " << k << ", t* = " << t << ": " << test::describePair(pairs[k].a, pairs[k].b);
  }
  EXPECT_GT(judged, 500);
}

TEST(OverlapBatch, RefusesUnequalSizesAndInvalidEllipsesNamingThem) {
  EllipseBatch a, b;
  ASSERT_EQ(a.add(Ellipse{}), "");
  std::vector<std::uint8_t> out(2, 7);
  EXPECT_EQ(overlapBatch(a, b, out.data()), "batch sizes differ: a has 1 ellipses, b has 0");
  EXPECT_EQ(out[0], 7) << "nothing is written on refusal";

  Ellipse bad;
  bad.radius_x = -1.0;
  EXPECT_EQ(b.add(bad), invalidReason(bad));
  EXPECT_EQ(b.add(bad).rfind("radius_x", 0), 0u);
  EXPECT_EQ(b.size(), 0u) << "an invalid ellipse is not added";
  EXPECT_EQ(overlapOneToMany(bad, a, out.data()), invalidReason(bad));
  EXPECT_EQ(out[0], 7);
}

}  // namespace
}  // namespace ellipse_collision::core

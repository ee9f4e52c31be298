// The broadphase must return exactly the pairs brute force finds, in (first, second) order, and
// its boxes must never separate two ellipses that overlap.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "contact_scale_oracle.h"
#include "ellipse_collision/core/broadphase.h"
#include "random_source.h"

namespace ellipse_collision::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

class Random : public ellipse_collision::test::RandomSource {
 public:
  using RandomSource::RandomSource;

  /// Square-ish boxes of half-size in [min_half, max_half] [m], centres in a square of side
  /// `world` [m].
  std::vector<BoundingBox> boxes(int count, double world, double min_half, double max_half) {
    std::vector<BoundingBox> result;
    for (int i = 0; i < count; ++i) {
      const double x = uniform(-0.5 * world, 0.5 * world), y = uniform(-0.5 * world, 0.5 * world);
      const double hx = logUniform(min_half, max_half), hy = logUniform(min_half, max_half);
      result.push_back({x - hx, y - hy, x + hx, y + hy});
    }
    return result;
  }

  Ellipse ellipse(double world, double min_major, double max_major, double max_ratio) {
    Ellipse e;
    e.center = {uniform(-0.5 * world, 0.5 * world), uniform(-0.5 * world, 0.5 * world)};
    const double major = logUniform(min_major, max_major);
    e.radius_x = major;
    e.radius_y = major / logUniform(1.0, max_ratio);
    e.angle = uniform(-kPi, kPi);
    return e;
  }

};

std::vector<IndexPair> bruteForce(const std::vector<BoundingBox>& a,
                                  const std::vector<BoundingBox>& b) {
  std::vector<IndexPair> pairs;
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (boxesOverlap(a[i], b[j])) pairs.push_back({i, j});
    }
  }
  return pairs;
}

std::vector<IndexPair> bruteForce(const std::vector<BoundingBox>& boxes) {
  std::vector<IndexPair> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      if (boxesOverlap(boxes[i], boxes[j])) pairs.push_back({i, j});
    }
  }
  return pairs;
}

/// Compares with brute force element by element, so that the order is checked too.
void expectSamePairs(const std::vector<IndexPair>& expected, const std::vector<IndexPair>& got,
                     const std::string& scene) {
  ASSERT_EQ(expected.size(), got.size()) << scene;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    ASSERT_TRUE(expected[k] == got[k])
        << scene << ": pair " << k << " is (" << got[k].first << ", " << got[k].second
        << "), brute force has (" << expected[k].first << ", " << expected[k].second << ")";
  }
}

struct SceneShape {
  int count_a;
  int count_b;
  double world;     ///< [m]
  double min_half;  ///< [m]
  double max_half;  ///< [m]
};

// Sizes from empty to thousands, sparse to fully crowded, equal and very unequal box sizes.
const SceneShape kScenes[] = {
    {0, 0, 10, 0.1, 1},        {0, 7, 10, 0.1, 1},         {7, 0, 10, 0.1, 1},
    {1, 1, 10, 1, 5},          {1, 500, 10, 0.1, 1},       {500, 1, 10, 0.1, 1},
    {50, 1000, 50, 0.05, 0.5}, {1000, 50, 50, 0.05, 0.5},  {50, 3000, 10, 0.05, 0.5},
    {300, 300, 5, 0.1, 2},     {300, 300, 100, 0.01, 0.1}, {200, 700, 20, 0.001, 10},
    {100, 100, 1, 1, 3},       {2000, 2000, 1000, 0.1, 1}};

TEST(Broadphase, TwoSetsGiveExactlyTheBruteForcePairsInOrder) {
  Random random(1);
  int total_pairs = 0;
  for (const SceneShape& s : kScenes) {
    const auto a = random.boxes(s.count_a, s.world, s.min_half, s.max_half);
    const auto b = random.boxes(s.count_b, s.world, s.min_half, s.max_half);
    const auto expected = bruteForce(a, b);
    total_pairs += static_cast<int>(expected.size());
    const std::string scene = std::to_string(s.count_a) + " x " + std::to_string(s.count_b) +
                              " boxes in " + std::to_string(s.world) + " m";
    expectSamePairs(expected, overlappingBoxPairs(a, b), scene);
  }
  EXPECT_GT(total_pairs, 10000);  // the scenes must contain pairs to mean anything
}

TEST(Broadphase, OneSetGivesExactlyTheBruteForcePairsInOrder) {
  Random random(2);
  int total_pairs = 0;
  for (const SceneShape& s : kScenes) {
    const auto boxes = random.boxes(s.count_a + s.count_b, s.world, s.min_half, s.max_half);
    const auto expected = bruteForce(boxes);
    total_pairs += static_cast<int>(expected.size());
    const std::string scene =
        std::to_string(boxes.size()) + " boxes in " + std::to_string(s.world) + " m";
    expectSamePairs(expected, overlappingBoxPairs(boxes), scene);
    expectSamePairs(expected, BoxGrid(boxes).overlappingPairs(), scene + ", BoxGrid");
  }
  EXPECT_GT(total_pairs, 10000);
}

TEST(Broadphase, BoxGridFindsExactlyTheOverlappingBoxesInIncreasingOrder) {
  Random random(8);
  for (const SceneShape& s : kScenes) {
    const auto gridded = random.boxes(s.count_a, s.world, s.min_half, s.max_half);
    const auto queries = random.boxes(s.count_b, s.world, s.min_half, s.max_half);
    const BoxGrid grid(gridded);
    std::vector<std::size_t> found = {12345};  // must be replaced, not appended to
    for (const BoundingBox& query : queries) {
      std::vector<std::size_t> expected;
      for (std::size_t i = 0; i < gridded.size(); ++i) {
        if (boxesOverlap(gridded[i], query)) expected.push_back(i);
      }
      grid.overlapping(query, &found);
      ASSERT_EQ(found, expected) << s.count_a << " gridded boxes in " << s.world << " m";
    }
  }
}

TEST(Broadphase, BoxesAllAtOnePointPairEveryone) {
  const std::vector<BoundingBox> points(40, BoundingBox{2.5, -1.0, 2.5, -1.0});
  const std::vector<BoundingBox> others(30, BoundingBox{2.5, -1.0, 2.5, -1.0});
  EXPECT_EQ(overlappingBoxPairs(points).size(), 40u * 39u / 2u);
  expectSamePairs(bruteForce(points, others), overlappingBoxPairs(points, others), "points");
  EXPECT_EQ(overlappingBoxPairs(points, others).size(), 40u * 30u);
}

TEST(Broadphase, HugeBoxCoveringAllPairsWithEveryone) {
  Random random(3);
  for (const bool huge_in_small_set : {true, false}) {
    auto small = random.boxes(20, 10, 0.1, 0.5);
    auto large = random.boxes(2000, 10, 0.1, 0.5);
    auto& holder = huge_in_small_set ? small : large;
    holder[holder.size() / 2] = {-1e6, -1e6, 1e6, 1e6};
    expectSamePairs(bruteForce(small, large), overlappingBoxPairs(small, large), "huge in a");
    expectSamePairs(bruteForce(large, small), overlappingBoxPairs(large, small), "huge in b");
    expectSamePairs(bruteForce(holder), overlappingBoxPairs(holder), "huge in one set");
  }
}

TEST(Broadphase, OneDistantOutlierDoesNotLoseAnyPair) {
  Random random(4);
  auto a = random.boxes(300, 2, 0.01, 0.05);
  auto b = random.boxes(300, 2, 0.01, 0.05);
  a.push_back({1e8, 1e8, 1e8 + 1, 1e8 + 1});  // stretches the grid's extent enormously
  b.push_back({1e8 + 0.5, 1e8 + 0.5, 1e8 + 2, 1e8 + 2});
  expectSamePairs(bruteForce(a, b), overlappingBoxPairs(a, b), "outlier");
  expectSamePairs(bruteForce(a), overlappingBoxPairs(a), "outlier, one set");
}

TEST(Broadphase, TinyBoxesAlongALongLineKeepTheGridSmall) {
  // Median size 1e-9 m over 10 m in x, no extent in y: cells of the median size would number
  // 1e10, and spreading the cap evenly over both sides would leave 4e6 columns of one row.
  Random random(9);
  std::vector<BoundingBox> a, b;
  for (int i = 0; i < 400; ++i) {
    const double x = random.uniform(0.0, 10.0);
    a.push_back({x, 0.0, x + 1e-9, 0.0});
    b.push_back({x + 5e-10, 0.0, x + 2e-9, 0.0});
  }
  a.push_back({-1.0, 0.0, 10.0, 0.0});
  EXPECT_LE(BoxGrid(a).cellCount(), 4 * a.size());
  expectSamePairs(bruteForce(a, b), overlappingBoxPairs(a, b), "line");
  expectSamePairs(bruteForce(a), overlappingBoxPairs(a), "line, one set");
}

TEST(Broadphase, BoxesThatOnlyTouchArePaired) {
  // Closed boxes: a shared edge or corner is an overlap, as for the closed ellipses.
  const std::vector<BoundingBox> a = {{0, 0, 1, 1}};
  const std::vector<BoundingBox> b = {
      {1, 0, 2, 1}, {1, 1, 2, 2}, {0, 1, 1, 2}, {1.000001, 0, 2, 1}};
  const auto pairs = overlappingBoxPairs(a, b);
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[0].second, 0u);
  EXPECT_EQ(pairs[1].second, 1u);
  EXPECT_EQ(pairs[2].second, 2u);
}

TEST(Broadphase, BoxWithNaNPairsWithNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<BoundingBox> a = {{0, 0, 1, 1}, {nan, 0, 1, 1}, {0, 0, nan, nan}};
  const std::vector<BoundingBox> b = {{0.5, 0.5, 2, 2}, {nan, nan, nan, nan}};
  expectSamePairs(bruteForce(a, b), overlappingBoxPairs(a, b), "NaN");
  EXPECT_EQ(overlappingBoxPairs(a, b).size(), 1u);
  EXPECT_EQ(overlappingBoxPairs(a).size(), 0u);
}

TEST(Broadphase, EmptySetsGiveNoPairs) {
  const std::vector<BoundingBox> none;
  const std::vector<BoundingBox> some = {{0, 0, 1, 1}, {0, 0, 1, 1}};
  EXPECT_TRUE(overlappingBoxPairs(none, some).empty());
  EXPECT_TRUE(overlappingBoxPairs(some, none).empty());
  EXPECT_TRUE(overlappingBoxPairs(none).empty());
  EXPECT_TRUE(overlappingBoxPairs(std::vector<BoundingBox>{{0, 0, 1, 1}}).empty());
}

TEST(Broadphase, RobotAmong10000ObstaclesNeedsFarFewerThanAllPairTests) {
  Random random(5);
  std::vector<BoundingBox> links, obstacles;
  for (int i = 0; i < 50; ++i) links.push_back(boundingBox(random.ellipse(2.0, 0.05, 0.4, 8.0)));
  for (int i = 0; i < 10000; ++i) {
    obstacles.push_back(boundingCircleBox(random.ellipse(50.0, 0.05, 0.5, 5.0)));
  }
  const auto pairs = overlappingBoxPairs(links, obstacles);
  expectSamePairs(bruteForce(links, obstacles), pairs, "robot");
  EXPECT_GT(pairs.size(), 0u);
  EXPECT_LT(pairs.size(), 5000u) << "of 500,000 link-obstacle pairs";
}

/// The extremes of the ellipse's rim along x and y, sampled densely [m].
BoundingBox sampledRimBox(const Ellipse& e) {
  BoundingBox box{e.center.x(), e.center.y(), e.center.x(), e.center.y()};
  const double c = std::cos(e.angle), s = std::sin(e.angle);
  for (int k = 0; k < 20000; ++k) {
    const double t = 2.0 * kPi * k / 20000;
    const double u = e.radius_x * std::cos(t), v = e.radius_y * std::sin(t);
    const double x = e.center.x() + c * u - s * v, y = e.center.y() + s * u + c * v;
    box = {std::min(box.min_x, x), std::min(box.min_y, y), std::max(box.max_x, x),
           std::max(box.max_y, y)};
  }
  return box;
}

TEST(Broadphase, BoundingBoxIsTightAroundTheEllipse) {
  Random random(6);
  for (int i = 0; i < 200; ++i) {
    const Ellipse e = random.ellipse(20.0, 0.01, 5.0, 50.0);
    const BoundingBox box = boundingBox(e);
    const BoundingBox rim = sampledRimBox(e);
    // Contains every sampled rim point, and is no larger than the sampling error (~ r (2 pi /
    // 20000)^2 / 2) plus the 1e-12 widening.
    const double slack = 1e-6 * boundingRadius(e);
    EXPECT_LE(box.min_x, rim.min_x);
    EXPECT_LE(box.min_y, rim.min_y);
    EXPECT_GE(box.max_x, rim.max_x);
    EXPECT_GE(box.max_y, rim.max_y);
    EXPECT_GT(box.min_x, rim.min_x - slack);
    EXPECT_GT(box.min_y, rim.min_y - slack);
    EXPECT_LT(box.max_x, rim.max_x + slack);
    EXPECT_LT(box.max_y, rim.max_y + slack);

    const BoundingBox circle = boundingCircleBox(e);
    EXPECT_LE(circle.min_x, box.min_x);
    EXPECT_LE(circle.min_y, box.min_y);
    EXPECT_GE(circle.max_x, box.max_x);
    EXPECT_GE(circle.max_y, box.max_y);
  }
}

TEST(Broadphase, OverlappingEllipsesAlwaysHaveOverlappingBoxes) {
  // Pairs placed with the oracle just inside tangency, in all directions, some far from the
  // origin: the widening must absorb the rounding of every box bound.
  Random random(7);
  int overlapping = 0;
  for (int i = 0; i < 3000; ++i) {
    const double world = i % 3 == 0 ? 2e6 : 20.0;
    const Ellipse a = random.ellipse(world, 0.01, 3.0, 20.0);
    Ellipse b = random.ellipse(0.0, 0.01, 3.0, 20.0);
    const double phi = random.uniform(-kPi, kPi);
    b.center = a.center + Eigen::Vector2d(std::cos(phi), std::sin(phi));
    b = test::placeAtContactScale(a, b, 1.0 - random.logUniform(1e-12, 1e-6));
    if (!test::oracleOverlap(a, b)) continue;
    ++overlapping;
    EXPECT_TRUE(boxesOverlap(boundingBox(a), boundingBox(b))) << test::describePair(a, b);
    EXPECT_TRUE(boxesOverlap(boundingCircleBox(a), boundingCircleBox(b)))
        << test::describePair(a, b);
  }
  EXPECT_GT(overlapping, 2500);
}

}  // namespace
}  // namespace ellipse_collision::core

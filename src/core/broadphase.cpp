#include "ellipse_collision/core/broadphase.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "broadphase_detail.h"
#include "sin_cos.h"

namespace ellipse_collision::core {
namespace {

// At most this many cells per element of the gridded set: bounds the memory and the cells a huge
// query box has to visit.
constexpr std::size_t kCellsPerBox = 4;

// A gridded box spanning more cells than this is kept in a short list checked against every
// query instead: a huge box would otherwise fill the whole grid.
constexpr long kMaxCellsSpanned = 16;

// Up to this many boxes a linear scan (branch-free box tests, already in index order) beats the
// grid's cell walk and sort, and building no grid saves more: measured on 50 clustered links.
constexpr std::size_t kLinearScanMaxBoxes = 64;


/// min <= max on both axes; false for NaN bounds: such a box overlaps nothing and is left out.
bool isOrdered(const BoundingBox& box) { return box.min_x <= box.max_x && box.min_y <= box.max_y; }

/// Median of `values` (reordered), or 0 for none.
double median(std::vector<double>* values) {
  if (values->empty()) return 0.0;
  const auto middle = values->begin() + static_cast<std::ptrdiff_t>(values->size() / 2);
  std::nth_element(values->begin(), middle, values->end());
  return *middle;
}

/// Cell coordinate of `offset` from the grid's low edge, clamped to the grid; monotonic, which
/// the reporting rule in BoxGrid::collect() needs, and NaN and infinities land on a valid cell.
long cellOf(double offset, double inverse_cell, long cells) {
  const double t = offset * inverse_cell;
  if (!(t > 0.0)) return 0;
  if (!(t < static_cast<double>(cells))) return cells - 1;
  return static_cast<long>(t);
}

}  // namespace

namespace detail {

BoundingBox boundingBoxFromTrig(const Ellipse& ellipse, double cos_angle, double sin_angle) {
  // Half-extents of the rotated ellipse: the support function along x and y.
  const double rx_cos = ellipse.radius_x * cos_angle, rx_sin = ellipse.radius_x * sin_angle;
  const double ry_cos = ellipse.radius_y * cos_angle, ry_sin = ellipse.radius_y * sin_angle;
  return detail::boxAround(ellipse.center, std::sqrt(rx_cos * rx_cos + ry_sin * ry_sin),
                   std::sqrt(rx_sin * rx_sin + ry_cos * ry_cos));
}

}  // namespace detail

BoundingBox boundingBox(const Ellipse& ellipse) {
  const detail::SinCos trig = detail::sinCos(ellipse.angle);
  return detail::boundingBoxFromTrig(ellipse, trig.cos, trig.sin);
}

BoxGrid::BoxGrid(std::vector<BoundingBox> boxes) : boxes_(std::move(boxes)) {
  std::size_t ordered = 0;
  for (const BoundingBox& box : boxes_) {
    if (!isOrdered(box)) continue;
    if (ordered++ == 0) extent_ = box;
    extent_.min_x = std::min(extent_.min_x, box.min_x);
    extent_.min_y = std::min(extent_.min_y, box.min_y);
    extent_.max_x = std::max(extent_.max_x, box.max_x);
    extent_.max_y = std::max(extent_.max_y, box.max_y);
  }
  if (ordered == 0 || boxes_.size() <= kLinearScanMaxBoxes) {
    cell_start_.assign(2, 0);  // one empty cell: collect() scans all boxes instead
    return;
  }
  // The sizes only where cells are chosen: collecting them for a robot's 50 links grew two
  // vectors 14 times per check.
  std::vector<double> widths, heights;
  widths.reserve(ordered);
  heights.reserve(ordered);
  for (const BoundingBox& box : boxes_) {
    if (!isOrdered(box)) continue;
    widths.push_back(box.max_x - box.min_x);
    heights.push_back(box.max_y - box.min_y);
  }
  chooseCells(median(&widths), median(&heights), ordered);
  fill();
}

void BoxGrid::chooseCells(double cell_width, double cell_height, std::size_t count) {
  const double width = extent_.max_x - extent_.min_x;
  const double height = extent_.max_y - extent_.min_y;
  // Cells of the median box size, merged uniformly until there are few enough.
  double columns = cell_width > 0.0 ? std::ceil(width / cell_width) : 1.0;
  double rows = cell_height > 0.0 ? std::ceil(height / cell_height) : 1.0;
  if (!std::isfinite(columns) || columns < 1.0) columns = 1.0;
  if (!std::isfinite(rows) || rows < 1.0) rows = 1.0;
  const double max_cells = static_cast<double>(kCellsPerBox * count);
  if (columns * rows > max_cells) {
    const double shrink = std::sqrt(columns * rows / max_cells);
    columns = std::max(1.0, std::floor(columns / shrink));
    rows = std::max(1.0, std::floor(rows / shrink));
    // A side already at one cell (boxes along a line) leaves the other too long: cap it.
    columns = std::min(columns, max_cells);
    rows = std::min(rows, std::floor(max_cells / columns));
  }
  columns_ = static_cast<long>(columns);
  rows_ = static_cast<long>(rows);
  inverse_cell_width_ = width > 0.0 ? columns / width : 0.0;
  inverse_cell_height_ = height > 0.0 ? rows / height : 0.0;
}

void BoxGrid::fill() {
  // Counting pass, then filling in increasing index order, so each cell's list is sorted.
  cell_start_.assign(static_cast<std::size_t>(columns_ * rows_) + 1, 0);
  const auto forEachCell = [this](const BoundingBox& box, auto&& visit) {
    for (long r = row(box.min_y); r <= row(box.max_y); ++r) {
      for (long c = column(box.min_x); c <= column(box.max_x); ++c) {
        visit(static_cast<std::size_t>(r * columns_ + c));
      }
    }
  };
  std::vector<bool> in_cells(boxes_.size(), false);
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    const BoundingBox& box = boxes_[i];
    if (!isOrdered(box)) continue;
    const long spanned =
        (column(box.max_x) - column(box.min_x) + 1) * (row(box.max_y) - row(box.min_y) + 1);
    if (spanned > kMaxCellsSpanned) {
      oversized_.push_back(i);
      continue;
    }
    in_cells[i] = true;
    forEachCell(box, [this](std::size_t cell) { ++cell_start_[cell + 1]; });
  }
  for (std::size_t cell = 1; cell < cell_start_.size(); ++cell) {
    cell_start_[cell] += cell_start_[cell - 1];
  }
  entries_.resize(cell_start_.back());
  std::vector<std::size_t> next(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    if (!in_cells[i]) continue;
    forEachCell(boxes_[i], [this, &next, i](std::size_t cell) { entries_[next[cell]++] = i; });
  }
}

void BoxGrid::collect(const BoundingBox& query, std::vector<std::size_t>* indices) const {
  if (boxes_.size() <= kLinearScanMaxBoxes) {
    for (std::size_t index = 0; index < boxes_.size(); ++index) {
      if (boxesOverlap(boxes_[index], query)) indices->push_back(index);
    }
    return;
  }
  for (const std::size_t index : oversized_) {
    if (boxesOverlap(boxes_[index], query)) indices->push_back(index);
  }
  const long col_lo = column(query.min_x), col_hi = column(query.max_x);
  const long row_lo = row(query.min_y), row_hi = row(query.max_y);
  const bool single_cell = col_lo == col_hi && row_lo == row_hi;
  for (long r = row_lo; r <= row_hi; ++r) {
    for (long c = col_lo; c <= col_hi; ++c) {
      const std::size_t cell = static_cast<std::size_t>(r * columns_ + c);
      for (std::size_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
        const std::size_t index = entries_[k];
        const BoundingBox& box = boxes_[index];
        if (!boxesOverlap(box, query)) continue;
        // A pair sharing several cells is reported by the one holding the lower-left corner of
        // the boxes' intersection only, which lies in both boxes' cell ranges.
        if (!single_cell && (column(std::max(box.min_x, query.min_x)) != c ||
                             row(std::max(box.min_y, query.min_y)) != r)) {
          continue;
        }
        indices->push_back(index);
      }
    }
  }
  // A single cell and no oversized box: already increasing.
  if (!single_cell || !oversized_.empty()) std::sort(indices->begin(), indices->end());
}

long BoxGrid::column(double x) const {
  return cellOf(x - extent_.min_x, inverse_cell_width_, columns_);
}

long BoxGrid::row(double y) const { return cellOf(y - extent_.min_y, inverse_cell_height_, rows_); }

std::vector<IndexPair> overlappingBoxPairs(const std::vector<BoundingBox>& a,
                                           const std::vector<BoundingBox>& b) {
  std::vector<IndexPair> pairs;
  if (a.empty() || b.empty()) return pairs;
  std::vector<std::size_t> found;
  if (b.size() <= a.size()) {
    // Grid over b, a streamed in order: each query's partners come sorted.
    const BoxGrid grid(b);
    for (std::size_t i = 0; i < a.size(); ++i) {
      grid.overlapping(a[i], &found);
      for (const std::size_t j : found) pairs.push_back({i, j});
    }
    return pairs;
  }
  // Grid over a, b streamed in order: the pairs come sorted by second, and a stable counting sort
  // by first then gives (first, second) order.
  const BoxGrid grid(a);
  std::vector<IndexPair> by_second;
  for (std::size_t j = 0; j < b.size(); ++j) {
    grid.overlapping(b[j], &found);
    for (const std::size_t i : found) by_second.push_back({i, j});
  }
  std::vector<std::size_t> start(a.size() + 1, 0);
  for (const IndexPair& pair : by_second) ++start[pair.first + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  pairs.resize(by_second.size());
  for (const IndexPair& pair : by_second) pairs[start[pair.first]++] = pair;
  return pairs;
}

std::vector<IndexPair> BoxGrid::overlappingPairs() const {
  std::vector<IndexPair> pairs;
  // A robot's links meet their neighbours along its chains: about one pair per box, found
  // without growing the vector on the way.
  pairs.reserve(boxes_.size());
  if (boxes_.size() <= kLinearScanMaxBoxes) {
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
      for (std::size_t j = i + 1; j < boxes_.size(); ++j) {
        if (boxesOverlap(boxes_[i], boxes_[j])) pairs.push_back({i, j});
      }
    }
    return pairs;
  }
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    overlapping(boxes_[i], &found);
    // Each pair is found from both sides; the query of its first box reports it.
    for (const std::size_t j : found) {
      if (j > i) pairs.push_back({i, j});
    }
  }
  return pairs;
}

std::vector<IndexPair> overlappingBoxPairs(const std::vector<BoundingBox>& boxes) {
  if (boxes.size() < 2) return {};
  return BoxGrid(boxes).overlappingPairs();
}

}  // namespace ellipse_collision::core

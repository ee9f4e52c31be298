#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace ellipse_collision::core {

/// The plane cut into 2^k axis-aligned rectangular cells that hold about equal shares of a set of
/// points: a k-d tree of depth k (Bentley 1975), each node cutting its points at their median
/// along the wider side of their bounding box. Used to group ellipses for drawing: the ellipses of
/// a cell lie together, so a viewer that culls by bounding box (rviz) skips every cell out of view,
/// and a change in one place touches the few cells there; grouping by a hash of the name spreads
/// every group over the whole field.
///
/// A point's cell is found by descending the tree (k comparisons): below a node's cut it goes to
/// the lower cell, at or above it to the upper one. The partition was built by the same rule, so
/// every point of the set lies in the cell cellOf() gives it, and points it was not built for
/// (ellipses that moved or appeared since) get the cell of their place.
class MedianPartition {
 public:
  /// One cell, the whole plane.
  MedianPartition() = default;

  /// The largest power of two not above `cells` (at least 1, at most 2^20) cells for `points`.
  /// A cut lies halfway between the last point below the median and the median itself, so where
  /// no two points share a coordinate that is cut on, each cell holds floor or ceil of
  /// size / cells points; points on a common line can only be cut where their coordinates differ.
  /// Points with a NaN coordinate are left out of the cuts. The cuts depend only on the set of
  /// points, not on their order.
  MedianPartition(std::vector<Eigen::Vector2d> points, std::uint32_t cells);

  std::uint32_t cells() const { return cells_; }

  /// Cuts anew the `count` cells from `first` on (`count` a power of two that divides `first`:
  /// the cells under one node of the tree) for `points`, which must be the points that lie in
  /// them, as the constructor cuts the plane: the rest of the plane keeps its cells. For points
  /// that crowded into one part of it since the cut, at the cost of that part only. Returns
  /// false, changing nothing, for a range that is not such a node's.
  bool recut(std::uint32_t first, std::uint32_t count, std::vector<Eigen::Vector2d> points);

  /// The cell of `point`, in [0, cells()). Any point has one: beyond the points the partition was
  /// built for, the outer cells extend to infinity; a NaN coordinate counts as above every cut.
  std::uint32_t cellOf(const Eigen::Vector2d& point) const;

 private:
  struct Cut {
    double value{0.0};
    int axis{0};  ///< 0: x, 1: y
  };
  using Iterator = std::vector<Eigen::Vector2d>::iterator;
  /// Cuts node `node` and the nodes below it, `levels_below` levels, for the points in
  /// [begin, end) (NaN left out by the caller).
  void cutNode(std::size_t node, Iterator begin, Iterator end, int levels_below);

  std::uint32_t cells_{1};
  int levels_{0};
  std::vector<Cut> cuts_;  ///< heap order: node n's lower child is 2n + 1, its upper one 2n + 2
};

}  // namespace ellipse_collision::core

#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::core {

/// The part of one beam a sensor saw free: the points t * direction with from < t < to [m] (the
/// open segment; empty when to <= from), direction a unit vector from the sensor origin.
struct FreeSegment {
  Eigen::Vector2d direction{1.0, 0.0};
  double from{0.0};       ///< [m]
  double to{0.0};         ///< [m]
  bool no_return{false};  ///< the beam saw nothing up to its range limit (a scan's +inf)
};

/// The free segments of one sensor message, sorted by angle about the sensor origin, with the
/// exact tests an obstacle ellipse must pass: it enters no free segment and does not contain the
/// origin. Only the segments whose beams pass within the ellipse's bounding circle are looked at
/// (a binary search on angle), so a test costs O(log n + beams near the ellipse).
class FreeSpace {
 public:
  FreeSpace() = default;
  explicit FreeSpace(std::vector<FreeSegment> segments);

  /// True when `e` meets the open free part of some beam or contains the sensor origin. Exact: per
  /// beam the normalised quadratic form along the ray is a quadratic in t, minimised in closed
  /// form over (from, to); it enters when that minimum is below 1 + kFreeSpaceMargin (so a
  /// segment that grazes the rim to rounding counts as entering: the test errs on the safe side).
  /// When it enters and `where` is given, *where is the direction of the first beam it enters
  /// (zero when it contains the origin).
  bool entered(const Ellipse& e, Eigen::Vector2d* where = nullptr) const;

  /// True when the segment [a, b] [m] meets the open free part of some beam or passes within
  /// 1e-12 m of the origin. Every ellipse containing a and b contains the segment, so this is a
  /// cheap necessary test before fitting an ellipse to points from a to b. When it is crossed
  /// and `where` is given, *where is the direction of a beam crossing it (zero for the origin).
  bool crossed(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
               Eigen::Vector2d* where = nullptr) const;

  /// The distance [m] from `p` to the nearest free segment within `radius` [m] of it, or to the
  /// origin if nearer; `radius` when nothing is nearer.
  double clearance(const Eigen::Vector2d& p, double radius) const;

  /// The beams on either side of the angles swept counter-clockwise from `first` to `last` (less
  /// than half a turn): the nearest segment clockwise of `first` and the nearest counter-clockwise
  /// of `last`, each more than 1e-9 rad away (a return's own beam is not beside it); nullptr where
  /// there is none, or where it lies half a turn or more away.
  std::pair<const FreeSegment*, const FreeSegment*> beside(const Eigen::Vector2d& first,
                                                           const Eigen::Vector2d& last) const;

  const std::vector<FreeSegment>& segments() const { return segments_; }

  /// Refilling in place, keeping the storage (a sensor's next message): clear(), then
  /// appendInOrder() of each segment in the order FreeSpace(segments) would keep them, `angle`
  /// [rad] being the atan2 of its direction (ScanBeams knows both for a scan's beams). The result
  /// is the same as FreeSpace(segments), without its atan2 calls and sort. An empty segment
  /// (to <= from) is dropped as the constructor drops it.
  void clear() {
    segments_.clear();
    angles_.clear();
  }
  void appendInOrder(const FreeSegment& segment, double angle) {
    if (!(segment.to > segment.from) || !segment.direction.allFinite()) return;
    segments_.push_back(segment);
    angles_.push_back(angle);
  }

 private:
  /// Calls visit(segment) for every segment whose beam angle lies within `half_width` [rad] of
  /// `angle` [rad] (every segment when half_width >= pi); stops when visit returns true.
  template <typename Visit>
  bool anyWithin(double angle, double half_width, Visit visit) const;

  std::vector<FreeSegment> segments_;
  std::vector<double> angles_;  ///< atan2 of each direction, ascending, in [-pi, pi]
};

/// The margin of FreeSpace::entered() on the normalised quadratic form (dimensionless).
constexpr double kFreeSpaceMargin = 1e-9;

}  // namespace ellipse_collision::core

#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/core/batch_overlap.h"
#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core {

/// Whether `e`, moved by at most `sweep` [m], can come within `reach` [m] of `point`: its
/// bounding circle widened by the sweep meets the disc of radius `reach` about the point. The
/// velocity gate's cull of the obstacles no link can touch within its horizon.
inline bool mayComeWithin(const Ellipse& e, double sweep, const Eigen::Vector2d& point,
                          double reach) {
  return !((e.center - point).norm() > reach + boundingRadius(e) + sweep);
}

/// Obstacles validated and gridded once, for a caller whose obstacles stay put from one check to
/// the next while its links move (obstacles in the map, a robot driving through them): each check
/// then costs in proportion to the movers and the obstacles near them (checkMoversAgainst()),
/// not to all obstacles. The grid is a BoxGrid over the obstacles' boundingCircleBox()es, the
/// very boxes checkScene() streams, so the pairs tested and the answer are the same bit for bit.
/// Each obstacle is also prepared once here, in an EllipseBatch that keeps its culling columns
/// side by side (centre x, y, bounding and inscribed radius), so that a check culls its pairs straight
/// from the index and prepares no obstacle: 160 bytes per obstacle beyond the entries and the
/// grid (doc/core_library.md).
class IndexedObstacles {
 public:
  /// No obstacles.
  IndexedObstacles();
  /// Validates every entry (role Obstacle and a valid ellipse; the names the caller vouches for,
  /// as for checkValidatedScene()) and grids them. A refused set keeps no obstacle and says
  /// why in error(), naming the entry: "obstacles[3] ('rock'): radius_x = -1 must be > 0".
  explicit IndexedObstacles(std::vector<NamedEllipse> obstacles);

  const std::vector<NamedEllipse>& obstacles() const { return obstacles_; }
  const BoxGrid& grid() const { return grid_; }
  /// obstacles()[k]'s ellipse at k, prepared once with the index, with the culling columns the
  /// pair tests read (centre x and y, bounding and inscribed radius).
  const EllipseBatch& batch() const { return batch_; }
  /// Empty unless the obstacles were refused.
  const std::string& error() const { return error_; }

  /// Replaces `indices` with those k, increasing, whose obstacle can come within `reach` [m] of
  /// `point` (mayComeWithin() with no sweep): the very obstacles a scan of all of them keeps,
  /// found through the grid in time proportional to the obstacles near the point.
  void within(const Eigen::Vector2d& point, double reach, std::vector<std::size_t>* indices) const;

 private:
  std::vector<NamedEllipse> obstacles_;
  std::string error_;  // before grid_: the grid's initialiser fills them both
  EllipseBatch batch_;
  BoxGrid grid_;
};

/// checkValidatedScene() of the scene `movers` (queries and links) plus obstacles.obstacles(),
/// the same answer bit for bit (pair_tests included), with each mover's candidate box looked up
/// in the obstacles' grid instead of every obstacle streamed past the movers. The movers' names
/// are vouched for; their ellipses are validated (they are few). Refused for an invalid mover
/// (entries named "movers[i]"), an obstacle among the movers, obstacles that were refused or a
/// warning distance that is negative or not finite.
SceneCheckResult checkMoversAgainst(const std::vector<NamedEllipse>& movers,
                                    const IndexedObstacles& obstacles, const SceneRules& rules,
                                    const std::set<std::string>& only_names = {});

}  // namespace ellipse_collision::core

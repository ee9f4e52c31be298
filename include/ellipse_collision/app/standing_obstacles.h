#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "ellipse_collision/core/indexed_obstacles.h"

namespace ellipse_collision::app {

/// The obstacles' grid (core::IndexedObstacles), kept from one full check to the next while the
/// obstacles stand still, so that a check costs in proportion to the links and the obstacles near
/// them, not to all obstacles. Gridding costs about ten streamed checks (bench_scene_check:
/// indexed_build), so the grid is built only once the obstacles have stood still for
/// kChecksBeforeIndexing checks: obstacles that change every few checks (a scan-fed topic) keep
/// the streamed check and pay nothing for gridding.
class StandingObstacles {
 public:
  static constexpr std::size_t kChecksBeforeIndexing = 16;

  /// After one check's placement: `unchanged` says whether its obstacles are exactly the ones
  /// of the previous check (same registry, every obstacle reused bit for bit); this check's
  /// placed obstacles are the entries of `scene` from `first_obstacle` on. Returns the grid of
  /// exactly those obstacles to check the movers against, or nullptr to stream the obstacles.
  /// Shared: a check's outcome keeps the grid of its own obstacles (CheckOutcome::standing) even
  /// after a later change drops it here.
  std::shared_ptr<const core::IndexedObstacles> update(bool unchanged, const core::Scene& scene,
                                                       std::size_t first_obstacle);

  /// Checks in a row whose obstacles stood still (for tests and diagnostics).
  std::size_t standingChecks() const { return standing_checks_; }
  bool indexed() const { return index_ != nullptr; }

 private:
  std::size_t standing_checks_{0};
  std::shared_ptr<const core::IndexedObstacles> index_;
};

}  // namespace ellipse_collision::app

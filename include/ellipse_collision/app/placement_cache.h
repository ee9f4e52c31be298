#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/frame_placer.h"
#include "ellipse_collision/app/standing_obstacles.h"
#include "ellipse_collision/core/ellipse.h"

namespace ellipse_collision::app {

/// The stored ellipses' projections from earlier checks, kept by the node from one periodic check
/// to the next so that ellipses in the fixed frame or in frames that did not move are not
/// projected again. An entry is reused only while the registry is unchanged (its revision()), the
/// padding is the same and its frame's transform is bit for bit the one it was projected through
/// (and usable now: found and fresh), so the answer is exactly that of projecting again. Each
/// frame is compared once per check, not once per ellipse.
class PlacementCache {
 public:
  /// Starts one check of `registry`: forgets everything when the registry or the padding changed.
  void begin(const EllipseRegistry& registry, double global_padding_m);

  /// One stored ellipse in placing order: its index in registry.entries() order (the index
  /// reuse() and store() take) and the entry itself.
  struct OrderedEntry {
    std::size_t index;
    const std::pair<const std::string, StoredEllipse>* entry;
    core::EllipseRole role;  ///< entry's, kept here: a reused entry's map node is not read
  };
  /// The registry's entries as a check places them, links before obstacles (so the core reads
  /// the scene once), kept from begin() to begin(): walking the map twice per check cost as
  /// much as the scene check at 1,000 ellipses.
  const std::vector<OrderedEntry>& placingOrder() const { return order_; }

  /// The projection of entry `index` (in registry().entries() order) made through the transform
  /// `placement` now reports for its frame, or nullptr when it must be projected (again).
  /// Inline: it is asked for every stored ellipse of every check.
  const core::Ellipse* reuse(std::size_t index, FramePlacer& placement) {
    if (index >= entries_.size() || !entries_[index].valid) return nullptr;
    const Entry& entry = entries_[index];
    Frame& frame = frames_[entry.frame];
    if (frame.compared_in_check != check_) compare(frame, placement);
    return frame.unchanged ? &entry.ellipse : nullptr;
  }

  /// A `placed` scene of an earlier check made with this cache, handed back by its owner once
  /// done with it (the node, when a newer check replaces it): while the registry is unchanged and
  /// that check placed every stored ellipse, it already holds every name in placing order, and
  /// the next check only rewrites the geometry instead of copying every name again (at 1,000
  /// ellipses the copies were a third of a check). Any other scene is dropped.
  void recycle(core::Scene placed);
  /// The recycled scene for this check (after begin()), or an empty one. Its names and roles
  /// are those of placingOrder(); its geometry is stale and must be rewritten entry by entry.
  core::Scene takeRecycled();
  /// Checks that refilled a recycled scene (for tests and benchmarks).
  std::size_t refilledChecks() const { return refilled_checks_; }
  /// Tells the cache that `placed` is the complete placement of this check (every stored
  /// ellipse, in placingOrder(), no query), so that it may be recycled later.
  void produced(const core::Scene& placed);

  /// Refills `placed`, the scene takeRecycled() returned, frame by frame: the entries of a frame
  /// that did not move since the recycled scene was made are not visited at all, those of a
  /// frame that moved only since then get their cached projection, and those of a frame that
  /// moved now are handed to `project(position)`, which projects, store()s and writes the entry
  /// at that position of placingOrder() (false if it could not be placed). Returns false, with
  /// `placed` partly written, unless every stored entry has a projection, every frame is usable
  /// now and every projection succeeded: then refill entry by entry. `reused_obstacles` counts
  /// the obstacles whose projection was reused.
  bool refillByFrame(core::Scene& placed, FramePlacer& placement,
                     const std::function<bool(std::size_t position)>& project,
                     std::size_t* reused_obstacles);
  /// Obstacles among placingOrder().
  std::size_t obstacleCount() const { return obstacle_count_; }
  /// Positions in placingOrder() of the obstacles with a velocity of their own
  /// (registry.movingNames()), increasing; found once per registry revision: looking every
  /// placed name up on each gated command cost milliseconds at 100,000 obstacles.
  const std::vector<std::size_t>& ownMotionPositions() const { return own_motion_positions_; }
  /// Checks refilled frame by frame (for tests and benchmarks).
  std::size_t frameRefills() const { return frame_refills_; }

  /// The obstacles' grid, kept with the projections it was made of.
  StandingObstacles& standingObstacles() { return standing_; }

  /// Remembers that entry `index`, in `frame`, projects to `ellipse` through `transform`.
  void store(std::size_t index, const std::string& frame, const Eigen::Isometry3d& transform,
             const core::Ellipse& ellipse);

 private:
  struct Frame {
    std::string name;
    Eigen::Isometry3d transform{Eigen::Isometry3d::Identity()};
    std::uint64_t compared_in_check{0};  ///< check_ when `unchanged` was last decided
    bool unchanged{false};               ///< in the current check
    bool usable{false};                  ///< found and fresh in the current check
    std::uint64_t stored_in_check{0};    ///< check_ of the last store() of one of its entries
    std::vector<std::uint32_t> positions;  ///< its entries' places in order_ (byFrameReady())
    std::size_t obstacles{0};              ///< obstacles among them
  };
  struct Entry {
    bool valid{false};
    std::uint32_t frame{0};  ///< index into frames_
    core::Ellipse ellipse;
  };

  /// Decides once per check whether `frame` still has the transform its entries were made with.
  void compare(Frame& frame, FramePlacer& placement);
  /// Whether every entry has a projection; then each frame lists its entries' positions.
  bool byFrameReady();

  bool started_{false};
  std::uint64_t revision_{0};
  double global_padding_m_{0.0};
  std::uint64_t check_{0};
  std::vector<Frame> frames_;
  std::map<std::string, std::uint32_t> frame_index_;
  std::vector<Entry> entries_;
  std::vector<OrderedEntry> order_;
  StandingObstacles standing_;
  /// The buffers of the complete placements produced since the last reset (a scene keeps its
  /// buffer when moved): the node alternates between two.
  struct Produced {
    const void* storage;  ///< core::Scene::storage()
    std::uint64_t check;  ///< check_ that made it: entries stored later are stale in it
  };
  std::vector<Produced> produced_;
  core::Scene recycled_;
  std::uint64_t recycled_check_{0};
  std::size_t refilled_checks_{0};
  std::size_t frame_refills_{0};
  std::size_t obstacle_count_{0};
  std::vector<std::size_t> own_motion_positions_;
  bool by_frame_{false};  ///< frames' positions are complete (byFrameReady())
};

}  // namespace ellipse_collision::app

#pragma once

// The narrow phase of the scene checks (scene_check.cpp): the movers of one check and the
// PairCollector that culls, tests and sorts their candidate pairs. Internal to the core
// (src/core).

#include <cstddef>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "contact_scale_quartic.h"
#include "ellipse_collision/core/batch_overlap.h"
#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "ellipse_collision/core/scene_check.h"
#include "pair_culling.h"
#include "scene_entry_ref.h"

namespace ellipse_collision::core::detail {

/// The queries and links of one check ("movers": every pair has one), each prepared once with the
/// box its partners must meet (candidateBox()).
struct Movers {
  std::vector<EntryRef> entries;
  std::vector<PreparedEllipse> prepared;
  std::vector<BoundingBox> boxes;

  void reserve(std::size_t count) {
    entries.reserve(count);
    prepared.reserve(count);
    boxes.reserve(count);
  }
  void add(const EntryRef& entry, double warning_distance);
};

/// The narrow phase and the answer, shared by every entry point: each candidate pair is tested
/// in canonical order (so neither the input order nor the broadphase can change a rounding bit)
/// and the answer is sorted, so it depends only on the set of pairs tested. Every pair has a
/// mover (query or link) first; the movers are ranked in canonical order once, so that sorting
/// the pairs compares two names only for pairs of one mover with two obstacles.
/// The pairs are gathered, up to kPairBlock at a time, into columns and culled as overlapBatch()
/// culls (pair_culling.h: the circle tests of overlap(), without a branch per pair), then only the
/// pairs left open go through overlap()'s exact stages: the same answer as overlap() on each pair,
/// and a streamed obstacle is prepared only when a pair needs its exact stages or its contact
/// scale (an IndexedObstacles holds its obstacles prepared, with their columns). Behind the grid
/// few candidates are far apart (13 % in the benchmark scenes), so for streamed obstacles this
/// costs about what testing pair by pair did; from the index, 6-7 % fewer instructions and 9 %
/// less time where many obstacles are near the links (doc/benchmarks.md, batch pair tests).
class PairCollector {
 public:
  PairCollector(detail::BatchKernel kernel, double warning_distance, const Movers& movers);

  /// Mover `i` (always first in its pair with an obstacle) against `obstacle`, prepared if its
  /// pair needs it.
  void checkWithObstacle(std::size_t i, const EntryRef& obstacle) {
    add(i, kObstacle, obstacle, nullptr);
  }

  /// Mover `i` against obstacle `k` of `index`: its culling columns and its prepared form read
  /// from the index, which built them once.
  void checkWithIndexedObstacle(std::size_t i, const IndexedObstacles& index, std::size_t k) {
    const EllipseBatch& batch = index.batch();
    addWithColumns(i, kObstacle, refOf(index.obstacles()[k]), &batch.prepared(k),
                   batch.centerX()[k], batch.centerY()[k], batch.boundingRadius()[k],
                   batch.inscribedRadius()[k]);
  }

  /// Movers among themselves (query-link always, link-link with self collision): the pairs of
  /// their gridded candidate boxes.
  void checkMoverPairs(const BoxGrid& grid, const SceneRules& rules,
                       const std::set<std::string>& only_names);

  SceneCheckResult finish();

 private:
  /// The order of `pairs` with (first, second) in (role, name) order: the first's rank, then a
  /// mover second before an obstacle second (roles Query, Link < Obstacle), movers by rank,
  /// obstacles by name. Counted out by the first's rank (one pass), then each mover's pairs
  /// sorted, by insertion when they are few: a general sort of all the pairs was a twentieth of
  /// a check of 50 links and 100 obstacles.
  template <typename Found>
  std::vector<std::uint32_t> canonicalOrder(const std::vector<Found>& pairs) const;

  static constexpr std::size_t kExpectedPairs = 128;
  /// The pairs gathered before they are tested: few enough that the columns, the waiting pairs
  /// and their prepared obstacles (16 KB) stay in the first-level cache with the movers (256
  /// measured alike: doc/benchmarks.md, batch pair tests).
  static constexpr std::size_t kPairBlock = 64;
  static_assert(kPairBlock <= detail::kCullBlock, "a block the culling takes in one call");
  static constexpr std::uint32_t kInsertionSortLimit = 16;
  /// The second rank of an obstacle: after every mover.
  static constexpr std::uint32_t kObstacle = std::numeric_limits<std::uint32_t>::max();

  /// A pair found, ranked for sorting. Collisions (their contact scales solved apart, in
  /// scale_problems_) and warnings are kept apart so that sorting the collisions reads 24 bytes
  /// per pair, not the 80 of one that also holds a clearance.
  struct Pair {
    const std::string* first;  // names
    const std::string* second;
    std::uint32_t first_rank;
    std::uint32_t second_rank;  // kObstacle for an obstacle
  };
  struct Warning : Pair {
    Clearance clearance;
  };

  /// A pair waiting in the columns: mover `first` first, then `second`, a mover (`prepared`
  /// given) or an obstacle (prepared, if needed, once for the pairs of one obstacle that wait
  /// side by side: its first such pair, `group`, holds where).
  struct Pending {
    const std::string* second_name;
    const Ellipse* second;
    const PreparedEllipse* prepared;  ///< the second's, or null: see preparedSecond()
    std::uint32_t first;
    std::uint32_t second_rank;  ///< kObstacle for an obstacle
    std::uint32_t group;        ///< the first waiting pair with the same second
    std::uint32_t slot;         ///< for a group's first pair: its place in prepared_obstacles_
  };
  static constexpr std::uint32_t kNoSlot = std::numeric_limits<std::uint32_t>::max();

  /// Mover `i` first, then `second` of rank `second_rank` (kObstacle for an obstacle), its
  /// prepared form given for a mover: gathered into the columns, tested with the block.
  void add(std::size_t i, std::uint32_t second_rank, const EntryRef& second,
           const PreparedEllipse* prepared_second) {
    // What PreparedEllipse computes (max and min of the semi-axes): the obstacle needs no sincos
    // and no division for the culling to decide it.
    const Ellipse& ellipse = *second.ellipse;
    addWithColumns(i, second_rank, second, prepared_second, ellipse.center.x(), ellipse.center.y(),
                   boundingRadius(ellipse), inscribedRadius(ellipse));
  }

  /// add() with the second's culling columns given.
  void addWithColumns(std::size_t i, std::uint32_t second_rank, const EntryRef& second,
                      const PreparedEllipse* prepared_second, double x, double y, double bounding,
                      double inscribed) {
    ++pair_tests_;
    if (pending_count_ == kPairBlock) testPending();
    const std::size_t k = pending_count_++;
    const PreparedEllipse& first = prepared_movers_[i];
    first_x_[k] = first.ellipse().center.x();
    first_y_[k] = first.ellipse().center.y();
    first_bounding_[k] = first.boundingRadius();
    first_inscribed_[k] = first.inscribedRadius();
    second_x_[k] = x;
    second_y_[k] = y;
    second_bounding_[k] = bounding;
    second_inscribed_[k] = inscribed;
    const bool same_second = k > 0 && pending_[k - 1].second == second.ellipse;
    pending_[k] = {
        second.name,     second.ellipse,
        prepared_second, static_cast<std::uint32_t>(i),
        second_rank,     same_second ? pending_[k - 1].group : static_cast<std::uint32_t>(k),
        kNoSlot};
  }

  /// The second ellipse of waiting pair `k`, prepared: a mover's as given, an obstacle's prepared
  /// on first need for its group.
  const PreparedEllipse& preparedSecond(std::size_t k);

  /// The waiting pairs: culled, the open ones through overlap()'s exact stages, then each
  /// collision and (with a warning distance) each near miss recorded in the order of testing.
  void testPending();

  void recordCollision(std::size_t k);

  /// A pair that does not overlap: a warning if it is closer than the warning distance.
  void recordIfNear(std::size_t k);

  bool avx2_;
  double warning_distance_;
  const std::vector<EntryRef>& movers_;
  const std::vector<PreparedEllipse>& prepared_movers_;
  std::vector<std::uint32_t> rank_;  ///< each mover's place in (role, name) order
  std::size_t pair_tests_{0};
  std::vector<Pair> collisions_;
  std::vector<detail::ScaleProblem> scale_problems_;  ///< one per collision, same order
  std::vector<Warning> warnings_;
  // The waiting pairs (pending_count_ of them) and their columns for the culling.
  std::size_t pending_count_{0};
  Pending pending_[kPairBlock];
  double first_x_[kPairBlock];
  double first_y_[kPairBlock];
  double first_bounding_[kPairBlock];
  double first_inscribed_[kPairBlock];
  double second_x_[kPairBlock];
  double second_y_[kPairBlock];
  double second_bounding_[kPairBlock];
  double second_inscribed_[kPairBlock];
  std::uint8_t overlaps_[kPairBlock];
  /// The open pairs after culling, then the colliding ones.
  std::size_t indices_[kPairBlock + detail::kCullSurvivorSlack];
  /// The block's obstacles that a pair needed prepared (prepared_count_ of them), built in place
  /// as needed: neither a vector (an allocation per check) nor an array of std::optional, which
  /// the constructor cleared (a memset of 8 KB per check).
  PreparedEllipse* preparedObstacle(std::uint32_t slot) {
    return reinterpret_cast<PreparedEllipse*>(prepared_storage_) + slot;
  }
  static_assert(std::is_trivially_destructible_v<PreparedEllipse>, "left without destruction");
  std::uint32_t prepared_count_{0};
  alignas(PreparedEllipse) unsigned char prepared_storage_[kPairBlock * sizeof(PreparedEllipse)];
};

}  // namespace ellipse_collision::core::detail

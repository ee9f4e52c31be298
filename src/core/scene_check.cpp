#include "ellipse_collision/core/scene_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <type_traits>
#include <string_view>

#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/distance.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "ellipse_collision/core/unique_names.h"
#include "contact_scale_quartic.h"
#include "pair_culling.h"
#include "scene_check_detail.h"
#include "scene_entry.h"
#include "scene_entry_ref.h"

namespace ellipse_collision::core {
namespace {

using detail::distanceLowerBound;
using detail::EntryRef;
using detail::entryProblem;
using detail::nearPair;
using detail::refOf;
using detail::wanted;
using detail::warningDistanceProblem;

// Relative margin of the warning pad in candidateBox(): distance()'s absolute error (about
// epsilon times the radii and the centre distance, distance.h) and the rounding of the padded
// bounds are far smaller, so a pair the boxes rule out is one distance() never reports. The
// obstacle's own size is covered by the margin of its boundingCircleBox().
constexpr double kPadMargin = 1e-6;

/// The box a mover's candidate partners must meet: its tight box grown by the warning distance
/// and a margin, so that every pair distance() could report as closer than the warning distance
/// has overlapping boxes. Without warnings, the tight box: ellipses that overlap have overlapping
/// boxes (broadphase.h).
BoundingBox candidateBox(const PreparedEllipse& mover, double warning_distance) {
  BoundingBox box = mover.box();
  if (warning_distance <= 0.0) return box;
  const Eigen::Vector2d& center = mover.ellipse().center;
  const double pad = warning_distance + kPadMargin * (warning_distance + (box.max_x - box.min_x) +
                                                      (box.max_y - box.min_y) +
                                                      std::abs(center.x()) + std::abs(center.y()));
  return {box.min_x - pad, box.min_y - pad, box.max_x + pad, box.max_y + pad};
}

/// The role in the top byte, then the first 7 bytes of `name`, zero-padded, big-endian: where
/// two such numbers differ they order the pairs (role, name) as comparing the role and then
/// std::string's operator< does (bytes compared as unsigned char, a proper prefix first); where
/// they are equal the names must be compared in full.
std::uint64_t roleAndPrefix(EllipseRole role, const std::string& name) {
  std::uint64_t key = static_cast<std::uint64_t>(role);
  for (std::size_t k = 0; k < 7; ++k) {
    const std::uint64_t byte = k < name.size() ? static_cast<unsigned char>(name[k]) : 0u;
    key = (key << 8) | byte;
  }
  return key;
}

}  // namespace

bool pairWanted(const NamedEllipse& a, const NamedEllipse& b, const SceneRules& rules,
                const std::set<std::string>& only_names) {
  return wanted(refOf(a), refOf(b), rules, only_names);
}

namespace {

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
  void add(const EntryRef& entry, double warning_distance) {
    entries.push_back(entry);
    prepared.emplace_back(*entry.ellipse);
    boxes.push_back(candidateBox(prepared.back(), warning_distance));
  }
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
  PairCollector(detail::BatchKernel kernel, double warning_distance, const Movers& movers)
      : avx2_(detail::useAvx2(kernel)),
        warning_distance_(warning_distance),
        movers_(movers.entries),
        prepared_movers_(movers.prepared),
        rank_(movers.entries.size()) {
    // Sorted on one number, the role and the name's first 7 bytes (roleAndPrefix()), and on the
    // whole names only where those tie: comparing names through memcmp was a twentieth of a
    // check of 50 links and 100 obstacles.
    struct Key {
      std::uint64_t role_and_prefix;
      std::uint32_t index;
    };
    std::vector<Key> keys(movers_.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
      keys[i] = {roleAndPrefix(movers_[i].role, *movers_[i].name), static_cast<std::uint32_t>(i)};
    }
    const auto before = [this](const Key& a, const Key& b) {
      if (a.role_and_prefix != b.role_and_prefix) return a.role_and_prefix < b.role_and_prefix;
      return *movers_[a.index].name < *movers_[b.index].name;
    };
    // The node's movers come in its registry's (role, name) order: one pass confirms it, where
    // sorting 50 links anew was 4 % of a check of 100 obstacles.
    if (!std::is_sorted(keys.begin(), keys.end(), before)) {
      std::sort(keys.begin(), keys.end(), before);
    }
    for (std::size_t k = 0; k < keys.size(); ++k) rank_[keys[k].index] = static_cast<std::uint32_t>(k);
    // Enough for a robot's self collisions without growing the vector on the way.
    collisions_.reserve(kExpectedPairs);
    scale_problems_.reserve(kExpectedPairs);
  }

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
                       const std::set<std::string>& only_names) {
    for (const IndexPair& pair : grid.overlappingPairs()) {
      std::size_t i = pair.first, j = pair.second;
      if (rank_[j] < rank_[i]) std::swap(i, j);
      if (!wanted(movers_[i], movers_[j], rules, only_names)) continue;
      add(i, rank_[j], movers_[j], &prepared_movers_[j]);
    }
  }

  SceneCheckResult finish() {
    testPending();
    // All contact scales at once: side by side their iterations overlap in the pipeline, where
    // one pair at a time waits on each division (bench_pair_tests contact_scale/: 56-67 against
    // 78-96 ns per pair); the same bits as contactScale() on each pair.
    std::vector<double> scales(scale_problems_.size());
    detail::solveContactScales(scale_problems_.data(), scale_problems_.size(), scales.data());

    SceneCheckResult result;
    result.pair_tests = pair_tests_;
    // Sized first and the names assigned in place: a pushed {name, name, scale} was built and then
    // moved, two copies of each name.
    result.collisions.resize(collisions_.size());
    const std::vector<std::uint32_t> collision_order = canonicalOrder(collisions_);
    for (std::size_t k = 0; k < collision_order.size(); ++k) {
      const Pair& pair = collisions_[collision_order[k]];
      CollidingPair& reported = result.collisions[k];
      reported.name_a = *pair.first;
      reported.name_b = *pair.second;
      reported.contact_scale = scales[collision_order[k]];
    }
    result.warnings.reserve(warnings_.size());
    for (const std::uint32_t k : canonicalOrder(warnings_)) {
      const Warning& pair = warnings_[k];
      result.warnings.push_back(nearPair(*pair.first, *pair.second, pair.clearance));
    }
    return result;
  }

 private:
  /// The order of `pairs` with (first, second) in (role, name) order: the first's rank, then a
  /// mover second before an obstacle second (roles Query, Link < Obstacle), movers by rank,
  /// obstacles by name. Counted out by the first's rank (one pass), then each mover's pairs
  /// sorted, by insertion when they are few: a general sort of all the pairs was a twentieth of
  /// a check of 50 links and 100 obstacles.
  template <typename Found>
  std::vector<std::uint32_t> canonicalOrder(const std::vector<Found>& pairs) const {
    std::vector<std::uint32_t> order(pairs.size());
    if (pairs.empty()) return order;
    // start[r] is first one past the last place of rank r's pairs (start[R] = all of them);
    // filling from the back, in decreasing k, counts each rank down to where its pairs start.
    std::vector<std::uint32_t> start(rank_.size() + 1, 0);
    for (const Found& pair : pairs) ++start[pair.first_rank];
    for (std::size_t r = 1; r < start.size(); ++r) start[r] += start[r - 1];
    for (std::size_t k = pairs.size(); k-- > 0;) {
      order[--start[pairs[k].first_rank]] = static_cast<std::uint32_t>(k);
    }
    const auto before = [&pairs](std::uint32_t a, std::uint32_t b) {
      const Pair& x = pairs[a];
      const Pair& y = pairs[b];
      if (x.second_rank != y.second_rank) return x.second_rank < y.second_rank;
      return x.second_rank == kObstacle && *x.second < *y.second;
    };
    for (std::size_t r = 0; r + 1 < start.size(); ++r) {
      // One mover among many obstacles (a large link, a query over a crowd): a general sort.
      if (start[r + 1] - start[r] > kInsertionSortLimit) {
        std::sort(order.begin() + start[r], order.begin() + start[r + 1], before);
        continue;
      }
      for (std::uint32_t k = start[r] + 1; k < start[r + 1]; ++k) {
        const std::uint32_t moving = order[k];
        std::uint32_t at = k;
        for (; at > start[r] && before(moving, order[at - 1]); --at) order[at] = order[at - 1];
        order[at] = moving;
      }
    }
    return order;
  }

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
    const std::string* first;   // names
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
    pending_[k] = {second.name,
                   second.ellipse,
                   prepared_second,
                   static_cast<std::uint32_t>(i),
                   second_rank,
                   same_second ? pending_[k - 1].group : static_cast<std::uint32_t>(k),
                   kNoSlot};
  }

  /// The second ellipse of waiting pair `k`, prepared: a mover's as given, an obstacle's prepared
  /// on first need for its group.
  const PreparedEllipse& preparedSecond(std::size_t k) {
    const Pending& pair = pending_[k];
    if (pair.prepared != nullptr) return *pair.prepared;
    Pending& group = pending_[pair.group];
    if (group.slot == kNoSlot) {
      group.slot = prepared_count_++;
      new (preparedObstacle(group.slot)) PreparedEllipse(*group.second);
    }
    return *std::launder(preparedObstacle(group.slot));
  }

  /// The waiting pairs: culled, the open ones through overlap()'s exact stages, then each
  /// collision and (with a warning distance) each near miss recorded in the order of testing.
  void testPending() {
    const std::size_t count = pending_count_;
    if (count == 0) return;
    const detail::CullColumns first{first_x_, first_y_, first_bounding_, first_inscribed_};
    const detail::CullColumns second{second_x_, second_y_, second_bounding_, second_inscribed_};
    const std::size_t open = detail::cullPairs(avx2_, first, second, 0, count, overlaps_, indices_);
    for (std::size_t s = 0; s < open; ++s) {
      const std::size_t k = indices_[s];
      overlaps_[k] = static_cast<std::uint8_t>(
          detail::overlapOfNearPair(prepared_movers_[pending_[k].first], preparedSecond(k)));
    }
    if (warning_distance_ <= 0.0) {
      // The colliding pairs listed without a branch per pair, as the culling lists the open ones.
      std::size_t colliding = 0;
      for (std::size_t k = 0; k < count; ++k) {
        indices_[colliding] = k;
        colliding += overlaps_[k];
      }
      for (std::size_t c = 0; c < colliding; ++c) recordCollision(indices_[c]);
    } else {
      for (std::size_t k = 0; k < count; ++k) {
        if (overlaps_[k] != 0) {
          recordCollision(k);
        } else {
          recordIfNear(k);
        }
      }
    }
    pending_count_ = 0;
    prepared_count_ = 0;
  }

  void recordCollision(std::size_t k) {
    const Pending& pair = pending_[k];
    collisions_.push_back({movers_[pair.first].name, pair.second_name, rank_[pair.first],
                           pair.second_rank});
    // The contact scale is solved in finish(), with every other pair's (see there).
    scale_problems_.push_back(detail::scaleProblem(
        detail::canonicalRelativeShape(prepared_movers_[pair.first], preparedSecond(k))));
  }

  /// A pair that does not overlap: a warning if it is closer than the warning distance.
  void recordIfNear(std::size_t k) {
    const Pending& pair = pending_[k];
    const Ellipse& first = *movers_[pair.first].ellipse;
    if (distanceLowerBound(first, *pair.second) >= warning_distance_) return;
    const Clearance clearance = distance(first, *pair.second);
    if (clearance.separated && clearance.distance < warning_distance_) {
      warnings_.push_back(
          {{movers_[pair.first].name, pair.second_name, rank_[pair.first], pair.second_rank},
           clearance});
    }
  }

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

/// The pairs of obstacle `name` with the movers `found` (checkObstacle()), handed to `pairs` side
/// by side; out of line, so that the loop streaming the obstacles keeps its few registers for the
/// many that meet no mover.
__attribute__((noinline)) bool checkFoundPairs(const std::string& name, const Ellipse& ellipse,
                                               const std::vector<std::size_t>& found,
                                               const Movers& movers, const SceneRules& rules,
                                               const std::set<std::string>& only_names,
                                               PairCollector& pairs) {
  if (!isValid(ellipse)) return false;
  const EntryRef obstacle{&name, EllipseRole::Obstacle, &ellipse};
  for (const std::size_t i : found) {
    if (wanted(movers.entries[i], obstacle, rules, only_names)) {
      pairs.checkWithObstacle(i, obstacle);
    }
  }
  return true;
}

/// Every wanted pair of `ellipse`, an obstacle, with the movers whose candidate boxes its
/// bounding-circle box meets (a mover always comes first in a pair with an obstacle). The box
/// needs no trigonometry and no division, so it is safe to make for any values; the obstacle is
/// prepared only if a pair needs it (PairCollector). Returns false, testing no pair, for an
/// invalid obstacle that meets a mover's box (a scene vouched for as validated that broke its
/// promise). `name_of()` gives its name, asked only when it meets a mover; `found` is scratch
/// space.
template <typename NameOf>
inline bool checkObstacle(const NameOf& name_of, const Ellipse& ellipse, const BoxGrid& grid,
                          const Movers& movers, const SceneRules& rules,
                          const std::set<std::string>& only_names, PairCollector& pairs,
                          std::vector<std::size_t>& found) {
  grid.overlapping(boundingCircleBox(ellipse), &found);
  // Most obstacles meet no mover.
  if (found.empty()) return true;
  return checkFoundPairs(name_of(), ellipse, found, movers, rules, only_names, pairs);
}

/// checkScene(). Every entry is validated once, in index order, so the first problem reported is
/// the same whichever way the scene is read. With `movers_first` it tries to read the scene
/// once: the leading queries and links are gridded, then every later entry is validated and
/// streamed in the same pass (at 100,000 obstacles reading the scene costs as much as the pair
/// tests). A query or link after an obstacle sends it back to the start in two passes: movers
/// first, then obstacles.
SceneCheckResult checkNamedScene(detail::BatchKernel kernel,
                                 const std::vector<NamedEllipse>& ellipses,
                                 const SceneRules& rules, const std::set<std::string>& only_names,
                                 bool movers_first) {
  SceneCheckResult result;
  result.error = warningDistanceProblem(rules);
  if (!result.error.empty()) return result;
  const double warning_distance = rules.warning_distance;

  // Every pair involves a query or a link (obstacle-obstacle is never checked): grid those few
  // "movers", prepared once, and stream the obstacles through the grid.
  Movers movers;
  detail::NameSet names(ellipses.size());
  std::size_t stream_from = movers_first ? ellipses.size() : 0;
  for (std::size_t i = 0; i < ellipses.size(); ++i) {
    const NamedEllipse& entry = ellipses[i];
    if (movers_first && entry.role == EllipseRole::Obstacle) {
      stream_from = i;  // validated as it streams
      break;
    }
    result.error = entryProblem(i, refOf(entry), names);
    if (!result.error.empty()) return result;
    if (entry.role == EllipseRole::Obstacle) continue;
    movers.add(refOf(entry), warning_distance);
  }
  PairCollector pairs(kernel, warning_distance, movers);
  const BoxGrid grid(std::move(movers.boxes));

  std::vector<std::size_t> found;
  found.reserve(movers.entries.size());  // the most an obstacle can meet: never grown
  for (std::size_t k = stream_from; k < ellipses.size(); ++k) {
    const NamedEllipse& obstacle = ellipses[k];
    if (movers_first) {
      if (k + detail::NameSet::kPrefetchAhead < ellipses.size()) {
        names.prefetch(ellipses[k + detail::NameSet::kPrefetchAhead].name);
      }
      if (obstacle.role != EllipseRole::Obstacle) {
        return checkNamedScene(kernel, ellipses, rules, only_names, /*movers_first=*/false);
      }
      result.error = entryProblem(k, refOf(obstacle), names);
      if (!result.error.empty()) return SceneCheckResult{{}, {}, result.error, 0};
    }
    if (obstacle.role != EllipseRole::Obstacle) continue;
    // Validated above: checkObstacle() has nothing to refuse.
    checkObstacle([&obstacle]() -> const std::string& { return obstacle.name; }, obstacle.ellipse,
                  grid, movers, rules, only_names, pairs, found);
  }
  pairs.checkMoverPairs(grid, rules, only_names);
  return pairs.finish();
}

}  // namespace

namespace detail {

SceneCheckResult checkMoversAgainstWith(BatchKernel kernel, const std::vector<NamedEllipse>& movers,
                                        const IndexedObstacles& obstacles, const SceneRules& rules,
                                        const std::set<std::string>& only_names) {
  SceneCheckResult result;
  result.error = warningDistanceProblem(rules);
  if (result.error.empty() && !obstacles.error().empty()) {
    result.error = "obstacles refused: " + obstacles.error();
  }
  if (!result.error.empty()) return result;
  const double warning_distance = rules.warning_distance;

  Movers mover_list;
  for (std::size_t i = 0; i < movers.size(); ++i) {
    const NamedEllipse& entry = movers[i];
    if (entry.role == EllipseRole::Obstacle) {
      result.error = detail::entryLabel("movers", i, entry) + " is an obstacle";
      return result;
    }
    if (!isValid(entry.ellipse)) {
      result.error = detail::invalidEntryReason("movers", i, entry);
      return result;
    }
    mover_list.add(refOf(entry), warning_distance);
  }

  // The pairs checkScene() finds by streaming each obstacle's box through the movers' grid,
  // found the other way round: each mover's box looked up in the obstacles' grid (the overlap
  // test of two boxes is symmetric). Each pair is culled from the index's columns and takes its
  // obstacle as the index prepared it: no obstacle is prepared per check (gathering the found
  // obstacles of one mover and culling them with cullOneAgainstMany() measured alike, but a
  // mover with one or two obstacles then made a block of its own: doc/benchmarks.md).
  PairCollector pairs(kernel, warning_distance, mover_list);
  const std::vector<NamedEllipse>& indexed = obstacles.obstacles();
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < mover_list.entries.size(); ++i) {
    obstacles.grid().overlapping(mover_list.boxes[i], &found);
    for (const std::size_t k : found) {
      if (!wanted(mover_list.entries[i], refOf(indexed[k]), rules, only_names)) continue;
      pairs.checkWithIndexedObstacle(i, obstacles, k);
    }
  }
  pairs.checkMoverPairs(BoxGrid(std::move(mover_list.boxes)), rules, only_names);
  return pairs.finish();
}

SceneCheckResult checkSceneWith(BatchKernel kernel, const std::vector<NamedEllipse>& ellipses,
                                const SceneRules& rules,
                                const std::set<std::string>& only_names) {
  return checkNamedScene(kernel, ellipses, rules, only_names, /*movers_first=*/true);
}

SceneCheckResult checkValidatedSceneWith(BatchKernel kernel, const Scene& scene,
                                         std::size_t first_obstacle, const SceneRules& rules,
                                         const std::set<std::string>& only_names) {
  SceneCheckResult result;
  result.error = warningDistanceProblem(rules);
  if (result.error.empty() && first_obstacle > scene.size()) {
    result.error = "first_obstacle = " + std::to_string(first_obstacle) + " is beyond the " +
                   std::to_string(scene.size()) + " ellipses";
  }
  if (!result.error.empty()) return result;
  const double warning_distance = rules.warning_distance;

  // The movers are few: each is checked (an obstacle among them would be paired with the other
  // obstacles). The obstacles are streamed as the bare broadphase streams them, from the packed
  // column of ellipses; only one whose box meets a mover's is tested, before any pair work
  // divides by its radii.
  Movers movers;
  movers.reserve(first_obstacle);
  for (std::size_t i = 0; i < first_obstacle; ++i) {
    if (scene.role(i) == EllipseRole::Obstacle) {
      result.error = detail::entryLabel("ellipses", i, scene.entry(i)) + " is an obstacle before " +
                     "first_obstacle = " + std::to_string(first_obstacle);
      return result;
    }
    if (!isValid(scene.ellipse(i))) {
      result.error = detail::invalidEntryReason("ellipses", i, scene.entry(i));
      return result;
    }
    movers.add(refOf(scene, i), warning_distance);
  }
  PairCollector pairs(kernel, warning_distance, movers);
  const BoxGrid grid(std::move(movers.boxes));
  std::vector<std::size_t> found;
  found.reserve(movers.entries.size());  // the most an obstacle can meet: never grown
  // The column read once: the compiler cannot tell that the pair tests leave the scene alone,
  // and reloading its size and storage per obstacle cost a third of the bare stream's time.
  const Ellipse* const column = scene.ellipses().data();
  const std::size_t count = scene.size();
  for (std::size_t k = first_obstacle; k < count; ++k) {
    const auto name_of = [&scene, k]() -> const std::string& { return scene.name(k); };
    if (!checkObstacle(name_of, column[k], grid, movers, rules, only_names, pairs, found)) {
      result.error = detail::invalidEntryReason("ellipses", k, scene.entry(k));
      return result;
    }
  }
  pairs.checkMoverPairs(grid, rules, only_names);
  return pairs.finish();
}

}  // namespace detail

SceneCheckResult checkMoversAgainst(const std::vector<NamedEllipse>& movers,
                                    const IndexedObstacles& obstacles, const SceneRules& rules,
                                    const std::set<std::string>& only_names) {
  return detail::checkMoversAgainstWith(detail::BatchKernel::Automatic, movers, obstacles, rules,
                                        only_names);
}

SceneCheckResult checkScene(const std::vector<NamedEllipse>& ellipses, const SceneRules& rules,
                            const std::set<std::string>& only_names) {
  return detail::checkSceneWith(detail::BatchKernel::Automatic, ellipses, rules, only_names);
}

SceneCheckResult checkValidatedScene(const Scene& scene, std::size_t first_obstacle,
                                     const SceneRules& rules,
                                     const std::set<std::string>& only_names) {
  return detail::checkValidatedSceneWith(detail::BatchKernel::Automatic, scene, first_obstacle,
                                         rules, only_names);
}

}  // namespace ellipse_collision::core

#include "pair_collector.h"

#include <algorithm>
#include <cmath>
#include <new>

#include "ellipse_collision/core/overlap.h"

namespace ellipse_collision::core::detail {
namespace {

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

void Movers::add(const EntryRef& entry, double warning_distance) {
  entries.push_back(entry);
  prepared.emplace_back(*entry.ellipse);
  boxes.push_back(candidateBox(prepared.back(), warning_distance));
}

PairCollector::PairCollector(detail::BatchKernel kernel, double warning_distance,
                             const Movers& movers)
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
  for (std::size_t k = 0; k < keys.size(); ++k)
    rank_[keys[k].index] = static_cast<std::uint32_t>(k);
  // Enough for a robot's self collisions without growing the vector on the way.
  collisions_.reserve(kExpectedPairs);
  scale_problems_.reserve(kExpectedPairs);
}

void PairCollector::checkMoverPairs(const BoxGrid& grid, const SceneRules& rules,
                                    const std::set<std::string>& only_names) {
  for (const IndexPair& pair : grid.overlappingPairs()) {
    std::size_t i = pair.first, j = pair.second;
    if (rank_[j] < rank_[i]) std::swap(i, j);
    if (!wanted(movers_[i], movers_[j], rules, only_names)) continue;
    add(i, rank_[j], movers_[j], &prepared_movers_[j]);
  }
}

template <typename Found>
std::vector<std::uint32_t> PairCollector::canonicalOrder(const std::vector<Found>& pairs) const {
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

SceneCheckResult PairCollector::finish() {
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

const PreparedEllipse& PairCollector::preparedSecond(std::size_t k) {
  const Pending& pair = pending_[k];
  if (pair.prepared != nullptr) return *pair.prepared;
  Pending& group = pending_[pair.group];
  if (group.slot == kNoSlot) {
    group.slot = prepared_count_++;
    new (preparedObstacle(group.slot)) PreparedEllipse(*group.second);
  }
  return *std::launder(preparedObstacle(group.slot));
}

void PairCollector::testPending() {
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

void PairCollector::recordCollision(std::size_t k) {
  const Pending& pair = pending_[k];
  collisions_.push_back(
      {movers_[pair.first].name, pair.second_name, rank_[pair.first], pair.second_rank});
  // The contact scale is solved in finish(), with every other pair's (see there).
  scale_problems_.push_back(detail::scaleProblem(
      detail::canonicalRelativeShape(prepared_movers_[pair.first], preparedSecond(k))));
}

void PairCollector::recordIfNear(std::size_t k) {
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

}  // namespace ellipse_collision::core::detail

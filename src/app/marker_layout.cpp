#include "ellipse_collision/app/marker_layout.h"

#include <algorithm>
#include <optional>
#include <type_traits>
#include <unordered_set>

namespace ellipse_collision::app {
namespace {

constexpr std::uint32_t kIdMask = 0x7fffffffu;  // marker ids are int32; keep them >= 0
constexpr std::size_t kStateCount = kMarkerStates.size();
// B's ceiling: beyond 1024 x kEllipsesPerMarker = 32,768 ellipses the buckets grow instead.
// rviz draws each marker with a draw call of its own, some 4-7 us of its one render thread per
// marker and frame (scripts/rviz_fps.sh --synthetic: the same 4,096 triangles in 4,096 markers
// took all of a core at 25-30 frames/s, in 1,024 markers 57-66 % at 31), so 4,096 markers of
// 100,000 obstacles would cost it most of a frame at 30 Hz before any triangle was drawn; larger
// buckets re-send more per change (at 100,000 obstacles, 24 against 17 MB/s).
constexpr std::uint32_t kMaxBuckets = 1024;
static_assert(kMaxBuckets <= static_cast<std::uint32_t>(MarkerLayout::kIdsPerState));

std::uint32_t fnv1a(const std::string& bytes) {
  std::uint32_t hash = 2166136261u;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 16777619u;
  }
  return hash;
}

/// One string per ordered pair of names; the length first keeps ("ab", "c") and ("a", "bc") apart.
std::string pairKey(const std::string& name_a, const std::string& name_b) {
  return std::to_string(name_a.size()) + ":" + name_a + name_b;
}

std::size_t stateIndex(MarkerState state) { return static_cast<std::size_t>(state); }

core::EllipseRole roleOf(std::size_t layer) {
  return layer == 0 ? core::EllipseRole::Link : core::EllipseRole::Obstacle;
}

/// The inverse of MarkerLayout::fillId() in a namespace of `buckets` buckets: the slot
/// (state index * B + bucket) of fill marker `id`, or none if no current slot has that id.
std::optional<std::size_t> slotOfFillId(std::int32_t id, std::uint32_t buckets) {
  const std::int32_t code = id / MarkerLayout::kIdsPerState;
  const auto bucket = static_cast<std::uint32_t>(id % MarkerLayout::kIdsPerState);
  const auto row = std::find_if(kMarkerStates.begin(), kMarkerStates.end(),
                                [code](const MarkerStateStyle& r) { return r.code == code; });
  if (row == kMarkerStates.end() || bucket >= buckets) return std::nullopt;
  return stateIndex(row->state) * buckets + bucket;
}

bool sameEllipse(const core::Ellipse& a, const core::Ellipse& b) {
  return a.center == b.center && a.radius_x == b.radius_x && a.radius_y == b.radius_y &&
         a.angle == b.angle;
}

/// B for `count` ellipses, starting from the current `buckets`: doubled while a bucket would hold
/// more than kEllipsesPerMarker on average, halved while it would hold fewer than a quarter of
/// that (the gap keeps a count near a threshold from re-bucketing every cycle).
std::uint32_t bucketsFor(std::size_t count, std::uint32_t buckets) {
  const std::size_t per = MarkerLayout::kEllipsesPerMarker;
  while (count > per * buckets && buckets < kMaxBuckets) buckets *= 2;
  while (buckets > 1 && count < per / 4 * buckets) buckets /= 2;
  return buckets;
}

MarkerLayout::FillChange deletedFill(core::EllipseRole role, std::int32_t id) {
  return {role, id, MarkerLayout::Action::Delete, MarkerState::Free, {}};
}

MarkerLayout::LineChange deletedLine(std::int32_t id) {
  return {id, MarkerLayout::Action::Delete, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
}

}  // namespace

const char* MarkerLayout::nameSpace(core::EllipseRole role) {
  return role == core::EllipseRole::Link ? "links" : "obstacles";
}

std::int32_t MarkerLayout::fillId(MarkerState state, std::uint32_t bucket) {
  return markerStyle(state).code * kIdsPerState + static_cast<std::int32_t>(bucket);
}

std::int32_t MarkerLayout::preferredId(const std::string& name_a, const std::string& name_b) {
  return static_cast<std::int32_t>(fnv1a(pairKey(name_a, name_b)) & kIdMask);
}

std::int32_t MarkerLayout::lineId(const std::string& key, std::int32_t preferred,
                                  const std::map<std::string, std::int32_t>& ids_now,
                                  const std::map<std::int32_t, Points>& lines_now) const {
  const auto now = ids_now.find(key);
  if (now != ids_now.end()) return now->second;
  const auto shown = line_ids_.find(key);
  if (shown != line_ids_.end()) return shown->second;
  // A new line avoids every id shown in the last update (its pair may come later in this one)
  // and every id taken in this one.
  std::int32_t id = preferred;
  while (lines_shown_.count(id) || lines_now.count(id)) {
    id = static_cast<std::int32_t>((static_cast<std::uint32_t>(id) + 1) & kIdMask);
  }
  return id;
}

void MarkerLayout::noteLineDeleted(std::int32_t id) {
  const std::uint64_t number = ++line_deletions_;
  line_deletion_number_[id] = number;
  line_deleted_by_number_[number] = id;
  if (line_deleted_by_number_.size() > kSweptLineDeletions) {
    const auto oldest = line_deleted_by_number_.begin();
    line_deletion_number_.erase(oldest->second);
    line_deleted_by_number_.erase(oldest);
  }
}

std::vector<std::size_t> MarkerLayout::ellipsesPerCell(const Layer& layer) {
  std::vector<std::size_t> in_cell(layer.buckets, 0);
  for (std::size_t slot = 0; slot < layer.members.size(); ++slot) {
    in_cell[slot % layer.buckets] += layer.members[slot].size();
  }
  return in_cell;
}

void MarkerLayout::recutCrowdedCells(Layer& layer, std::vector<char>& dirty) {
  const std::uint32_t buckets = layer.buckets;
  const std::size_t normal = std::max(layer.largest_cell_when_cut, kEllipsesPerMarker);
  std::vector<std::size_t> in_cell = ellipsesPerCell(layer);
  for (std::uint32_t cell = 0; cell < buckets; ++cell) {
    if (in_cell[cell] <= 2 * normal) continue;
    // The smallest part of the tree around the cell whose ellipses fit its cells at the normal
    // size (the whole plane at worst): the cells under one node, a power of two from `first`.
    std::uint32_t first = cell, count = 1;
    std::size_t total = in_cell[cell];
    while (count < buckets && total > count * normal) {
      count *= 2;
      first = cell / count * count;
      total = 0;
      for (std::uint32_t c = first; c < first + count; ++c) total += in_cell[c];
    }
    std::vector<Entry*> moving;
    std::vector<Eigen::Vector2d> centres;
    moving.reserve(total);
    centres.reserve(total);
    for (std::size_t state = 0; state < kStateCount; ++state) {
      for (std::uint32_t c = first; c < first + count; ++c) {
        const std::size_t slot = state * buckets + c;
        for (Entry* entry : layer.members[slot]) {
          moving.push_back(entry);
          centres.push_back(entry->ellipse.center);
        }
        layer.members[slot].clear();
        dirty[slot] = 1;  // re-sent as it is now, or deleted if it ends empty
      }
    }
    layer.partition.recut(first, count, std::move(centres));
    std::size_t largest = 0;
    for (std::uint32_t c = first; c < first + count; ++c) in_cell[c] = 0;
    for (Entry* entry : moving) {
      // Within the part: the cuts above it did not change.
      entry->cell = layer.partition.cellOf(entry->ellipse.center);
      layer.members[stateIndex(entry->state) * buckets + entry->cell].push_back(entry);
      largest = std::max(largest, ++in_cell[entry->cell]);
    }
    // Ellipses no cut can part (many at one point) stay crowded: that is the size to beat now,
    // or they would be cut again on every update.
    if (largest > 2 * normal) layer.largest_cell_when_cut = largest;
    cell = first + count - 1;
  }
}

void MarkerLayout::appendFills(std::size_t layer, const std::vector<char>& wanted,
                               std::vector<FillChange>& out) const {
  const Layer& l = layers_[layer];
  for (std::size_t index = 0; index < wanted.size(); ++index) {
    if (!wanted[index] || l.members[index].empty()) continue;
    const MarkerState state = kMarkerStates[index / l.buckets].state;
    FillChange fill{roleOf(layer),
                    fillId(state, static_cast<std::uint32_t>(index % l.buckets)),
                    Action::Show,
                    state,
                    {}};
    fill.ellipses.members_ = &l.members[index];
    out.push_back(fill);
  }
}

void MarkerLayout::Layer::begin(std::size_t count) {
  const std::uint32_t wanted = bucketsFor(count, buckets);
  // Every marker changes (or, at the first update, none exists yet): cut anew and send all, once
  // the entries are where the scene has them now.
  regroup = wanted != buckets || members.size() != kStateCount * wanted;
  buckets = wanted;
  dirty.assign(kStateCount * buckets, regroup ? 1 : 0);
  seen = 0;
}

// In a layer cut anew everything is sent and grouped at the end: nothing to mark or move.
void MarkerLayout::Layer::markDirty(MarkerState state, std::uint32_t cell) {
  if (!regroup) dirty[slotOf(state, cell)] = 1;
}

void MarkerLayout::Layer::join(Entry* entry) {
  if (!regroup) members[slotOf(entry->state, entry->cell)].push_back(entry);
}

void MarkerLayout::Layer::leave(Entry* entry) {
  if (regroup) return;
  std::vector<Entry*>& slot = members[slotOf(entry->state, entry->cell)];
  const auto it = std::find(slot.begin(), slot.end(), entry);
  *it = slot.back();
  slot.pop_back();
}

std::size_t MarkerLayout::Layer::slotOf(MarkerState state, std::uint32_t cell) const {
  return stateIndex(state) * buckets + cell;
}

MarkerLayout::Entry* MarkerLayout::meet(Layer& l, std::size_t position, const std::string& name,
                                        const core::Ellipse& ellipse, MarkerState state) {
  // Scenes mostly list the same names in the same order: try last cycle's entry at this place
  // before the hash lookup.
  Entry* entry = position < l.by_position.size() && l.by_position[position]->name == name
                     ? l.by_position[position]
                     : nullptr;
  if (!entry) {
    const auto found = l.entries.find(name);
    if (found != l.entries.end()) entry = &found->second;
  }
  if (!entry) {
    entry = &l.entries[name];
    entry->name = name;
    entry->ellipse = ellipse;
    entry->state = state;
    if (!l.regroup) entry->cell = l.partition.cellOf(ellipse.center);
    l.markDirty(state, entry->cell);
    l.join(entry);
  } else if (l.regroup) {
    entry->ellipse = ellipse;
    entry->state = state;
  } else if (entry->state != state || !sameEllipse(entry->ellipse, ellipse)) {
    // An ellipse that moved into another cell leaves its old marker for that cell's.
    const std::uint32_t cell =
        entry->ellipse.center == ellipse.center ? entry->cell : l.partition.cellOf(ellipse.center);
    l.markDirty(entry->state, entry->cell);
    l.markDirty(state, cell);
    if (entry->state != state || entry->cell != cell) {
      l.leave(entry);
      entry->state = state;
      entry->cell = cell;
      l.join(entry);
    }
    entry->ellipse = ellipse;
  }
  if (entry->generation != generation_) ++l.seen;
  entry->generation = generation_;
  return entry;
}

void MarkerLayout::finishLayer(std::size_t layer, std::vector<Entry*> positions, Changes& changes) {
  Layer& l = layers_[layer];
  // When every entry was met in this update nothing went away: no pass over the namespace.
  for (auto it = l.entries.begin(); l.seen != l.entries.size() && it != l.entries.end();) {
    if (it->second.generation == generation_) {
      ++it;
      continue;
    }
    l.markDirty(it->second.state, it->second.cell);
    l.leave(&it->second);
    it = l.entries.erase(it);
  }
  l.by_position = std::move(positions);
  if (l.regroup) {
    std::vector<Eigen::Vector2d> centres;
    centres.reserve(l.entries.size());
    for (const auto& [name, entry] : l.entries) centres.push_back(entry.ellipse.center);
    l.partition = core::MedianPartition(std::move(centres), l.buckets);
    l.members.assign(kStateCount * l.buckets, {});
    for (auto& [name, entry] : l.entries) {
      entry.cell = l.partition.cellOf(entry.ellipse.center);
      l.members[l.slotOf(entry.state, entry.cell)].push_back(&entry);
    }
    const std::vector<std::size_t> in_cell = ellipsesPerCell(l);
    l.largest_cell_when_cut = *std::max_element(in_cell.begin(), in_cell.end());
  } else {
    recutCrowdedCells(l, l.dirty);
  }

  const std::size_t first_sent = changes.fills.size();
  appendFills(layer, l.dirty, changes.fills);
  std::set<std::int32_t> sent;
  for (std::size_t i = first_sent; i < changes.fills.size(); ++i) sent.insert(changes.fills[i].id);
  for (auto it = l.shown.begin(); it != l.shown.end();) {
    const std::optional<std::size_t> slot = slotOfFillId(*it, l.buckets);
    const bool asked = l.regroup || !slot || l.dirty[*slot];
    if (!asked || sent.count(*it)) {
      ++it;
      continue;
    }
    changes.fills.push_back(deletedFill(roleOf(layer), *it));
    it = l.shown.erase(it);
  }
  l.shown.insert(sent.begin(), sent.end());
  l.ever_sent.insert(sent.begin(), sent.end());
}

void MarkerLayout::updateLines(const std::vector<core::NearPair>& warnings, Changes& changes) {
  std::map<std::int32_t, Points> lines_now;
  std::map<std::string, std::int32_t> ids_now;
  for (const core::NearPair& pair : warnings) {
    const std::string key = pairKey(pair.name_a, pair.name_b);
    const std::int32_t id = lineId(key, preferredId(pair.name_a, pair.name_b), ids_now, lines_now);
    ids_now[key] = id;
    lines_now[id] = {pair.point_a, pair.point_b};
  }
  for (const auto& [id, points] : lines_now) {
    const auto old = lines_shown_.find(id);
    if (old == lines_shown_.end() || old->second.first != points.first ||
        old->second.second != points.second) {
      changes.lines.push_back({id, Action::Show, points.first, points.second});
    }
    const auto deleted = line_deletion_number_.find(id);
    if (deleted != line_deletion_number_.end()) {  // shown again
      line_deleted_by_number_.erase(deleted->second);
      line_deletion_number_.erase(deleted);
    }
  }
  for (const auto& [id, points] : lines_shown_) {
    if (lines_now.count(id)) continue;
    changes.lines.push_back(deletedLine(id));
    noteLineDeleted(id);
  }
  lines_shown_ = std::move(lines_now);
  line_ids_ = std::move(ids_now);
}

MarkerLayout::Changes MarkerLayout::update(const core::Scene& placed,
                                           const std::vector<core::CollidingPair>& collisions,
                                           const std::vector<core::NearPair>& warnings,
                                           const std::set<std::string>& predicted) {
  ++generation_;
  std::unordered_set<std::string> colliding;
  for (const core::CollidingPair& pair : collisions) colliding.insert({pair.name_a, pair.name_b});
  std::unordered_set<std::string> warned;
  for (const core::NearPair& pair : warnings) warned.insert({pair.name_a, pair.name_b});
  // The highest-ranked state the ellipse qualifies for.
  const auto stateOf = [&](const std::string& name) {
    if (colliding.count(name)) return MarkerState::Collision;
    if (predicted.count(name)) return MarkerState::Predicted;
    if (warned.count(name)) return MarkerState::Warning;
    return MarkerState::Free;
  };
  const auto layerOf = [](core::EllipseRole role) {
    return role == core::EllipseRole::Link ? 0u : 1u;
  };

  std::array<std::size_t, kLayers> counts{};
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (placed.role(i) != core::EllipseRole::Query) ++counts[layerOf(placed.role(i))];
  }
  for (std::size_t layer = 0; layer < kLayers; ++layer) layers_[layer].begin(counts[layer]);

  // Each layer's entries in the order `placed` lists them: next update's fast path.
  std::array<std::vector<Entry*>, kLayers> positions;
  for (std::size_t layer = 0; layer < kLayers; ++layer) positions[layer].reserve(counts[layer]);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const core::EllipseRole role = placed.role(i);
    if (role == core::EllipseRole::Query) continue;
    const std::size_t layer = layerOf(role);
    const std::string& name = placed.name(i);
    positions[layer].push_back(
        meet(layers_[layer], positions[layer].size(), name, placed.ellipse(i), stateOf(name)));
  }

  Changes changes;
  for (std::size_t layer = 0; layer < kLayers; ++layer) {
    finishLayer(layer, std::move(positions[layer]), changes);
  }
  updateLines(warnings, changes);
  return changes;
}

MarkerLayout::Changes MarkerLayout::refresh(
    double fraction, const std::set<std::pair<std::string, std::int32_t>>& already_sent) {
  // The sweep's parts: each layer's fill ids, then the clearance ids, those shown and those
  // deleted lately (a shown id has no deletion number, so the two never share an id).
  constexpr std::size_t kParts = kLayers + 1;
  const auto firstAfter = [](const auto& ordered, std::int64_t after) -> std::int64_t {
    const auto it =
        after < 0 ? ordered.begin() : ordered.upper_bound(static_cast<std::int32_t>(after));
    if (it == ordered.end()) return -1;
    if constexpr (std::is_same_v<std::decay_t<decltype(ordered)>, std::set<std::int32_t>>) {
      return *it;
    } else {
      return it->first;
    }
  };
  // The part's first id after `after` (-1: none; ids are >= 0).
  const auto nextIn = [&](std::size_t part, std::int64_t after) -> std::int64_t {
    if (part < kLayers) return firstAfter(layers_[part].ever_sent, after);
    const std::int64_t shown = firstAfter(lines_shown_, after);
    const std::int64_t deleted = firstAfter(line_deletion_number_, after);
    if (shown < 0 || deleted < 0) return std::max(shown, deleted);
    return std::min(shown, deleted);
  };
  Changes changes;
  const std::size_t total = layers_[0].ever_sent.size() + layers_[1].ever_sent.size() +
                            lines_shown_.size() + line_deletion_number_.size();
  if (total == 0 || !(fraction > 0.0)) return changes;
  // A long gap owes one whole sweep, not several.
  refresh_owed_ = std::min(refresh_owed_ + std::min(fraction, 1.0) * static_cast<double>(total),
                           static_cast<double>(total));
  std::size_t due = static_cast<std::size_t>(refresh_owed_);
  refresh_owed_ -= static_cast<double>(due);

  const auto nameSpaceOf = [](std::size_t part) -> std::string {
    if (part == kLayers) return kClearanceNamespace;
    return nameSpace(roleOf(part));
  };
  // Walk the sweep: ids in order within a part, the parts in turn. An id already sent counts as
  // refreshed (it goes out now anyway).
  std::array<std::vector<std::int32_t>, kParts> chosen;
  for (std::size_t visited = 0; due > 0 && visited < total;) {
    const std::int64_t next = nextIn(refresh_part_, refresh_after_);
    if (next < 0) {
      refresh_part_ = (refresh_part_ + 1) % kParts;
      refresh_after_ = -1;
      continue;
    }
    refresh_after_ = next;
    ++visited;
    --due;
    const auto id = static_cast<std::int32_t>(next);
    if (!already_sent.count({nameSpaceOf(refresh_part_), id})) {
      chosen[refresh_part_].push_back(id);
    }
  }

  for (std::size_t layer = 0; layer < kLayers; ++layer) {
    const Layer& l = layers_[layer];
    std::vector<char> wanted(kStateCount * l.buckets, 0);
    for (const std::int32_t id : chosen[layer]) {
      if (!l.shown.count(id)) {
        changes.fills.push_back(deletedFill(roleOf(layer), id));
        continue;
      }
      // A shown id is always of a current bucket (a change of B deletes the rest).
      if (const std::optional<std::size_t> slot = slotOfFillId(id, l.buckets)) wanted[*slot] = 1;
    }
    appendFills(layer, wanted, changes.fills);
  }
  for (const std::int32_t id : chosen[kLayers]) {
    const auto shown = lines_shown_.find(id);
    if (shown == lines_shown_.end()) {
      changes.lines.push_back(deletedLine(id));
      continue;
    }
    changes.lines.push_back({id, Action::Show, shown->second.first, shown->second.second});
  }
  return changes;
}

MarkerLayout::Changes MarkerLayout::full() const {
  Changes changes;
  for (std::size_t layer = 0; layer < kLayers; ++layer) {
    appendFills(layer, std::vector<char>(kStateCount * layers_[layer].buckets, 1), changes.fills);
  }
  for (const auto& [id, points] : lines_shown_) {
    changes.lines.push_back({id, Action::Show, points.first, points.second});
  }
  return changes;
}

}  // namespace ellipse_collision::app

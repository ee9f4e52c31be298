#include "ellipse_collision/app/placement_cache.h"

#include <algorithm>
#include <cstring>
#include <set>
#include <string>

namespace ellipse_collision::app {
namespace {

/// Bit for bit: a transform that moved by any amount projects again.
bool sameBits(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return std::memcmp(a.matrix().data(), b.matrix().data(), sizeof(double) * 16) == 0;
}

}  // namespace

void PlacementCache::begin(const EllipseRegistry& registry, double global_padding_m) {
  ++check_;
  const bool same_bits_padding =
      std::memcmp(&global_padding_m, &global_padding_m_, sizeof(double)) == 0;
  if (started_ && registry.revision() == revision_ && same_bits_padding &&
      entries_.size() == registry.entries().size()) {
    return;
  }
  started_ = true;
  revision_ = registry.revision();
  global_padding_m_ = global_padding_m;
  frames_.clear();
  frame_index_.clear();
  produced_.clear();
  recycled_.clear();
  recycled_check_ = 0;
  by_frame_ = false;
  entries_.assign(registry.entries().size(), Entry{});
  order_.clear();
  order_.reserve(registry.entries().size());
  obstacle_count_ = 0;
  for (const core::EllipseRole pass : {core::EllipseRole::Link, core::EllipseRole::Obstacle}) {
    std::size_t index = 0;
    for (const auto& entry : registry.entries()) {
      if (entry.second.role() == pass) order_.push_back({index, &entry, pass});
      ++index;
    }
  }
  own_motion_positions_.clear();
  const std::set<std::string>& moving = registry.movingNames();
  for (std::size_t position = 0; position < order_.size(); ++position) {
    const OrderedEntry& entry = order_[position];
    if (entry.role != core::EllipseRole::Obstacle) continue;
    ++obstacle_count_;
    if (!moving.empty() && moving.count(entry.entry->first)) {
      own_motion_positions_.push_back(position);
    }
  }
}

void PlacementCache::produced(const core::Scene& placed) {
  if (placed.size() != order_.size() || placed.empty()) return;
  const auto same = [&placed](const Produced& p) { return p.storage == placed.storage(); };
  produced_.erase(std::remove_if(produced_.begin(), produced_.end(), same), produced_.end());
  // A few at most: the node's current and previous state. More means buffers were dropped.
  if (produced_.size() >= 4) produced_.erase(produced_.begin());
  produced_.push_back({placed.storage(), check_});
}

void PlacementCache::recycle(core::Scene placed) {
  if (placed.size() != order_.size() || placed.empty()) return;
  for (const Produced& p : produced_) {
    if (p.storage != placed.storage()) continue;
    recycled_ = std::move(placed);
    recycled_check_ = p.check;
    return;
  }
}

core::Scene PlacementCache::takeRecycled() {
  core::Scene taken = std::move(recycled_);
  recycled_ = core::Scene();
  // Handed out to be refilled: it is no longer a complete placement until produced() again.
  const auto same = [&taken](const Produced& p) { return p.storage == taken.storage(); };
  produced_.erase(std::remove_if(produced_.begin(), produced_.end(), same), produced_.end());
  if (taken.size() != order_.size()) taken.clear();
  refilled_checks_ += taken.empty() ? 0 : 1;
  if (taken.empty()) recycled_check_ = 0;
  return taken;
}

void PlacementCache::compare(Frame& frame, FramePlacer& placement) {
  frame.compared_in_check = check_;
  const FrameTransform& now = placement.lookup(frame.name);
  frame.usable = placement.usable(now);
  frame.unchanged = frame.usable && sameBits(now.fixed_from_frame, frame.transform);
}

bool PlacementCache::byFrameReady() {
  if (by_frame_) return true;
  for (const OrderedEntry& entry : order_) {
    if (!entries_[entry.index].valid) return false;
  }
  for (Frame& frame : frames_) {
    frame.positions.clear();
    frame.obstacles = 0;
  }
  for (std::size_t position = 0; position < order_.size(); ++position) {
    Frame& frame = frames_[entries_[order_[position].index].frame];
    frame.positions.push_back(static_cast<std::uint32_t>(position));
    frame.obstacles += order_[position].role == core::EllipseRole::Obstacle;
  }
  by_frame_ = true;
  return true;
}

bool PlacementCache::refillByFrame(core::Scene& placed, FramePlacer& placement,
                                   const std::function<bool(std::size_t position)>& project,
                                   std::size_t* reused_obstacles) {
  *reused_obstacles = 0;
  if (recycled_check_ == 0 || placed.size() != order_.size() || !byFrameReady()) return false;
  for (Frame& frame : frames_) {
    if (frame.compared_in_check != check_) compare(frame, placement);
    if (!frame.usable) return false;  // its entries are skipped: entry by entry
  }
  for (Frame& frame : frames_) {
    if (frame.unchanged) {
      *reused_obstacles += frame.obstacles;
      // Stored after the recycled scene was made: its projections there are stale.
      if (frame.stored_in_check <= recycled_check_) continue;
      for (const std::uint32_t position : frame.positions) {
        placed.ellipse(position) = entries_[order_[position].index].ellipse;
      }
      continue;
    }
    for (const std::uint32_t position : frame.positions) {
      if (!project(position)) return false;
    }
  }
  ++frame_refills_;
  return true;
}

void PlacementCache::store(std::size_t index, const std::string& frame,
                           const Eigen::Isometry3d& transform, const core::Ellipse& ellipse) {
  if (index >= entries_.size()) return;
  auto found = frame_index_.find(frame);
  if (found == frame_index_.end()) {
    found = frame_index_.emplace(frame, static_cast<std::uint32_t>(frames_.size())).first;
    Frame added;
    added.name = frame;
    frames_.push_back(std::move(added));
  }
  Frame& slot = frames_[found->second];
  // The frame moved since its other entries were stored: they project again in this check too
  // (their reuse() found it changed), so the slot takes the new transform.
  slot.transform = transform;
  slot.stored_in_check = check_;
  // An entry projected for the first time changes the frames' position lists.
  if (!entries_[index].valid) by_frame_ = false;
  entries_[index] = Entry{true, found->second, ellipse};
}

}  // namespace ellipse_collision::app

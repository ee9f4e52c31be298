#include "ellipse_collision/app/placement_cache.h"

#include <algorithm>
#include <cstring>

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
  entries_.assign(registry.entries().size(), Entry{});
  order_.clear();
  order_.reserve(registry.entries().size());
  for (const core::EllipseRole pass : {core::EllipseRole::Link, core::EllipseRole::Obstacle}) {
    std::size_t index = 0;
    for (const auto& entry : registry.entries()) {
      if (entry.second.role() == pass) order_.push_back({index, &entry, pass});
      ++index;
    }
  }
}

void PlacementCache::produced(const std::vector<core::NamedEllipse>& placed) {
  if (placed.size() != order_.size() || placed.empty()) return;
  if (std::find(produced_.begin(), produced_.end(), placed.data()) != produced_.end()) return;
  // A few at most: the node's current and previous state. More means buffers were dropped.
  if (produced_.size() >= 4) produced_.erase(produced_.begin());
  produced_.push_back(placed.data());
}

void PlacementCache::recycle(std::vector<core::NamedEllipse> placed) {
  const bool ours = placed.size() == order_.size() && !placed.empty() &&
                    std::find(produced_.begin(), produced_.end(), placed.data()) != produced_.end();
  if (ours) recycled_ = std::move(placed);
}

std::vector<core::NamedEllipse> PlacementCache::takeRecycled() {
  std::vector<core::NamedEllipse> taken = std::move(recycled_);
  recycled_.clear();
  // Handed out to be refilled: it is no longer a complete placement until produced() again.
  produced_.erase(std::remove(produced_.begin(), produced_.end(), taken.data()), produced_.end());
  if (taken.size() != order_.size()) taken.clear();
  refilled_checks_ += taken.empty() ? 0 : 1;
  return taken;
}

void PlacementCache::compare(Frame& frame, ScenePlacement& placement) {
  frame.compared_in_check = check_;
  const FrameTransform& now = placement.lookup(frame.name);
  frame.unchanged = placement.usable(now) && sameBits(now.fixed_from_frame, frame.transform);
}

void PlacementCache::store(std::size_t index, const std::string& frame,
                           const Eigen::Isometry3d& transform, const core::Ellipse& ellipse) {
  if (index >= entries_.size()) return;
  auto found = frame_index_.find(frame);
  if (found == frame_index_.end()) {
    found = frame_index_.emplace(frame, static_cast<std::uint32_t>(frames_.size())).first;
    frames_.push_back(Frame{frame, transform, 0, false});
  }
  Frame& slot = frames_[found->second];
  // The frame moved since its other entries were stored: they project again in this check too
  // (their reuse() found it changed), so the slot takes the new transform.
  slot.transform = transform;
  entries_[index] = Entry{true, found->second, ellipse};
}

}  // namespace ellipse_collision::app

#include "ellipse_collision/app/stored_placement.h"

#include <set>
#include <utility>

namespace ellipse_collision::app {
namespace {

using RegistryEntry = std::pair<const std::string, StoredEllipse>;

/// One check's placing of the stored ellipses into a scene that is either new or recycled.
class StoredEllipsePlacer {
 public:
  StoredEllipsePlacer(FramePlacer& placement, PlacementCache* cache, std::size_t capacity)
      : placement_(placement), cache_(cache) {
    if (cache_) result_.scene = cache_->takeRecycled();
    rewrite_end_ = result_.scene.size();
    result_.scene.reserve(capacity);
  }

  /// A recycled scene, frame by frame: the entries of frames that stood still are not visited.
  /// False when it cannot be done (no recycled scene, or a frame is not usable now).
  bool refillByFrame() {
    if (!cache_ || rewrite_end_ == 0) return false;
    const auto project = [this](std::size_t at) {
      const PlacementCache::OrderedEntry& item = cache_->placingOrder()[at];
      const EllipseSpec& spec = item.entry->second.spec;
      const FramePlacer::Placement placed = placement_.place(spec, item.role);
      if (placed.status != FramePlacer::Status::Placed) return false;
      remember(item.index, spec, placed.ellipse.ellipse);
      result_.scene.ellipse(at) = placed.ellipse.ellipse;
      return true;
    };
    if (!cache_->refillByFrame(result_.scene, placement_, project, &result_.reused_obstacles)) {
      result_.reused_obstacles = 0;  // the frame-by-frame refill may have counted some
      return false;
    }
    result_.obstacles = cache_->obstacleCount();
    return true;
  }

  /// Entry `entry` (its index in registry order, for the cache) placed in its turn.
  void place(std::size_t entry, const RegistryEntry& item, core::EllipseRole role) {
    const bool obstacle = role == core::EllipseRole::Obstacle;
    result_.obstacles += obstacle;
    if (const core::Ellipse* reused = cache_ ? cache_->reuse(entry, placement_) : nullptr) {
      put(item, role, *reused);
      result_.reused_obstacles += obstacle;
      return;
    }
    const std::string& name = item.first;
    const EllipseSpec& spec = item.second.spec;
    const FramePlacer::Placement placed = placement_.place(spec, role);
    // A recycled scene holds every stored name in placing order only up to the first entry not
    // placed: the rest is dropped and appended as in a new scene.
    if (placed.status != FramePlacer::Status::Placed && position_ < rewrite_end_) {
      result_.scene.truncate(position_);
      rewrite_end_ = position_;
    }
    switch (placed.status) {
      case FramePlacer::Status::Placed:
        if (cache_) remember(entry, spec, placed.ellipse.ellipse);
        put(item, role, placed.ellipse.ellipse);
        break;
      case FramePlacer::Status::FrameUnavailable:
        unavailable_.insert(spec.frame_id);
        result_.skipped.push_back(name + ": frame '" + spec.frame_id + "' unavailable");
        break;
      case FramePlacer::Status::Stale:
        stale_.insert(spec.frame_id);
        result_.skipped.push_back(name + ": frame '" + spec.frame_id + "' stale (" +
                                  placed.error + ")");
        break;
      case FramePlacer::Status::Degenerate:
        result_.skipped.push_back(placed.error);
        break;
    }
  }

  StoredPlacement finish() {
    result_.unavailable_frames.assign(unavailable_.begin(), unavailable_.end());
    result_.stale_frames.assign(stale_.begin(), stale_.end());
    if (cache_ && result_.skipped.empty()) cache_->produced(result_.scene);
    return std::move(result_);
  }

 private:
  /// In a recycled scene only the geometry is written: a reused entry touches neither its name
  /// nor its spec.
  void put(const RegistryEntry& item, core::EllipseRole role, const core::Ellipse& ellipse) {
    if (position_ < rewrite_end_) {
      result_.scene.ellipse(position_++) = ellipse;
    } else {
      result_.scene.push_back(item.first, role, ellipse);
      ++position_;
    }
  }
  /// A projection made now, kept for the next check.
  void remember(std::size_t entry, const EllipseSpec& spec, const core::Ellipse& ellipse) {
    cache_->store(entry, spec.frame_id, placement_.lookup(spec.frame_id).fixed_from_frame,
                  ellipse);
  }

  FramePlacer& placement_;
  PlacementCache* cache_;
  StoredPlacement result_;
  std::size_t rewrite_end_{0};  ///< entries of the recycled scene still in placing order
  std::size_t position_{0};     ///< of the next entry placed
  std::set<std::string> unavailable_;
  std::set<std::string> stale_;
};

}  // namespace

StoredPlacement placeStoredEllipses(const EllipseRegistry& registry, FramePlacer& placement,
                                    double global_padding_m, PlacementCache* cache,
                                    std::size_t query_count) {
  if (cache) cache->begin(registry, global_padding_m);
  StoredEllipsePlacer placer(placement, cache, registry.entries().size() + query_count);
  if (placer.refillByFrame()) return placer.finish();
  if (cache) {
    for (const PlacementCache::OrderedEntry& item : cache->placingOrder()) {
      placer.place(item.index, *item.entry, item.role);
    }
    return placer.finish();
  }
  for (const core::EllipseRole pass : {core::EllipseRole::Link, core::EllipseRole::Obstacle}) {
    std::size_t index = 0;
    for (const RegistryEntry& item : registry.entries()) {
      const std::size_t entry = index++;
      if (item.second.role() == pass) placer.place(entry, item, pass);
    }
  }
  return placer.finish();
}

}  // namespace ellipse_collision::app

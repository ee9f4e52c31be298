#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/frame_placer.h"
#include "ellipse_collision/app/placement_cache.h"
#include "ellipse_collision/core/scene.h"

namespace ellipse_collision::app {

/// Every stored ellipse of a check placed in the fixed frame, and what could not be.
struct StoredPlacement {
  /// Links, then obstacles, each by name, as placed (an entry not placed is left out).
  core::Scene scene;
  std::vector<std::string> skipped;             ///< why each skipped ellipse was skipped
  std::vector<std::string> unavailable_frames;  ///< sorted
  std::vector<std::string> stale_frames;        ///< sorted
  std::size_t obstacles{0};                     ///< stored obstacles
  /// Obstacles whose projection came from the cache: all of them means they stood still since
  /// the last check, so its grid of them still holds (StandingObstacles).
  std::size_t reused_obstacles{0};
};

/// Places every stored ellipse of `registry` through `placement`, links before obstacles (so the
/// core reads the scene once, core::checkScene()). An ellipse whose frame is unavailable or stale,
/// or that projects to nothing, is skipped and said why.
/// With a `cache` (PlacementCache, kept from one check to the next): a projection through a
/// transform that is bit for bit the one it was made with is reused, a recycled scene of an
/// earlier check has only its geometry rewritten (frame by frame when it can), and a complete
/// placement is handed to the cache for recycling. The scene is the same bit for bit either way.
/// The scene keeps room for `query_count` more entries (the check's queries, put in front).
StoredPlacement placeStoredEllipses(const EllipseRegistry& registry, FramePlacer& placement,
                                    double global_padding_m, PlacementCache* cache,
                                    std::size_t query_count = 0);

}  // namespace ellipse_collision::app

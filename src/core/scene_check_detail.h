#pragma once

// The scene checks with the culling kernel of their narrow phase chosen (PairCollector in
// pair_collector.h culls its pairs as overlapBatch() does): the public entry points take
// BatchKernel::Automatic; the tests force each kernel to hold both to the same answer. Internal
// to the core (src/core).

#include <set>
#include <string>
#include <vector>

#include "ellipse_collision/core/batch_overlap.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/scene.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core::detail {

/// checkScene() with `kernel`.
SceneCheckResult checkSceneWith(BatchKernel kernel, const std::vector<NamedEllipse>& ellipses,
                                const SceneRules& rules, const std::set<std::string>& only_names);

/// checkValidatedScene() with `kernel`.
SceneCheckResult checkValidatedSceneWith(BatchKernel kernel, const Scene& scene,
                                         std::size_t first_obstacle, const SceneRules& rules,
                                         const std::set<std::string>& only_names);

/// checkMoversAgainst() with `kernel`.
SceneCheckResult checkMoversAgainstWith(BatchKernel kernel, const std::vector<NamedEllipse>& movers,
                                        const IndexedObstacles& obstacles, const SceneRules& rules,
                                        const std::set<std::string>& only_names);

}  // namespace ellipse_collision::core::detail

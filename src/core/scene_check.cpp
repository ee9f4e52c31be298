#include "ellipse_collision/core/scene_check.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/number_format.h"
#include "ellipse_collision/core/unique_names.h"
#include "pair_collector.h"
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
using detail::Movers;
using detail::PairCollector;
using detail::warningDistanceProblem;

}  // namespace

bool pairWanted(const NamedEllipse& a, const NamedEllipse& b, const SceneRules& rules,
                const std::set<std::string>& only_names) {
  return wanted(refOf(a), refOf(b), rules, only_names);
}

namespace {

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

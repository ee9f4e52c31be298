// Scene checks: 50 links against N obstacles, plus the links against each other, per cycle:
// "scene/" the robot in a 50 m x 50 m warehouse, "crowded/" among 2,000 obstacles in 4 m x 4 m.
// Every variant computes the same colliding pairs (verified before timing); they differ in how
// candidate pairs are found:
//   brute_force        overlap() on all 50 N + 1225 pairs
//   grid_streamed      the core's BoxGrid over the links' tight boxes; each obstacle's
//                      trigonometry-free bounding-circle box is made as it streams through
//   grid_streamed_with_scale  the same plus contactScale() of every colliding pair: what the
//                      answer itself costs, names and rules aside
//   grid_batch         overlappingBoxPairs() on stored boxes: tight for the links, bounding-circle
//                      for the obstacles; the links among themselves by the one-set variant
//   grid_tight_boxes   the same with tight boxes (one sincos each) for the obstacles too
//   grid_prepared      every ellipse prepared, tight boxes, prepared overlap()
//   sort_and_sweep     the alternative broadphase: both sets sorted on min x and swept
//   checkScene         the core's checkScene() on the named scene, as the node calls it: checks the
//                      names, grids the links, streams the obstacles, sorts the answer
//   checkScene_vouched checkValidatedScene(), as the node calls it: names, ellipses and the
//                      links-first order vouched for where they were made (registry, projection),
//                      so no entry is tested again every cycle
//   checkScene_warn    the same with a warning distance of 0.1 m (warning pairs via distance())
//   indexed_obstacles  checkMoversAgainst(): the obstacles gridded once before timing (as the
//                      node keeps them while they do not move), the links looked up in that grid
//   indexed_build      building that IndexedObstacles: what a check costs when obstacles moved
// Counters: pair_tests = overlap() calls per cycle, collisions = colliding pairs per cycle.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "bench_scenes.h"
#include "scene_test_helpers.h"
#include "ellipse_collision/core/broadphase.h"
#include "ellipse_collision/core/contact_scale.h"
#include "ellipse_collision/core/indexed_obstacles.h"
#include "ellipse_collision/core/overlap.h"
#include "ellipse_collision/core/prepared_ellipse.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::core::bench {
namespace {

constexpr int kLinks = 50;
constexpr double kWorldSize =
    50.0;  // [m]: a warehouse; the robot's links lie within 1 m of its centre
constexpr double kCrowdedWorldSize = 4.0;  // [m]: a yard packed around the robot

struct CycleResult {
  long pair_tests{0};
  long collisions{0};
};

CycleResult bruteForce(const RobotScene& scene) {
  CycleResult result;
  const auto& links = scene.links;
  for (std::size_t i = 0; i < links.size(); ++i) {
    for (const Ellipse& obstacle : scene.obstacles)
      result.collisions += overlap(links[i], obstacle);
    for (std::size_t j = i + 1; j < links.size(); ++j)
      result.collisions += overlap(links[i], links[j]);
  }
  result.pair_tests = static_cast<long>(links.size() * scene.obstacles.size() +
                                        links.size() * (links.size() - 1) / 2);
  return result;
}

template <typename Ellipses>
CycleResult checkCandidates(const Ellipses& first, const Ellipses& second,
                            const std::vector<IndexPair>& candidates, CycleResult result) {
  for (const IndexPair& pair : candidates) {
    result.collisions += overlap(first[pair.first], second[pair.second]);
  }
  result.pair_tests += static_cast<long>(candidates.size());
  return result;
}

template <typename BoxOf>
CycleResult grid(const RobotScene& scene, BoxOf obstacle_box) {
  std::vector<BoundingBox> link_boxes, obstacle_boxes;
  link_boxes.reserve(scene.links.size());
  obstacle_boxes.reserve(scene.obstacles.size());
  for (const Ellipse& link : scene.links) link_boxes.push_back(boundingBox(link));
  for (const Ellipse& obstacle : scene.obstacles) obstacle_boxes.push_back(obstacle_box(obstacle));
  CycleResult result = checkCandidates(scene.links, scene.obstacles,
                                       overlappingBoxPairs(link_boxes, obstacle_boxes), {});
  return checkCandidates(scene.links, scene.links, overlappingBoxPairs(link_boxes), result);
}

/// grid_streamed; with kWithScale also the contact scale of every colliding pair, which
/// checkScene()'s answer carries: the bare cost of the answer itself, names and rules aside.
template <bool kWithScale>
CycleResult gridStreamed(const RobotScene& scene) {
  std::vector<BoundingBox> link_boxes;
  link_boxes.reserve(scene.links.size());
  for (const Ellipse& link : scene.links) link_boxes.push_back(boundingBox(link));
  const BoxGrid grid(std::move(link_boxes));
  CycleResult result;
  double scales = 0.0;
  const auto test = [&](const Ellipse& a, const Ellipse& b) {
    ++result.pair_tests;
    if (!overlap(a, b)) return;
    ++result.collisions;
    if constexpr (kWithScale) scales += contactScale(a, b);
  };
  std::vector<std::size_t> found;
  for (const Ellipse& obstacle : scene.obstacles) {
    grid.overlapping(boundingCircleBox(obstacle), &found);
    for (const std::size_t i : found) test(scene.links[i], obstacle);
  }
  for (const IndexPair& pair : grid.overlappingPairs()) {
    test(scene.links[pair.first], scene.links[pair.second]);
  }
  benchmark::DoNotOptimize(scales);
  return result;
}

CycleResult gridPrepared(const RobotScene& scene) {
  std::vector<PreparedEllipse> links, obstacles;
  std::vector<BoundingBox> link_boxes, obstacle_boxes;
  links.reserve(scene.links.size());
  obstacles.reserve(scene.obstacles.size());
  for (const Ellipse& link : scene.links) {
    links.emplace_back(link);
    link_boxes.push_back(links.back().box());
  }
  for (const Ellipse& obstacle : scene.obstacles) {
    obstacles.emplace_back(obstacle);
    obstacle_boxes.push_back(obstacles.back().box());
  }
  CycleResult result =
      checkCandidates(links, obstacles, overlappingBoxPairs(link_boxes, obstacle_boxes), {});
  return checkCandidates(links, links, overlappingBoxPairs(link_boxes), result);
}

/// The alternative considered for the core: sort both sets on min x, sweep, sort the pairs.
std::vector<IndexPair> sortAndSweep(const std::vector<BoundingBox>& a,
                                    const std::vector<BoundingBox>& b) {
  struct Entry {
    double min_x;
    std::size_t index;
    bool in_a;
  };
  std::vector<Entry> entries;
  entries.reserve(a.size() + b.size());
  for (std::size_t i = 0; i < a.size(); ++i) entries.push_back({a[i].min_x, i, true});
  for (std::size_t j = 0; j < b.size(); ++j) entries.push_back({b[j].min_x, j, false});
  std::sort(entries.begin(), entries.end(),
            [](const Entry& l, const Entry& r) { return l.min_x < r.min_x; });
  std::vector<std::size_t> active_a, active_b;
  std::vector<IndexPair> pairs;
  const auto sweep = [](std::vector<std::size_t>* active, const std::vector<BoundingBox>& boxes,
                        double x) {
    active->erase(std::remove_if(active->begin(), active->end(),
                                 [&](std::size_t k) { return boxes[k].max_x < x; }),
                  active->end());
  };
  // Each active list is pruned only when the other set's entry is about to scan it, so every box
  // is added and removed once.
  for (const Entry& entry : entries) {
    if (entry.in_a) {
      sweep(&active_b, b, entry.min_x);
      for (const std::size_t j : active_b) {
        if (boxesOverlap(a[entry.index], b[j])) pairs.push_back({entry.index, j});
      }
      active_a.push_back(entry.index);
    } else {
      sweep(&active_a, a, entry.min_x);
      for (const std::size_t i : active_a) {
        if (boxesOverlap(a[i], b[entry.index])) pairs.push_back({i, entry.index});
      }
      active_b.push_back(entry.index);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

CycleResult sweepCheck(const RobotScene& scene) {
  std::vector<BoundingBox> link_boxes, obstacle_boxes;
  for (const Ellipse& link : scene.links) link_boxes.push_back(boundingBox(link));
  for (const Ellipse& obstacle : scene.obstacles) {
    obstacle_boxes.push_back(boundingCircleBox(obstacle));
  }
  CycleResult result =
      checkCandidates(scene.links, scene.obstacles, sortAndSweep(link_boxes, obstacle_boxes), {});
  return checkCandidates(scene.links, scene.links, overlappingBoxPairs(link_boxes), result);
}

/// The scene as checkScene() takes it: links and obstacles by name.
std::vector<NamedEllipse> namedScene(const RobotScene& scene) {
  std::vector<NamedEllipse> named;
  for (std::size_t i = 0; i < scene.links.size(); ++i) {
    named.push_back({"link_" + std::to_string(i), EllipseRole::Link, scene.links[i]});
  }
  for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
    named.push_back({"obstacle_" + std::to_string(i), EllipseRole::Obstacle, scene.obstacles[i]});
  }
  return named;
}

using Method = CycleResult (*)(const RobotScene&);

const std::pair<const char*, Method> kMethods[] = {
    {"brute_force", bruteForce},
    {"grid_streamed", gridStreamed<false>},
    {"grid_streamed_with_scale", gridStreamed<true>},
    {"grid_batch", [](const RobotScene& s) { return grid(s, boundingCircleBox); }},
    {"grid_tight_boxes",
     [](const RobotScene& s) { return grid(s, [](const Ellipse& e) { return boundingBox(e); }); }},
    {"grid_prepared", gridPrepared},
    {"sort_and_sweep", sweepCheck},
};

}  // namespace
}  // namespace ellipse_collision::core::bench

int main(int argc, char** argv) {
  using namespace ellipse_collision::core;
  using namespace ellipse_collision::core::bench;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  // "scene": the robot in the warehouse, most candidate pairs far apart; "crowded": the same
  // robot among obstacles packed around it (a 4 m x 4 m yard), where a check tests thousands of
  // pairs and most of them are near.
  struct SceneSize {
    const char* family;
    int obstacles;
    double world_size;  // [m]
  };
  static std::map<int, RobotScene> scenes;
  const SceneSize sizes[] = {{"scene", 100, kWorldSize},
                             {"scene", 1000, kWorldSize},
                             {"scene", 10000, kWorldSize},
                             {"scene", 100000, kWorldSize},
                             {"crowded", 2000, kCrowdedWorldSize}};
  for (int size = 0; size < static_cast<int>(std::size(sizes)); ++size) {
    const int obstacles = sizes[size].obstacles;
    const std::string family = std::string(sizes[size].family) + "/";
    scenes[size] = robotScene(kLinks, obstacles, sizes[size].world_size, 7);
    const RobotScene& scene = scenes[size];
    const long collisions = bruteForce(scene).collisions;
    for (const auto& [name, method] : kMethods) {
      const CycleResult check = method(scene);
      if (check.collisions != collisions) {
        std::fprintf(stderr, "%s finds %ld collisions with %d obstacles, brute force %ld\n", name,
                     check.collisions, obstacles, collisions);
        return 1;
      }
      const std::string label = family + name + "/" + std::to_string(obstacles);
      benchmark::RegisterBenchmark(label.c_str(), [&scene, method = method,
                                                   check](benchmark::State& state) {
        for (auto _ : state) benchmark::DoNotOptimize(method(scene));
        state.counters["pair_tests"] = static_cast<double>(check.pair_tests);
        state.counters["collisions"] = static_cast<double>(check.collisions);
        state.counters["obstacles"] = static_cast<double>(scene.obstacles.size());
      })->Unit(benchmark::kMicrosecond);
    }

    static std::map<int, std::vector<NamedEllipse>> named_scenes;
    const std::vector<NamedEllipse>& named = named_scenes[size] = namedScene(scene);
    using Check = SceneCheckResult (*)(const std::vector<NamedEllipse>&, const SceneRules&,
                                       const std::set<std::string>&);
    struct Variant {
      const char* name;
      double warning_distance;
      Check check;
    };
    for (const Variant& variant :
         {Variant{"checkScene", 0.0, checkScene},
          Variant{"checkScene_warn", 0.1, checkScene}}) {
      const char* name = variant.name;
      const Check check_scene = variant.check;
      SceneRules rules;  // self collision on, as in the other methods
      rules.warning_distance = variant.warning_distance;
      const SceneCheckResult check = check_scene(named, rules, {});
      if (!check.ok() || static_cast<long>(check.collisions.size()) != collisions) {
        std::fprintf(stderr, "%s finds %zu collisions with %d obstacles, brute force %ld %s\n",
                     name, check.collisions.size(), obstacles, collisions, check.error.c_str());
        return 1;
      }
      const std::string label = family + name + "/" + std::to_string(obstacles);
      benchmark::RegisterBenchmark(label.c_str(), [&named, rules, check, check_scene](
                                                      benchmark::State& state) {
        for (auto _ : state) benchmark::DoNotOptimize(check_scene(named, rules, {}));
        state.counters["pair_tests"] = static_cast<double>(check.pair_tests);
        state.counters["collisions"] = static_cast<double>(check.collisions.size());
        state.counters["warnings"] = static_cast<double>(check.warnings.size());
      })->Unit(benchmark::kMicrosecond);
    }

    // The node's scene when its obstacles move: stored by column, links first, vouched for, each
    // role in the name order of the node's registry (a std::map), as its placing order has them.
    static std::map<int, Scene> column_scenes;
    const Scene& columns = column_scenes[size] = Scene(scene_test::inRegistryOrder(named));
    const SceneCheckResult vouched = checkValidatedScene(columns, kLinks, SceneRules{});
    if (!vouched.ok() || static_cast<long>(vouched.collisions.size()) != collisions) {
      std::fprintf(stderr, "checkValidatedScene finds %zu collisions with %d obstacles, brute force %ld %s\n",
                   vouched.collisions.size(), obstacles, collisions, vouched.error.c_str());
      return 1;
    }
    benchmark::RegisterBenchmark(
        (family + "checkScene_vouched/" + std::to_string(obstacles)).c_str(),
        [&columns, vouched](benchmark::State& state) {
          for (auto _ : state) {
            benchmark::DoNotOptimize(checkValidatedScene(columns, kLinks, SceneRules{}));
          }
          state.counters["pair_tests"] = static_cast<double>(vouched.pair_tests);
          state.counters["collisions"] = static_cast<double>(vouched.collisions.size());
          state.counters["warnings"] = 0.0;
        })
        ->Unit(benchmark::kMicrosecond);

    // The obstacles gridded once; movers are the links.
    std::vector<NamedEllipse> movers(named.begin(), named.begin() + kLinks);
    std::vector<NamedEllipse> obstacle_entries(named.begin() + kLinks, named.end());
    static std::map<int, IndexedObstacles> indexes;
    static std::map<int, std::vector<NamedEllipse>> mover_sets;
    const IndexedObstacles& index = indexes[size] = IndexedObstacles(obstacle_entries);
    const std::vector<NamedEllipse>& link_set = mover_sets[size] = movers;
    const SceneCheckResult indexed = checkMoversAgainst(link_set, index, SceneRules{});
    if (!indexed.ok() || static_cast<long>(indexed.collisions.size()) != collisions) {
      std::fprintf(stderr, "indexed_obstacles finds %zu collisions with %d obstacles, brute force %ld %s\n",
                   indexed.collisions.size(), obstacles, collisions, indexed.error.c_str());
      return 1;
    }
    benchmark::RegisterBenchmark(
        (family + "indexed_obstacles/" + std::to_string(obstacles)).c_str(),
        [&link_set, &index, indexed](benchmark::State& state) {
          for (auto _ : state) benchmark::DoNotOptimize(checkMoversAgainst(link_set, index, SceneRules{}));
          state.counters["pair_tests"] = static_cast<double>(indexed.pair_tests);
          state.counters["collisions"] = static_cast<double>(indexed.collisions.size());
        })
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(
        (family + "indexed_build/" + std::to_string(obstacles)).c_str(),
        [obstacle_entries](benchmark::State& state) {
          for (auto _ : state) benchmark::DoNotOptimize(IndexedObstacles(obstacle_entries));
        })
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

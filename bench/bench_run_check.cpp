// One check of the application layer (app::runCheck()), as the node's ~check_collisions and
// periodic check run it: the stored ellipses placed (through the PlacementCache, as the node keeps
// it between checks, handing back the placement of the check it replaces), the scene checked by
// the core, the answer collected: the node's own work per call without ROS.
//   cached        ten links and N obstacles, all in the fixed frame (as bench_service_roundtrip
//                 stores them): nothing moves
//   moving_links  the same with the links on a base that moves every check among the obstacles
//   core_only     checkValidatedScene() alone on the placed scene of `cached`, streamed
//   topic_message what the node does with one ~obstacles message of N obstacles that moved a few
//                 millimetres since the last one (a perception stream): validateAttached() and
//                 EllipseRegistry::replaceTopicObstacles(), the message already converted
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/placement_cache.h"
#include "ellipse_collision/core/scene_check.h"
#include "floor_obstacles.h"

namespace ellipse_collision::app {
namespace {

// The links of bench/service_roundtrip.yaml: a small mobile manipulator about the origin.
std::vector<EllipseSpec> links(const std::string& frame) {
  struct Link {
    const char* name;
    double x, y, angle, radius_x, radius_y;
  };
  const Link table[] = {
      {"base", 0.0, 0.0, 0.0, 0.5, 0.35},         {"mast", -0.2, 0.0, 0.0, 0.15, 0.15},
      {"shoulder", 0.3, 0.1, 0.3, 0.2, 0.1},      {"upper_arm", 0.6, 0.2, 0.3, 0.35, 0.08},
      {"elbow", 0.9, 0.3, 0.0, 0.1, 0.1},         {"forearm", 1.1, 0.2, -0.5, 0.3, 0.07},
      {"wrist", 1.3, 0.05, 0.0, 0.08, 0.08},      {"hand", 1.45, 0.0, 0.0, 0.15, 0.06},
      {"left_wheel", 0.0, 0.4, 0.0, 0.15, 0.05}, {"right_wheel", 0.0, -0.4, 0.0, 0.15, 0.05},
  };
  std::vector<EllipseSpec> specs;
  for (const Link& link : table) {
    EllipseSpec spec;
    spec.name = link.name;
    spec.frame_id = frame;
    spec.x = link.x;
    spec.y = link.y;
    spec.angle = link.angle;
    spec.radius_x = link.radius_x;
    spec.radius_y = link.radius_y;
    specs.push_back(spec);
  }
  return specs;
}

// Obstacles as bench_service_roundtrip adds them: over a 20 m x 20 m floor about the links.
std::vector<EllipseSpec> obstacles(int count) {
  return bench::floorObstacleSpecs(count, 10.0, 0.0, 11, "map");
}

CheckSettings settings() {
  CheckSettings settings;
  settings.fixed_frame = "map";
  settings.rules.warning_distance = 0.1;
  return settings;
}

FrameTransform fixedFrame(const std::string& frame) {
  FrameTransform transform;
  transform.ok = frame == "map";
  if (!transform.ok) transform.error = "unknown frame";
  return transform;
}

/// The links' frame driving around the map: a new pose every check.
struct MovingBase {
  int step{0};
  FrameTransform operator()(const std::string& frame) const {
    if (frame != "base_link") return fixedFrame(frame);
    FrameTransform transform;
    transform.ok = true;
    // Back and forth about the origin, among the obstacles.
    transform.fixed_from_frame.translate(
        Eigen::Vector3d(std::sin(0.01 * step), 0.5 * std::cos(0.013 * step), 0.0));
    transform.fixed_from_frame.rotate(Eigen::AngleAxisd(0.02 * step, Eigen::Vector3d::UnitZ()));
    return transform;
  }
};

/// runCheck as the node runs it, the replaced check's placement handed back to the cache.
void runLikeTheNode(benchmark::State& state, const EllipseRegistry& registry,
                    const CheckSettings& settings, PlacementCache* cache, MovingBase* base) {
  CheckOutcome previous;
  for (auto _ : state) {
    if (base) ++base->step;
    CheckOutcome outcome =
        base ? runCheck({}, registry, settings, TransformLookup(*base), 0.0, cache)
             : runCheck({}, registry, settings, fixedFrame, 0.0, cache);
    benchmark::DoNotOptimize(outcome);
    cache->recycle(std::move(previous.placed));
    previous = std::move(outcome);
  }
}

void registerSize(int count) {
  // Kept for the whole run: the benchmarks hold references.
  auto* registry = new EllipseRegistry(links("map"), obstacles(count));
  const CheckSettings* check_settings = new CheckSettings(settings());
  auto* cache = new PlacementCache;
  const CheckOutcome first = runCheck({}, *registry, *check_settings, fixedFrame, 0.0, cache);
  if (!first.error.empty()) {
    std::fprintf(stderr, "runCheck failed: %s\n", first.error.c_str());
    std::exit(1);
  }
  const std::string size = std::to_string(count + 10);
  benchmark::RegisterBenchmark(("run_check/cached/" + size).c_str(), [=](benchmark::State& state) {
    runLikeTheNode(state, *registry, *check_settings, cache, nullptr);
    state.counters["collisions"] = static_cast<double>(first.collisions.size());
    state.counters["warnings"] = static_cast<double>(first.warnings.size());
  })->Unit(benchmark::kMicrosecond);
  // The same scene with the links on a base that moves every check: the links are projected
  // again, the obstacles stand still.
  auto* moving_registry = new EllipseRegistry(links("base_link"), obstacles(count));
  auto* moving_cache = new PlacementCache;
  auto* base = new MovingBase;
  benchmark::RegisterBenchmark(("run_check/moving_links/" + size).c_str(),
                               [=](benchmark::State& state) {
                                 runLikeTheNode(state, *moving_registry, *check_settings,
                                                moving_cache, base);
                               })
      ->Unit(benchmark::kMicrosecond);
  auto* placed = new core::Scene(first.placed);
  std::size_t first_obstacle = 0;
  while (first_obstacle < placed->size() &&
         placed->role(first_obstacle) != core::EllipseRole::Obstacle) {
    ++first_obstacle;
  }
  benchmark::RegisterBenchmark(("run_check/core_only/" + size).c_str(),
                               [=](benchmark::State& state) {
                                 for (auto _ : state) {
                                   benchmark::DoNotOptimize(core::checkValidatedScene(
                                       *placed, first_obstacle, check_settings->rules));
                                 }
                               })
      ->Unit(benchmark::kMicrosecond);
}

void registerTopicMessage(int count) {
  // Two messages of the same names, alternating, as bench/node_load.py streams them.
  auto* messages = new std::vector<std::vector<EllipseSpec>>(2, obstacles(count));
  for (EllipseSpec& spec : (*messages)[1]) {
    spec.x += 0.003;
    spec.y -= 0.002;
  }
  auto* registry = new EllipseRegistry(links("map"), {},
                                       RegistryLimits{static_cast<std::size_t>(count), 256});
  const CheckSettings* check_settings = new CheckSettings(settings());
  benchmark::RegisterBenchmark(
      ("topic_message/" + std::to_string(count)).c_str(), [=](benchmark::State& state) {
        std::size_t sent = 0;
        for (auto _ : state) {
          const std::vector<EllipseSpec>& message = (*messages)[sent++ % 2];
          std::string error = validateAttached(message, "ellipses", *check_settings, fixedFrame);
          if (error.empty()) error = registry->replaceTopicObstacles(message, "ellipses", 1.0);
          if (!error.empty()) {
            state.SkipWithError(error.c_str());
            break;
          }
        }
      })
      ->Unit(benchmark::kMillisecond);
}

}  // namespace
}  // namespace ellipse_collision::app

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const int count : {90, 990, 9990}) ellipse_collision::app::registerSize(count);
  for (const int count : {10000, 100000}) ellipse_collision::app::registerTopicMessage(count);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

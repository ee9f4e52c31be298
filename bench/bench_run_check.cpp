// One check of the application layer (app::runCheck()), as the node's ~check_collisions and
// periodic check run it: the stored ellipses placed (through the PlacementCache, as the node keeps
// it between checks), the scene checked by the core, the answer collected. Ten links and N
// obstacles, all in the fixed frame as bench_service_roundtrip stores them, so that this is the
// node's own work per call without ROS. Beside it, the core's checkSceneOfUniqueNames() alone on
// the same placed scene: the difference is what placing and collecting cost.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_check.h"
#include "ellipse_collision/app/ellipse_registry.h"
#include "ellipse_collision/app/placement_cache.h"
#include "ellipse_collision/core/scene_check.h"

namespace ellipse_collision::app {
namespace {

// The links of bench/service_roundtrip.yaml: a small mobile manipulator about the origin.
std::vector<EllipseSpec> links() {
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
    spec.frame_id = "map";
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
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> position(-10.0, 10.0), radius(0.05, 0.4),
      angle(-3.1, 3.1);
  std::vector<EllipseSpec> specs;
  for (int i = 0; i < count; ++i) {
    EllipseSpec spec;
    spec.name = "obstacle_" + std::to_string(i);
    spec.frame_id = "map";
    spec.x = position(rng);
    spec.y = position(rng);
    spec.angle = angle(rng);
    spec.radius_x = radius(rng);
    spec.radius_y = spec.radius_x * 0.5;
    specs.push_back(spec);
  }
  return specs;
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

void registerSize(int count) {
  // Kept for the whole run: the benchmarks hold references.
  auto* registry = new EllipseRegistry(links(), obstacles(count));
  const CheckSettings* check_settings = new CheckSettings(settings());
  auto* cache = new PlacementCache;
  const CheckOutcome first = runCheck({}, *registry, *check_settings, fixedFrame, 0.0, cache);
  if (!first.error.empty()) {
    std::fprintf(stderr, "runCheck failed: %s\n", first.error.c_str());
    std::exit(1);
  }
  const std::string size = std::to_string(count + 10);
  benchmark::RegisterBenchmark(("run_check/cached/" + size).c_str(), [=](benchmark::State& state) {
    // As the node does: the replaced check's placement goes back to the cache.
    CheckOutcome previous;
    for (auto _ : state) {
      CheckOutcome outcome = runCheck({}, *registry, *check_settings, fixedFrame, 0.0, cache);
      benchmark::DoNotOptimize(outcome);
      cache->recycle(std::move(previous.placed));
      previous = std::move(outcome);
    }
    state.counters["collisions"] = static_cast<double>(first.collisions.size());
    state.counters["warnings"] = static_cast<double>(first.warnings.size());
  })->Unit(benchmark::kMicrosecond);
  auto* placed = new std::vector<core::NamedEllipse>(first.placed);
  benchmark::RegisterBenchmark(("run_check/core_only/" + size).c_str(),
                               [=](benchmark::State& state) {
                                 for (auto _ : state) {
                                   benchmark::DoNotOptimize(core::checkSceneOfUniqueNames(
                                       *placed, check_settings->rules));
                                 }
                               })
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace
}  // namespace ellipse_collision::app

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const int count : {90, 990, 9990}) ellipse_collision::app::registerSize(count);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

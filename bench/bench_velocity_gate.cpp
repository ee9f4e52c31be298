// The velocity gate (core::gateTwist()) for one command: a 20-link base (ringBase()) driving at
// 0.5 m/s and turning at 0.3 rad/s, horizon 3 s, among 1,000 / 10,000 / 100,000 obstacles scattered
// at one per 4 m^2 (so a few are within reach whatever their number), all standing or 10 % moving;
// or, `crowded`, all on 20 m x 20 m (25 per m^2 at 10,000: hundreds within reach of each link).
// Target: p99 well under 1 ms at 10,000 obstacles. Counters: p50 and p99 of the call [us], pair
// tests, and the scale the gate chose (the scenes are built so that it slows).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "bench_scenes.h"
#include "ellipse_collision/core/velocity_gate.h"

namespace ellipse_collision::core::bench {
namespace {

constexpr int kLinks = 20;

PathScene makeScene(int obstacles, bool moving, bool crowded) {
  std::mt19937 rng(27);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PathScene scene;
  scene.links = ringBase(kLinks, rng);
  const double side = crowded ? 20.0 : 2.0 * std::sqrt(static_cast<double>(obstacles));
  while (static_cast<int>(scene.obstacles.size()) < obstacles) {
    Ellipse e;
    e.center = {side * (u(rng) - 0.5), side * (u(rng) - 0.5)};
    if (e.center.norm() < 1.2) continue;  // none in contact now
    e.radius_x = 0.1 + 0.3 * u(rng);
    e.radius_y = 0.05 + 0.1 * u(rng);
    e.angle = M_PI * u(rng);
    Motion m;
    if (moving && u(rng) < 0.1) m.velocity = {u(rng) - 0.5, u(rng) - 0.5};
    scene.obstacles.push_back(
        {"obstacle" + std::to_string(scene.obstacles.size()), EllipseRole::Obstacle, e});
    scene.obstacle_motions.push_back(m);
  }
  // One wall ahead, so that the command is slowed.
  Ellipse wall;
  wall.center = {1.3, 0.5};
  wall.radius_x = 0.05;
  wall.radius_y = 1.0;
  scene.obstacles.push_back({"wall", EllipseRole::Obstacle, wall});
  scene.obstacle_motions.push_back({});
  return scene;
}

void BM_GateCommand(benchmark::State& state) {
  const PathScene scene =
      makeScene(static_cast<int>(state.range(0)), state.range(1) != 0, state.range(2) != 0);
  const Twist twist{0.5, 0.0, 0.3};
  GateSettings settings;
  settings.horizon = 3.0;
  settings.time_before_collision = 2.0;
  settings.stop_time = 0.3;
  settings.margin = 0.05;
  settings.resolution = 0.01;
  std::vector<double> times;
  GateResult result;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    result = gateTwist(scene, twist, settings);
    const auto end = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(result);
    times.push_back(std::chrono::duration<double, std::micro>(end - start).count());
  }
  std::sort(times.begin(), times.end());
  state.counters["p50_us"] = times[times.size() / 2];
  state.counters["p99_us"] = times[times.size() * 99 / 100];
  state.counters["pair_tests"] = static_cast<double>(result.pair_tests);
  state.counters["scale"] = result.scale;
}

BENCHMARK(BM_GateCommand)
    ->ArgNames({"obstacles", "moving", "crowded"})
    ->Args({1000, 0, 0})
    ->Args({10000, 0, 0})
    ->Args({100000, 0, 0})
    ->Args({1000, 1, 0})
    ->Args({10000, 1, 0})
    ->Args({100000, 1, 0})
    ->Args({1000, 0, 1})
    ->Args({10000, 0, 1})
    ->Args({100000, 0, 1})
    ->Args({1000, 1, 1})
    ->Args({10000, 1, 1})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace ellipse_collision::core::bench

BENCHMARK_MAIN();

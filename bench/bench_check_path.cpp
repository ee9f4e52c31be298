// Continuous path checks (core::checkPath()) at the size: 10,000 poses of a base with 20
// links against 1,000 obstacles, every segment checked continuously (swept boxes through the
// grid, segmentContact() on the candidates) and the minimum clearance measured at every pose.
// The obstacles line a 1 km corridor that the path follows without touching them (the worst case:
// no early stop at a contact), plus a variant where the corridor narrows so that the path meets
// an obstacle near its end, and a timed variant where 10 % of the obstacles move (along the
// corridor, so the whole path is checked). Budget: 100 ms
// for the full check (issue 14). Counters: pair tests done, segments, whether a contact was found.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "bench_scenes.h"
#include "ellipse_collision/core/path_check.h"

namespace ellipse_collision::core::bench {
namespace {

constexpr int kPoses = 10000;
constexpr int kObstacles = 1000;
constexpr int kLinks = 20;
constexpr double kSpacing = 0.1;  // [m] between poses: a 1 km path

struct Problem {
  PathScene scene;
  std::vector<PathPose> poses;
};

// Links: ringBase(), 20 of them. Path: along x with a gentle weave (yaw follows the heading), 1 s
// per 1 m. Obstacles: along both sides of the corridor, 1.2 to 4 m from its centre line.
Problem makeProblem(bool blocked, bool moving) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Problem p;
  p.scene.links = ringBase(kLinks, rng);
  const auto centreLine = [](double x) { return 0.3 * std::sin(x / 15.0); };
  for (int k = 0; k < kPoses; ++k) {
    const double x = k * kSpacing;
    const double slope = 0.3 / 15.0 * std::cos(x / 15.0);
    p.poses.push_back({x, centreLine(x), std::atan(slope), moving ? x : 0.0});
  }
  const double length = (kPoses - 1) * kSpacing;
  for (int i = 0; i < kObstacles; ++i) {
    Ellipse e;
    const double x = length * u(rng);
    const double side = (i % 2 == 0) ? 1.0 : -1.0;
    e.center = {x, centreLine(x) + side * (1.2 + 2.8 * u(rng))};
    e.radius_x = 0.1 + 0.3 * u(rng);
    e.radius_y = 0.05 + 0.1 * u(rng);
    e.angle = M_PI * u(rng);
    Motion m;
    // Moving ones drift along the corridor (up to 0.5 m/s) and turn: they never cross the path.
    if (moving && i % 10 == 0) m = Motion{{u(rng) - 0.5, 0.0}, 0.4 * (u(rng) - 0.5)};
    p.scene.obstacles.push_back({"obstacle" + std::to_string(i), EllipseRole::Obstacle, e});
    p.scene.obstacle_motions.push_back(m);
  }
  if (blocked) {
    Ellipse wall;
    wall.center = {0.9 * length, centreLine(0.9 * length)};
    wall.radius_x = 0.02;
    wall.radius_y = 0.5;
    p.scene.obstacles.back().ellipse = wall;
    p.scene.obstacle_motions.back() = Motion{};
  }
  return p;
}

void run(benchmark::State& state, bool blocked, bool moving) {
  const Problem p = makeProblem(blocked, moving);
  PathCheckResult result;
  for (auto _ : state) {
    result = checkPath(p.scene, p.poses, moving);
    benchmark::DoNotOptimize(result);
  }
  if (!result.ok()) state.SkipWithError(result.error.c_str());
  state.counters["pair_tests"] = static_cast<double>(result.pair_tests);
  state.counters["contact"] = result.collision_free ? 0.0 : 1.0;
  state.counters["contact_segment"] = static_cast<double>(result.segment);
  state.counters["min_clearance_m"] = result.min_clearance;
}

void BM_CheckPath_10kPoses_1kObstacles_20Links_Clear(benchmark::State& state) {
  run(state, false, false);
}
void BM_CheckPath_10kPoses_1kObstacles_20Links_ContactAt90pc(benchmark::State& state) {
  run(state, true, false);
}
void BM_CheckPath_10kPoses_1kObstacles_20Links_Timed10pcMoving(benchmark::State& state) {
  run(state, false, true);
}

BENCHMARK(BM_CheckPath_10kPoses_1kObstacles_20Links_Clear)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckPath_10kPoses_1kObstacles_20Links_ContactAt90pc)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckPath_10kPoses_1kObstacles_20Links_Timed10pcMoving)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace ellipse_collision::core::bench

BENCHMARK_MAIN();

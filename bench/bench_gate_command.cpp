// Command in to command out without ROS: app::CollisionMonitor::gateCommand(), what the node does
// in its ~cmd_vel_in callback (a full check at the latest transforms through the placement cache,
// the robot placed, core::gateTwist()), for 20 links on a base that moves every command among N
// standing obstacles. Two floors: `warehouse`, one obstacle per 4 m^2 (a 200 m x 200 m floor at
// 10,000), a few within the robot's reach; `crowded`, all N on 20 m x 20 m as bench_run_check
// places them (25 per m^2 at 10,000: hundreds within reach, every command slowed). The command
// turns (0.8 m/s, 0.3 rad/s), so every near pair takes the certified turning first contact.
// `*_braking`: the same with the braking rule on (a base 0.1 s late braking at 0.8 m/s^2).
// `*_no_recorder`: the same with the incident recorder off (incident/enabled: false), for its cost
// side by side; `recorderMemory`: the heap the recorder's ring buffer holds after 10 s of commands
// at 20 Hz (incident/before 10 s) among N standing obstacles.
// Reports the median and the 99th percentile of the per-command latency (counters p50_us, p99_us)
// besides Google Benchmark's mean.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "ellipse_collision/app/collision_monitor.h"
#include "floor_obstacles.h"

namespace ellipse_collision::app {
namespace {

/// 20 links: a mobile manipulator's base, wheels, mast and two arms, about base_link's origin.
std::vector<EllipseSpec> links() {
  std::vector<EllipseSpec> specs;
  for (int i = 0; i < 20; ++i) {
    EllipseSpec spec;
    spec.name = "link_" + std::to_string(i);
    spec.frame_id = "base_link";
    const double a = 2.0 * M_PI * i / 20.0;
    spec.x = 0.3 * std::cos(a);
    spec.y = 0.2 * std::sin(a);
    spec.angle = a;
    spec.radius_x = 0.12;
    spec.radius_y = 0.05;
    specs.push_back(spec);
  }
  return specs;
}

/// `count` standing obstacles in map, a clearing of 1.5 m about the robot's track.
std::vector<EllipseSpec> obstacles(int count, double half_side) {
  return bench::floorObstacleSpecs(count, half_side, 1.5, 11, "map");
}

/// base_link driving slowly about the origin: a new pose for every command.
struct MovingBase {
  int step{0};
  FrameTransform operator()(const std::string& frame) const {
    FrameTransform transform;
    transform.ok = frame == "map" || frame == "base_link";
    if (!transform.ok) {
      transform.error = "unknown frame";
      return transform;
    }
    if (frame == "base_link") {
      transform.fixed_from_frame.translate(
          Eigen::Vector3d(0.3 * std::sin(0.01 * step), 0.3 * std::cos(0.013 * step), 0.0));
      transform.fixed_from_frame.rotate(Eigen::AngleAxisd(0.02 * step, Eigen::Vector3d::UnitZ()));
    }
    return transform;
  }
};

void gateCommands(benchmark::State& state, bool crowded, bool braking = false,
                  bool recorder = true) {
  MonitorSettings settings;
  settings.incident.enabled = recorder;
  settings.check.fixed_frame = "map";
  settings.gate.enabled = true;
  // A real base (0.1 s late, 0.8 m/s^2, 2 rad/s^2): the braking rule on every command.
  if (braking) settings.gate.base = {0.1, 0.8, 2.0};
  settings.gate.timing.horizon = 3.0;
  settings.gate.timing.time_before_collision = 1.5;
  CollisionMonitor monitor(settings, links(), obstacles(static_cast<int>(state.range(0)),
                                                     crowded ? 10.0 : std::sqrt(state.range(0))),
                           {}, {});
  MovingBase base;
  const TransformAtLookup at = [](const std::string&, double) { return FrameTransform(); };
  VelocityCommand command;
  command.linear.x() = 0.8;
  command.angular.z() = 0.3;
  std::vector<double> latencies_us;
  std::size_t slowed = 0;
  for (auto _ : state) {
    ++base.step;
    const auto start = std::chrono::steady_clock::now();
    const GateDecision decision =
        monitor.gateCommand(command, 1.0 + 0.05 * base.step, TransformLookup(base), at);
    latencies_us.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count());
    slowed += decision.scale < 1.0;
    benchmark::DoNotOptimize(decision);
  }
  std::sort(latencies_us.begin(), latencies_us.end());
  const auto quantile = [&](double q) {
    return latencies_us[std::min(latencies_us.size() - 1,
                                 static_cast<std::size_t>(q * latencies_us.size()))];
  };
  state.counters["p50_us"] = quantile(0.5);
  state.counters["p99_us"] = quantile(0.99);
  state.counters["slowed_share"] = static_cast<double>(slowed) / latencies_us.size();
}

/// The heap the monitor holds after 200 commands 0.05 s apart, with the recorder on, less the
/// same with it off [kB] (malloc's bytes in use).
void recorderMemory(benchmark::State& state) {
  const auto heapAfterCommands = [&](bool recorder) {
    const std::size_t before = mallinfo2().uordblks;
    MonitorSettings settings;
    settings.check.fixed_frame = "map";
    settings.gate.enabled = true;
    settings.incident.enabled = recorder;
    settings.incident.before_s = 10.0;
    CollisionMonitor monitor(settings, links(),
                             obstacles(static_cast<int>(state.range(0)), std::sqrt(state.range(0))),
                             {}, {});
    MovingBase base;
    const TransformAtLookup at = [](const std::string&, double) { return FrameTransform(); };
    VelocityCommand command;
    command.linear.x() = 0.8;
    command.angular.z() = 0.3;
    for (int i = 0; i < 200; ++i) {
      ++base.step;
      monitor.gateCommand(command, 1.0 + 0.05 * base.step, TransformLookup(base), at);
    }
    if (recorder) {
      state.counters["buffered_decisions"] =
          static_cast<double>(monitor.incidents().bufferedDecisions());
    }
    return static_cast<double>(mallinfo2().uordblks) - static_cast<double>(before);
  };
  double kb = 0.0;
  for (auto _ : state) kb = (heapAfterCommands(true) - heapAfterCommands(false)) / 1024.0;
  state.counters["ring_buffer_kb"] = kb;
}

BENCHMARK_CAPTURE(gateCommands, warehouse, false)
    ->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(gateCommands, warehouse_no_recorder, false, false, false)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(gateCommands, crowded, true)
    ->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(gateCommands, crowded_no_recorder, true, false, false)
    ->Arg(1000)
    ->Arg(10000)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(recorderMemory)->Arg(10000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(gateCommands, warehouse_braking, false, true)
    ->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(gateCommands, crowded_braking, true, true)
    ->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace ellipse_collision::app

BENCHMARK_MAIN();

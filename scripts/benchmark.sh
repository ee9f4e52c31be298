#!/usr/bin/env bash
# Builds the collision benchmarks in build/ws (-DELLIPSE_COLLISION_BENCHMARKS=ON), runs them and
# prints one table: per pair mix (scene-like: 50 links each against the same 40 obstacles; near;
# near-tangent; 20,000 independent random pairs in a 20 m square, about 1 % overlapping; one
# ellipse against 1,000 and 10,000 in one batch call) each method's ns per pair, its
# speed relative to FCL 0.7 and its misclassifications against the quad-precision oracle; the
# polygonal iteration-cap study; then scene checks of 50 links against 100 to 100,000 obstacles
# and against 2,000 crowded into 4 m x 4 m
# (us per cycle, pair tests done, growth with N); scan_obstacles' cost per 720-beam LaserScan;
# continuous path checks of 10,000 poses x 1,000 obstacles x 20 links (issue 14, budget 100 ms);
# one app::runCheck with the node's cache (the node's own work per call); from Python, the
# bindings' overlap_batch of 1,000,000 pairs beside shapely 64-gons (time and misclassifications
# near tangency against a 40-digit oracle). Times are CPU times,
# medians of repetitions interleaved at random, so that the methods share the machine's noise
# within one run.
# Last, the service round trip (issue 7): a roscore of its own on a free port, the node with
# bench/service_roundtrip.yaml, and bench_service_roundtrip calling ~check_collisions 10,000 times
# with 100 and 1,000 ellipses stored (p50/p99 latency, calls per second, wall time), in alternating
# blocks with an empty std_srvs/Trigger service (the ROS floor; p50 ratio, goal <= 1.5). Both are
# stopped at the end, on failure and on Ctrl-C. Then the node as a user runs it
# (scripts/node_load.sh): 20 moving links, N obstacles, a ~markers subscriber; CPU % and RSS. And
# the scan pipeline as separate processes against nodelets in one manager (scripts/nodelet_cpu.sh),
# the obstacle sources inside the node (scripts/nodelet_cpu.sh --sources), and a fleet of N
# robots on one master (scripts/fleet_load.sh).
#
#   scripts/benchmark.sh                 full run (a few minutes)
#   scripts/benchmark.sh --smoke         every benchmark once, briefly, on few pairs, 200 service
#                                        calls (for CI)
#   scripts/benchmark.sh --pairs         the pair tests alone (bench_pair_tests and its table, about
#                                        3 minutes; with --smoke, briefly)
#
# The raw output (Google Benchmark console and JSON, round trip, roscore and node logs) is kept
# in build/benchmark/.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=script_helpers.sh
source "${repo}/scripts/script_helpers.sh"
smoke=false
pairs_only=false
for arg in "$@"; do
  case "${arg}" in
    --smoke) smoke=true ;;
    --pairs) pairs_only=true ;;
    *) echo "usage: $0 [--smoke] [--pairs]" >&2; exit 2 ;;
  esac
done

out="${repo}/build/benchmark"
mkdir -p "${out}"
echo "Building the benchmarks (log: build/benchmark/build.txt)"
# --force-cmake: catkin_make runs CMake only when its arguments change, and the option is switched
# off again below, behind its back.
targets=(bench_pair_tests)
if ! "${pairs_only}"; then
  targets+=(bench_scene_check bench_distance bench_first_contact bench_scan_obstacles
            bench_service_roundtrip bench_check_path bench_run_check bench_velocity_gate
            bench_gate_command bench_gate_roundtrip ellipse_collision_node
            ellipse_collision_python_core)
fi
if ! bash "${repo}/scripts/build.sh" --force-cmake -DELLIPSE_COLLISION_BENCHMARKS=ON \
    "${targets[@]}" > "${out}/build.txt" 2>&1; then
  cat "${out}/build.txt" >&2
  exit 1
fi
# The option stays in the workspace's CMake cache: switch it off again (the programs just built
# stay), so that the next scripts/build.sh does not build every benchmark as well.
cmake -DELLIPSE_COLLISION_BENCHMARKS=OFF "${repo}/build/ws/build" >> "${out}/build.txt" 2>&1
bin="${repo}/build/ws/devel/lib/ellipse_collision"
if "${smoke}"; then
  pair_args=(--pairs_per_mix=64 --random_pairs=640 --one_to_many=32,320
             --benchmark_min_time=0.01)
  scene_args=(--benchmark_min_time=0.01)
  distance_args=(--benchmark_min_time=0.01)
  contact_args=(--pairs=64 --benchmark_min_time=0.01)
  scan_args=(--benchmark_min_time=0.01)
  path_args=(--benchmark_min_time=0.01)
  run_check_args=(--benchmark_min_time=0.01)
  gate_args=(--benchmark_min_time=0.01)
  roundtrip_calls=200
  gate_roundtrip_args=(--commands 100 --sizes 1000)
  python_args=(--pairs 10000 --repetitions 1 --tangent-pairs 5)
else
  repeat=(--benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
          --benchmark_report_aggregates_only=true)
  pair_args=(--pairs_per_mix=2000 --random_pairs=20000 --one_to_many=1000,10000
             --benchmark_min_time=0.3 "${repeat[@]}")
  scene_args=(--benchmark_min_time=0.3 "${repeat[@]}")
  distance_args=(--benchmark_min_time=0.3 "${repeat[@]}")
  contact_args=(--pairs=5000 --benchmark_min_time=0.3 "${repeat[@]}")
  scan_args=(--benchmark_min_time=0.5 "${repeat[@]}")
  path_args=(--benchmark_min_time=0.5 "${repeat[@]}")
  run_check_args=(--benchmark_min_time=0.3 "${repeat[@]}")
  gate_args=(--benchmark_min_time=0.3 "${repeat[@]}")
  roundtrip_calls=10000
  gate_roundtrip_args=(--commands 2000 --sizes 1000,10000,100000)
  python_args=(--pairs 1000000 --repetitions 5 --tangent-pairs 100)
fi

# Runs one benchmark program with its console output in build/benchmark/<name>.txt, shown only
# if the program fails.
run() {
  local name="$1"
  shift
  if ! "${bin}/${name}" "$@" --benchmark_out="${out}/${name}.json" --benchmark_out_format=json \
      > "${out}/${name}.txt" 2>&1; then
    cat "${out}/${name}.txt" >&2
    echo "${name} failed" >&2
    exit 1
  fi
}
if "${pairs_only}"; then
  echo "Running bench_pair_tests (output: build/benchmark/)"
  run bench_pair_tests "${pair_args[@]}"
  echo
  /usr/bin/python3 "${repo}/bench/benchmark_table.py" "${out}/bench_pair_tests.json"
  exit 0
fi
echo "Running bench_pair_tests and bench_scene_check (output: build/benchmark/)"
run bench_pair_tests "${pair_args[@]}"
run bench_scene_check "${scene_args[@]}"
echo

/usr/bin/python3 "${repo}/bench/benchmark_table.py" "${out}/bench_pair_tests.json" \
  "${out}/bench_scene_check.json"

# ---- distance() beside FCL's distance query, with accuracy against the quad rim oracle -----------
echo
echo "Running bench_distance (ns per pair; max/median relative error against the oracle)"
run bench_distance "${distance_args[@]}"
grep -E '^(Benchmark|BM_)' "${out}/bench_distance.txt" | grep -vE '_(mean|stddev|cv)( |$)' || true

# ---- firstContact() beside the secant method it replaced, FCL's continuousCollide and sampling --
# ---- and, for rotating pairs, beside the plain conservative advancement it replaced --------------
echo
echo "Running bench_first_contact (us per pair, new beside old, translating and rotating mixes;"
echo "misclassifications, time errors against the oracle, distance() calls and pairs at the step cap)"
run bench_first_contact "${contact_args[@]}"
grep -vE '_(mean|stddev|cv)( |$)|^(Run on|CPU|  L[123]|Load Average|\*\*\*)' "${out}/bench_first_contact.txt" \
  | grep -v '^-*$' || true

# ---- Python: overlap_batch beside shapely polygons, against the 40-digit oracle near tangency ----
echo
echo "Running bench/bench_python_overlap.py (the Python bindings beside shapely 64-gons; a few minutes,"
echo "about 4 GB for the million pairs' polygons)"
# In the workspace's environment, where `from ellipse_collision import core` finds the module
# (setup.bash reads unset variables: not under set -u).
if ! (set +u; source "${repo}/build/ws/devel/setup.bash" &&
      /usr/bin/python3 "${repo}/bench/bench_python_overlap.py" "${python_args[@]}") \
    2>&1 | tee "${out}/bench_python_overlap.txt"; then
  echo "bench_python_overlap.py failed" >&2
  exit 1
fi

# ---- scan_obstacles: 720-beam LaserScans and a 100,000-point cloud, the old path beside the new --
echo
echo "Running bench_scan_obstacles (us per message; % of one core at 40 Hz for scans, budget 2 %;"
echo "at 10 Hz for the cloud, budget 20 %)"
run bench_scan_obstacles "${scan_args[@]}"
grep -E '^(Benchmark|BM_)' "${out}/bench_scan_obstacles.txt" | grep -vE '_(stddev|cv)( |$)' || true

# ---- ~check_path's core: 10,000 poses x 1,000 obstacles x 20 links, budget 100 ms (issue 14) ----
echo
echo "Running bench_check_path (ms per path of 10,000 poses, 1,000 obstacles, 20 links; budget 100 ms)"
run bench_check_path "${path_args[@]}"
grep -E '^(Benchmark|BM_)' "${out}/bench_check_path.txt" | grep -vE '_(stddev|cv)( |$)' || true

# ---- one check of the application layer, the node's own work per ~check_collisions call -------
echo
echo "Running bench_run_check (us per app::runCheck with the node's cache, beside the core check alone;"
echo "ms per ~obstacles message of N obstacles, validated and stored)"
run bench_run_check "${run_check_args[@]}"
grep -E '^(Benchmark|run_check|topic_message)' "${out}/bench_run_check.txt" | grep -vE '_(stddev|cv)( |$)' || true

# ---- the velocity gate: the core decision, and command in to command out without ROS ------------
echo
echo "Running bench_velocity_gate (us per core::gateCommand, 20 links) and bench_gate_command"
echo "(us per app::CollisionMonitor::gateCommand: full check + gate; p50_us and p99_us per command)"
run bench_velocity_gate "${gate_args[@]}"
grep -E '^(Benchmark|BM_|gate)' "${out}/bench_velocity_gate.txt" | grep -vE '_(stddev|cv)( |$)' || true
run bench_gate_command "${gate_args[@]}"
grep -E '^(Benchmark|gateCommands)' "${out}/bench_gate_command.txt" | grep -vE '_(stddev|cv)( |$)' || true

# ---- service round trip (issue 7) ---------------------------------------------------------------
# Started here, stopped by the EXIT trap whatever ends the script: the node first, then roscore
# (which stops its rosmaster and rosout on SIGINT).
# shellcheck source=scripts/tracked_processes.sh
source "${repo}/scripts/tracked_processes.sh"

export PATH="/usr/bin:${PATH}"
port="$(free_port)"
export ROS_MASTER_URI="http://127.0.0.1:${port}" ROS_IP=127.0.0.1 ROS_LOG_DIR="${out}/ros_log"
echo
echo "Running bench_service_roundtrip against ellipse_collision_node (roscore on port ${port})"
start_roscore "${port}" "${out}/roscore.txt" || exit 1
rosparam load "${repo}/bench/service_roundtrip.yaml" /ellipse_collision
"${bin}/ellipse_collision_node" __name:=ellipse_collision > "${out}/node.txt" 2>&1 &
pids+=($!)
# The ROS floor (issue 16): an empty std_srvs/Trigger service in a process of its own.
"${bin}/bench_service_roundtrip" --serve-trigger /ros_floor __name:=ros_floor \
  > "${out}/ros_floor.txt" 2>&1 &
pids+=($!)
if ! "${bin}/bench_service_roundtrip" --calls "${roundtrip_calls}" --sizes 100,1000 \
    --node /ellipse_collision --trigger /ros_floor 2>&1 | tee "${out}/bench_service_roundtrip.txt"; then
  tail -n 20 "${out}/node.txt" >&2
  echo "bench_service_roundtrip failed" >&2
  exit 1
fi
stop_all

# ---- the velocity gate through ROS: ~cmd_vel_in -> ~cmd_vel_out, beside a plain relay ------------
echo
echo "Running bench_gate_roundtrip against ellipse_collision_node (20 links, a turning command;"
echo "goal: p99 under 1 ms at 10,000 obstacles)"
start_roscore "${port}" "${out}/roscore_gate.txt" || exit 1
rosparam load "${repo}/bench/gate_roundtrip.yaml" /ellipse_collision
"${bin}/ellipse_collision_node" __name:=ellipse_collision > "${out}/node_gate.txt" 2>&1 &
pids+=($!)
"${bin}/bench_gate_roundtrip" --relay /relay/in /relay/out __name:=relay \
  > "${out}/relay.txt" 2>&1 &
pids+=($!)
if ! "${bin}/bench_gate_roundtrip" "${gate_roundtrip_args[@]}" --node /ellipse_collision \
    --relay-in /relay/in --relay-out /relay/out 2>&1 | tee "${out}/bench_gate_roundtrip.txt"; then
  tail -n 20 "${out}/node_gate.txt" >&2
  echo "bench_gate_roundtrip failed" >&2
  exit 1
fi
stop_all

# ---- the node as a user runs it (issue 16) -------------------------------------------------------
# 20 links on tf frames moving at 30 Hz, N obstacles in `map`, warnings on, a ~markers subscriber:
# the node's CPU (% of one core) and RSS, by scripts/node_load.sh (roscore and node of its own).
echo
echo "Running the node under load (scripts/node_load.sh; goals: 10000@30 Hz < 10 % of a core and"
echo "RSS < 100 MB, 100000@10 Hz < 50 %)"
if "${smoke}"; then
  bash "${repo}/scripts/node_load.sh" --smoke
else
  bash "${repo}/scripts/node_load.sh"
fi
echo "Obstacles streamed on ~obstacles at 30 Hz (1,000; 200 with --smoke), the obstacle store on as by default:"
if "${smoke}"; then
  bash "${repo}/scripts/node_load.sh" --smoke --stream 30 --store
else
  bash "${repo}/scripts/node_load.sh" --runs "1000@30" --stream 30 --store
fi

# ---- the scan pipeline as separate processes and as nodelets in one manager -------------------------
# A 720-beam LaserScan at 40 Hz -> scan_obstacles -> the collision node, both ways alternating, by
# scripts/nodelet_cpu.sh (roscore and launch files of its own): CPU % of each process, medians.
echo
echo "Running the scan pipeline, separate processes against nodelets (scripts/nodelet_cpu.sh)"
if "${smoke}"; then
  bash "${repo}/scripts/nodelet_cpu.sh" --smoke
else
  bash "${repo}/scripts/nodelet_cpu.sh" --runs 3
fi

# ---- robots that see each other ---------------------------------------------------------------------
# N collision nodes of 20 links on one master, each publishing itself and taking the others in, by
# scripts/fleet_load.sh (roscore and nodes of its own): each node's CPU % and the footprint traffic.
echo
echo "Running a fleet on one master (scripts/fleet_load.sh)"
if "${smoke}"; then
  bash "${repo}/scripts/fleet_load.sh" --smoke
else
  bash "${repo}/scripts/fleet_load.sh" --robots "8 20" --runs 3 --alone
fi

# ---- the obstacle sources inside the collision node (issue 42) --------------------------------------
# One scan source with tracking; two scanners, a depth cloud and the gate; by scripts/nodelet_cpu.sh
# --sources: the node's CPU % (goals: one_scan < 2 % of a core, sensor_set < 15 %), medians.
echo
echo "Running the obstacle sources in the node (scripts/nodelet_cpu.sh --sources; goals: one_scan"
echo "< 2 % of a core, sensor_set < 15 %)"
if "${smoke}"; then
  bash "${repo}/scripts/nodelet_cpu.sh" --sources --smoke
else
  bash "${repo}/scripts/nodelet_cpu.sh" --sources --runs 3
fi

#!/usr/bin/env bash
# Builds the collision benchmarks in build/ws (-DELLIPSE_COLLISION_BENCHMARKS=ON), runs them and
# prints one table: per pair mix (scene-like, near, near-tangent) each method's ns per pair, its
# speed relative to FCL 0.7 and its misclassifications against the quad-precision oracle; the
# polygonal iteration-cap study; then scene checks of 50 links against 100 to 100,000 obstacles
# (us per cycle, pair tests done, growth with N). Times are CPU times, medians of repetitions
# interleaved at random, so that the methods share the machine's noise within one run.
#
#   scripts/benchmark.sh                 full run (a few minutes)
#   scripts/benchmark.sh --smoke         every benchmark once, briefly, on few pairs (for CI)
#
# The raw Google Benchmark output (console and JSON) is kept in build/benchmark/.
# TODO(issue 7): the service round-trip benchmark (CheckCollisions through the node) belongs here
# once src/ros provides the node; it is not measured yet.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
smoke=false
for arg in "$@"; do
  case "${arg}" in
    --smoke) smoke=true ;;
    *) echo "usage: $0 [--smoke]" >&2; exit 2 ;;
  esac
done

out="${repo}/build/benchmark"
mkdir -p "${out}"
echo "Building the benchmarks (log: build/benchmark/build.txt)"
if ! bash "${repo}/scripts/build.sh" -DELLIPSE_COLLISION_BENCHMARKS=ON bench_pair_tests \
    bench_scene_check > "${out}/build.txt" 2>&1; then
  cat "${out}/build.txt" >&2
  exit 1
fi
bin="${repo}/build/ws/devel/lib/ellipse_collision"
if "${smoke}"; then
  pair_args=(--pairs_per_mix=64 --benchmark_min_time=0.01)
  scene_args=(--benchmark_min_time=0.01)
else
  repeat=(--benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
          --benchmark_report_aggregates_only=true)
  pair_args=(--pairs_per_mix=2000 --benchmark_min_time=0.3 "${repeat[@]}")
  scene_args=(--benchmark_min_time=0.3 "${repeat[@]}")
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
echo "Running bench_pair_tests and bench_scene_check (output: build/benchmark/)"
run bench_pair_tests "${pair_args[@]}"
run bench_scene_check "${scene_args[@]}"
echo

/usr/bin/python3 "${repo}/bench/benchmark_table.py" "${out}/bench_pair_tests.json" \
  "${out}/bench_scene_check.json"

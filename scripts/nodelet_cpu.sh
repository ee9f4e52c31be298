#!/usr/bin/env bash
# Issue 33: the CPU of the scan pipeline (720-beam LaserScan at 40 Hz -> scan_obstacles -> obstacle
# ellipses -> the collision node's checks at 40 Hz), started by the package's launch files either
# as separate processes (launch/ellipse_collision.launch + launch/scan_obstacles.launch) or as
# nodelets in one manager (launch/scan_pipeline_nodelets.launch), the two alternating in one run on
# this machine. bench/scan_pipeline_load.py publishes the scans and measures each node's CPU
# (% of one core, from /proc/<pid>/stat). Prints one line per run, then the medians per mode.
#
#   scripts/nodelet_cpu.sh [--runs N] [--seconds S]   (default: 5 runs of each, 30 s windows)
#   scripts/nodelet_cpu.sh --smoke                    (1 run of each, 3 s: the script works)
#   scripts/nodelet_cpu.sh --threads N                (the manager's num_worker_threads; default 2)
#   scripts/nodelet_cpu.sh --sources                  (issue 42: the obstacle sources inside the
#       collision node alone, no scan_obstacles, alternating one_scan: one scan source with
#       tracking (bench/sources_one_scan.yaml) and sensor_set: two scanners, a 20,000-point cloud
#       at 15 Hz and the gate fed at 20 Hz (bench/sources_sensor_set.yaml))
#
# Measured nodes (their processes): separate: /ellipse_collision, /scan_obstacles and the config
# guard /ellipse_collision_config_check; nodelets: the same names (there the `nodelet load`
# processes) and /scan_pipeline_manager, which runs both nodelets.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=script_helpers.sh
source "${repo}/scripts/script_helpers.sh"
runs=5
seconds=30
warmup=5
threads=2
modes="separate nodelets"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --smoke) runs=1; seconds=3; warmup=1 ;;
    --runs) runs="$2"; shift ;;
    --seconds) seconds="$2"; shift ;;
    --threads) threads="$2"; shift ;;
    --sources) modes="one_scan sensor_set" ;;
    *) echo "usage: $0 [--smoke] [--runs N] [--seconds S] [--threads N] [--sources]" >&2; exit 2 ;;
  esac
  shift
done

out="${repo}/build/benchmark/nodelet_cpu"
mkdir -p "${out}"
: > "${out}/runs.txt"
export PATH="/usr/bin:${PATH}"
# shellcheck disable=SC1091
set +u  # the setup scripts read unset variables
source "${repo}/build/ws/devel/setup.bash"
set -u

# shellcheck source=scripts/tracked_processes.sh
source "${repo}/scripts/tracked_processes.sh"

config="${repo}/bench/scan_pipeline.yaml"
common=(/ellipse_collision /ellipse_collision_config_check /scan_obstacles)
for run in $(seq "${runs}"); do
  for mode in ${modes}; do
    port="$(free_port)"
    export ROS_MASTER_URI="http://127.0.0.1:${port}" ROS_IP=127.0.0.1 ROS_LOG_DIR="${out}/ros_log"
    start_roscore "${port}" "${out}/roscore.txt" || exit 1
    load=()
    if [[ "${mode}" == one_scan || "${mode}" == sensor_set ]]; then
      roslaunch ellipse_collision ellipse_collision.launch \
        config:="${repo}/bench/sources_${mode}.yaml" > "${out}/launch_collision.txt" 2>&1 &
      pids+=($!)
      nodes=(/ellipse_collision /ellipse_collision_config_check)
      load=(--scans /scan)
      if [[ "${mode}" == sensor_set ]]; then
        load=(--scans /front/scan /rear/scan --cloud /depth/points --gate-hz 20)
      fi
    elif [[ "${mode}" == separate ]]; then
      roslaunch ellipse_collision ellipse_collision.launch config:="${config}" \
        > "${out}/launch_collision.txt" 2>&1 &
      pids+=($!)
      roslaunch ellipse_collision scan_obstacles.launch scan:=/scan > "${out}/launch_scan.txt" 2>&1 &
      pids+=($!)
      nodes=("${common[@]}")
    else
      roslaunch ellipse_collision scan_pipeline_nodelets.launch config:="${config}" scan:=/scan \
        num_worker_threads:="${threads}" > "${out}/launch_nodelets.txt" 2>&1 &
      pids+=($!)
      nodes=("${common[@]}" /scan_pipeline_manager)
    fi
    # Every node registered before the measurement looks up its pid.
    for node in "${nodes[@]}"; do
      for _ in $(seq 150); do
        rosnode info "${node}" > /dev/null 2>&1 && break
        sleep 0.2
      done
    done
    if ! /usr/bin/python3 "${repo}/bench/scan_pipeline_load.py" --mode "${mode}" \
        --nodes "${nodes[@]}" --seconds "${seconds}" --warmup "${warmup}" "${load[@]}" \
        2> "${out}/load_err.txt" | tee -a "${out}/runs.txt"; then
      cat "${out}/load_err.txt" >&2
      tail -n 20 "${out}"/launch_*.txt >&2
      exit 1
    fi
    stop_all
  done
done
/usr/bin/python3 "${repo}/bench/scan_pipeline_load.py" --median "${out}/runs.txt"

#!/usr/bin/env bash
# The node as a user runs it (issue 16), measured by bench/node_load.py: 20 links on moving tf
# frames at 30 Hz, N obstacles in `map`, warnings on, a subscriber on ~markers. For each
# (obstacles, rate) it starts a roscore of its own on a free port and the node, measures the
# node's CPU (% of one core) and RSS over the window, and stops both. Prints one line per run.
#
#   scripts/node_load.sh [--smoke] [--node PATH] [--seconds S] [--runs "N@HZ N@HZ ..."]
#                        [--no-markers]   (the check cycle alone, without a ~markers subscriber)
#                        [--stream HZ]    (the obstacles published on ~obstacles at HZ, moving a
#                                          little each message, instead of added once)
#                        [--stream-frame F] (the streamed obstacles in frame F, e.g. link_0: a sensor
#                                          on the moving robot; default map)
#                        [--store]        (the obstacle store on, as by default, in build/benchmark)
#
# Default runs: 200@30 2000@30 10000@30 100000@10 over 20 s each (goals: 10000@30 under 10 % of
# a core and RSS under 100 MB, 100000@10 under 50 %). --smoke: 200@30 for 3 s (for CI).
# --node compares another build of the node (e.g. main's) in the same run on the same machine.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=script_helpers.sh
source "${repo}/scripts/script_helpers.sh"
node="${repo}/build/ws/devel/lib/ellipse_collision/ellipse_collision_node"
seconds=20
runs="200@30 2000@30 10000@30 100000@10"
markers=()
stream=()
store=false
while [[ $# -gt 0 ]]; do
  case "$1" in
    --smoke) seconds=3; runs="200@30" ;;
    --node) node="$2"; shift ;;
    --seconds) seconds="$2"; shift ;;
    --runs) runs="$2"; shift ;;
    --no-markers) markers=(--no-markers) ;;
    --stream) stream+=(--stream "$2"); shift ;;
    --stream-frame) stream+=(--stream-frame "$2"); shift ;;
    --store) store=true ;;
    *) echo "usage: $0 [--smoke] [--node PATH] [--seconds S] [--runs \"N@HZ ...\"] [--no-markers] [--stream HZ] [--stream-frame F] [--store]" >&2
       exit 2 ;;
  esac
  shift
done

out="${repo}/build/benchmark/node_load"
mkdir -p "${out}"
export PATH="/usr/bin:${PATH}"
# shellcheck disable=SC1091
set +u  # the setup scripts read unset variables
source "${repo}/build/ws/devel/setup.bash"
set -u

# shellcheck source=scripts/tracked_processes.sh
source "${repo}/scripts/tracked_processes.sh"

for run in ${runs}; do
  obstacles="${run%@*}"
  rate="${run#*@}"
  port="$(free_port)"
  export ROS_MASTER_URI="http://127.0.0.1:${port}" ROS_IP=127.0.0.1 ROS_LOG_DIR="${out}/ros_log"
  start_roscore "${port}" "${out}/roscore.txt" || exit 1
  {
    echo "fixed_frame: map"
    echo "rate: ${rate}"
    echo "tf_timeout: 0.1"
    echo "warning_distance: 0.1"
    echo "self_collision: true"
    if ! ${store}; then
      echo "obstacle_store: ''"
    else
      rm -f "${out}/node_load.obstacles"
      echo "obstacle_store: ${out}/node_load.obstacles"
    fi
    echo "links:"
    for i in $(seq 0 19); do
      echo "  - {name: link_${i}, frame: link_${i}, x: 0.1, y: 0.0, angle: 0.0, radius_x: 0.25, radius_y: 0.1}"
    done
  } > "${out}/config.yaml"
  rosparam load "${out}/config.yaml" /ellipse_collision
  # The libraries of the node's own build (another worktree's node would otherwise load this
  # build's libraries through the devel space's LD_LIBRARY_PATH).
  LD_LIBRARY_PATH="$(dirname "$(dirname "${node}")"):${LD_LIBRARY_PATH:-}" \
    "${node}" __name:=ellipse_collision > "${out}/node.txt" 2>&1 &
  node_pid=$!
  pids+=("${node_pid}")
  if ! /usr/bin/python3 "${repo}/bench/node_load.py" --node /ellipse_collision --pid "${node_pid}" \
      --obstacles "${obstacles}" --seconds "${seconds}" "${markers[@]}" "${stream[@]}" 2> "${out}/node_load_err.txt" \
      | sed "s/^/rate=${rate} /"; then
    cat "${out}/node_load_err.txt" >&2
    tail -n 20 "${out}/node.txt" >&2
    exit 1
  fi
  stop_all
done

#!/usr/bin/env bash
# Robots that see each other, at scale: N collision nodes (r1..rN, L links each) on one master of
# the script's own, each publishing its robot on /fleet/footprints and taking the others in
# through a robots source, checking at 10 Hz with a 2 s prediction horizon, while
# bench/fleet_load.py moves every robot through tf. Prints, per node count, each node's CPU
# (median, min, max, % of one core, from /proc/<pid>/stat) and the footprint traffic.
#
#   scripts/fleet_load.sh [--robots "8 20"] [--links L] [--seconds S]   (default 8 and 20
#                                                                       robots, 20 links, 20 s)
#   scripts/fleet_load.sh --runs N      (N rounds; default 1)
#   scripts/fleet_load.sh --alone       (each run also without the fleet: fleet off, no robots
#                                        source, the same links and checks: the fleet's share)
#   scripts/fleet_load.sh --smoke                                      (3 robots, 3 s)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=script_helpers.sh
source "${repo}/scripts/script_helpers.sh"
robots="8 20"
links=20
seconds=20
warmup=5
runs=1
alone=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --smoke) robots="3"; seconds=3; warmup=2 ;;
    --robots) robots="$2"; shift ;;
    --links) links="$2"; shift ;;
    --seconds) seconds="$2"; shift ;;
    --runs) runs="$2"; shift ;;
    --alone) alone=(--alone) ;;
    *) echo "usage: $0 [--smoke] [--robots \"N ...\"] [--links L] [--seconds S] [--runs N] [--alone]" >&2
       exit 2 ;;
  esac
  shift
done

out="${repo}/build/benchmark/fleet_load"
mkdir -p "${out}"
export PATH="/usr/bin:${PATH}"
# shellcheck disable=SC1091
set +u  # the setup scripts read unset variables
source "${repo}/build/ws/devel/setup.bash"
set -u
# shellcheck source=scripts/tracked_processes.sh
source "${repo}/scripts/tracked_processes.sh"

port="$(free_port)"
export ROS_MASTER_URI="http://127.0.0.1:${port}" ROS_IP=127.0.0.1 ROS_LOG_DIR="${out}/ros_log"
start_roscore "${port}" "${out}/roscore.txt" || exit 1
# shellcheck disable=SC2086  # the robot counts are words
/usr/bin/python3 "${repo}/bench/fleet_load.py" \
  --node "${repo}/build/ws/devel/lib/ellipse_collision/ellipse_collision_node" \
  --robots ${robots} --links "${links}" --seconds "${seconds}" --warmup "${warmup}" \
  --runs "${runs}" "${alone[@]}" \
  | tee "${out}/runs.txt"

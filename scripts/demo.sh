#!/usr/bin/env bash
# Starts the demo (demo/launch/demo.launch): the demo robot, its driver, ellipse_collision_node and rviz.
#
# With a display, rviz opens on it. Without one (no $DISPLAY, or --headless) rviz runs in a
# virtual X server (Xvfb) and the screen is saved every few seconds to a PNG whose path is printed,
# so that a server shows what the robot sees. Ctrl-C (SIGINT), SIGTERM or a closed terminal (SIGHUP)
# stop every process started here.
#
# usage: scripts/demo.sh [--headless] [--screenshot PATH] [--period SECONDS] [ROSLAUNCH_ARGS...]
#   --headless         use Xvfb even when $DISPLAY is set
#   --screenshot PATH  where the headless screenshot goes (default: $TMPDIR or /tmp,
#                      ellipse_collision_demo.png)
#   --period SECONDS   time between screenshots (default 5)
#   ROSLAUNCH_ARGS     passed to roslaunch, e.g. config:=my_overlay.yaml or rviz:=false
# Uses the ROS master at $ROS_MASTER_URI (roslaunch starts one there if none is running).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
headless=false
screenshot="${TMPDIR:-/tmp}/ellipse_collision_demo.png"
period=5
launch_args=()
while (($# > 0)); do
  case "$1" in
    --headless) headless=true ;;
    --screenshot) screenshot="$2"; shift ;;
    --period) period="$2"; shift ;;
    -h | --help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) launch_args+=("$1") ;;
  esac
  shift
done
[[ -z "${DISPLAY:-}" ]] && headless=true

# Debian's ROS lives in /usr; a python3 from pyenv or a venv earlier on PATH lacks its modules.
export PATH="/usr/bin:${PATH}"
if ! rospack find ellipse_collision >/dev/null 2>&1; then
  if [[ ! -f "${repo}/build/ws/devel/setup.bash" ]]; then
    echo "demo.sh: ellipse_collision is not built; run scripts/build.sh first" >&2
    exit 1
  fi
  # setup.bash reads unset variables, which set -u would reject.
  set +u
  # shellcheck source=/dev/null
  source "${repo}/build/ws/devel/setup.bash"
  set -u
fi

need() {
  if ! command -v "$1" >/dev/null; then
    echo "demo.sh: '$1' not found; install the Debian package $2 (scripts/setup.sh does)" >&2
    exit 1
  fi
}
need roslaunch python3-roslaunch
if $headless; then
  need Xvfb xvfb
  need import imagemagick
fi

workdir="$(mktemp -d "${TMPDIR:-/tmp}/ellipse_collision_demo.XXXXXX")"
launch_pid=""
xvfb_pid=""
shooter_pid=""

# All processes below `pid` (roslaunch's nodes run in sessions of their own, so its process group
# does not hold them; its children list does, as long as roslaunch is alive).
descendants() {
  local frontier=("$1") found=() pid child
  while ((${#frontier[@]} > 0)); do
    pid="${frontier[0]}"
    frontier=("${frontier[@]:1}")
    for child in $(ps -o pid= --ppid "${pid}" 2>/dev/null || true); do
      found+=("${child}")
      frontier+=("${child}")
    done
  done
  echo "${found[@]:-}"
}

alive() { [[ -n "$1" ]] && kill -0 "$1" 2>/dev/null; }

# Waits up to $2 seconds for all pids in $1 (space separated) to end; true if they did.
wait_gone() {
  local deadline=$((SECONDS + $2)) pid
  while ((SECONDS < deadline)); do
    local any=false
    for pid in $1; do alive "${pid}" && any=true; done
    $any || return 0
    sleep 0.2
  done
  return 1
}

cleaned=false
cleanup() {
  $cleaned && return
  cleaned=true
  trap '' INT TERM HUP
  echo "demo.sh: stopping"
  if alive "${shooter_pid}"; then kill -TERM -- "-${shooter_pid}" 2>/dev/null || true; fi
  if alive "${launch_pid}"; then
    local tree
    tree="$(descendants "${launch_pid}")"
    # roslaunch shuts its nodes down on SIGINT (SIGINT, then SIGTERM after 15 s, per node).
    kill -INT "${launch_pid}" 2>/dev/null || true
    wait_gone "${launch_pid} ${tree}" 25 || true
    # Whatever outlived it: its own process group, then each process it had started.
    kill -KILL -- "-${launch_pid}" 2>/dev/null || true
    for pid in ${tree}; do
      if alive "${pid}"; then kill -TERM "${pid}" 2>/dev/null || true; fi
    done
    wait_gone "${tree}" 3 || for pid in ${tree}; do kill -KILL "${pid}" 2>/dev/null || true; done
  fi
  if alive "${xvfb_pid}"; then
    kill -TERM -- "-${xvfb_pid}" 2>/dev/null || true
    wait_gone "${xvfb_pid}" 5 || kill -KILL -- "-${xvfb_pid}" 2>/dev/null || true
  fi
  rm -rf "${workdir}"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
# A closed terminal too: the nodes must not outlive it.
trap 'exit 129' HUP

# Each background job gets a process group of its own (job control), so that Ctrl-C reaches only
# this script and cleanup() stops the rest in order: the nodes before the X server rviz draws on.
set -m

if $headless; then
  # -displayfd: Xvfb picks a free display and writes its number once it accepts clients.
  Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"${workdir}/display" \
    >"${workdir}/xvfb.log" 2>&1 &
  xvfb_pid=$!
  for _ in $(seq 100); do
    [[ -s "${workdir}/display" ]] && break
    alive "${xvfb_pid}" || break
    sleep 0.1
  done
  if [[ ! -s "${workdir}/display" ]]; then
    echo "demo.sh: Xvfb did not start:" >&2
    cat "${workdir}/xvfb.log" >&2
    exit 1
  fi
  export DISPLAY=":$(head -n1 "${workdir}/display")"
  # Xvfb has no GPU: Mesa's software renderer draws rviz.
  export LIBGL_ALWAYS_SOFTWARE=1
  echo "demo.sh: no display; rviz runs headless on ${DISPLAY} (Xvfb)"
fi

# By path: `roslaunch PACKAGE FILE` would search the whole package directory for FILE.
roslaunch "$(rospack find ellipse_collision)/demo/launch/demo.launch" "${launch_args[@]}" &
launch_pid=$!

if $headless; then
  mkdir -p "$(dirname "${screenshot}")"
  echo "demo.sh: screenshot of rviz every ${period} s: ${screenshot}"
  (
    while sleep "${period}"; do
      # Written next to the target and renamed, so a reader never sees half a PNG.
      if import -display "${DISPLAY}" -window root "${workdir}/shot.png" 2>/dev/null; then
        mv -f "${workdir}/shot.png" "${screenshot}"
      fi
    done
  ) &
  shooter_pid=$!
fi
set +m

echo "demo.sh: running; Ctrl-C stops it"
status=0
wait "${launch_pid}" || status=$?
exit "${status}"

#!/usr/bin/env bash
# Checks the README's run command as a user would: starts `scripts/run.sh --headless` (the demo,
# with rviz under Xvfb) on a ROS master of its own, waits until the demo's screenshot file appears,
# reads one state from `rostopic echo -n 1 /ellipse_collision/collisions` (Debian's Python CLI),
# lets the demo run for the rest of the given time, then stops it with Ctrl-C (SIGINT) and checks
# that it ended. scripts/fresh_machine.sh runs it inside the fresh root.
#
# usage: scripts/check_run.sh [SECONDS]   (default 60: how long the demo runs in all)
# Exit status 0 iff every check passed; each check prints one line.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=script_helpers.sh
source "${repo}/scripts/script_helpers.sh"
duration="${1:-60}"
export PATH="/usr/bin:${PATH}"

out="$(mktemp -d "${TMPDIR:-/tmp}/ellipse_collision_check_run.XXXXXX")"
screenshot="${out}/demo.png"
port="$(free_port)"
export ROS_MASTER_URI="http://localhost:${port}" ROS_LOG_DIR="${out}/ros_log"

check_prefix=check_run
failures=0

run_pid=""
# Ctrl-C in a terminal sends SIGINT to the foreground process group; run.sh runs as a job in a
# process group of its own (set -m), which also keeps SIGINT from being ignored as it would be
# for a background command of a script without job control.
ctrl_c() { kill -INT -- "-${run_pid}" 2>/dev/null || true; }
stop_run() {
  if [[ -n "${run_pid}" ]] && kill -0 "${run_pid}" 2>/dev/null; then
    ctrl_c
    for _ in $(seq 200); do kill -0 "${run_pid}" 2>/dev/null || break; sleep 0.2; done
    kill -KILL -- "-${run_pid}" 2>/dev/null || true
  fi
}
trap stop_run EXIT

start=${SECONDS}
# run.sh execs demo.sh, which stops everything it started on SIGINT, as after a user's Ctrl-C.
# A script started in the background of a shell without job control (a CI runner, `cmd &` in a
# script) inherits SIGINT ignored, and bash cannot trap a signal ignored at its start: run.sh
# starts with SIGINT at its default, as in the terminal of the user whose Ctrl-C this checks.
set -m
env --default-signal=INT bash "${repo}/scripts/run.sh" --headless --screenshot "${screenshot}" \
  --period 5 > "${out}/run.log" 2>&1 &
run_pid=$!
set +m

# 1. The screenshot file appears (setup and build are quick after scripts/test.sh ran).
deadline=$((SECONDS + 240 + duration))
while [[ ! -s "${screenshot}" ]] && ((SECONDS < deadline)) && kill -0 "${run_pid}" 2>/dev/null; do
  sleep 1
done
if [[ -s "${screenshot}" ]]; then
  check "screenshot ${screenshot} appeared after $((SECONDS - start)) s" 0 ""
else
  check "screenshot appears" 1 "no file at ${screenshot}; run.sh log:
$(tail -n 30 "${out}/run.log")"
fi

# 2. A user reads the state with Debian's rostopic (Python messages must be installed).
set +u
# shellcheck source=/dev/null
source "${repo}/build/ws/devel/setup.bash"
set -u
echo_status=0
timeout 30 rostopic echo -n 1 /ellipse_collision/collisions > "${out}/echo.txt" 2>&1 \
  || echo_status=$?
if ((echo_status == 0)) && grep -q '^in_collision: ' "${out}/echo.txt"; then
  check "rostopic echo -n 1 /ellipse_collision/collisions printed a state ($(grep -c . "${out}/echo.txt") lines)" 0 ""
else
  check "rostopic echo -n 1 /ellipse_collision/collisions prints a state" 1 \
    "exit ${echo_status}: $(head -c 2000 "${out}/echo.txt")"
fi

# 3. The demo keeps running for the rest of the time, then Ctrl-C ends it.
while ((SECONDS - start < duration)) && kill -0 "${run_pid}" 2>/dev/null; do sleep 1; done
if kill -0 "${run_pid}" 2>/dev/null; then
  check "demo still running after ${duration} s" 0 ""
else
  check "demo keeps running for ${duration} s" 1 "run.sh ended early; log:
$(tail -n 30 "${out}/run.log")"
fi
ctrl_c
stopped=1
for _ in $(seq 200); do
  if ! kill -0 "${run_pid}" 2>/dev/null; then stopped=0; break; fi
  sleep 0.2
done
check "Ctrl-C stops the demo" "${stopped}" "run.sh still alive 40 s after SIGINT; the demo's processes:
$(ps -e -o pid=,ppid=,pgid=,stat=,args= 2>/dev/null \
    | grep -E 'run\.sh|demo\.sh|roslaunch|ellipse_collision|Xvfb|rviz' | grep -v grep | cut -c1-160)
run.sh log:
$(tail -n 30 "${out}/run.log")"
run_pid=""

# rviz's harmless media_export look-up (README) prints two lines; anything else is shown.
grep -i 'error' "${out}/run.log" | grep -v -e 'media_export' -e 'librospack' | head -n 5 | sed 's/^/check_run: demo log: /' || true
rm -rf "${out}"
((failures == 0))

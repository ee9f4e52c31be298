#!/usr/bin/env bash
# Checks the install space as a user who installs the package sees it: `catkin_make install` in
# the workspace scripts/build.sh made (after scripts/test.sh or run.sh built it), then, in a clean
# environment with only the install space's setup.bash sourced:
#   - no file of the install space is a symbolic link (build.sh links the repository's entries
#     into the workspace; an installed link would point back into it, and break there);
#   - rospack finds the package in the install space, and its launch files resolve;
#   - the Python modules import (the core bindings, the messages, the dynamic_reconfigure configs);
#   - `roslaunch ellipse_collision ellipse_collision.launch` on a master of its own answers
#     `rosservice call /ellipse_collision/check_collisions`.
# scripts/fresh_machine.sh runs it inside the fresh root. Each check prints one line.
#
# usage: scripts/check_install.sh
# Exit status 0 iff every check passed.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=script_helpers.sh
source "${repo}/scripts/script_helpers.sh"
workspace="${repo}/build/ws"
install_space="${workspace}/install"
out="$(mktemp -d "${TMPDIR:-/tmp}/ellipse_collision_check_install.XXXXXX")"
export PATH="/usr/bin:${PATH}"

check_prefix=check_install
failures=0

# In a clean environment: only the install space's setup.bash, as on a machine without the sources.
in_install_space() {
  env -i HOME="${HOME}" LANG=C.UTF-8 PATH=/usr/bin:/bin ROS_LOG_DIR="${out}/ros_log" \
    ROS_MASTER_URI="${ROS_MASTER_URI:-http://localhost:11311}" \
    bash -c "source '${install_space}/setup.bash' && $1"
}

status=0
(cd "${workspace}" && catkin_make install -DPYTHON_EXECUTABLE=/usr/bin/python3 \
  -j"${ELLIPSE_COLLISION_JOBS:-2}") > "${out}/install.log" 2>&1 || status=$?
check "catkin_make install" "${status}" "$(tail -n 20 "${out}/install.log")"

links="$(find "${install_space}" -type l)"
check "no symbolic link in the install space" "$([[ -z "${links}" ]] && echo 0 || echo 1)" \
  "${links}"

found="$(in_install_space 'rospack find ellipse_collision' 2>&1 || true)"
check "rospack find ellipse_collision: ${found}" \
  "$([[ "${found}" == "${install_space}/share/ellipse_collision" ]] && echo 0 || echo 1)" \
  "expected ${install_space}/share/ellipse_collision"

status=0
for launch in ellipse_collision.launch scan_obstacles.launch scan_pipeline_nodelets.launch; do
  in_install_space "roslaunch --files ellipse_collision ${launch}" > "${out}/files.txt" 2>&1 \
    || status=$?
done
check "roslaunch --files of the package's launch files" "${status}" "$(cat "${out}/files.txt")"

status=0
in_install_space 'python3 -c "from ellipse_collision import core
from ellipse_collision.msg import Ellipse
from ellipse_collision.srv import CheckCollisions
from ellipse_collision.cfg import CheckParametersConfig, GateParametersConfig
assert core.overlap(core.Ellipse(0, 0, 1, 1), core.Ellipse(1.5, 0, 1, 1))"' \
  > "${out}/python.txt" 2>&1 || status=$?
check "the Python modules import" "${status}" "$(cat "${out}/python.txt")"

port="$(free_port)"
export ROS_MASTER_URI="http://localhost:${port}"
set -m
in_install_space "roslaunch -p ${port} ellipse_collision ellipse_collision.launch" \
  > "${out}/launch.log" 2>&1 &
launch_pid=$!
set +m
stop_launch() { kill -INT -- "-${launch_pid}" 2>/dev/null || true; }
trap 'stop_launch; rm -rf "${out}"' EXIT
answer=""
for _ in $(seq 60); do
  answer="$(in_install_space 'timeout 10 rosservice call /ellipse_collision/check_collisions "{}"' 2>&1 || true)"
  grep -q '^success: True' <<<"${answer}" && break
  sleep 1
done
check "the installed node answers check_collisions" \
  "$(grep -q '^success: True' <<<"${answer}" && echo 0 || echo 1)" \
  "${answer}
$(tail -n 20 "${out}/launch.log")"
stop_launch
for _ in $(seq 100); do kill -0 "${launch_pid}" 2>/dev/null || break; sleep 0.2; done

((failures == 0))

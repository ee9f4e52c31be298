#!/usr/bin/env bash
# Installs the dependencies, builds the package and runs its main job.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

bash "${repo}/scripts/setup.sh"
bash "${repo}/scripts/build.sh"

export PATH="/usr/bin:${PATH}"
# setup.bash reads unset variables, which set -u would reject.
set +u
# shellcheck source=/dev/null
source "${repo}/build/ws/devel/setup.bash"
set -u

# The main job: the demo robot, the node and rviz (headless under Xvfb with periodic screenshots
# when there is no display). exec, so that Ctrl-C reaches demo.sh, which ends everything it started.
# For the command-line tool alone: rosrun ellipse_collision check_ellipses < examples/pairs.txt
exec bash "${repo}/scripts/demo.sh" "$@"

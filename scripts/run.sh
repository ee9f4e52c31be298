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

# The main job. Replace the body of this function to change what run.sh demonstrates.
main_job() {
  echo "run.sh: rosrun ellipse_collision check_ellipses < examples/pairs.txt"
  local status=0
  rosrun ellipse_collision check_ellipses <"${repo}/examples/pairs.txt" || status=$?
  # The example holds one deliberate bad line to show the error format, so status 1 is expected.
  if ((status == 1)); then
    echo "run.sh: check_ellipses exited with 1 because examples/pairs.txt has one deliberate" \
      "bad line (the 'error' line above); that is the expected result."
  elif ((status != 0)); then
    echo "run.sh: check_ellipses failed with exit status ${status}" >&2
    return "${status}"
  fi
}

main_job

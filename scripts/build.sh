#!/usr/bin/env bash
# Builds ellipse_collision in the catkin workspace build/ws, whose only package is this repository
# (build/ is not in git). Arguments are passed on to catkin_make: CMake options
# (-DELLIPSE_COLLISION_WERROR=ON) and/or make targets (tests, run_tests).
# ELLIPSE_COLLISION_JOBS sets the number of parallel jobs (default 2).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
workspace="${repo}/build/ws"
package="${workspace}/src/ellipse_collision"

# The package directory links every top-level entry of the repository except build/ and .git.
# A single symlink to the repository root would contain the workspace inside itself: rosrun's
# `find -L` then reports a file system loop, and roslaunch's node search (os.walk following links)
# walks the loop ~40 levels deep and finds each executable once per level.
if [[ -L "${package}" ]]; then
  rm -- "${package}"  # the link itself, never its target
fi
mkdir -p "${package}"
shopt -s dotglob nullglob
for entry in "${repo}"/*; do
  name="$(basename -- "${entry}")"
  [[ "${name}" == build || "${name}" == .git ]] && continue
  # Relative, so that the links survive moving the repository.
  ln -sfn -- "../../../../${name}" "${package}/${name}"
done
# Drop links to entries that no longer exist in the repository.
for link in "${package}"/*; do
  if [[ -L "${link}" && ! -e "${link}" ]]; then
    rm -- "${link}"
  fi
done
shopt -u dotglob nullglob

# Debian's ROS lives in /usr; a python3 from pyenv or a venv earlier on PATH lacks its modules.
export PATH="/usr/bin:${PATH}"
cd "${workspace}"
catkin_make -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release \
  -j"${ELLIPSE_COLLISION_JOBS:-2}" "$@"

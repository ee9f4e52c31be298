#!/usr/bin/env bash
# Issue 42: N seeded crossings of a person (a 0.25 m circle, 2-4 m ahead at 0.5-1.5 m/s) in front
# of a robot commanded at 1 m/s through the real node's gate, on a base 0.1 s late braking at
# 1 m/s^2, seen through a ray-cast 720-beam laser at 40 Hz: one node tracking its scan source, one
# not, side by side (test/ros/crossings.test, test_crossings.cpp, on simulated time; CI runs 6).
# Prints one line per crossing (contact while the base moved, closest approach, the gate's
# actions per node), the table tracked vs untracked, and the rolling cart's line; the whole
# rostest output goes to build/benchmark/crossings/rostest.txt. Exits non-zero if the test failed.
#
#   scripts/crossings.sh [N]   (default 50; about 3 s of wall time a crossing on a quiet machine)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
count="${1:-50}"
if ! [[ "${count}" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 [N]   (N: how many crossings, a positive integer)" >&2
  exit 2
fi
out="${repo}/build/benchmark/crossings"
mkdir -p "${out}"
export PATH="/usr/bin:${PATH}" ROS_LOG_DIR="${out}/ros_log"
# shellcheck disable=SC1091
set +u  # the setup scripts read unset variables
source "${repo}/build/ws/devel/setup.bash"
set -u

status=0
rostest --text ellipse_collision crossings.test crossings:="${count}" > "${out}/rostest.txt" 2>&1 \
  || status=$?
grep -E '^(crossing |crossings table|\||rolling cart)' "${out}/rostest.txt" || true
if [[ "${status}" != 0 ]]; then
  echo "crossings.test failed (exit ${status}); see ${out}/rostest.txt" >&2
fi
exit "${status}"

#!/usr/bin/env bash
# Installs the dependencies, builds with warnings as errors, runs every gtest and rostest the
# package defines (catkin_make run_tests) and counts the results. The last line printed is
# "N passed, N failed" (plus ", N skipped" if any); the exit status is non-zero if a test failed,
# crashed or wrote no result.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
results="${repo}/build/ws/build/test_results"

bash "${repo}/scripts/setup.sh"
# Build everything, the tests included, before running any: a compile error stops here.
bash "${repo}/scripts/build.sh" -DELLIPSE_COLLISION_WERROR=ON all tests

# Results of earlier runs must not be counted.
rm -rf "${results}"
# One test at a time: rostests start their own roscore and the timing-sensitive tests should
# not share the 2 cores. run_tests itself succeeds even when tests fail; the counter decides.
ELLIPSE_COLLISION_JOBS=1 bash "${repo}/scripts/build.sh" run_tests

/usr/bin/python3 "${repo}/scripts/count_test_results.py" "${results}"

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

# Runs one more check outside catkin and records it as a JUnit test case, so the counter below
# counts it like any other test (and a failure fails the run).
record_check() {
  local name="$1"
  shift
  local log="${results}/ellipse_collision/${name}.log"
  local status=0
  mkdir -p "${results}/ellipse_collision"
  "$@" > "${log}" 2>&1 || status=$?
  tail -n 5 "${log}"
  /usr/bin/python3 - "${results}/ellipse_collision/check-${name}.xml" "${name}" "${status}" "${log}" <<'PY'
import sys
from xml.sax.saxutils import escape
path, name, status, log = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
failure = ""
if status != 0:
    tail = open(log, errors="replace").read()[-4000:]
    # Terminal colours (ESC) and other control characters are not allowed in XML.
    tail = "".join(c for c in tail if c in "\n\t" or ord(c) >= 32)
    failure = '<failure message="exit status %d">%s</failure>' % (status, escape(tail))
with open(path, "w") as out:
    out.write('<?xml version="1.0" encoding="UTF-8"?>\n<testsuite name="%s" tests="1" failures="%d" '
              'errors="0"><testcase classname="checks" name="%s">%s</testcase></testsuite>\n'
              % (name, 1 if status else 0, name, failure))
PY
}

# The libFuzzer targets, built with clang, ASan and UBSan, run for about a minute in all, the same
# inputs on every run (the committed seeds, then a fixed seed and number of inputs); one JUnit
# test case per target (scripts/fuzz.sh --campaign SECONDS searches for new findings).
bash "${repo}/scripts/fuzz.sh" --ci --junit "${results}/fuzz/fuzz.xml" || true

# The benchmarks compile and run once, briefly, so that they never rot (the full run is
# scripts/benchmark.sh).
record_check benchmark_smoke bash "${repo}/scripts/benchmark.sh" --smoke

/usr/bin/python3 "${repo}/scripts/count_test_results.py" "${results}"

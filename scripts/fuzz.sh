#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# (standalone CMake build in build/fuzz, see cmake/fuzz.cmake) and runs each of them.
#
#   scripts/fuzz.sh --ci                 about a minute in all, shared among the targets
#   scripts/fuzz.sh --long SECONDS       SECONDS per target, e.g. --long 3600 for an hour each
#   options: --only TARGET   run one target
#            --junit FILE    also write a JUnit XML file with one test case per target
#
# Each target starts from its committed seeds in test/fuzz_corpus/<target>/ (read-only) and keeps
# what it discovers in build/fuzz/corpus/<target>/, so longer runs build on earlier ones. A crash,
# sanitizer report, broken invariant, leak, timeout (> 10 s for one input) or memory blow-up
# (> 2 GiB) fails the target; the input is saved under build/fuzz/findings/ and the command that
# reproduces it is printed. The last line is "fuzz: N passed, N failed"; the exit status is
# non-zero if any target failed or the build failed.
# Needs Debian's clang and libclang-rt-14-dev (libFuzzer), installed by scripts/setup.sh.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${repo}/build/fuzz"
seconds=""
only=""
junit=""

usage() { sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

while (($#)); do
  case "$1" in
    --ci) seconds=ci ;;
    --long)
      seconds="${2:-}"
      shift
      if ! [[ "${seconds}" =~ ^[1-9][0-9]*$ ]]; then
        echo "fuzz.sh: --long needs a whole number of seconds" >&2
        exit 2
      fi
      ;;
    --only) only="${2:?--only needs a target name}"; shift ;;
    --junit) junit="${2:?--junit needs a file name}"; shift ;;
    -h | --help) usage; exit 0 ;;
    *) echo "fuzz.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
  shift
done
if [[ -z "${seconds}" ]]; then
  usage >&2
  exit 2
fi

# A pyenv or venv python3 earlier on PATH lacks Debian's ROS modules (gencpp).
export PATH="/usr/bin:${PATH}"
xml_escape() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g' -e 's/"/\&quot;/g' | tr -d '\000-\010\013\014\016-\037'; }

write_junit() {  # tests failures cases
  [[ -n "${junit}" ]] || return 0
  mkdir -p "$(dirname "${junit}")"
  printf '<?xml version="1.0" encoding="UTF-8"?>\n<testsuite name="fuzz" tests="%d" failures="%d" errors="0">%s</testsuite>\n' \
    "$1" "$2" "$3" >"${junit}"
}

for tool in clang clang++ cmake; do
  if ! command -v "${tool}" >/dev/null; then
    echo "fuzz.sh: ${tool} not found; install Debian's clang and libclang-rt-14-dev (scripts/setup.sh)" >&2
    write_junit 1 1 "<testcase classname=\"fuzz\" name=\"build\"><failure message=\"${tool} not found\"/></testcase>"
    echo "fuzz: 0 passed, 1 failed"
    exit 1
  fi
done

echo "fuzz.sh: building the fuzz targets in ${build}"
mkdir -p "${build}"
build_log="${build}/build.log"
if ! { cmake -S "${repo}/fuzz" -B "${build}" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE= && cmake --build "${build}" -j"${ELLIPSE_COLLISION_JOBS:-2}"; } >"${build_log}" 2>&1; then
  grep -E -A3 "error|Error" "${build_log}" | head -40 >&2 || tail -40 "${build_log}" >&2
  write_junit 1 1 "<testcase classname=\"fuzz\" name=\"build\"><failure message=\"the fuzz targets did not build\">$(tail -60 "${build_log}" | xml_escape)</failure></testcase>"
  echo "fuzz.sh: the fuzz targets did not build (log: ${build_log})" >&2
  echo "fuzz: 0 passed, 1 failed"
  exit 1
fi

mapfile -t targets < <(find "${build}" -maxdepth 1 -type f -name 'fuzz_*' -executable -printf '%f\n' | sort)
if [[ -n "${only}" ]]; then
  if [[ ! -x "${build}/${only}" ]]; then
    echo "fuzz.sh: no target ${only}; built: ${targets[*]}" >&2
    exit 2
  fi
  targets=("${only}")
fi
if ((${#targets[@]} == 0)); then
  echo "fuzz.sh: the build produced no fuzz target" >&2
  exit 2
fi
if [[ "${seconds}" == ci ]]; then
  seconds=$((60 / ${#targets[@]}))
  ((seconds >= 5)) || seconds=5
fi

# Sanitizer reports end the run (the code is also built with -fno-sanitize-recover=all).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

passed=0
failed=0
cases=""
summary=""
for target in "${targets[@]}"; do
  seeds="${repo}/test/fuzz_corpus/${target}"
  corpus="${build}/corpus/${target}"
  findings="${build}/findings"
  log="${build}/${target}.log"
  mkdir -p "${corpus}" "${findings}"
  corpora=("${corpus}")
  if [[ -d "${seeds}" ]]; then
    corpora+=("${seeds}")
  else
    echo "fuzz.sh: warning: ${target} has no seed corpus in ${seeds}" >&2
  fi

  echo "fuzz.sh: ${target} for ${seconds} s"
  start=${SECONDS}
  status=0
  # New inputs go to the first directory only, so the committed seeds are never written to.
  "${build}/${target}" -max_total_time="${seconds}" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="${findings}/${target}-" \
    "${corpora[@]}" >"${log}" 2>&1 || status=$?
  elapsed=$((SECONDS - start))

  runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "${log}" | tail -1)"
  rss="$(sed -n 's/^stat::peak_rss_mb: *//p' "${log}" | tail -1)"
  per_second="$(sed -n 's/.*exec\/s: \([0-9]*\).*/\1/p' "${log}" | tail -1)"
  stats="${runs:-?} executions, ${per_second:-?}/s, peak RSS ${rss:-?} MB, corpus $(ls "${corpus}" | wc -l) files"
  if ((status == 0)); then
    passed=$((passed + 1))
    line="PASS ${target}: ${stats}"
    cases+="<testcase classname=\"fuzz\" name=\"${target}\" time=\"${elapsed}\"><system-out>$(xml_escape <<<"${stats}")</system-out></testcase>"
  else
    failed=$((failed + 1))
    artifact="$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "${log}" | tail -1)"
    line="FAIL ${target} (exit ${status}): ${stats}"
    echo "---- ${target}: end of ${log}" >&2
    grep -E -A25 "INVARIANT VIOLATED|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error" "${log}" | head -60 >&2 || tail -40 "${log}" >&2
    if [[ -n "${artifact}" ]]; then
      echo "---- reproduce: ${build}/${target} ${artifact}" >&2
    fi
    message="$(grep -m1 -E "INVARIANT VIOLATED|ERROR: |runtime error" "${log}" || echo "exit status ${status}")"
    cases+="<testcase classname=\"fuzz\" name=\"${target}\" time=\"${elapsed}\"><failure message=\"$(xml_escape <<<"${message}")\">$(tail -60 "${log}" | xml_escape)
input: ${artifact:-none}</failure></testcase>"
  fi
  echo "fuzz.sh: ${line}"
  summary+="${line}"$'\n'
done

write_junit $((passed + failed)) "${failed}" "${cases}"

echo
echo "fuzz.sh summary (${seconds} s per target, sanitizers: address, undefined, float-divide-by-zero):"
printf '%s' "${summary}"
echo "fuzz: ${passed} passed, ${failed} failed"
((failed == 0))

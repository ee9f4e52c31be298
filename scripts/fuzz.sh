#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# (standalone CMake build in build/fuzz, see cmake/fuzz.cmake) and runs each of them.
#
#   scripts/fuzz.sh --ci                  reproducible, about a minute in all (what scripts/test.sh
#                                         runs): each target replays every committed seed, then
#                                         fuzzes from those seeds alone with a fixed random seed
#                                         for a fixed number of inputs, so every run on every
#                                         machine executes the same inputs
#   scripts/fuzz.sh --campaign SECONDS    a search for new findings: SECONDS per target (e.g. 3600),
#                                         a new random seed each run (printed), building on the
#                                         corpus earlier campaigns left in build/fuzz/corpus/
#   scripts/fuzz.sh --add-seed FINDING NAME
#                                         keeps a finding (after its fix) as the committed seed
#                                         test/fuzz_corpus/<target>/NAME, replayed by every --ci run
#   options: --only TARGET   run one target
#            --junit FILE    also write a JUnit XML file with one test case per target
#
# A crash, sanitizer report, broken invariant, leak, timeout (> 10 s for one input) or memory
# blow-up (> 2 GiB) fails the target; the input is saved under build/fuzz/findings/ and the
# commands that reproduce it and keep it as a seed are printed. The last line is
# "fuzz: N passed, N failed"; the exit status is non-zero if any target failed or the build failed.
# Needs Debian's clang and libclang-rt-14-dev (libFuzzer), installed by scripts/setup.sh.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${repo}/build/fuzz"
findings="${build}/findings"
mode=""
seconds=""
only=""
junit=""

# --ci: libFuzzer's -seed, and the inputs each target runs after its seeds (-runs), chosen so that
# all targets take about a minute under ASan (49-69 s in all on a 2-core machine shared with other
# builds; the campaign's exec/s lines show each target's rate).
readonly kCiSeed=20261127
declare -A kCiRuns=(
  [fuzz_core_pair]=40000
  [fuzz_first_contact]=5000
  [fuzz_node_config]=12000
  [fuzz_obstacle_store]=80000
  [fuzz_pair_line_parser]=80000
  [fuzz_ros_request]=7000
  [fuzz_scene]=6000
)
readonly kCiRunsDefault=5000

usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

add_seed() {  # finding name
  local finding="$1" name="$2" base target destination
  base="$(basename -- "${finding}")"
  target="${base%%-*}"
  if [[ ! -f "${finding}" || "${target}" != fuzz_* ]]; then
    echo "fuzz.sh: --add-seed needs a finding saved as build/fuzz/findings/<target>-...; got '${finding}'" >&2
    exit 2
  fi
  if ! [[ "${name}" =~ ^[a-z0-9][a-z0-9.-]*$ ]]; then
    echo "fuzz.sh: seed name '${name}' must be lower-case letters, digits, '-' and '.' (say what the input is)" >&2
    exit 2
  fi
  if [[ "${name}" == seed-* ]]; then
    echo "fuzz.sh: seed-* names belong to fuzz/make_seeds.py, which rewrites them; choose another" >&2
    exit 2
  fi
  destination="${repo}/test/fuzz_corpus/${target}/${name}"
  if [[ -e "${destination}" ]]; then
    echo "fuzz.sh: ${destination} exists already" >&2
    exit 2
  fi
  mkdir -p "$(dirname "${destination}")"
  cp -- "${finding}" "${destination}"
  echo "fuzz.sh: kept ${finding} as ${destination#"${repo}/"}; every --ci run replays it."
  echo "  commit it with the fix (and a test of the case): git add ${destination#"${repo}/"}"
}

while (($#)); do
  case "$1" in
    --ci) mode=ci ;;
    --campaign | --long)
      mode=campaign
      seconds="${2:-}"
      shift
      if ! [[ "${seconds}" =~ ^[1-9][0-9]*$ ]]; then
        echo "fuzz.sh: --campaign needs a whole number of seconds" >&2
        exit 2
      fi
      ;;
    --add-seed)
      add_seed "${2:?--add-seed needs a finding}" "${3:?--add-seed needs a seed name}"
      exit 0
      ;;
    --only) only="${2:?--only needs a target name}"; shift ;;
    --junit) junit="${2:?--junit needs a file name}"; shift ;;
    -h | --help) usage; exit 0 ;;
    *) echo "fuzz.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
  shift
done
if [[ -z "${mode}" ]]; then
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

# Sanitizer reports end the run (the code is also built with -fno-sanitize-recover=all).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:symbolize=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# -reload=0: the corpus directory is not re-read on a timer, which would make a run depend on time.
common=(-timeout=10 -rss_limit_mb=2048 -reload=0 -print_final_stats=1)

passed=0
failed=0
cases=""
summary=""
mkdir -p "${findings}"
for target in "${targets[@]}"; do
  seeds="${repo}/test/fuzz_corpus/${target}"
  log="${build}/${target}.log"
  prefix="${findings}/${target}-"
  seed_files=()
  if [[ -d "${seeds}" ]]; then
    mapfile -t seed_files < <(find "${seeds}" -maxdepth 1 -type f | sort)
  fi
  if ((${#seed_files[@]} == 0)); then
    echo "fuzz.sh: warning: ${target} has no seeds in ${seeds}" >&2
  fi
  start=${SECONDS}
  status=0
  : >"${log}"
  if [[ "${mode}" == ci ]]; then
    runs="${kCiRuns[${target}]:-${kCiRunsDefault}}"
    echo "fuzz.sh: ${target}: ${#seed_files[@]} seeds replayed, then ${runs} inputs from seed ${kCiSeed}"
    # 1. Every committed seed (fuzz findings kept as seeds included), each run once.
    if ((${#seed_files[@]})); then
      "${build}/${target}" "${common[@]}" -artifact_prefix="${prefix}" "${seed_files[@]}" \
        >>"${log}" 2>&1 || status=$?
    fi
    # 2. Fuzzing from the committed seeds alone (a fresh working corpus, not what earlier runs left
    #    behind), libFuzzer's random generator seeded with kCiSeed, a fixed number of inputs.
    #    -use_cmp=0: the operands of traced comparisons include addresses, which address-space
    #    randomisation changes from run to run (with them two runs here reached different inputs).
    if ((status == 0)); then
      corpus="${build}/ci_corpus/${target}"
      rm -rf -- "${corpus}"
      mkdir -p "${corpus}"
      corpora=("${corpus}")
      [[ -d "${seeds}" ]] && corpora+=("${seeds}")
      echo "---- fuzzing" >>"${log}"
      "${build}/${target}" "${common[@]}" -seed="${kCiSeed}" -runs="${runs}" -use_cmp=0 \
        -artifact_prefix="${prefix}" "${corpora[@]}" >>"${log}" 2>&1 || status=$?
    fi
  else
    # New inputs go to the first directory only, so the committed seeds are never written to.
    corpus="${build}/corpus/${target}"
    mkdir -p "${corpus}"
    corpora=("${corpus}")
    [[ -d "${seeds}" ]] && corpora+=("${seeds}")
    echo "fuzz.sh: ${target} for ${seconds} s"
    "${build}/${target}" "${common[@]}" -max_total_time="${seconds}" -artifact_prefix="${prefix}" \
      "${corpora[@]}" >"${log}" 2>&1 || status=$?
  fi
  elapsed=$((SECONDS - start))

  executions="$(sed -n 's/^stat::number_of_executed_units: *//p' "${log}" | tail -1)"
  new_units="$(sed -n 's/^stat::new_units_added: *//p' "${log}" | tail -1)"
  coverage="$(sed -n 's/.* cov: \([0-9]*\) ft: \([0-9]*\).*/\1 edges, \2 features/p' "${log}" | tail -1)"
  rss="$(sed -n 's/^stat::peak_rss_mb: *//p' "${log}" | tail -1)"
  seed_used="$(sed -n 's/^INFO: Seed: \([0-9]*\).*/\1/p' "${log}" | tail -1)"
  stats="${executions:-?} executions (seed ${seed_used:-?}), ${new_units:-?} new inputs, ${coverage:-coverage ?}, peak RSS ${rss:-?} MB, ${elapsed} s"
  if ((status == 0)); then
    passed=$((passed + 1))
    line="PASS ${target}: ${stats}"
    cases+="<testcase classname=\"fuzz\" name=\"${target}\" time=\"${elapsed}\"><system-out>$(xml_escape <<<"${stats}")</system-out></testcase>"
  else
    failed=$((failed + 1))
    artifact="$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "${log}" | tail -1)"
    failing_seed="$(sed -n 's/^Running: \(.*\)$/\1/p' "${log}" | tail -1)"
    line="FAIL ${target} (exit ${status}): ${stats}"
    echo "---- ${target}: end of ${log}" >&2
    grep -E -A25 "INVARIANT VIOLATED|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error" "${log}" | head -60 >&2 || tail -40 "${log}" >&2
    if [[ -n "${artifact}" ]]; then
      echo "---- reproduce: ${build}/${target} ${artifact}" >&2
      echo "---- once fixed, keep it as a seed: scripts/fuzz.sh --add-seed ${artifact} <what-it-is>" >&2
    elif [[ -n "${failing_seed}" ]]; then
      echo "---- the committed seed ${failing_seed} fails; reproduce: ${build}/${target} ${failing_seed}" >&2
    fi
    message="$(grep -m1 -E "INVARIANT VIOLATED|ERROR: |runtime error" "${log}" || echo "exit status ${status}")"
    cases+="<testcase classname=\"fuzz\" name=\"${target}\" time=\"${elapsed}\"><failure message=\"$(xml_escape <<<"${message}")\">$(tail -60 "${log}" | xml_escape)
input: ${artifact:-${failing_seed:-none}}</failure></testcase>"
  fi
  echo "fuzz.sh: ${line}"
  summary+="${line}"$'\n'
done

write_junit $((passed + failed)) "${failed}" "${cases}"

echo
if [[ "${mode}" == ci ]]; then
  echo "fuzz.sh summary (seeds replayed, then fixed inputs from seed ${kCiSeed}; sanitizers: address, undefined, float-divide-by-zero):"
else
  echo "fuzz.sh summary (campaign, ${seconds} s per target, random seeds; sanitizers: address, undefined, float-divide-by-zero):"
fi
printf '%s' "${summary}"
if [[ "${mode}" == campaign ]] && ((failed)); then
  echo "Findings are in ${findings#"${repo}/"}/. For each: reproduce it (the command above), fix the code"
  echo "(or the target's invariant, if the invariant was wrong), add a test of the case, then keep the"
  echo "input as a seed so that every --ci run replays it: scripts/fuzz.sh --add-seed FINDING descriptive-name"
fi
echo "fuzz: ${passed} passed, ${failed} failed"
((failed == 0))

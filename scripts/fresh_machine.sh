#!/usr/bin/env bash
# Runs the README's test command (and checks its run command) as a new user would, on a new
# Debian 12: a minimal root made from Debian's archive (mmdebstrap, minbase variant), with nothing
# in it but what scripts/setup.sh installs. A missing install step fails here even when the host
# has the package from an earlier install by hand. .ci/run runs this.
#
# Phases (each one's time is printed at the end):
#   base      the minbase root as a tarball, cached between runs (ELLIPSE_COLLISION_FRESH_CACHE,
#             default /var/cache/ellipse_collision_fresh); made from the host's own apt sources
#   root      the tarball unpacked into a new folder, /etc/hosts naming localhost and this host,
#             a clean clone of HEAD at /root/ellipse_collision and ../shared beside it
#   test      `bash scripts/test.sh` inside (chroot with /proc, /sys and /dev bound); installs with
#             setup.sh, builds, runs every test, prints "N passed, N failed"
#   run       `bash scripts/run.sh` inside, headless, for about a minute: the demo's screenshot file
#             must appear and `rostopic echo -n 1 /ellipse_collision/collisions` must print a state;
#             then the install space (scripts/check_install.sh: `catkin_make install`, no links,
#             the installed node answers from a clean environment)
# Every mount is undone and the root removed on exit, on failure and on Ctrl-C (--keep keeps the
# root for a look inside). Downloaded .deb files are cached beside the tarball, so a second run
# does not download them again; the install step itself runs every time.
#
# usage: scripts/fresh_machine.sh [--keep] [--skip-run]
# The last line printed is "N passed, N failed": the test command's counts plus the run checks.
# Needs root (chroot, mount).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
keep=false
skip_run=false
for arg in "$@"; do
  case "${arg}" in
    --keep) keep=true ;;
    --skip-run) skip_run=true ;;
    *) echo "usage: $0 [--keep] [--skip-run]" >&2; exit 2 ;;
  esac
done
if ((EUID != 0)); then
  echo "fresh_machine.sh: needs root (chroot and mount)" >&2
  exit 1
fi

cache="${ELLIPSE_COLLISION_FRESH_CACHE:-/var/cache/ellipse_collision_fresh}"
suite=bookworm
base_tarball="${cache}/${suite}-minbase.tar"
work="$(mktemp -d /var/tmp/ellipse_collision_fresh.XXXXXX)"
root="${work}/root"
mounts=()  # mount points inside the root, in the order they were mounted

# Every process still running inside the root (a test or the demo that outlived its stop): killed
# before the mounts go, so nothing keeps running on the host with its root deleted.
kill_root_processes() {
  local proc pid
  for proc in /proc/[0-9]*; do
    pid="${proc#/proc/}"
    [[ "$(readlink "${proc}/root" 2>/dev/null)" == "${root}"* ]] || continue
    echo "fresh_machine.sh: killing $(tr '\0' ' ' < "${proc}/cmdline" 2>/dev/null | head -c 120) (pid ${pid}), left running in the root" >&2
    kill -KILL "${pid}" 2>/dev/null || true
  done
}

cleanup() {
  local status=$?
  local i
  kill_root_processes
  for ((i = ${#mounts[@]} - 1; i >= 0; i--)); do
    umount -R "${mounts[i]}" 2>/dev/null || umount -lR "${mounts[i]}" 2>/dev/null || true
  done
  # Never remove a root that still has something mounted in it (rm would reach into the host).
  if grep -q " ${work}/" /proc/mounts; then
    echo "fresh_machine.sh: mounts left under ${work}; not removing it" >&2
  elif ! ${keep}; then
    rm -rf --one-file-system "${work}"
  else
    echo "fresh_machine.sh: root kept at ${root}"
  fi
  exit "${status}"
}
trap cleanup EXIT
trap 'exit 130' INT TERM HUP

phase_names=()
phase_seconds=()
phase_start=0
begin_phase() {
  phase_start=${SECONDS}
  echo
  echo "==== fresh_machine: $1"
  phase_names+=("$1")
}
end_phase() { phase_seconds+=($((SECONDS - phase_start))); }
print_times() {
  local i
  echo
  echo "fresh_machine phase times:"
  for i in "${!phase_seconds[@]}"; do
    printf '  %-6s %5d s\n' "${phase_names[i]}" "${phase_seconds[i]}"
  done
}

# ---- base: the minbase root, from the archive the host's apt uses -------------------------------
begin_phase base
mkdir -p "${cache}/archives/partial"
if [[ ! -f "${base_tarball}" ]]; then
  if ! command -v mmdebstrap >/dev/null; then
    apt-get update -q
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends mmdebstrap
  fi
  # The host's apt sources (deb822 .sources and one-line .list files) become the root's, so the
  # root reaches Debian's archive the same way the host does.
  sources=()
  [[ -s /etc/apt/sources.list ]] && sources+=(/etc/apt/sources.list)
  for file in /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list; do
    [[ -s "${file}" ]] && sources+=("${file}")
  done
  if ((${#sources[@]} == 0)); then
    echo "fresh_machine.sh: the host has no apt sources to make the root from" >&2
    exit 1
  fi
  mmdebstrap --variant=minbase --format=tar --quiet "${suite}" "${base_tarball}.partial" \
    "${sources[@]}"
  mv "${base_tarball}.partial" "${base_tarball}"
else
  echo "cached: ${base_tarball}"
fi
end_phase

# ---- root: unpack, name the host, put the clone in ----------------------------------------------
begin_phase root
mkdir -p "${root}"
tar -C "${root}" -xf "${base_tarball}"
host="$(hostname)"
# What any installed Debian has: roslaunch resolves localhost and the host's own name.
cat > "${root}/etc/hosts" <<EOF
127.0.0.1	localhost
127.0.1.1	${host}
::1	localhost ip6-localhost ip6-loopback
EOF
echo "${host}" > "${root}/etc/hostname"
cp -L /etc/resolv.conf "${root}/etc/resolv.conf"
git clone --quiet --no-hardlinks "${repo}" "${root}/root/ellipse_collision"
echo "clone of $(git -C "${repo}" rev-parse --short HEAD) at /root/ellipse_collision"
if [[ -d "${repo}/../shared" ]]; then
  cp -a "${repo}/../shared" "${root}/root/shared"
fi
mount_in() {  # mount_in TYPE_OR_--bind SOURCE TARGET_IN_ROOT
  mkdir -p "${root}$3"
  if [[ "$1" == --bind ]]; then
    mount --rbind "$2" "${root}$3"
    mount --make-rslave "${root}$3"
  else
    mount -t "$1" "$2" "${root}$3"
  fi
  mounts+=("${root}$3")
}
mount_in proc proc /proc
mount_in --bind /sys /sys
mount_in --bind /dev /dev
mount_in --bind "${cache}/archives" /var/cache/apt/archives
end_phase

# Runs a command in the root as a login of a new user would: a clean environment, root's home.
in_root() {
  chroot "${root}" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb CI="${CI:-}" \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    /bin/bash -c "$1"
}

# ---- test: the README's test command -------------------------------------------------------------
begin_phase test
test_log="${work}/test.log"
test_status=0
in_root 'cd /root/ellipse_collision && bash scripts/test.sh' 2>&1 | tee "${test_log}" \
  || test_status=$?
end_phase
counts="$(grep -E '^([A-Za-z]+: )?[0-9]+ passed, [0-9]+ failed' "${test_log}" | tail -n 1 || true)"
passed="$(sed -E 's/^([A-Za-z]+: )?([0-9]+) passed.*/\2/' <<<"${counts}")"
failed="$(sed -E 's/^.* ([0-9]+) failed.*/\1/' <<<"${counts}")"
if [[ -z "${counts}" ]]; then
  echo "fresh_machine.sh: the test command printed no 'N passed, N failed' line" >&2
  passed=0
  failed=1
elif ((test_status != 0 && failed == 0)); then
  failed=1  # it failed before or after counting (install, build): that is a failure too
fi

# ---- run: the README's run command, headless, checked as a user would ---------------------------
if ! ${skip_run}; then
  begin_phase run
  run_checks_failed=0
  # roscore of the demo on a port of its own; the screenshot where a user would look for it.
  if in_root 'cd /root/ellipse_collision && bash scripts/check_run.sh 60'; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    run_checks_failed=1
  fi
  # What a user who installs the package gets.
  if in_root 'cd /root/ellipse_collision && bash scripts/check_install.sh'; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    run_checks_failed=1
  fi
  end_phase
  ((run_checks_failed == 0)) && echo "run check: passed" || echo "run check: FAILED"
fi

print_times
echo "${passed} passed, ${failed} failed"
((failed == 0))

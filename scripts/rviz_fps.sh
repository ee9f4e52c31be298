#!/usr/bin/env bash
# rviz's frame rate while it shows the node's ~markers (issue 16): for each given build of
# ellipse_collision_node, a roscore of its own, the node (20 links on moving frames, N obstacles in
# `map`, 30 Hz, warnings on), the scene driver bench/rviz_fps_scene.py (tf at 30 Hz, the obstacles
# on ~obstacles) and real rviz (bench/rviz_fps.rviz, the whole field in view) in a virtual X
# server with software OpenGL. rviz has no frame-rate readout: bench/glx_frame_log.c, preloaded,
# logs every glXSwapBuffers (one drawn frame). After --warmup s, over --window s it measures
# rviz's frames per second, the CPU of rviz and of the node (% of one core) and what the node
# published on ~markers (messages/s, MB/s). Builds are interleaved run by run (--runs each), so
# they share the machine's noise; medians per build at the end. Not part of CI.
#
#   scripts/rviz_fps.sh [--obstacles N] [--runs R] [--warmup S] [--window S] [--display :97]
#                       [--scale PX_PER_M] [--centre X,Y] [--screenshot PATH] [--still]
#                       [--synthetic MARKERS,TRIANGLES] [--rviz-arg ARG]... LABEL=PATH/TO/ellipse_collision_node...
#
# --still parks the links (the scene never changes): rviz's drawing ceiling without marker traffic.
# --centre puts the view's focal point at X, Y [m] in `map` (default: the field's centre). Far off
# the field (e.g. --centre -1000,-1000) nothing is in view and the graphics driver draws no
# triangle (rviz culls each marker by its bounding box): what is left is rviz's own work on the
# markers (receiving them, rebuilding the changed ones, walking the scene), which a GPU does not
# take off the CPU.
# --rviz-arg passes ARG to rviz, e.g. --rviz-arg --disable-anti-aliasing (rviz asks the driver for
# a multisampled window unless told not to, and software OpenGL rasterises every sample).
# --synthetic M,T replaces the node and its scene by bench/rviz_marker_count.py: M markers of T
# tiny triangles each, published once, nearly nothing to rasterise, the view on them (the
# LABEL=PATH arguments are ignored). rviz's cost per marker drawn, which a GPU does not remove
# either: compare M,T with M/8,8T (the same triangles in fewer markers).
#
# A build's libraries are taken from the node's RUNPATH, or from a `lib` directory beside the
# binary if there is one (a saved copy of an older build). Without LABEL=... it measures this
# worktree's build/ws. --screenshot grabs the screen at the end of the last run of the last build.
# Output: build/rviz_fps/ (results.txt, logs).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=script_helpers.sh
source "${repo}/scripts/script_helpers.sh"
obstacles=10000
runs=3
warmup=20
window=30
display=":97"
scale=""
view_centre=""
screenshot=""
scene_args=()
synthetic=""
rviz_args=()
builds=()
while (($#)); do
  case "$1" in
    --obstacles) obstacles="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --warmup) warmup="$2"; shift 2 ;;
    --window) window="$2"; shift 2 ;;
    --display) display="$2"; shift 2 ;;
    --scale) scale="$2"; shift 2 ;;
    --centre) view_centre="$2"; shift 2 ;;
    --screenshot) screenshot="$2"; shift 2 ;;
    --still) scene_args+=(--still); shift ;;
    --synthetic) synthetic="$2"; shift 2 ;;
    --rviz-arg) rviz_args+=("$2"); shift 2 ;;
    *=*) builds+=("$1"); shift ;;
    *) sed -n '2,32p' "$0" >&2; exit 2 ;;
  esac
done
((${#builds[@]})) || builds=("current=${repo}/build/ws/devel/lib/ellipse_collision/ellipse_collision_node")
if [[ -n "${synthetic}" ]]; then
  builds=("synthetic_${synthetic/,/x}=none")
  # The grid the synthetic triangles lie on, in place of the obstacles'.
  obstacles="$((${synthetic%%,*} * ${synthetic#*,}))"
fi

out="${repo}/build/rviz_fps"
mkdir -p "${out}"
export PATH="/usr/bin:${PATH}"
set +u
source "${repo}/build/ws/devel/setup.bash"
set -u
gcc -shared -fPIC -O2 -Wall -o "${out}/glx_frame_log.so" "${repo}/bench/glx_frame_log.c" -ldl

# The field: a side x side grid at 0.6 m (rviz_fps_scene.py); the view fits it into 1000 x 800 px.
side_m="$(/usr/bin/python3 -c "import math; print(math.ceil(math.sqrt(${obstacles})) * 0.6)")"
[[ -n "${scale}" ]] || scale="$(/usr/bin/python3 -c "print(round(700 / (${side_m} + 2), 2))")"
centre="$(/usr/bin/python3 -c "print(${side_m} / 2 - 0.3)")"
centre_x="${view_centre%%,*}"
centre_y="${view_centre#*,}"
[[ -n "${view_centre}" ]] || { centre_x="${centre}"; centre_y="${centre}"; }
sed -e "s/@SCALE@/${scale}/" -e "s/@X@/${centre_x}/" -e "s/@Y@/${centre_y}/" \
  "${repo}/bench/rviz_fps.rviz" > "${out}/view.rviz"

# The node's configuration: 20 links, one per moving frame; no configured obstacles.
{
  echo "fixed_frame: map"
  echo "rate: 30.0"
  echo "warning_distance: 0.1"
  echo "self_collision: false"
  echo "max_obstacles: 1000000"
  echo "obstacle_store: ${out}/obstacle_store"
  echo "obstacles: []"
  echo "links:"
  for i in $(seq 0 19); do
    echo "  - {name: link_${i}, frame: link_${i}, x: 0.0, y: 0.0, angle: 0.0, radius_x: 0.3, radius_y: 0.12}"
  done
} > "${out}/node.yaml"

# shellcheck source=scripts/tracked_processes.sh
source "${repo}/scripts/tracked_processes.sh"

monotonic() { /usr/bin/python3 -c 'import time; print(time.monotonic())'; }
cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }

Xvfb "${display}" -screen 0 1280x1024x24 > "${out}/xvfb.txt" 2>&1 &
pids+=($!)
port="$(free_port)"
export ROS_MASTER_URI="http://127.0.0.1:${port}" ROS_IP=127.0.0.1 ROS_LOG_DIR="${out}/ros_log"
roscore -p "${port}" > "${out}/roscore.txt" 2>&1 &
pids+=($!)
for _ in $(seq 100); do rosparam get /run_id > /dev/null 2>&1 && break; sleep 0.2; done

hz="$(getconf CLK_TCK)"
results="${out}/results.txt"
echo "build run fps rviz_cpu_pct node_cpu_pct marker_msgs_per_s marker_MB_per_s" > "${results}"
for run in $(seq "${runs}"); do
  for build in "${builds[@]}"; do
    label="${build%%=*}"
    node="${build#*=}"
    libs=""
    [[ -d "$(dirname "${node}")/lib" ]] && libs="$(dirname "${node}")/lib"
    tag="${label}_${run}"
    rm -f "${out}/obstacle_store" "${out}/frames_${tag}.log" "${out}/scene_${tag}.json"
    rosparam delete /ellipse_collision > /dev/null 2>&1 || true
    rosparam load "${out}/node.yaml" /ellipse_collision
    if [[ -n "${synthetic}" ]]; then
      # "node CPU" is then the publisher's.
      /usr/bin/python3 "${repo}/bench/rviz_marker_count.py" "${synthetic%%,*}" "${synthetic#*,}" \
        > "${out}/node_${tag}.txt" 2>&1 &
      node_pid=$!
      pids+=(${node_pid})
    else
      LD_LIBRARY_PATH="${libs}${LD_LIBRARY_PATH:+:${LD_LIBRARY_PATH}}" "${node}" __name:=ellipse_collision \
        > "${out}/node_${tag}.txt" 2>&1 &
      node_pid=$!
      pids+=(${node_pid})
      /usr/bin/python3 "${repo}/bench/rviz_fps_scene.py" --obstacles "${obstacles}" --warmup "${warmup}" \
        --window "${window}" --stats "${out}/scene_${tag}.json" ${scene_args[@]+"${scene_args[@]}"} > "${out}/scene_${tag}.txt" 2>&1 &
      pids+=($!)
    fi
    DISPLAY="${display}" LIBGL_ALWAYS_SOFTWARE=1 FRAME_LOG="${out}/frames_${tag}.log" \
      LD_PRELOAD="${out}/glx_frame_log.so" rviz -d "${out}/view.rviz" ${rviz_args[@]+"${rviz_args[@]}"} > "${out}/rviz_${tag}.txt" 2>&1 &
    rviz_pid=$!
    pids+=(${rviz_pid})
    sleep "${warmup}"
    t0="$(monotonic)"; r0="$(cpu_ticks "${rviz_pid}")"; n0="$(cpu_ticks "${node_pid}")"
    sleep "${window}"
    t1="$(monotonic)"; r1="$(cpu_ticks "${rviz_pid}")"; n1="$(cpu_ticks "${node_pid}")"
    sleep 2  # the scene driver writes its counts
    if [[ -n "${screenshot}" && "${run}" == "${runs}" && "${build}" == "${builds[-1]}" ]]; then
      DISPLAY="${display}" import -window root "${screenshot}"
    fi
    stop_all
    Xvfb "${display}" -screen 0 1280x1024x24 >> "${out}/xvfb.txt" 2>&1 &
    pids+=($!)
    roscore -p "${port}" >> "${out}/roscore.txt" 2>&1 &
    pids+=($!)
    for _ in $(seq 100); do rosparam get /run_id > /dev/null 2>&1 && break; sleep 0.2; done
    /usr/bin/python3 - "${out}/frames_${tag}.log" "${out}/scene_${tag}.json" "${t0}" "${t1}" \
      "$((r1 - r0))" "$((n1 - n0))" "${hz}" "${label}" "${run}" >> "${results}" <<'PY'
import json, sys
frames, scene, t0, t1, rviz_ticks, node_ticks, hz, label, run = sys.argv[1:]
t0, t1, hz = float(t0), float(t1), float(hz)
with open(frames) as f:
    times = [float(line) for line in f if line.strip()]
fps = sum(t0 <= t <= t1 for t in times) / (t1 - t0)
try:
    with open(scene) as f:
        s = json.load(f)
    msgs, mbytes = s["marker_messages"] / s["window_s"], s["marker_bytes"] / s["window_s"] / 1e6
except (OSError, ValueError, KeyError):
    msgs, mbytes = float("nan"), float("nan")
print(f"{label} {run} {fps:.1f} {100 * int(rviz_ticks) / hz / (t1 - t0):.0f} "
      f"{100 * int(node_ticks) / hz / (t1 - t0):.1f} {msgs:.1f} {mbytes:.2f}")
PY
    tail -1 "${results}"
  done
done

echo
if [[ -n "${synthetic}" ]]; then
  echo "Medians over ${runs} runs (${synthetic%%,*} markers of ${synthetic#*,} triangles, no node: \"node CPU\" is the publisher's; rviz target 30 fps):"
else
  echo "Medians over ${runs} runs (${obstacles} obstacles, 20 moving links, node at 30 Hz, rviz target 30 fps):"
fi
/usr/bin/python3 - "${results}" <<'PY'
import statistics, sys
rows = [line.split() for line in open(sys.argv[1])][1:]
labels = list(dict.fromkeys(r[0] for r in rows))
print("build      fps   rviz CPU %   node CPU %   marker msgs/s   marker MB/s")
for label in labels:
    mine = [list(map(float, r[2:])) for r in rows if r[0] == label]
    med = [statistics.median(col) for col in zip(*mine)]
    print(f"{label:<9} {med[0]:5.1f}   {med[1]:10.0f}   {med[2]:10.1f}   {med[3]:13.1f}   {med[4]:11.2f}")
PY

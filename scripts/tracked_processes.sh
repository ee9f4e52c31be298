# Sourced by the scripts that start ROS processes in the background (benchmark.sh, node_load.sh,
# rviz_fps.sh): each started process's pid goes into `pids`; stop_all stops them newest first with
# Ctrl-C (SIGINT, as roslaunch and rosnode expect) and waits for each. It runs on exit, failure and
# Ctrl-C of the sourcing script.
pids=()
stop_all() {
  local i
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
    kill -INT "${pids[i]}" 2>/dev/null || true
    wait "${pids[i]}" 2>/dev/null || true
  done
  pids=()
}
# start_roscore PORT LOG: a roscore on PORT in the background (tracked), its output in LOG; waits
# until the master answers (up to 20 s). Returns 1, with LOG shown, if it never does.
start_roscore() {
  roscore -p "$1" > "$2" 2>&1 &
  pids+=($!)
  local _
  for _ in $(seq 100); do
    rosparam get /run_id > /dev/null 2>&1 && return 0
    sleep 0.2
  done
  cat "$2" >&2
  echo "roscore did not start" >&2
  return 1
}
trap stop_all EXIT
trap 'exit 130' INT TERM

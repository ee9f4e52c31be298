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
trap stop_all EXIT
trap 'exit 130' INT TERM

# Helpers shared by the scripts in this folder; sourced by them, not run.

# A TCP port on 127.0.0.1 that nothing listens on now: for a ROS master of the script's own, so
# that it never meets a user's roscore on 11311 (or another script's).
free_port() {
  /usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# check NAME STATUS DETAIL: one line per check, "<check_prefix>: ok     NAME" when STATUS is 0,
# else "<check_prefix>: FAILED NAME: DETAIL", counted in `failures`. The caller sets check_prefix
# and failures=0.
check() {
  if [[ "$2" == 0 ]]; then
    echo "${check_prefix}: ok     $1"
  else
    echo "${check_prefix}: FAILED $1: $3"
    failures=$((failures + 1))
  fi
}

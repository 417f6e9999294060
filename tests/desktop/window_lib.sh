# window_lib.sh — sourced by the window tests (bash, set -euo pipefail): start
# pogon-desktop under the X server xvfb-run gives, find its window, and wait for what it
# prints.

# start_window LOG COMMAND [ARGS...]: run the program in the background with its output
# in LOG, kill it on exit if it is still running, and wait for its window. Sets pid, wid
# and log.
start_window() {
  log=$1; shift
  "$@" >"$log" 2>&1 &
  pid=$!
  trap 'kill -9 $pid 2>/dev/null || true' EXIT
  wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^pogon$' | head -n 1)
  [ -n "$wid" ] || { echo "FAIL: no window"; cat "$log"; exit 1; }
  xdotool windowfocus --sync "$wid" || true
}

# wait_for PATTERN [COUNT]: wait until the program's log holds COUNT lines matching
# PATTERN (the window prints the app's messages), so that a loaded machine slows the test
# down instead of failing it.
wait_for() {
  local n=${2:-1}
  for _ in $(seq 1 300); do
    [ "$(grep -c -- "$1" "$log" || true)" -ge "$n" ] && return 0
    sleep 0.1
  done
  echo "FAIL: waited 30 s for '$1' (x$n) in the program's output"; cat "$log"; exit 1
}

# close_window: press Escape and wait for the program to end by itself.
close_window() {
  xdotool key --window "$wid" Escape
  for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  wait "$pid"
  trap - EXIT
}

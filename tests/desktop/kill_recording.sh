#!/usr/bin/env bash
# kill_recording.sh — a recording survives kill -9.
#
# Usage (inside xvfb-run): kill_recording.sh DESKTOP REPLAY_TOOL SCENE WORKDIR
# Starts the window recording SCENE, adds bodies for a while, kills the program with
# SIGKILL (no chance to write anything at exit), and checks that the replay file it
# left is whole: pogon-replay verify passes on it, and it holds at least the first
# second of the session (the recorder rewrites the file once a second).
set -euo pipefail
desktop=$1 replay=$2 scene=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
file=$work/killed.pgr
source "$(dirname "$0")/window_lib.sh"
start_window "$work/log" "$desktop" --scene "$scene" -o "$file"
xdotool key --window "$wid" 3; wait_for "tool ball"
for x in 100 200 300 400 500 600 700; do
  xdotool mousemove --window "$wid" $x 200 click 1
  sleep 0.4
done
wait_for "Added a ball"
sleep 1.5   # the recorder's next write comes within a second
kill -9 $pid
wait $pid 2>/dev/null || true
trap - EXIT
cat "$work/log"
[ -f "$file" ] || { echo "FAIL: no replay file after kill -9"; exit 1; }
"$replay" verify "$file"
frames=$("$replay" info "$file" | awk '$1 == "frames" { print $2 }')
makes=$("$replay" info "$file" | awk '$1 == "make" { print $2 }')
echo "after kill -9: $frames frames, ${makes:-0} bodies added"
[ "$frames" -ge 60 ] || { echo "FAIL: expected at least the first second (60 frames), got $frames"; exit 1; }
[ "${makes:-0}" -ge 1 ] || { echo "FAIL: expected the bodies added before the last second"; exit 1; }
echo "kill -9 recording: OK"

#!/usr/bin/env bash
# window_segments.sh — a preset change and the scene picker start new recordings, and
# the earlier ones are kept.
#
# Usage (inside xvfb-run): window_segments.sh DESKTOP REPLAY_TOOL SCENE WORKDIR
# Starts the window on SCENE recording to WORKDIR/s.pgr, waits, presses F9 (preset fast:
# the app restarts from the current state with 2 substeps), waits, presses Tab (the next
# scene of SCENE's folder), waits and closes. Expects s.pgr (SCENE, 4 substeps),
# s-2.pgr (2 substeps) and s-3.pgr (another scene), each verifying.
set -euo pipefail
desktop=$1 replay=$2 scene=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
"$desktop" --scene "$scene" -o "$work/s.pgr" >"$work/log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^pogon$' | head -n 1)
xdotool windowfocus --sync "$wid" || true
log=$work/log
# Wait until the program's log holds COUNT lines matching PATTERN, so that a loaded
# machine slows the test down instead of failing it.
wait_for() { # PATTERN [COUNT]
  local n=${2:-1}
  for _ in $(seq 1 300); do
    [ "$(grep -c -- "$1" "$log" || true)" -ge "$n" ] && return 0
    sleep 0.1
  done
  echo "FAIL: waited 30 s for '$1' (x$n) in the program's output"; cat "$log"; exit 1
}
sleep 1.5; xdotool key --window "$wid" F9; wait_for "now $work/s-2.pgr"
sleep 1.5; xdotool key --window "$wid" Tab; wait_for "now $work/s-3.pgr"
sleep 1.5; xdotool key --window "$wid" Escape
for _ in $(seq 1 100); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
wait $pid
trap - EXIT
cat "$work/log"
for f in s s-2 s-3; do "$replay" verify "$work/$f.pgr"; done
sub() { "$replay" info "$work/$1.pgr" | sed -n 's/^  step .*, \([0-9]*\) substeps.*/\1/p'; }
bodies() { "$replay" info "$work/$1.pgr" | sed -n 's/^  bodies *\([0-9]*\).*/\1/p'; }
echo "substeps: $(sub s) $(sub s-2) $(sub s-3); bodies: $(bodies s) $(bodies s-2) $(bodies s-3)"
[ "$(sub s)" = 4 ] && [ "$(sub s-2)" = 2 ] || { echo "FAIL: expected 4 substeps, then 2 after F9"; exit 1; }
cmp -s <("$replay" info "$work/s-2.pgr" | sed -n '/^scene/,/^commands/p') \
       <("$replay" info "$work/s-3.pgr" | sed -n '/^scene/,/^commands/p') &&
  { echo "FAIL: Tab should have loaded another scene"; exit 1; }
grep -q "a new recording (scene or preset changed): now $work/s-3.pgr" "$work/log"
echo "window segments: OK"

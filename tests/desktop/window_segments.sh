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
source "$(dirname "$0")/window_lib.sh"
start_window "$work/log" "$desktop" --scene "$scene" -o "$work/s.pgr"
sleep 1.5; xdotool key --window "$wid" F9; wait_for "now $work/s-2.pgr"
sleep 1.5; xdotool key --window "$wid" Tab; wait_for "now $work/s-3.pgr"
sleep 1.5; close_window
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

#!/usr/bin/env bash
# window_playback.sh — the window plays a replay file and jumps in it.
#
# Usage (inside xvfb-run): window_playback.sh DESKTOP REPLAY_FILE WORKDIR
# Opens REPLAY_FILE from the command line, pauses, jumps to the end (End), takes a
# screenshot (F12), jumps back to the start (Home), steps once (N), takes another, and
# closes the window. The screenshots must be of the last frame and of frame 1, and each
# must show the bodies where the replay has them (--check-image).
set -euo pipefail
desktop=$1 file=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
log=$work/window.log
source "$(dirname "$0")/window_lib.sh"
start_window "$log" "$desktop" --play "$file" -o "$work/live.pgr" --screenshot "$work/shot"
act() { xdotool "$@"; sleep 0.4; }
n=$("$desktop" --headless --play "$file" | sed -n 's/.*: frame \([0-9]*\) of \([0-9]*\),.*/\2/p')
act key --window "$wid" space                                    # pause
act key --window "$wid" End; wait_for "jumped to frame $n"       # jump to the last frame
act key --window "$wid" F12; wait_for "screenshot of frame" 1
act key --window "$wid" Home; wait_for "jumped to frame 0"       # back to frame 0 (a kept snapshot)
act key --window "$wid" n; wait_for "jumped to frame 1\$"        # one step: frame 1
act key --window "$wid" F12; wait_for "screenshot of frame" 2
close_window
cat "$log"
mapfile -t shots < <(sed -n 's/.*screenshot of frame \([0-9]*\) written to \(.*\)$/\1 \2/p' "$log")
[ ${#shots[@]} -eq 2 ] || { echo "FAIL: expected 2 screenshots, got ${#shots[@]}"; exit 1; }
[ "${shots[0]%% *}" = "$n" ] || { echo "FAIL: End should show frame $n, the screenshot is of frame ${shots[0]%% *}"; exit 1; }
[ "${shots[1]%% *}" = 1 ] || { echo "FAIL: Home then N should show frame 1, the screenshot is of frame ${shots[1]%% *}"; exit 1; }
for s in "${shots[@]}"; do
  "$desktop" --headless --play "$file" --until "${s%% *}" --check-image "${s#* }"
done
echo "window playback: OK"

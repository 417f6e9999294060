#!/usr/bin/env bash
# window_session.sh — the desktop window driven like a user, under a virtual X server.
#
# Usage (CTest runs it inside xvfb-run): window_session.sh DESKTOP REPLAY_TOOL SCENE WORKDIR
# Starts pogon-desktop on SCENE, then with xdotool: adds a ball and a box, selects the
# ball with the move tool and drags it, pushes it with the arrow keys, pins the scene's
# triangle to the world above it (tool 9), toggles gravity off and on, pauses, takes a
# screenshot (F12), steps once (N), takes another, and closes the window (Escape). Then
# it checks that
#   - the replay the program wrote verifies (pogon-replay verify) and holds the adds,
#     the drag (a mouse joint) and key pushes, the pin, the gravity toggles;
#   - the two screenshots are of consecutive frames (a single step while paused);
#   - each screenshot shows the bodies where the replay has them at its frame
#     (pogon-desktop --headless --play --until F --check-image).
set -euo pipefail
desktop=$1 replay=$2 scene=$3 work=$4
rm -rf "$work"; mkdir -p "$work"
log=$work/window.log

# The default view: world (0, 9) at the centre of 960x600, 22 px per metre.
px() { awk -v x="$1" 'BEGIN { printf "%d", 480 + x * 22 }'; }
py() { awk -v y="$1" 'BEGIN { printf "%d", 300 - (y - 9) * 22 }'; }

source "$(dirname "$0")/window_lib.sh"
start_window "$log" "$desktop" --scene "$scene" -o "$work/session.pgr" --screenshot "$work/shot"
act() { xdotool "$@"; sleep 0.25; }

act key --window "$wid" 3; wait_for "tool ball"                                  # tool 3: ball
act mousemove --window "$wid" "$(px -8)" "$(py 6)" click 1; wait_for "Added a ball"   # a ball at (-8, 6)
act key --window "$wid" 5; wait_for "tool box"                                   # tool 5: box
act mousemove --window "$wid" "$(px 0)" "$(py 9)" click 1; wait_for "Added a box"     # a box at (0, 9)
sleep 1.5                                                                        # let them fall
act key --window "$wid" 1; wait_for "tool move"                                  # tool 1: move
act mousemove --window "$wid" "$(px -10)" "$(py 0.5)"                            # the scene's ball rests at (-10, 0.5)
act mousedown --window "$wid" 1; wait_for "Selected body"                        # select it and hold it
for x in -9.5 -9 -8.5 -8 -7.5 -7; do act mousemove --window "$wid" "$(px "$x")" "$(py 2)"; done
act mouseup --window "$wid" 1
act keydown --window "$wid" Right; sleep 0.5; act keyup --window "$wid" Right   # push the selected body
act key --window "$wid" 9; wait_for "tool pin"                                   # tool 9: pin
act mousemove --window "$wid" "$(px 2)" "$(py 0.3)" click 1; wait_for "Pin body" # the scene's triangle rests at (2, 0.35)
act mousemove --window "$wid" "$(px 2)" "$(py 4)" click 1; wait_for "Pinned body"   # to the world 3.7 m above it
act key --window "$wid" g; wait_for "Gravity off"
sleep 0.5
act key --window "$wid" g; wait_for "Gravity on"
sleep 0.5
act key --window "$wid" p                                                        # pause
act key --window "$wid" F12; wait_for "screenshot of frame" 1                    # screenshot of frame F
act key --window "$wid" n                                                        # one step
act key --window "$wid" F12; wait_for "screenshot of frame" 2                    # screenshot of frame F + 1
close_window
cat "$log"

file=$work/session.pgr
grep -q "recording to $file" "$log"
grep -q "recorded [0-9]* frames to $file" "$log"
"$replay" verify "$file"
info=$("$replay" info "$file")
count() { awk -v k="$1" '$1 == k { print $2 }' <<<"$info"; }
makes=$(count make); grav=$(count set_gravity); mouse=$(count create_mouse_joint); force=$(count apply_force)
pins=$(count create_revolute_joint)
echo "make ${makes:-0}, set_gravity ${grav:-0}, create_mouse_joint ${mouse:-0}, apply_force ${force:-0}, create_revolute_joint ${pins:-0}"
[ "${makes:-0}" -ge 2 ] || { echo "FAIL: expected the ball and the box to be added (2 make commands)"; exit 1; }
[ "${grav:-0}" -ge 2 ] || { echo "FAIL: expected gravity off and on (2 set_gravity commands)"; exit 1; }
[ "${mouse:-0}" -ge 1 ] || { echo "FAIL: expected the drag as a mouse joint"; exit 1; }
[ "${force:-0}" -ge 1 ] || { echo "FAIL: expected the key push as apply_force"; exit 1; }
[ "${pins:-0}" -ge 1 ] || { echo "FAIL: expected the pin as a revolute joint"; exit 1; }

mapfile -t shots < <(sed -n 's/.*screenshot of frame \([0-9]*\) written to \(.*\)$/\1 \2/p' "$log")
[ ${#shots[@]} -eq 2 ] || { echo "FAIL: expected 2 screenshots, got ${#shots[@]}"; exit 1; }
f1=${shots[0]%% *} f2=${shots[1]%% *}
[ "$f2" -eq $(( f1 + 1 )) ] || { echo "FAIL: one step while paused should go from frame $f1 to $(( f1 + 1 )), got $f2"; exit 1; }
for s in "${shots[@]}"; do
  "$desktop" --headless --play "$file" --until "${s%% *}" --check-image "${s#* }"
done
echo "window session: OK"

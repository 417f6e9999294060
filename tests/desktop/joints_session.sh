#!/usr/bin/env bash
# joints_session.sh — the joint tools without a window: records joints_session.script
# (a pin to the world, a rod, a spring, a mouse-joint drag, the pin deleted) on the demo
# scene, then checks that
#   - the recording verifies checkpoint by checkpoint (pogon-replay verify) and plays in
#     the desktop's headless player;
#   - it holds the joint commands the tools give: a revolute joint, two distance joints,
#     a mouse joint whose target moved, the drag's and the pin's destroy_joint, and the
#     pin's anchor removed with it.
# Usage: joints_session.sh DESKTOP REPLAY_TOOL SCENE SCRIPT WORKDIR
set -euo pipefail
desktop=$1 replay=$2 scene=$3 script=$4 work=$5
rm -rf "$work"; mkdir -p "$work"
file=$work/joints.pgr
"$desktop" --headless --scene "$scene" --script "$script" --frames 300 -o "$file" | tee "$work/record.log"
grep -q "Pinned body [0-9]* to the world" "$work/record.log"
grep -q "Added a rod 4 m long between two bodies" "$work/record.log"
grep -q "Added a spring .* between a body and the world" "$work/record.log"
grep -q "Deleted joint [0-9]* (a pin)" "$work/record.log"
"$replay" verify "$file"
"$desktop" --headless --play "$file" | tee "$work/play.log"
grep -q "0 diverged" "$work/play.log"
info=$("$replay" info "$file")
count() { awk -v k="$1" '$1 == k { print $2 }' <<<"$info"; }
expect() { # NAME AT_LEAST
  local n; n=$(count "$1"); n=${n:-0}
  echo "$1 $n (at least $2)"
  [ "$n" -ge "$2" ] || { echo "FAIL: expected at least $2 $1 commands"; exit 1; }
}
expect create_revolute_joint 1
expect create_distance_joint 2
expect create_mouse_joint 1
expect set_mouse_target 1
expect destroy_joint 2
expect destroy_body 1
echo "joints session: OK"

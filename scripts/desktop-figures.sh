#!/usr/bin/env bash
# desktop-figures.sh — measure pogon-desktop's figures and write them to a results file,
# from which tools/docs/desktop_table.js renders docs/desktop.md's table (docs/generated.md).
#
# Usage: scripts/desktop-figures.sh [BUILD_DIR] [RESULTS]
#   BUILD_DIR: default build/release, built already; RESULTS: default docs/results/desktop.tsv.
#   Then: node tools/docs/regions.js --update
#
# Measures, on this machine, under xvfb-run with SDL's software renderer:
#   - frames per second of the window (one step per drawn frame, no vsync) with the
#     pyramid awake (scenes/pyramid.scene, sleeping off) and with 2 000 circles (a scene
#     this script writes), 5 s after a 1 s warm-up;
#   - the replay file's bytes per minute of a typical session (a generated one-minute
#     script: adds, key pushes, a drag, gravity toggles), recorded headless;
#   - the time to jump to the last frame of a 10-minute replay (36 000 frames, the same
#     script pattern for ten minutes): straight from frame 0 in a fresh player, and after
#     playing through (from the nearest kept snapshot), with the snapshots' memory.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build/release}
results=${2:-docs/results/desktop.tsv}
desktop=$build/ports/desktop/pogon-desktop
[ -x "$desktop" ] || { echo "desktop-figures: build $desktop first (cmake --build --preset release)" >&2; exit 2; }
work=$build/desktop-figures
rm -rf "$work"; mkdir -p "$work"

# 2 000 balls of radius 0.25 m on a 50 x 40 grid in a 40 m bin.
{
  echo "pogon-scene 1"
  echo "# circles: 2 000 balls for pogon-desktop's frames-per-second figure (scripts/desktop-figures.sh)"
  echo "max_bodies 2100"; echo "max_shapes 2100"; echo "max_contacts 16000"
  echo "wall 42 1 position 0 -0.5"; echo "wall 1 40 position -20.5 20"; echo "wall 1 40 position 20.5 20"
  awk 'BEGIN { for (j = 0; j < 40; j++) for (i = 0; i < 50; i++) printf "ball 0.25 position %.2f %.2f\n", -14.7 + i * 0.6, 0.3 + j * 0.6 }'
} >"$work/circles.scene"

# A typical session: every 10 s (600 ticks) add a body, push the player left and right
# with the keys, drag it there and back, toggle gravity off and on.
session_script() { # MINUTES
  awk -v minutes="$1" 'BEGIN {
    split("ball box star capsule triangle", kinds, " ");
    for (t = 0; t < minutes * 3600; t += 600) {
      k = kinds[(t / 600) % 5 + 1]; x = -16 + (t / 600 % 9) * 3.5;
      if (k == "triangle") { printf "%d tool triangle\n%d click %g 12\n%d click %g 12\n%d click %g 13\n", t, t+2, x, t+4, x+1, t+6, x+0.5 }
      else printf "%d tool %s\n%d click %g 12\n", t, k, t+2, x;
      printf "%d tool move\n%d click 12 1\n", t+60, t+62;
      printf "%d key left down\n%d key left up\n%d key right down\n%d key right up\n", t+100, t+160, t+200, t+260;
      printf "%d down 12 1\n%d move 10 1\n%d move 12 1\n%d up 12 1\n", t+300, t+320, t+340, t+360;
      printf "%d gravity\n%d gravity\n", t+400, t+460;
    } }'
}
session_script 1 >"$work/minute.script"
session_script 10 >"$work/ten.script"

stamp=$(date -u '+%Y-%m-%d %H:%M UTC')
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
machine="$cpu, $(nproc) cores, $(uname -sm)"
load=$(cut -d' ' -f1-3 /proc/loadavg)

bench() { # SCENE EFFECTS VIEW...
  SDL_RENDER_DRIVER=software xvfb-run -a -s "-screen 0 1280x800x24" \
    "$desktop" --quiet --scene "$1" --effects "$2" --bench 5 -o "$work/bench.pgr" "${@:3}" | sed -n 's/^bench: //p'
}
pyramid=$(bench scenes/pyramid.scene gravity+rotation+friction+restitution+damping+continuous)
circles=$(bench "$work/circles.scene" all --view 0 13 19)

"$desktop" --headless --quiet --scene scenes/demo.scene --script "$work/minute.script" --frames 3600 -o "$work/minute.pgr" >/dev/null
minute_bytes=$(stat -c %s "$work/minute.pgr")
minute_frames=$("$desktop" --headless --play "$work/minute.pgr" | sed -n 's/.*: frame [0-9]* of \([0-9]*\),.*/\1/p')
"$desktop" --headless --quiet --scene scenes/demo.scene --script "$work/ten.script" --frames 36000 -o "$work/ten.pgr" >/dev/null
ten_bytes=$(stat -c %s "$work/ten.pgr")
cold=$("$desktop" --headless --play "$work/ten.pgr" --until 36000 | sed -n 's/^until //p')
warm=$("$desktop" --headless --play "$work/ten.pgr" --jump 0 --jump 36000 --jump 35999 | sed -n 's/^\(jump 3[0-9]*\|snapshots\)/\1/p')

# pogon-desktop's own lines, as it printed them; the table's wording is desktop_table.js's.
{
  echo "# pogon-desktop figures: one a line, tab-separated: figure, value (as pogon-desktop printed it)"
  echo "# measured: $stamp"
  echo "# machine: $machine"
  echo "# load: $load"
  echo "# command: scripts/desktop-figures.sh${*:+ $*}"
  printf 'window_pyramid\t%s\n' "$pyramid"
  printf 'window_circles\t%s\n' "$circles"
  printf 'minute_bytes\t%s\n' "$minute_bytes"
  printf 'minute_frames\t%s\n' "$minute_frames"
  printf 'ten_minutes_bytes\t%s\n' "$ten_bytes"
  printf 'jump_fresh\t%s\n' "$cold"
  printf 'jumps_played\t%s\n' "$(echo "$warm" | paste -sd';' | sed 's/;/; /g')"
} >"$results"
cat "$results"
echo "desktop-figures: wrote $results; render the documents with node tools/docs/regions.js --update" >&2

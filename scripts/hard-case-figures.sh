#!/usr/bin/env bash
# hard-case-figures.sh — run the hard-case suite and commit what it measured.
#
# Usage: scripts/hard-case-figures.sh [BUILD_DIR]     (default: build/release, built)
#
# Runs the stability programs of BUILD_DIR/tests (docs/hard-cases.md: the hard cases, both
# groups, the stacks, bounces, envelope shapes, houses of cards, random piles and the heap) with
# POGON_HARD_RESULTS set, so that each appends every figure it checks against a bound
# (tests/stability/hard_results.h), and writes them to docs/results/hard_cases.tsv under
# three lines saying when, on what machine and by which command. A failing program
# stops the script and writes nothing. Then `node tools/docs/regions.js --update`
# renders the tables of docs/hard-cases.md from that file (docs/generated.md). The slow
# group (a million-step spin, an hour of simulated time) takes the longest; run this
# under `nice` on a shared machine.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build/release}
programs=(test_hard_cases test_hard_cases_slow test_stacking test_bounce_energy test_envelope_shapes
          test_house_of_cards test_random_piles test_heap_sleeps test_heap_sleeps_slow)
out=docs/results/hard_cases.tsv
tmp=$(mktemp "${TMPDIR:-/tmp}/pogon-hard.XXXXXX")
trap 'rm -f "$tmp" "$tmp.tsv"' EXIT
for p in "${programs[@]}"; do
  exe="$build/tests/$p"
  [ -x "$exe" ] || { echo "hard-case-figures: $exe is not built (cmake --build $build)" >&2; exit 2; }
  echo "hard-case-figures: $p" >&2
  POGON_HARD_RESULTS="$tmp" "$exe" > /dev/null
done
# the commit measured; "+changes" when the library or the tests differ from it
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- src include tests/stability tests/unit tools/scenes 2>/dev/null || commit="$commit+changes"
machine="$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1), $(uname -sm)"
{
  echo "# pogon hard-case figures: program, function, figure, value, bound ('-': printed, not asserted)"
  echo "# measured: $(date -u +%Y-%m-%d), pogon $commit"
  echo "# machine: $machine"
  echo "# command: scripts/hard-case-figures.sh $build"
  cat "$tmp"
} > "$tmp.tsv"
mkdir -p "$(dirname "$out")"
mv "$tmp.tsv" "$out"
echo "hard-case-figures: $(grep -vc '^#' "$out") figures in $out" >&2

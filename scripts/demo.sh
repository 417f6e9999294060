#!/usr/bin/env bash
# demo.sh — the main job: install what is missing, build the release preset and run
# the example programs.
#
# Usage: scripts/demo.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

stage() { printf '\n==== %s\n' "$*"; }

stage "setup: scripts/setup-deps.sh"
scripts/setup-deps.sh

stage "configure and build: release preset (build/release)"
cmake --preset release
cmake --build --preset release --parallel "$(nproc 2>/dev/null || echo 2)"

# The example programs, in the order they are shown.
examples=(
  build/release/examples/pogon-math-demo
)
for exe in "${examples[@]}"; do
  stage "run: $exe"
  "$exe"
done

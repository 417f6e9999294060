#!/bin/sh
# static-analysis.sh — clang-tidy and cppcheck on the library's sources (src/core, src/io), which must
# have no findings: a finding that is not a bug is suppressed where it stands, with its
# reason (NOLINT(check): reason; /* cppcheck-suppress id ; reason */).
#
# Usage: scripts/static-analysis.sh clang-tidy|cppcheck|all BUILD_DIR
#   clang-tidy  the checks of .clang-tidy (bugprone-*, cert-*, clang-analyzer-*) on each
#               src/*/*.c, with the compile commands of BUILD_DIR (compile_commands.json),
#               nproc files at a time. The analyser explores at most POGON_ANALYZER_NODES
#               (default 20000) nodes per function instead of its default 225000,
#               which spends most of its time on a few long functions (set 225000 for a
#               deep run)
#   cppcheck    cppcheck's warning, portability and performance checks, C99, with the
#               defines the build uses
# The CTest tests static_clang_tidy and static_cppcheck (label static, the clang preset)
# run it. Exit 0: no findings; 1: findings (printed); 2: usage or a missing tool (77 when
# the tool is not installed: scripts/setup-deps.sh installs both).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
what=${1:-}
build=${2:-}
if [ -z "$what" ] || [ -z "$build" ]; then
  sed -n '2,16p' "$0" >&2
  exit 2
fi
jobs=$(nproc 2>/dev/null || echo 2)
status=0

run_clang_tidy() {
  tidy=$(command -v clang-tidy || command -v clang-tidy-14 || true)
  if [ -z "$tidy" ]; then echo "static-analysis: clang-tidy not found (scripts/setup-deps.sh)"; exit 77; fi
  if [ ! -f "$build/compile_commands.json" ]; then
    echo "static-analysis: no $build/compile_commands.json (configure with CMAKE_EXPORT_COMPILE_COMMANDS=ON)"; exit 2
  fi
  out=$(mktemp)
  # one file per process, nproc at a time; --quiet leaves only the findings
  nodes=${POGON_ANALYZER_NODES:-20000}
  if ! ls "$root"/src/*/*.c | xargs -P "$jobs" -n 1 "$tidy" --quiet -p "$build" \
         --extra-arg=-Xclang --extra-arg=-analyzer-config --extra-arg=-Xclang --extra-arg=max-nodes="$nodes" \
         > "$out" 2>&1; then status=1; fi
  if grep -q 'warning:\|error:' "$out"; then
    cat "$out"
    echo "static-analysis: clang-tidy found $(grep -c 'warning:\|error:' "$out") problems in src/"
    status=1
  elif [ "$status" -ne 0 ]; then
    cat "$out"; echo "static-analysis: clang-tidy failed"
  else
    echo "static-analysis: clang-tidy: no findings in $(ls "$root"/src/*/*.c | wc -l) files"
  fi
  rm -f "$out"
}

run_cppcheck() {
  if ! command -v cppcheck > /dev/null; then echo "static-analysis: cppcheck not found (scripts/setup-deps.sh)"; exit 77; fi
  bits=$(sed -n 's/^PG_TRIG_TABLE_BITS:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null || true)
  if ! cppcheck --std=c99 --enable=warning,portability,performance --inline-suppr --error-exitcode=1 --quiet \
         -j "$jobs" -I "$root/include" -I "$root/src/core" -DPG_TRIG_TABLE_BITS="${bits:-12}" \
         --suppress=missingIncludeSystem "$root/src"; then
    echo "static-analysis: cppcheck found problems in src/ (above)"
    status=1
  else
    echo "static-analysis: cppcheck: no findings"
  fi
}

case $what in
  clang-tidy) run_clang_tidy ;;
  cppcheck) run_cppcheck ;;
  all) run_cppcheck; run_clang_tidy ;;
  *) echo "static-analysis: unknown check $what" >&2; exit 2 ;;
esac
exit "$status"

#!/usr/bin/env bash
# build_and_run.sh — the determinism_* tests (tests/targets/CMakeLists.txt).
#
#   build_and_run.sh native OUTPUT [RUNNER...] PROBE
#       Run the native pogon-probe (optionally under an emulator) and write its output to
#       OUTPUT: the reference the other targets are compared with (a CTest fixture, so it
#       is produced in the same test run, never a stored hash).
#
#   build_and_run.sh target NAME WORK_DIR NATIVE_OUTPUT SOURCES_FILE [--root SRC_DIR]
#                    [--run WORD]... [--arg WORD]... [--cache CACHE_DIR]
#                    [--skip-native REGEX] -- CC [FLAG...]
#       In SRC_DIR (default: the current directory; relative paths in SOURCES_FILE and in
#       -I flags are relative to it), compile every file listed in SOURCES_FILE (one a
#       line: the library's sources, tools/scenes/scenes.c, tools/probe/probe.c) with
#       `CC FLAG...` in one call, run the program (prefixed by the --run words: qemu-arm,
#       node, ...; followed by the --arg words) in WORK_DIR, and compare its output line
#       by line with NATIVE_OUTPUT, less the native lines that match --skip-native (which
#       the program is built not to print: the Cortex-M0+ firmware leaves out rain 1000).
#       Exit 0 when every line is identical, 1 when not (or when the build or the run
#       fails), 77 (CTest's SKIP_RETURN_CODE) when the compiler or the runner is missing.
#       The program is reused while the compile command and the contents of the sources
#       and of the headers and linker scripts under the -I directories are unchanged
#       (emcc takes ~10 s): it is kept in CACHE_DIR/NAME-STAMP/ (default CACHE_DIR:
#       WORK_DIR), where STAMP hashes all of those, so build trees may share one
#       CACHE_DIR (scripts/test.sh does, for its presets; tests/targets compiles with
#       paths relative to SRC_DIR for that).
set -uo pipefail

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", b - a }'; }

mode=${1:-}
shift || true

if [ "$mode" = native ]; then
  out=$1; shift
  t0=$(now)
  if ! "$@" >"$out.tmp"; then
    echo "native probe failed: $*" >&2
    exit 1
  fi
  mv "$out.tmp" "$out"
  echo "native probe ($(elapsed "$t0") s): $*"
  cat "$out"
  exit 0
fi

if [ "$mode" != target ] || [ $# -lt 6 ]; then
  sed -n '2,/^set -uo/p' "$0" | sed '$d' >&2
  exit 2
fi
name=$1 work=$2 native=$3 sources_file=$4
shift 4
runner=()
program_args=()
cache=$work
root=.
skip_native=
while [ $# -gt 0 ] && [ "$1" != -- ]; do
  case $1 in
    --run) runner+=("$2"); shift 2 ;;
    --root) root=$2; shift 2 ;;
    --skip-native) skip_native=$2; shift 2 ;;
    --arg) program_args+=("$2"); shift 2 ;;
    --cache) cache=${2:-$work}; [ -n "$cache" ] || cache=$work; shift 2 ;;
    *) echo "build_and_run.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
shift  # --
compile=("$@")

# Missing tools: skip (scripts/setup-deps.sh installs them all).
for tool in "${compile[0]}" ${runner[0]:+"${runner[0]}"}; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIPPED determinism_$name: '$tool' not found (scripts/setup-deps.sh installs it)"
    exit 77
  fi
done
if [ ! -s "$native" ]; then
  echo "determinism_$name: no native output at $native (the determinism_native fixture failed?)" >&2
  exit 1
fi

mapfile -t sources <"$sources_file"
mkdir -p "$work" "$cache"
work=$(cd "$work" && pwd) cache=$(cd "$cache" && pwd) native=$(cd "$(dirname "$native")" && pwd)/$(basename "$native")
if ! cd "$root"; then
  echo "determinism_$name: no source directory $root (build the project first: it copies the sources there)" >&2
  exit 1
fi
case ${compile[0]} in
  *emcc*) program_name=probe.js ;;
  *) program_name=probe ;;
esac

# Stamp: the command line, the compiler's version, the sources and every header and
# linker script under the -I directories.
include_dirs=()
for flag in "${compile[@]}"; do
  case $flag in -I?*) include_dirs+=("${flag#-I}") ;; esac
done
stamp=$( {
  printf '%s\n' "${compile[@]}" "${sources[@]}"
  "${compile[0]}" --version 2>/dev/null | head -n 1
  cat "${sources[@]}"
  find "${include_dirs[@]}" -maxdepth 2 -type f \( -name '*.h' -o -name '*.inc' -o -name '*.ld' \) -print 2>/dev/null | LC_ALL=C sort | xargs cat
} | sha256sum | cut -c1-16)
bin_dir="$cache/$name-$stamp"
program="$bin_dir/$program_name"

t0=$(now)
if [ -f "$program" ]; then
  echo "build: up to date ($program)"
else
  # Build in a private directory, then rename it into place: concurrent runs sharing the
  # cache never see half a program.
  tmp=$(mktemp -d "$cache/.$name-XXXXXX")
  echo "build: ${compile[*]} <${#sources[@]} sources: $sources_file> -o $program"
  if ! "${compile[@]}" "${sources[@]}" -o "$tmp/$program_name"; then
    rm -rf "$tmp"
    echo "determinism_$name: build FAILED" >&2
    exit 1
  fi
  if ! mv -T "$tmp" "$bin_dir" 2>/dev/null; then
    rm -rf "$tmp"  # another run built the same program meanwhile
  fi
  echo "build: $(elapsed "$t0") s"
  # Programs of older sources: drop those unused for an hour.
  find "$cache" -mindepth 1 -maxdepth 1 -name "$name-*" ! -name "$name-$stamp" -mmin +60 -exec rm -rf {} + 2>/dev/null
fi
touch "$bin_dir"

t0=$(now)
if ! (cd "$work" && ${runner[0]:+"${runner[@]}"} "$program" ${program_args[0]:+"${program_args[@]}"}) >"$work/output.txt" 2>"$work/stderr.txt"; then
  echo "determinism_$name: run FAILED: ${runner[*]} $program" >&2
  cat "$work/stderr.txt" >&2
  cat "$work/output.txt"
  exit 1
fi
echo "run: ${runner[*]:+${runner[*]} }$program${program_args[0]:+ ${program_args[*]}} ($(elapsed "$t0") s)"

# Line by line: label count steps hash [world=hash]
if [ -n "$skip_native" ]; then
  mapfile -t want < <(grep -Ev -- "$skip_native" "$native")
  echo "not expected from $name (built without them): $(grep -cE -- "$skip_native" "$native") native line(s) matching '$skip_native'"
else
  mapfile -t want <"$native"
fi
mapfile -t got <"$work/output.txt"
status=0
n=${#want[@]}
[ ${#got[@]} -gt "$n" ] && n=${#got[@]}
printf '%-8s %-44s %s\n' "" "native" "$name"
for ((i = 0; i < n; ++i)); do
  a=${want[i]:-<missing>} b=${got[i]:-<missing>}
  if [ "$a" = "$b" ]; then
    printf '%-8s %s\n' "same" "$a"
  else
    printf '%-8s %s\n%-8s %s\n' "DIFFERS" "native: $a" "" "$name: $b"
    status=1
  fi
done
if [ "$status" -eq 0 ]; then
  echo "determinism_$name: all $n lines identical to the native build"
else
  echo "determinism_$name: output differs from the native build (rerun the probe with --every 10 to find the first step that differs)" >&2
fi
exit "$status"

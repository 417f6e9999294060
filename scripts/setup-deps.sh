#!/usr/bin/env bash
# setup-deps.sh — install the Debian packages pogon's builds and tests need.
#
# Usage: scripts/setup-deps.sh [--check] [GROUP...]
#   GROUP    one or more of the groups below; default: the groups scripts/test.sh
#            and scripts/demo.sh need (build test wasm cross web desktop cortex-m)
#   --check  only report what is missing; exit 1 if anything is
#
# Idempotent: packages already installed (dpkg says "install ok installed") are left
# alone, and when nothing is missing apt is not touched at all. Otherwise it runs
# `apt-get update` once and installs only the missing packages, non-interactively.
# Works as root, or through sudo for another user.
#
# TO ADD A PACKAGE: add a line "group|package|why it is needed" to PACKAGES below. A new
# group is installed only when named on the command line, or after it is added to
# DEFAULT_GROUPS (do that when scripts/test.sh starts to need it).
set -euo pipefail

PACKAGES=(
  # --- build: compile the library, the examples and the tools -----------------------
  "build|gcc|the default C compiler (gcc 12 also ships the ASan/UBSan runtimes of the debug-asan preset)"
  "build|libc6-dev|C library headers and crt files for linking programs"
  "build|make|the generator CMake uses by default (Unix Makefiles)"
  "build|cmake|the build system; CMakePresets.json (schema 6) needs 3.25, Debian bookworm has 3.25"
  "build|pkg-config|the consumer test compiles against the installed pogon.pc"
  "build|binutils|objdump, for the no_float_in_library test that disassembles the library"
  # --- test: the unit tests and the second compiler ----------------------------------
  "test|libcmocka-dev|unit-test framework (CMocka 1.1.5) for the tests in tests/"
  "test|clang|the second compiler (clang preset): warnings and gcc-vs-clang determinism"
  "test|doxygen|the API reference (target docs) and docs_api_complete, which fails on an undocumented public item"
  "test|clang-tidy|static analysis of src/ (scripts/static-analysis.sh, CTest static_clang_tidy in the clang preset)"
  "test|cppcheck|static analysis of src/ (scripts/static-analysis.sh, CTest static_cppcheck in the clang preset)"
  "test|llvm|llvm-profdata and llvm-cov: the clang preset's coverage report of src/ (tools/coverage/coverage.py, docs/coverage.md)"
  "test|libclang-rt-dev|clang's runtimes (compiler-rt, libclang-rt-14-dev): libFuzzer and ASan/UBSan for the fuzz targets the clang preset builds (tests/fuzz); clang only recommends it"
  # --- wasm, cross: the determinism_* tests (tests/targets) build the probe for other
  # targets and compare its hashes with the native build's. scripts/test.sh runs them, so
  # both groups are in the default set. The cross compilers only *recommend* their C
  # libraries, and apt-get runs here with --no-install-recommends: list them explicitly.
  "wasm|emscripten|WebAssembly build (emscripten preset, determinism_wasm32); needs NODE_PATH=/usr/share/nodejs"
  "wasm|nodejs|runs the wasm32 programs (determinism_wasm32, the emscripten preset's tests)"
  "cross|gcc-arm-linux-gnueabihf|32-bit ARM cross compiler (determinism_arm32: another ISA, 32-bit long and pointers)"
  "cross|libc6-dev-armhf-cross|C library headers and static libc for the ARM cross compiler"
  "cross|gcc-s390x-linux-gnu|big-endian cross compiler (determinism_s390x: byte order)"
  "cross|libc6-dev-s390x-cross|C library headers and static libc for the s390x cross compiler"
  "cross|qemu-user|runs the static ARM and s390x programs (qemu-arm, qemu-s390x); no binfmt needed"
  # --- desktop: pogon-desktop (ports/desktop) and its window tests (label desktop) ----
  "desktop|libsdl2-dev|SDL2: the desktop program's window, input and renderer"
  "desktop|libsdl2-gfx-dev|SDL2_gfx: filled polygons and circles and the 8x8 text font the desktop program draws with"
  "desktop|xvfb|a virtual X server: the window tests run pogon-desktop under xvfb-run"
  "desktop|xauth|xvfb-run needs it to authorise its clients"
  "desktop|xdotool|the window tests click and press keys in pogon-desktop's window"
  # --- cortex-m: the firmware of ports/cortex-m under qemu (determinism_cortex_m*) and
  # the flash limits (cortex_m_flash, tools/size/size_table.py); in the default set.
  "cortex-m|gcc-arm-none-eabi|bare-metal Cortex-M compiler (ports/cortex-m, tools/size)"
  "cortex-m|libnewlib-arm-none-eabi|C library (newlib-nano, librdimon for semihosting) for the Cortex-M firmware"
  "cortex-m|qemu-system-arm|runs the firmware on the mps2-an385 (Cortex-M3, M0+) and mps2-an386 (Cortex-M4) boards"
  "cortex-m|python3|runs tools/size/size_table.py (the size table and the cortex_m_flash test)"
  # --- web: the browser demo's end-to-end test (tests/web, label web) runs the page in
  # headless Chromium driven by playwright-core (npm, package.json); scripts/node-deps.sh
  # runs `npm ci`. npm itself comes with node; where node is Debian's, the npm group
  # (not a default: it would replace a node that brings its own npm) installs it.
  "web|chromium|headless browser for the web demo's end-to-end test and benchmark (tests/web, tools/bench/web_bench.mjs)"
  "npm|npm|the npm client, for scripts/node-deps.sh where node does not bring its own (installed on demand by that script)"
  # --- optional groups for later work: install with e.g. scripts/setup-deps.sh peers ---
  "peers|libbox2d-dev|Box2D 2.4.1, a float peer for the benchmarks"
  "peers|libchipmunk-dev|Chipmunk2D 7.0.3, a float peer for the benchmarks"
  "peers|g++|C++ compiler for the Box2D harness (tools/bench/peers; matter.js comes from npm, node and emcc from the wasm group)"
  "bench|valgrind|callgrind, which counts the instructions of pogon-bench's awake steps (docs/solver-design.md, Inlining)"
)
DEFAULT_GROUPS=(build test wasm cross web desktop cortex-m)

check_only=0
groups=()
for arg in "$@"; do
  case $arg in
    --check) check_only=1 ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    -*) echo "setup-deps: unknown option $arg" >&2; exit 2 ;;
    *) groups+=("$arg") ;;
  esac
done
if [ ${#groups[@]} -eq 0 ]; then groups=("${DEFAULT_GROUPS[@]}"); fi

known_groups=" "
for entry in "${PACKAGES[@]}"; do known_groups+="${entry%%|*} "; done
for g in "${groups[@]}"; do
  case $known_groups in
    *" $g "*) ;;
    *) echo "setup-deps: unknown group '$g' (known: $(tr ' ' '\n' <<<"$known_groups" | sort -u | xargs))" >&2; exit 2 ;;
  esac
done

installed() {
  [ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" = "install ok installed" ]
}

wanted=()
missing=()
for entry in "${PACKAGES[@]}"; do
  group=${entry%%|*}
  rest=${entry#*|}
  pkg=${rest%%|*}
  for g in "${groups[@]}"; do
    if [ "$g" = "$group" ]; then
      wanted+=("$pkg")
      installed "$pkg" || missing+=("$pkg")
    fi
  done
done

echo "setup-deps: groups: ${groups[*]}; ${#wanted[@]} packages, ${#missing[@]} missing${missing[*]:+: ${missing[*]}}"
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
if [ "$check_only" -eq 1 ]; then exit 1; fi

if ! command -v apt-get >/dev/null 2>&1; then
  echo "setup-deps: apt-get not found: install these packages by hand: ${missing[*]}" >&2
  exit 1
fi
as_root=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
  else
    echo "setup-deps: not root and no sudo: install these packages as root: ${missing[*]}" >&2
    exit 1
  fi
fi

# Wait for a concurrent apt/dpkg run instead of failing on its lock.
apt_opts=(-o DPkg::Lock::Timeout=600 -o Acquire::Retries=3)
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get "${apt_opts[@]}" update -q
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get "${apt_opts[@]}" install -y -q \
  --no-install-recommends "${missing[@]}"

still=()
for pkg in "${missing[@]}"; do installed "$pkg" || still+=("$pkg"); done
if [ ${#still[@]} -ne 0 ]; then
  echo "setup-deps: still missing after apt-get install: ${still[*]}" >&2
  exit 1
fi
echo "setup-deps: installed ${missing[*]}"

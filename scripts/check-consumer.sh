#!/bin/sh
# check-consumer.sh — install a pogon build into a temporary prefix and build the
# small consumer in cmake/consumer-test against it three ways:
#   1. find_package(pogon) + target pogon::pogon  (the exported CMake package)
#   2. a plain compiler line from `pkg-config --cflags --libs pogon`
#   3. add_subdirectory() of the source tree       (vendored use; options default OFF)
# Each consumer checks a few exact results and must exit 0.
#
# Usage: scripts/check-consumer.sh BUILD_DIR SOURCE_DIR [CONFIG]
# Environment (set by the CTest test consumer_find_package):
#   CMAKE_COMMAND  cmake to use (default: cmake)
#   POGON_CC       C compiler (default: cc)
#   POGON_CFLAGS   C flags the library was built with (e.g. sanitizers), reused here
#   POGON_LDFLAGS  linker flags for executables
#   POGON_VERSION  expected package version (checked against pkg-config --modversion)
#   POGON_TRIG_TABLE_BITS  expected PG_TRIG_TABLE_BITS in the pkg-config Cflags
set -eu

if [ $# -lt 2 ]; then
  echo "usage: $0 BUILD_DIR SOURCE_DIR [CONFIG]" >&2
  exit 2
fi
build=$1
src=$2
config=${3:-}
cmake=${CMAKE_COMMAND:-cmake}
cc=${POGON_CC:-cc}
cflags=${POGON_CFLAGS:-}
ldflags=${POGON_LDFLAGS:-}
consumer="$src/cmake/consumer-test"

tmp=$(mktemp -d "${TMPDIR:-/tmp}/pogon-consumer.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
prefix="$tmp/prefix"

step() { echo; echo "=== consumer: $*"; }
fail() { echo "FAIL: $*" >&2; exit 1; }

# Configure arguments shared by the CMake consumers.
set -- -DCMAKE_C_COMPILER="$cc" -DCMAKE_C_FLAGS="$cflags" -DCMAKE_EXE_LINKER_FLAGS="$ldflags"
if [ -n "$config" ]; then set -- "$@" -DCMAKE_BUILD_TYPE="$config"; fi

step "install $build into $prefix"
if [ -n "$config" ]; then
  "$cmake" --install "$build" --prefix "$prefix" --config "$config"
else
  "$cmake" --install "$build" --prefix "$prefix"
fi
for f in include/pogon/fixed.h include/pogon/config.h include/pogon/version.h \
         include/pogon/detail/fixed_internal.h; do
  [ -f "$prefix/$f" ] || fail "$f was not installed"
done
pc=$(find "$prefix" -name pogon.pc | head -n 1)
cfg=$(find "$prefix" -name pogonConfig.cmake | head -n 1)
[ -n "$pc" ] || fail "pogon.pc was not installed"
[ -n "$cfg" ] || fail "pogonConfig.cmake was not installed"
echo "installed: ${pc#"$prefix"/} ${cfg#"$prefix"/}"

step "[1/3] find_package(pogon)"
# Ask for the major.minor being tested, as a project built against this version would.
required=""
[ -z "${POGON_VERSION:-}" ] || required=$(echo "$POGON_VERSION" | cut -d. -f1,2)
"$cmake" -S "$consumer" -B "$tmp/fp" "$@" -DCMAKE_PREFIX_PATH="$prefix" \
  -DPOGON_REQUIRED_VERSION="$required" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF
found=$(sed -n 's/^pogon_DIR:PATH=//p' "$tmp/fp/CMakeCache.txt")
case $found in
  "$prefix"/*) ;;
  *) fail "find_package found pogon in '$found', not in the temporary prefix" ;;
esac
"$cmake" --build "$tmp/fp"
LD_LIBRARY_PATH="$(dirname "$pc")/..${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$tmp/fp/consumer"

step "[2/3] pkg-config"
command -v pkg-config >/dev/null 2>&1 || fail "pkg-config is not installed (scripts/setup-deps.sh installs it)"
PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
export PKG_CONFIG_PATH
version=$(pkg-config --modversion pogon)
pc_cflags=$(pkg-config --cflags pogon)
pc_libs=$(pkg-config --libs pogon)
echo "pkg-config: version $version; cflags: $pc_cflags; libs: $pc_libs"
if [ -n "${POGON_VERSION:-}" ] && [ "$version" != "$POGON_VERSION" ]; then
  fail "pkg-config --modversion gave $version, expected $POGON_VERSION"
fi
case " $pc_cflags " in
  *" -DPG_TRIG_TABLE_BITS=${POGON_TRIG_TABLE_BITS:-}"*) ;;
  *) fail "pkg-config Cflags lack -DPG_TRIG_TABLE_BITS=${POGON_TRIG_TABLE_BITS:-}" ;;
esac
# Word splitting of the flag strings is intended here.
# shellcheck disable=SC2086
(set -x; "$cc" -std=c99 $cflags $pc_cflags "$consumer/main.c" -o "$tmp/consumer-pc" $ldflags $pc_libs)
# no LD_LIBRARY_PATH: a shared build's pkg-config line carries the run path
"$tmp/consumer-pc"

if [ -f "$build/tools/pogon-replay" ] || [ -f "$build/tools/pogon-replay.exe" ]; then
  step "installed pogon-replay runs from bin/ (no LD_LIBRARY_PATH)"
  [ -x "$prefix/bin/pogon-replay" ] || fail "pogon-replay was not installed into bin/"
  "$prefix/bin/pogon-replay" --help >/dev/null || fail "the installed pogon-replay --help failed"
fi

step "[3/3] add_subdirectory($src)"
"$cmake" -S "$consumer" -B "$tmp/sub" "$@" -DPOGON_SOURCE_DIR="$src"
"$cmake" --build "$tmp/sub"
"$tmp/sub/consumer"

echo
echo "PASS: find_package, pkg-config and add_subdirectory consumers built and ran"

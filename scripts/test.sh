#!/usr/bin/env bash
# test.sh — THE test command: every test of pogon, from a fresh Debian machine.
#
# Usage: scripts/test.sh [PRESET...]     (default: release debug-asan clang table8)
#
# Installs what is missing (scripts/setup-deps.sh), then for each CMake preset
# configures, builds and runs ctest (--output-on-failure); after the clang preset's tests
# it prints the line and branch coverage of src/ (docs/coverage.md). A failing preset does not
# stop the others; the script exits 1 if any stage of any preset failed. The last line
# is the total over all presets: "pogon: N passed, N failed" (a preset that fails to
# configure or build counts as one failure).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

presets=("$@")
if [ ${#presets[@]} -eq 0 ]; then presets=(release debug-asan clang table8); fi
jobs=$(nproc 2>/dev/null || echo 2)
start=$(date +%s)

stage() { printf '\n==== [%s +%ss] %s\n' "$(date +%H:%M:%S)" "$(( $(date +%s) - start ))" "$*"; }

stage "setup: scripts/setup-deps.sh"
scripts/setup-deps.sh

mkdir -p build
passed=0
failed=0
skipped=0
summary=()
status=0
for preset in "${presets[@]}"; do
  log="build/ctest-$preset.log"
  stage "$preset: configure (cmake --preset $preset -DPOGON_TARGETS_BUILD_CACHE=build/targets-cache)"
  # The determinism_* tests (tests/targets) keep the programs they build for other
  # targets in one directory shared by the presets: each target is compiled once.
  if ! cmake --preset "$preset" -DPOGON_TARGETS_BUILD_CACHE="$PWD/build/targets-cache"; then
    summary+=("$preset: configure FAILED"); status=1; failed=$(( failed + 1 )); continue
  fi
  stage "$preset: build (cmake --build --preset $preset)"
  if ! cmake --build --preset "$preset" --parallel "$jobs"; then
    summary+=("$preset: build FAILED"); status=1; failed=$(( failed + 1 )); continue
  fi
  stage "$preset: test (ctest --preset $preset)"
  # A build instrumented for coverage (the clang preset, POGON_COVERAGE) starts from no
  # profiles, so the report below counts this run's tests only.
  coverage=0
  if grep -q '^POGON_COVERAGE:BOOL=ON$' "build/$preset/CMakeCache.txt" 2>/dev/null; then
    coverage=1
    rm -rf "build/$preset/coverage"
  fi
  rc=0
  ctest --preset "$preset" --output-on-failure --parallel "$jobs" 2>&1 | tee "$log" || rc=$?
  if [ "$coverage" -eq 1 ]; then
    stage "$preset: coverage of src/ (tools/coverage/coverage.py report build/$preset)"
    tools/coverage/coverage.py report "build/$preset" || echo "coverage: no report (see above)"
  fi
  # "100% tests passed, 0 tests failed out of 12"
  line=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1 || true)
  if [ -n "$line" ]; then
    total=$(sed -E 's/.* out of ([0-9]+).*/\1/' <<<"$line")
    nfail=$(sed -E 's/.*passed, ([0-9]+) tests? failed.*/\1/' <<<"$line")
    # CTest counts a skipped test (exit 77, e.g. a missing cross compiler) as passed;
    # here it is not, and it is listed: "  21 - determinism_arm32 (Skipped)"
    nskip=$(grep -cE '^[[:space:]]*[0-9]+ - .* \(Skipped\)$' "$log" || true)
    passed=$(( passed + total - nfail - nskip ))
    failed=$(( failed + nfail ))
    skipped=$(( skipped + nskip ))
    [ "$nskip" -eq 0 ] || line+=", $nskip skipped"
  fi
  if [ "$rc" -ne 0 ]; then
    summary+=("$preset: tests FAILED (${line:-ctest exit $rc})"); status=1
    [ -n "$line" ] || failed=$(( failed + 1 ))
  else
    summary+=("$preset: ok (${line:-no summary})")
  fi
done

stage "summary ($(( $(date +%s) - start )) s)"
printf '  %s\n' "${summary[@]}"
if [ "$status" -ne 0 ]; then echo "FAILED: see the output above"; else echo "all presets passed"; fi
if [ "$skipped" -ne 0 ]; then echo "pogon: $skipped tests skipped (see 'did not run' above)"; fi
echo "pogon: $passed passed, $failed failed"
exit "$status"

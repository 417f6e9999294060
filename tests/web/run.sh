#!/usr/bin/env bash
# run.sh — the web_e2e test (tests/web/CMakeLists.txt).
#
# Usage: tests/web/run.sh BUILD_DIR POGON_REPLAY
#   Installs the npm packages when needed (scripts/node-deps.sh), builds the page into
#   BUILD_DIR (scripts/build-web.sh), then runs tests/web/e2e.test.mjs against
#   BUILD_DIR/site with POGON_REPLAY (the native pogon-replay) to verify the page's
#   recording. Its files (the downloaded recording, the screenshot) go to BUILD_DIR/e2e.
# Exit 77 (skip) when emcmake, node or chromium is missing: scripts/setup-deps.sh installs
# them all (npm, when node lacks it, is installed by scripts/node-deps.sh).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
build=${1:?usage: run.sh BUILD_DIR POGON_REPLAY}
replay=${2:?usage: run.sh BUILD_DIR POGON_REPLAY}

for tool in emcmake node /usr/bin/chromium; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIPPED web_e2e: '$tool' not found (scripts/setup-deps.sh installs it)"
    exit 77
  fi
done
scripts/node-deps.sh
scripts/build-web.sh "$build"
mkdir -p "$build/e2e"
exec node --no-deprecation tests/web/e2e.test.mjs \
  --site "$build/site" --replay-tool "$replay" --out "$build/e2e"

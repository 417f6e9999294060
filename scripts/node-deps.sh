#!/usr/bin/env bash
# node-deps.sh — install the npm packages of package.json (http-server, playwright-core)
# into node_modules with `npm ci`, exactly as package-lock.json pins them.
#
# Usage: scripts/node-deps.sh
#
# Does nothing when node_modules is newer than package-lock.json. Installs Debian's npm
# first when no npm is found (scripts/setup-deps.sh npm). Exit 1 when npm ci fails (the
# npm registry must be reachable the first time).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

stamp=node_modules/.package-lock.json   # npm writes it at the end of every install
if [ -f "$stamp" ] && [ "$stamp" -nt package-lock.json ]; then
  exit 0
fi
if ! command -v npm >/dev/null 2>&1; then
  scripts/setup-deps.sh npm
fi
echo "node-deps: npm ci (package-lock.json)"
npm ci --no-audit --no-fund --loglevel=error

#!/usr/bin/env bash
# demo.sh — the main job: install what is missing, build the browser demo and serve it.
#
# Usage: scripts/demo.sh [--no-serve] [--port PORT]
#   --no-serve   build only (for CI); the site is left in build/web/site
#   --port PORT  serve on this port (default 8080)
#
# Installs the Debian packages (scripts/setup-deps.sh) and the npm packages
# (scripts/node-deps.sh: npm ci), builds the page with Emscripten
# (scripts/build-web.sh), then serves build/web/site on 127.0.0.1 with http-server
# (npm, pinned in package.json) until Ctrl-C, printing the address to open.
# The page is described in docs/web-demo.md.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

serve=1
port=8080
while [ $# -gt 0 ]; do
  case $1 in
    --no-serve) serve=0; shift ;;
    --port) port=${2:?--port needs a number}; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "demo.sh: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
done

stage() { printf '\n==== %s\n' "$*"; }

stage "setup: scripts/setup-deps.sh and scripts/node-deps.sh"
scripts/setup-deps.sh
scripts/node-deps.sh

stage "build: scripts/build-web.sh (build/web)"
scripts/build-web.sh build/web

if [ "$serve" -eq 0 ]; then
  echo "demo.sh: built build/web/site (not served: --no-serve)"
  exit 0
fi
stage "serve: http-server build/web/site"
echo "pogon demo: open http://127.0.0.1:$port/ in a browser (Ctrl-C stops the server)"
NODE_OPTIONS=--no-deprecation exec node_modules/.bin/http-server build/web/site -a 127.0.0.1 -p "$port" -c-1 --silent

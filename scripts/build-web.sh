#!/usr/bin/env bash
# build-web.sh — build the browser demo (ports/web) and lay out its site.
#
# Usage: scripts/build-web.sh [BUILD_DIR]        (default: build/web)
#
# Compiles the library, the shared app (ports/app) and the binding with Emscripten
# (emcmake, in BUILD_DIR), then writes BUILD_DIR/site: the page, its scripts, the wasm
# module, the scene files of scenes/ and the replays of tests/replays (and
# tests/replays/recorded), with site/manifest.json listing those files for the page's
# pickers. Serve BUILD_DIR/site with any static server (scripts/demo.sh does).
#
# Exit status: 0 built; 1 a step failed; 77 when emcmake is missing (install it with
# scripts/setup-deps.sh wasm).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root=$PWD
build=${1:-build/web}

if ! command -v emcmake >/dev/null 2>&1; then
  echo "build-web: emcmake not found (scripts/setup-deps.sh wasm installs Debian's emscripten)" >&2
  exit 77
fi
# Debian's emcc needs acorn, which Debian installs where this node does not look.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}

mkdir -p "$build"
emcmake cmake -S ports/web -B "$build" -DCMAKE_BUILD_TYPE=Release >"$build/configure.log" 2>&1 || {
  cat "$build/configure.log" >&2; exit 1; }
cmake --build "$build" --parallel 2

site=$build/site
rm -rf "$site"
mkdir -p "$site/js" "$site/scenes" "$site/replays/recorded"
cp ports/web/index.html ports/web/style.css "$site/"
cp ports/web/js/*.js "$site/js/"
cp "$build/pogon_web.js" "$build/pogon_web.wasm" "$site/"
cp scenes/*.scene "$site/scenes/"
cp tests/replays/*.pgr "$site/replays/"
if compgen -G 'tests/replays/recorded/*.pgr' >/dev/null; then
  cp tests/replays/recorded/*.pgr "$site/replays/recorded/"
fi

# manifest.json: the files the page offers, in name order.
node - "$site" <<'JS'
const fs = require('fs'), path = require('path');
const site = process.argv[2];
const list = (dir, ext) => fs.readdirSync(path.join(site, dir)).filter((f) => f.endsWith(ext)).sort()
  .map((f) => `${dir}/${f}`);
const manifest = {
  scenes: list('scenes', '.scene'),
  replays: [...list('replays', '.pgr'), ...list('replays/recorded', '.pgr')],
};
fs.writeFileSync(path.join(site, 'manifest.json'), JSON.stringify(manifest, null, 2) + '\n');
JS
echo "build-web: site in $site ($(du -sh "$site" | cut -f1))"

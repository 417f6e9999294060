#!/bin/sh
# record.sh — (re)make the replay corpus from corpus.txt: the scenes and scripts are the
# source, the .pgr files the result. Run from anywhere:
#     tests/replays/record.sh build/release/tools/pogon-replay
# Only needed when a scene or script changes or a replay is added; after an intended
# change of the numerics use `pogon-replay rehash tests/replays/*.pgr` instead.
set -eu
tool=${1:?usage: record.sh PATH/TO/pogon-replay}
case $tool in /*) ;; *) tool=$(pwd)/$tool ;; esac
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
grep -v '^#' tests/replays/corpus.txt | while read -r name scene script frames interval; do
  [ -n "$name" ] || continue
  if [ "$script" = "-" ]; then
    "$tool" record --scene "$scene" --frames "$frames" --checkpoint "$interval" -o "tests/replays/$name.pgr"
  else
    "$tool" record --scene "$scene" --script "$script" --frames "$frames" --checkpoint "$interval" -o "tests/replays/$name.pgr"
  fi
done

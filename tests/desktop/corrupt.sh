#!/usr/bin/env bash
# corrupt.sh — damaged replays and scripts are refused with where and what, never a crash.
#
# Usage: corrupt.sh DESKTOP GOOD_REPLAY WORKDIR
# A truncated copy, a copy with a flipped byte in a command and one with a bad header
# must each exit 2 with "offset N" and "field" in the message; so must a script with a
# bad line (with its line:column).
set -euo pipefail
desktop=$1 good=$2 work=$3
rm -rf "$work"; mkdir -p "$work"
size=$(stat -c %s "$good")
head -c $(( size * 2 / 3 )) "$good" >"$work/truncated.pgr"
cp "$good" "$work/version.pgr"; printf '\x09' | dd of="$work/version.pgr" bs=1 seek=8 conv=notrunc status=none
cp "$good" "$work/checksum.pgr"; printf '\xff' | dd of="$work/checksum.pgr" bs=1 seek=$(( size - 12 )) conv=notrunc status=none
: >"$work/empty.pgr"
for f in truncated version checksum empty; do
  rc=0
  "$desktop" --headless --play "$work/$f.pgr" >"$work/$f.out" 2>&1 || rc=$?
  cat "$work/$f.out"
  [ "$rc" -eq 2 ] || { echo "FAIL: $f.pgr: exit $rc, expected 2"; exit 1; }
  grep -q "offset [0-9]* (.*field [a-z_]*)" "$work/$f.out" || { echo "FAIL: $f.pgr: no offset and field in the message"; exit 1; }
done
printf '0 tool ball\n5 click 1 zz\n' >"$work/bad.script"
rc=0
"$desktop" --headless --scene /dev/null --script "$work/bad.script" --frames 10 -o "$work/x.pgr" >"$work/script.out" 2>&1 || rc=$?
cat "$work/script.out"
[ "$rc" -eq 2 ] && grep -q "bad.script:2:11: Y is not a number" "$work/script.out" || { echo "FAIL: bad script (exit $rc)"; exit 1; }
echo "corrupt: OK"

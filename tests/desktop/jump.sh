#!/usr/bin/env bash
# jump.sh — jumping gives the state that playing straight there gives.
#
# Usage: jump.sh DESKTOP REPLAY
# For frames 0, N/2 and N (N = the replay's frame count) the hash after a jump (which
# restores a snapshot kept while playing through: the jumps go to N, then 0, then N/2,
# so both directions and a restore from the middle are exercised) must equal the hash
# after playing straight from frame 0 (--until, nothing restored).
set -euo pipefail
desktop=$1 file=$2
n=$("$desktop" --headless --play "$file" | sed -n 's/.*: frame \([0-9]*\) of \([0-9]*\),.*/\2/p')
[ -n "$n" ] && [ "$n" -gt 0 ] || { echo "FAIL: no frame count for $file"; exit 1; }
half=$(( n / 2 ))
jumps=$("$desktop" --headless --play "$file" --jump "$n" --jump 0 --jump "$half")
echo "$jumps"
for f in 0 "$half" "$n"; do
  straight=$("$desktop" --headless --play "$file" --until "$f" | sed -n 's/^until [0-9]*: hash \(0x[0-9a-f]*\).*/\1/p')
  jumped=$(sed -n "s/^jump $f: hash \(0x[0-9a-f]*\).*/\1/p" <<<"$jumps")
  echo "frame $f: straight $straight, jumped $jumped"
  [ -n "$straight" ] && [ "$straight" = "$jumped" ] || { echo "FAIL: frame $f differs"; exit 1; }
done
grep -q "^jump $half: .*(from frame $(( half / 300 * 300 ))," <<<"$jumps" ||
  { echo "FAIL: the jump to $half should restore the snapshot of frame $(( half / 300 * 300 ))"; exit 1; }
echo "jump: OK"

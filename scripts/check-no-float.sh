#!/bin/sh
# check-no-float.sh — prove that a built pogon library contains no floating point.
#
# Usage: scripts/check-no-float.sh LIBRARY [OBJDUMP]
#   LIBRARY  the static (.a) or shared (.so) library, or an object file
#   OBJDUMP  the objdump to use (default: objdump); GNU objdump and llvm-objdump
#            output are both understood
#
# Fails (exit 1) when the x86-64 disassembly contains
#   - an x87 instruction (every x87 mnemonic starts with "f": fld, fstp, fmul, ...),
#   - a conversion (any mnemonic containing "cvt": cvtsi2sd, cvttss2si, vcvt...),
#   - an SSE/AVX floating-point operation on xmm/ymm/zmm registers (mnemonics ending
#     in ss/sd/ps/pd/sh/ph: addss, mulsd, movaps, vfmadd231sd, ucomisd, ...),
#     MXCSR access (ldmxcsr/stmxcsr) or a 3DNow! float op (pfadd, pi2fd, ...),
# or when the 32-bit ARM (Cortex-M, Thumb) disassembly contains
#   - a VFP/Neon instruction (every one starts with "v": vldr, vmov, vpush, vadd.f32,
#     vcvt, vmrs, ...) or a coprocessor 10/11 access (mrc/mcr/ldc/stc p10, p11),
# or when the library calls or references
#   - a soft-float helper (__aeabi_f*/__aeabi_d*, __addsf3, __muldf3, __floatsidf,
#     __fixdfsi, __extendsfdf2, __truncdfsf2, __mulsc3, ...) or
#   - a libm function (sqrt, sin, cos, atan2, floor, ... with or without f/l suffix).
# Integer SIMD on vector registers is allowed (it is not float), though pogon's
# core is compiled with -mgeneral-regs-only and normally has none.
set -eu

if [ $# -lt 1 ] || [ $# -gt 2 ]; then
  echo "usage: $0 LIBRARY [OBJDUMP]" >&2
  exit 2
fi
lib=$1
objdump=${2:-objdump}
if [ ! -f "$lib" ]; then
  echo "check-no-float: no such file: $lib" >&2
  exit 2
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/pogon-nofloat.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM

# -d disassembles, -r shows relocations so calls to external helpers are named even
# in unlinked objects, -t lists symbols (undefined ones are what the library uses).
"$objdump" -dr --no-show-raw-insn "$lib" > "$tmp/dis" || {
  echo "check-no-float: $objdump -d failed on $lib" >&2
  exit 2
}
"$objdump" -t "$lib" > "$tmp/sym" 2>/dev/null || true

awk -F '\t' '
function softfloat(s) {
  sub(/[-+]0x[0-9a-f]+$/, "", s)      # relocation addend
  sub(/@.*$/, "", s)                  # symbol version / @plt
  return s ~ /^__aeabi_[fd][a-z0-9]*$/ ||
         s ~ /^__aeabi_[a-z0-9]*2[fdh]$/ ||
         s ~ /^__(add|sub|mul|div|neg|cmp|unord|eq|ne|ge|gt|le|lt|pow|powi)[sdtxhk]f[23]$/ ||
         s ~ /^__float/ || s ~ /^__fix/ ||
         s ~ /^__extend[a-z]*f2$/ || s ~ /^__trunc[a-z]*f2$/ ||
         s ~ /^__(mul|div)[sdtx]c3$/ || s ~ /^__gnu_[fh]2[fh]/ ||
         s ~ /^(sqrt|cbrt|hypot|sin|cos|tan|asin|acos|atan|atan2|sinh|cosh|tanh|exp|exp2|expm1|log|log2|log10|log1p|pow|floor|ceil|round|lround|llround|rint|lrint|llrint|nearbyint|trunc|fmod|remainder|fabs|fmin|fmax|fma|ldexp|frexp|modf|copysign|sincos)[fl]?$/
}
FNR == 1 { file = FILENAME }
file ~ /dis$/ && $0 ~ /file format elf32-(little|big)arm/ { arch = "arm" }
file ~ /dis$/ {
  if ($0 ~ /^In archive /) next
  if ($0 ~ /file format /) { member = $0; sub(/:.*$/, "", member); next }
  if ($0 ~ /^[0-9a-f]+ <.*>:$/) { fn = $0; sub(/^[0-9a-f]+ /, "", fn); sub(/:$/, "", fn); nfunc++; next }
  # relocation line: "\t\t\t5: R_X86_64_PLT32\t__floatsidf-0x4"
  if ($0 ~ /R_[A-Z0-9_]+/) {
    sym = $NF
    if (softfloat(sym)) { printf "%s %s: reference to %s\n", member, fn, sym; bad++ }
    next
  }
  # instruction line: GNU "   1f:\tmov    %eax,%ebx", LLVM "      1f:      \tmovl\t%eax, %ebx"
  if ($1 !~ /^ *[0-9a-f]+: *$/ || NF < 2) next
  text = $2
  for (j = 3; j <= NF; j++) text = text " " $j
  n = split(text, w, /[ ]+/)
  i = 1
  while (i <= n && w[i] ~ /^(lock|rep|repz|repnz|repe|repne|data16|data32|addr16|addr32|cs|ds|es|fs|gs|ss|notrack|bnd|xacquire|xrelease|rex(\.[WRXB]+)?|\{[a-z0-9]+\})$/) i++
  if (i > n) next
  m = w[i]
  ops = ""
  for (j = i + 1; j <= n; j++) ops = ops " " w[j]
  ninsn++
  why = ""
  if (arch == "arm") {
    if (m ~ /^v/) why = "VFP/Neon"
    else if (m ~ /^(mrc|mcr|mrrc|mcrr|ldc|stc|cdp)2?l?$/ && ops ~ /p1[01],/) why = "VFP coprocessor access"
    if (why != "") { printf "%s %s: %s: %s%s\n", member, fn, why, m, ops; bad++ }
    next
  }
  if (m ~ /^f/) why = "x87"
  else if (m ~ /cvt/) why = "float conversion"
  else if (m ~ /^v?(ld|st)mxcsr$/) why = "MXCSR access"
  else if (m ~ /^(pf[a-z0-9]+|pi2f[dw])$/) why = "3DNow! float"
  else if (m ~ /(ss|sd|ps|pd|sh|ph)$/ && ops ~ /%[xyz]mm/) why = "SSE/AVX float"
  if (why != "") { printf "%s %s: %s: %s%s\n", member, fn, why, m, ops; bad++ }
  else if (ops ~ /%[xyz]mm/) vec++
}
file ~ /sym$/ {
  if ($0 ~ /\*UND\*/) {
    k = split($0, t, /[ \t]+/)
    sym = t[k]
    if (softfloat(sym)) { printf "undefined symbol %s (a float helper or libm function)\n", sym; bad++ }
  }
}
END {
  if (ninsn == 0) { print "check-no-float: no instructions found: is this an x86-64 or 32-bit ARM library?"; exit 2 }
  printf "check-no-float: %d functions, %d instructions, %d integer vector instructions, %d float uses\n", nfunc, ninsn, vec, bad
  exit bad > 0 ? 1 : 0
}' "$tmp/dis" "$tmp/sym" || {
  rc=$?
  if [ "$rc" -eq 1 ]; then echo "FAIL: floating point found in $lib" >&2; fi
  exit "$rc"
}
echo "PASS: no floating point in $lib"

#!/bin/sh
# check-layers.sh — prove that the library's files form layers: no file depends,
# directly or through others, on a file that depends on it.
#
# Usage: scripts/check-layers.sh [--markdown] [SRC_DIR]    (default: src beside this script;
#        its files and those of its subdirectories, src/core and src/io)
#   --markdown  print the layers inside a ``` block, as docs/architecture.md's generated
#               region holds them (tools/docs/regions.js checks that it matches)
#
# A module is a file name without its extension: world.c and world.h are the module
# "world"; a header without a .c (wide.h) is a module of its own; X_internal.h belongs
# to module X (fixed_internal.h declares what fixed.c keeps out of pogon/fixed.h). Module X depends on
# module Y (X -> Y) when
#   - X.c or X.h has #include "Y.h", or
#   - X.c calls a function whose definition (a non-static function, name starting
#     with pg_, at the start of a line) is in Y.c: this sees calls made through a
#     header that another module implements, or through the public headers.
# A header must declare only what its own module defines, or a call into Y through
# X.h would be missed: the check fails when a name declared as a function in X.h is
# defined in a .c other than X.c.
# The dependencies must have no cycle (tsort finds one). On success it prints the
# layers, lowest first: a module's layer is one above the highest of what it depends
# on, so a file may use only what sits in lower layers. docs/architecture.md shows
# this output (--markdown) in a generated region, which the CTest test
# docs_generated_regions compares with it. Exit 0: acyclic; 1: a cycle or a misplaced declaration; 2: usage.
set -eu

markdown=0
if [ "${1:-}" = "--markdown" ]; then markdown=1; shift; fi
src=${1:-$(dirname "$0")/../src}
if [ ! -d "$src" ]; then
  echo "check-layers: no such directory: $src" >&2
  exit 2
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/pogon-layers.XXXXXX")
# the files of one extension in SRC_DIR and in its subdirectories (src/core, src/io): a
# module is named by its file name, whichever directory holds it
files() {
  for f in "$src"/*."$1" "$src"/*/*."$1"; do
    if [ -f "$f" ]; then echo "$f"; fi
  done
}
# whether a header of that name is in SRC_DIR or one of its subdirectories
has_header() {
  for f in "$src/$1.h" "$src"/*/"$1.h"; do
    if [ -f "$f" ]; then return 0; fi
  done
  return 1
}
trap 'rm -rf "$tmp"' EXIT INT TERM

# code: a file without its comments and string literals, so that a name in a message
# or in an explanation is not taken for a call (line breaks are kept)
code() {
  awk '{ out = ""; i = 1; n = length($0)
         while (i <= n) {
           c = substr($0, i, 2)
           if (incomment) { if (c == "*/") { incomment = 0; i += 2 } else i++; continue }
           if (c == "/*") { incomment = 1; i += 2; continue }
           if (c == "//") break
           ch = substr($0, i, 1)
           if (ch == "\"" || ch == "\047") {
             q = ch; i++
             while (i <= n && substr($0, i, 1) != q) i += (substr($0, i, 1) == "\\") ? 2 : 1
             i++; out = out q q; continue }
           out = out ch; i++ }
         print out }' "$1"
}

# defs: "function module" for every non-static pg_ function defined in a .c file
for f in $(files c); do
  m=$(basename "$f" .c)
  sed -n 's/^[A-Za-z_][A-Za-z0-9_ *]*[ *]\(pg_[A-Za-z0-9_]*\)(.*[^;]$/\1/p; s/^[A-Za-z_][A-Za-z0-9_ *]*[ *]\(pg_[A-Za-z0-9_]*\)(.*,$/\1/p' "$f" |
    grep -v '^$' | sed "s/\$/ $m/"
done | awk '!/^static/' | sort -u > "$tmp/defs"
# a static definition is not a module's export: drop names defined "static" at line start
for f in $(files c); do
  sed -n 's/^static .*[ *]\(pg_[A-Za-z0-9_]*\)(.*/\1/p' "$f"
done | sort -u > "$tmp/statics"
awk 'FILENAME == ARGV[1] { s[$1] = 1; next } !($1 in s)' "$tmp/statics" "$tmp/defs" > "$tmp/exports"

status=0
# every module has a node, so one that depends on nothing still gets a layer
: > "$tmp/edges"
for f in $(files c) $(files h); do
  m=$(basename "$f"); m=${m%.*}; m=${m%_internal}
  echo "$m $m" >> "$tmp/edges"
  # includes of this directory's headers (public headers, <...> and .inc files are not modules)
  sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([A-Za-z0-9_]*\)\.h".*/\1/p' "$f" | while read -r h; do
    if has_header "$h" && [ "${h%_internal}" != "$m" ]; then echo "$m ${h%_internal}"; fi
  done >> "$tmp/edges"
  case $f in
    *.c)
      # calls: every pg_ name followed by "(" that another module exports
      code "$f" | grep -o 'pg_[A-Za-z0-9_]*[ ]*(' | sed 's/[ ]*($//' | sort -u > "$tmp/calls"
      awk -v m="$m" 'FILENAME == ARGV[1] { d[$1] = $2; next } ($1 in d) && d[$1] != m { print m, d[$1] }' \
        "$tmp/exports" "$tmp/calls" >> "$tmp/edges"
      ;;
    *.h)
      # declarations: a prototype "type pg_name(...);" at the start of a line
      sed -n 's/^[A-Za-z_][A-Za-z0-9_ *]*[ *]\(pg_[A-Za-z0-9_]*\)(.*/\1/p' "$f" | sort -u > "$tmp/decls"
      awk -v m="$m" -v f="$f" 'FILENAME == ARGV[1] { d[$1] = $2; next } ($1 in d) && d[$1] != m {
          printf "check-layers: %s declares %s, which %s.c defines: declare it in %s.h\n", f, $1, d[$1], d[$1]; bad = 1 }
          END { exit bad }' "$tmp/exports" "$tmp/decls" >&2 || status=1
      ;;
  esac
done
sort -u "$tmp/edges" -o "$tmp/edges"

if ! tsort "$tmp/edges" > "$tmp/order" 2> "$tmp/loop"; then
  echo "check-layers: the modules depend on each other in a cycle (tsort lists it):" >&2
  grep -v '^tsort: input contains a loop' "$tmp/loop" | sed 's/^tsort: /  /' >&2
  echo "dependencies of the modules in the cycle:" >&2
  for m in $(sed -n 's/^tsort: \([A-Za-z0-9_]*\)$/\1/p' "$tmp/loop"); do
    awk -v m="$m" '$1 == m && $2 != m { printf "  %s -> %s\n", $1, $2 }' "$tmp/edges" >&2
  done
  exit 1
fi

# The core library target (POGON_CORE_SOURCES in src/CMakeLists.txt, docs/modules.md)
# must link alone: a module of it may depend only on core modules and on headers without
# a .c (types, inline helpers), never on a file of another module target.
if [ -f "$src/CMakeLists.txt" ] && grep -q 'set(POGON_CORE_SOURCES' "$src/CMakeLists.txt"; then
  sed -n '/set(POGON_CORE_SOURCES/,/)/p' "$src/CMakeLists.txt" | sed -n 's/^[ \t]*\([A-Za-z0-9_]*\)\.c[ \t]*$/\1/p' > "$tmp/core"
  for f in $(files c); do basename "$f" .c; done > "$tmp/with_c"
  awk 'FILENAME == ARGV[1] { core[$1] = 1; next } FILENAME == ARGV[2] { hasc[$1] = 1; next }
       $1 != $2 && ($1 in core) && ($2 in hasc) && !($2 in core) {
         printf "check-layers: core module %s depends on %s, which is not in POGON_CORE_SOURCES (src/CMakeLists.txt)\n", $1, $2; bad = 1 }
       END { exit bad }' "$tmp/core" "$tmp/with_c" "$tmp/edges" >&2 || status=1
fi

# layers: tsort prints a module before what it depends on, so walk its order backwards
[ "$markdown" -eq 0 ] || echo '```'
awk '$1 != $2 { dep[$1] = dep[$1] " " $2 } END { for (m in dep) print m dep[m] }' "$tmp/edges" > "$tmp/deps"
tac "$tmp/order" | awk 'FILENAME == ARGV[1] { n = split($0, a, " "); for (i = 2; i <= n; ++i) d[$1] = d[$1] " " a[i]; next }
  { l = 0; n = split(d[$1], a, " "); for (i = 1; i <= n; ++i) if (layer[a[i]] + 1 > l) l = layer[a[i]] + 1;
    layer[$1] = l; if (l > top) top = l; names[l] = names[l] " " $1 }
  END { for (i = 0; i <= top; ++i) { k = split(names[i], s, " "); out = "";
          # sorted within a layer, so the output does not depend on tsort
          for (x = 1; x <= k; ++x) for (y = x + 1; y <= k; ++y) if (s[y] < s[x]) { t = s[x]; s[x] = s[y]; s[y] = t }
          for (x = 1; x <= k; ++x) out = out " " s[x];
          printf "layer %d:%s\n", i, out } }' "$tmp/deps" -
[ "$markdown" -eq 0 ] || echo '```'
exit $status

#!/usr/bin/env python3
"""coverage.py — line and branch coverage of src/ from a build instrumented with POGON_COVERAGE.

  tools/coverage/coverage.py report BUILD_DIR [--save FILE]
      merges BUILD_DIR/coverage/*.profraw (written by the tests: the clang preset sets
      LLVM_PROFILE_FILE), asks llvm-cov for the summary of every src/ file over all the
      build's instrumented executables, and prints it; --save writes it as a results file
      (TSV, with the date, machine and command) for docs/coverage.md.
  tools/coverage/coverage.py --table FILE
      prints the markdown table of a results file (docs/coverage.md's generated region).

scripts/test.sh runs `report build/clang` after the clang preset's tests. Exit status 2
when there is nothing to report (no profiles, no llvm tools).
"""
import datetime
import glob
import json
import os
import platform
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def tool(name):
    for candidate in (name, name + "-14", name + "-15", name + "-16"):
        path = shutil.which(candidate)
        if path:
            return path
    sys.exit(f"coverage: {name} not found (Debian package llvm, or llvm-14)")


def instrumented_executables(build):
    """Executables of the build holding a coverage map (the ones linking the instrumented library)."""
    found = []
    for dirpath, dirnames, filenames in os.walk(build):
        dirnames[:] = [d for d in dirnames if d not in ("CMakeFiles", "coverage", "fuzz", "targets-cache")]
        for f in filenames:
            path = os.path.join(dirpath, f)
            if not os.access(path, os.X_OK) or os.path.islink(path):
                continue
            with open(path, "rb") as fh:
                if fh.read(4) != b"\x7fELF":
                    continue
            sections = subprocess.run(["readelf", "-S", "-W", path], capture_output=True, text=True).stdout
            if "__llvm_covmap" in sections:
                found.append(path)
    return sorted(found)


def measure(build):
    profraws = glob.glob(os.path.join(build, "coverage", "*.profraw"))
    if not profraws:
        print(f"coverage: no profiles in {build}/coverage (run the tests of a POGON_COVERAGE build first)", file=sys.stderr)
        sys.exit(2)
    profdata = os.path.join(build, "coverage", "merged.profdata")
    listing = os.path.join(build, "coverage", "profraw-list.txt")
    with open(listing, "w") as fh:
        fh.write("\n".join(profraws) + "\n")
    subprocess.run([tool("llvm-profdata"), "merge", "-sparse", "-f", listing, "-o", profdata], check=True)
    objects = instrumented_executables(build)
    if not objects:
        sys.exit(f"coverage: no instrumented executables in {build}")
    cmd = [tool("llvm-cov"), "export", "-summary-only", "-instr-profile", profdata, objects[0]]
    for o in objects[1:]:
        cmd += ["-object", o]
    cmd.append(os.path.join(ROOT, "src"))
    data = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    rows = []
    for f in data["data"][0]["files"]:
        name = os.path.relpath(f["filename"], ROOT)
        if not name.startswith("src/"):
            continue
        s = f["summary"]
        rows.append((name, s["lines"]["count"], s["lines"]["covered"], s["branches"]["count"], s["branches"]["covered"]))
    rows.sort()
    return rows, len(profraws), len(objects)


def pct(covered, count):
    return "-" if count == 0 else f"{100.0 * covered / count:.1f} %"


def totals(rows):
    return ("total", sum(r[1] for r in rows), sum(r[2] for r in rows), sum(r[3] for r in rows), sum(r[4] for r in rows))


def print_report(rows):
    print(f"{'src/ file':<22} {'lines':>14} {'':>8} {'branches':>14} {'':>8}")
    for r in rows + [totals(rows)]:
        print(f"{r[0]:<22} {r[2]:>6}/{r[1]:<7} {pct(r[2], r[1]):>8} {r[4]:>6}/{r[3]:<7} {pct(r[4], r[3]):>8}")


def save(rows, path, profiles, objects):
    with open(path, "w") as fh:
        fh.write(f"# measured {datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC on {platform.node() or 'unknown'} "
                 f"({platform.machine()}, {os.cpu_count()} cores) by: scripts/test.sh clang, then "
                 f"tools/coverage/coverage.py report build/clang --save {os.path.relpath(path, ROOT)} "
                 f"({profiles} test processes, {objects} instrumented programs)\n")
        fh.write("file\tlines\tlines_covered\tbranches\tbranches_covered\n")
        for r in rows:
            fh.write("\t".join(str(x) for x in r) + "\n")


def table(path):
    with open(path) as fh:
        lines = fh.read().splitlines()
    header = lines[0].lstrip("# ")
    rows = [(c[0], int(c[1]), int(c[2]), int(c[3]), int(c[4])) for c in (l.split("\t") for l in lines[2:] if l)]
    print("| file | lines | line coverage | branches | branch coverage |")
    print("| --- | ---: | ---: | ---: | ---: |")
    for r in rows + [totals(rows)]:
        name = f"**{r[0]}**" if r[0] == "total" else f"`{r[0]}`"
        print(f"| {name} | {r[2]} / {r[1]} | {pct(r[2], r[1])} | {r[4]} / {r[3]} | {pct(r[4], r[3])} |")
    print()
    print(f"Coverage {header}.")


def main(argv):
    if len(argv) == 2 and argv[0] == "--table":
        table(argv[1])
        return 0
    if len(argv) in (2, 4) and argv[0] == "report":
        rows, profiles, objects = measure(argv[1])
        print_report(rows)
        if len(argv) == 4 and argv[2] == "--save":
            save(rows, argv[3], profiles, objects)
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

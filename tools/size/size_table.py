#!/usr/bin/env python3
"""size_table.py — pogon's flash, RAM, stack and step cost on Cortex-M, measured.

Usage (from anywhere; paths are relative to the repository):
  tools/size/size_table.py [--results docs/results/embedded.json] [--build DIR]
  tools/size/size_table.py --render --results docs/results/embedded.json
  tools/size/size_table.py --check [--build DIR]      the cortex_m_size_and_no_float test
  tools/size/size_table.py --update-limits             after a size change on purpose
  tools/size/size_table.py --one CONFIG [--cpu m4|m0plus]   one configuration's flash and
                                                       largest functions; writes nothing
  tools/size/size_table.py --stack                     the stack report only (Cortex-M4)
  tools/size/size_table.py --profile                   the step's instructions by function only

Builds the library with arm-none-eabi-gcc -mthumb -Os -ffunction-sections
-fdata-sections -mgeneral-regs-only, newlib-nano, --gc-sections, PG_FAST_DIV64=0, for
Cortex-M4 (hard-float ABI, where only -mgeneral-regs-only keeps gcc off the FPU
registers) and Cortex-M0+, and measures:
  flash   text + data of each configuration (tools/size/*.c) minus a program without
          pogon (baseline.c): step-only circles and boxes (step_only.c), the core without
          the file formats (every public function of every source file but scene_file.c,
          replay_file.c and replay_upgrade.c kept with -u), everything (all public functions);
  RAM     pg_world_memory_size on the target (world_memory.c under qemu-system-arm);
  stack   the deepest call chain below pg_world_step and below each public function,
          from gcc's -fcallgraph-info=su (frame sizes as in the .su files; library
          helpers such as memset and __aeabi_uldivmod count as 0); a call deeper than
          4 KiB that has an `_in` form (the same call with its work area from the
          caller, e.g. pg_scene_read_def_in) is listed with that form's depth;
          --stack prints this report alone (Cortex-M4 objects only, nothing written);
  cost    instructions per pyramid step under qemu -icount shift=0 (step_count.c), and
          the calls of libgcc's 64-bit division helpers in those steps (step_count.c
          with count_divisions.S), and where they go: the instructions each function runs
          in those steps (step_count.c built with no steps and with them, each run under
          qemu -d in_asm,exec,nochain: every translation block's length times its
          executions, by the symbol it lies in, the first run's counts subtracted);
          --profile prints this table alone (nothing written).
A measuring run prints the tables; --results FILE also writes every figure they show to
FILE (JSON, with the date, machine, load average, toolchain and command), and
--render --results FILE prints the tables from FILE without measuring: docs/embedded.md's
generated region is that output (node tools/docs/regions.js --update; docs/generated.md). --check measures the flash only and fails (exit 1) when a
configuration is larger than its limit in tools/size/flash_limits.txt (the size
measured when the limit was set, plus 2 %), or when scripts/check-no-float.sh finds
floating point in either CPU's library; it exits 77 when the toolchain is missing.
"""
import argparse
import bisect
import concurrent.futures
import datetime
import json
import os
import platform
import re
import shutil
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
HERE = os.path.join(ROOT, "tools", "size")
LIMITS = os.path.join(HERE, "flash_limits.txt")
CC = "arm-none-eabi-gcc"
QEMU = "qemu-system-arm"
CPUS = {  # name: (flags, qemu board)
    "M4": (["-mcpu=cortex-m4", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16"], "mps2-an386"),
    "M0+": (["-mcpu=cortex-m0plus"], "mps2-an385"),
}
COMMON = ["-mthumb", "-mgeneral-regs-only", "-Os", "-std=c99", "-ffunction-sections", "-fdata-sections",
          "-Iinclude", "-Isrc/core", "-DPG_TRIG_TABLE_BITS=12", "-DPG_FAST_DIV64=0"]
LINK = ["-Wl,--gc-sections", "-nostartfiles", "--specs=nano.specs"]
FILE_FORMATS = ("scene_file.c", "replay_file.c", "replay_upgrade.c")
# The budgets (issue 30), KiB of flash; the core module has none of its own.
BUDGETS = {"step-only": 16, "step-only-lean": 16, "step-only-small": 16, "core-module": None, "core": 32, "everything": 64}
CONFIG_TEXT = {
    "step-only": "step-only circles and boxes",
    "step-only-lean": "step-only circles and boxes, without sleeping and continuous collision (`PG_CONFIG_EFFECTS=0x1F`)",
    "step-only-small": "step-only circles and boxes, built without joints, other shape kinds, sleeping and continuous "
                       "collision (`PG_CONFIG_JOINTS=0`, `PG_CONFIG_SHAPES=0x03`, `PG_CONFIG_EFFECTS=0x1F`)",
    "core-module": "`pogon::core`: every public function of the core module",
    "core": "core without file formats (core, state, commands)",
    "everything": "everything",
}
CONFIGS = ("step-only", "step-only-lean", "step-only-small", "core-module", "core", "everything")
LEAN = ["-DPG_CONFIG_EFFECTS=0x1Fu"]  # the library of step-only-lean
SMALL = ["-DPG_CONFIG_JOINTS=0", "-DPG_CONFIG_SHAPES=0x03u", "-DPG_CONFIG_EFFECTS=0x1Fu"]  # of step-only-small
VARIANTS = (("step-only-lean", LEAN, "-lean"), ("step-only-small", SMALL, "-small"))
# Each effect left out on its own (pogon.h's PG_EFFECT_* bits; gravity has no code of its own).
EFFECTS = (("rotation", 0x02), ("friction", 0x04), ("restitution", 0x08), ("damping", 0x10), ("sleeping", 0x20),
           ("continuous collision", 0x40))
GROWTH = 1.02


def run(cmd, **kw):
    done = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True, **kw)
    if done.returncode != 0:
        raise SystemExit("size_table: failed (%d): %s\n%s%s" % (done.returncode, " ".join(cmd), done.stdout, done.stderr))
    return done.stdout


def library_sources():
    """src/core/*.c and src/io/*.c (object files are named by the file's base name)."""
    return sorted(os.path.join("src", d, f) for d in ("core", "io")
                  for f in os.listdir(os.path.join(ROOT, "src", d)) if f.endswith(".c"))


def core_sources():
    """The files of the pogon_core target: POGON_CORE_SOURCES in src/CMakeLists.txt."""
    with open(os.path.join(ROOT, "src", "CMakeLists.txt")) as f:
        m = re.search(r"set\(POGON_CORE_SOURCES\s+([^)]*)\)", f.read())
    return set(m.group(1).split())


def public_api():
    """The functions the public headers (include/pogon/*.h) declare."""
    names = set()
    inc = os.path.join(ROOT, "include", "pogon")
    for f in os.listdir(inc):
        if f.endswith(".h"):
            with open(os.path.join(inc, f)) as fh:
                names.update(re.findall(r"\b(pg_[A-Za-z0-9_]+)\s*\(", fh.read()))
    return names


def compile_all(build, cpu, jobs, extra=(), variant=""):
    """Objects of the library for one CPU, with their .su and .ci files beside them."""
    out = os.path.join(build, cpu.replace("+", "plus") + variant)
    os.makedirs(out, exist_ok=True)
    flags = CPUS[cpu][0] + COMMON + list(extra) + ["-fstack-usage", "-fcallgraph-info=su"]

    def one(src):
        obj = os.path.join(out, os.path.basename(src)[:-2] + ".o")
        run([CC] + flags + ["-c", src, "-o", obj])
        return obj

    with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
        objects = list(pool.map(one, library_sources()))
    return out, objects


def archive(out, objects):
    lib = os.path.join(out, "libpogon.a")
    if os.path.exists(lib):
        os.remove(lib)
    run(["arm-none-eabi-ar", "rcs", lib] + objects)
    return lib


def public_functions(objects, exclude=(), only=None):
    names = []
    for obj in objects:
        if os.path.basename(obj)[:-2] + ".c" in exclude:
            continue
        if only is not None and os.path.basename(obj)[:-2] + ".c" not in only:
            continue
        for line in run(["arm-none-eabi-nm", "-g", "--defined-only", obj]).splitlines():
            parts = line.split()
            if len(parts) == 3 and parts[1] == "T":
                names.append(parts[2])
    return sorted(names)


def flash_of(elf):
    line = run(["arm-none-eabi-size", "-B", elf]).splitlines()[1].split()
    return int(line[0]) + int(line[1])


def link_config(out, cpu, lib, main_src, keep, name):
    elf = os.path.join(out, name + ".elf")
    cmd = [CC] + CPUS[cpu][0] + COMMON + LINK + ["--specs=nosys.specs", "-e", "main",
                                                 "-Wl,-Map=" + elf[:-4] + ".map", main_src, lib, "-o", elf]
    cmd += ["-Wl,--undefined=" + f for f in keep]
    run(cmd)
    return elf


def holders(mapfile, top=4):
    """The library objects that take the most flash in a linked program (from the map)."""
    sizes = {}
    pattern = re.compile(r"^\s*(\.(?:text|rodata|data)\S*)?\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+\S*libpogon\.a\((\S+)\.o\)")
    pending = None
    in_discard = True
    with open(mapfile) as f:
        for line in f:
            if line.startswith("Linker script and memory map"):
                in_discard = False
            if in_discard:
                continue
            m = pattern.match(line)
            if m and (m.group(1) or pending):
                if int(m.group(2), 16) != 0:
                    sizes[m.group(4)] = sizes.get(m.group(4), 0) + int(m.group(3), 16)
                pending = None
            elif re.match(r"^\s*\.(text|rodata|data)\S*\s*$", line):
                pending = line.strip()  # long section names put the numbers on the next line
            else:
                pending = None
    return sorted(sizes.items(), key=lambda kv: -kv[1])[:top]


def measure_flash(build, jobs):
    result = {}
    for cpu in CPUS:
        out, objects = compile_all(build, cpu, jobs)
        lib = archive(out, objects)
        base = flash_of(link_config(out, cpu, lib, os.path.join(HERE, "baseline.c"), [], "baseline"))
        core = public_functions(objects, FILE_FORMATS)
        every = public_functions(objects)
        configs = {
            "step-only": (os.path.join(HERE, "step_only.c"), []),
            "core-module": (os.path.join(HERE, "baseline.c"), public_functions(objects, only=core_sources())),
            "core": (os.path.join(HERE, "baseline.c"), core),
            "everything": (os.path.join(HERE, "baseline.c"), every),
        }
        for name, (src, keep) in configs.items():
            elf = link_config(out, cpu, lib, src, keep, name)
            result[(name, cpu)] = (flash_of(elf) - base, holders(elf[:-4] + ".map"))
        for name, flags, suffix in VARIANTS:
            v_out, v_objects = compile_all(build, cpu, jobs, flags, suffix)
            v_lib = archive(v_out, v_objects)
            elf = link_config(v_out, cpu, v_lib, os.path.join(HERE, "step_only.c"), [], name)
            result[(name, cpu)] = (flash_of(elf) - base, holders(elf[:-4] + ".map"))
    return result


def measure_one(build, name, cpu, jobs, top=16):
    """Flash of one configuration on one CPU, its largest parts and its largest functions:
    the one library that configuration needs, not all of them (--one)."""
    flags, suffix = next(((f, s) for n, f, s in VARIANTS if n == name), ([], ""))
    out, objects = compile_all(build, cpu, jobs, flags, suffix)
    lib = archive(out, objects)
    base = flash_of(link_config(out, cpu, lib, os.path.join(HERE, "baseline.c"), [], "baseline"))
    keep = {"core-module": lambda: public_functions(objects, only=core_sources()),
            "core": lambda: public_functions(objects, FILE_FORMATS),
            "everything": lambda: public_functions(objects)}.get(name, lambda: [])()
    main_src = os.path.join(HERE, "baseline.c" if keep else "step_only.c")
    elf = link_config(out, cpu, lib, main_src, keep, name)
    mapfile = elf[:-4] + ".map"
    return flash_of(elf) - base, holders(mapfile), functions_of(mapfile, top)


def functions_of(mapfile, top=12):
    """The largest functions and tables of a linked program (from the map): (file, name,
    bytes), pogon's objects by source file, libgcc's helpers as libgcc."""
    found = []
    pattern = re.compile(r"^\s*\.(?:text|rodata|data)\.?(\S*)?\s+0x([0-9a-f]+)\s+0x([0-9a-f]+)\s+\S*?(libpogon|libgcc)\.a\((\S+)\.o\)")
    pending = None
    in_discard = True
    with open(mapfile) as f:
        for line in f:
            if line.startswith("Linker script and memory map"):
                in_discard = False
            if in_discard:
                continue
            m = pattern.match(pending + " " + line.strip() if pending else line)
            pending = None
            if m:
                if int(m.group(2), 16) != 0 and int(m.group(3), 16) != 0:
                    lib, obj = m.group(4), m.group(5)
                    name = m.group(1) or obj
                    found.append(("libgcc" if lib == "libgcc" else obj + ".c", name, int(m.group(3), 16)))
            elif re.match(r"^\s*\.(text|rodata|data)\S*\s*$", line):
                pending = line.rstrip()  # long section names put the numbers on the next line
    return sorted(found, key=lambda x: -x[2])[:top]


def measure_effects(build, jobs):
    """Cortex-M4 step-only program (step_only.c) of the full library with one effect left
    out at a time (PG_CONFIG_EFFECTS), and the largest functions of step-only-small."""
    cpu = "M4"
    sizes = []
    out = os.path.join(build, "M4")
    base = flash_of(os.path.join(out, "baseline.elf"))
    for name, bit in EFFECTS:
        e_out, e_objects = compile_all(build, cpu, jobs, ["-DPG_CONFIG_EFFECTS=0x%02Xu" % (0x7F & ~bit)], "-no-%d" % bit)
        e_lib = archive(e_out, e_objects)
        elf = link_config(e_out, cpu, e_lib, os.path.join(HERE, "step_only.c"), [], "step-only")
        sizes.append((name, 0x7F & ~bit, flash_of(elf) - base))
    small = functions_of(os.path.join(build, "M4-small", "step-only-small.map"), 16)
    return sizes, small


def read_limits():
    limits = {}
    if not os.path.exists(LIMITS):
        return limits
    with open(LIMITS) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                name, cpu, measured = line.split()
                limits[(name, cpu)] = int(measured)
    return limits


def write_limits(flash):
    with open(LIMITS, "w") as f:
        f.write("# Flash (bytes) of each configuration when its limit was set, by tools/size/size_table.py\n"
                "# --update-limits; the cortex_m_size_and_no_float test fails above this + 2 %. Lower them when the\n"
                "# code shrinks; raise them only for a growth that is worth its flash, in its own commit.\n")
        for (name, cpu), (size, _) in sorted(flash.items()):
            f.write("%s %s %d\n" % (name, cpu, size))


def firmware(build, cpu, sources, name, extra=()):
    out = os.path.join(build, cpu.replace("+", "plus"))
    os.makedirs(out, exist_ok=True)
    elf = os.path.join(out, name + ".elf")
    run([CC] + CPUS[cpu][0] + COMMON + LINK + list(extra) + [
        "-Itools/scenes", "-Iports/cortex-m", "--specs=rdimon.specs", "-Tports/cortex-m/mps2.ld",
        "ports/cortex-m/startup.c", "ports/cortex-m/syscalls.c", "tools/scenes/scenes.c"] + sources +
        library_sources() + ["-o", elf])
    return elf


def measure_divisions(build):
    """{cpu: (ldivmod calls, uldivmod calls) per pyramid step} from step_count.c built to
    count them (count_divisions.S)."""
    result = {}
    for cpu in CPUS:
        elf = firmware(build, cpu, ["tools/size/step_count.c", "tools/size/count_divisions.S"], "step_divisions",
                       ["-DPOGON_COUNT_DIVISIONS", "-Wl,--wrap=__aeabi_ldivmod", "-Wl,--wrap=__aeabi_uldivmod"])
        m = re.search(r"^divisions (\d+) (\d+) (\d+) (\d+)$", qemu(cpu, elf), re.M)
        if not m:
            raise RuntimeError("step_divisions on %s printed no divisions line" % cpu)
        steps = int(m.group(2)) - int(m.group(1)) + 1
        result[cpu] = (int(m.group(3)) / steps, int(m.group(4)) / steps)
    return result


def qemu_command(cpu, elf, icount=False):
    cmd = [QEMU, "-M", CPUS[cpu][1], "-nographic", "-semihosting", "-kernel", elf]
    if icount:
        cmd[1:1] = ["-icount", "shift=0"]
    return cmd


def qemu(cpu, elf, icount=False):
    return run(qemu_command(cpu, elf, icount), timeout=600)


def measure_memory(build):
    """{(bodies, shapes, contacts): bytes} and {(bodies, shapes, contacts): {part: bytes}}."""
    elf = firmware(build, "M4", ["tools/size/world_memory.c"], "world_memory")
    sizes, parts = {}, {}
    for line in qemu("M4", elf).splitlines():
        p = line.split()
        # "-lean": the world made with max_joints 0 and max_contact_events 0 (key ends "lean")
        lean = ("lean",) if p and p[0].endswith("-lean") else ()
        if p and p[0] in ("memory", "memory-lean"):
            sizes[tuple(int(x) for x in p[1:4]) + lean] = int(p[4])
        elif p and p[0] in ("part", "part-lean"):
            parts.setdefault(tuple(int(x) for x in p[1:4]) + lean, {})[" ".join(p[5:])] = int(p[4])
    return sizes, parts


def measure_steps(build):
    """{cpu: (instructions per step at -Os, per tick, rows, first, last, at -O2)}: the -O2 build
    (the same sources, gcc's later -O2 winning) forces the solver's rows inline as host
    builds do (PG__INLINE_ROW), so it shows what a build for speed costs per step."""
    result = {}
    for cpu in CPUS:
        runs = []
        for name, extra in (("step_count", []), ("step_count_o2", ["-O2"])):
            elf = firmware(build, cpu, ["tools/size/step_count.c"], name, extra)
            text = qemu(cpu, elf, icount=True)
            cal = re.search(r"^calibration (\d+) (\d+)$", text, re.M)
            pyr = re.search(r"^pyramid (\d+) (\d+) (\d+) (\d+)$", text, re.M)
            if not cal or not pyr:
                raise RuntimeError("%s on %s printed:\n%s" % (name, cpu, text))
            per_tick = int(cal.group(1)) / int(cal.group(2))
            steps = int(pyr.group(3)) - int(pyr.group(2)) + 1
            runs.append((int(pyr.group(4)) * per_tick / steps, per_tick, pyr.group(1), pyr.group(2), pyr.group(3)))
        result[cpu] = runs[0] + (runs[1][0],)
    return result


PROFILE_TOP = 12  # functions listed per CPU
PROFILE_STEPS = 10  # steps 1..PROFILE_STEPS, as step_count.c's own count
TB_INSN = re.compile(r"^0x([0-9a-f]+):\s")
TB_EXEC = re.compile(r"^Trace \d+: 0x[0-9a-f]+ \[[0-9a-f]+/([0-9a-f]+)/")


def executed_by_function(cpu, elf):
    """{function: instructions executed} of one run of elf under qemu's execution log."""
    cmd = qemu_command(cpu, elf) + ["-d", "in_asm,exec,nochain"]
    length, runs, block = {}, {}, None  # block: [first pc, instructions] being read
    with subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, universal_newlines=True) as p:
        for line in p.stderr:
            if line.startswith("IN:"):
                block = [None, 0]
                continue
            m = TB_INSN.match(line)
            if m and block is not None:
                if block[0] is None:
                    block[0] = int(m.group(1), 16)
                block[1] += 1
                length[block[0]] = block[1]
                continue
            m = TB_EXEC.match(line)
            if m:
                block = None
                pc = int(m.group(1), 16)
                runs[pc] = runs.get(pc, 0) + 1
    if p.returncode != 0:
        raise SystemExit("size_table: %s failed (%d)" % (" ".join(cmd), p.returncode))
    symbols = []
    for line in run(["arm-none-eabi-nm", "-n", "-S", elf]).splitlines():
        f = line.split()
        if len(f) == 4 and f[2] in "tTwW":
            symbols.append((int(f[0], 16) & ~1, int(f[1], 16), f[3]))
    starts = [a for a, _, _ in symbols]
    result = {}
    for pc, n in runs.items():
        i = bisect.bisect_right(starts, pc) - 1
        name = symbols[i][2] if i >= 0 and pc < symbols[i][0] + symbols[i][1] else "(outside any symbol)"
        result[name] = result.get(name, 0) + n * length.get(pc, 0)
    return result


def measure_profile(build):
    """{cpu: (steps, [(function, instructions per step)...] largest first)} for the steps of
    step_count.c: its run without steps subtracted from its run with them."""
    result = {}
    for cpu in CPUS:
        runs = []
        for last in (0, PROFILE_STEPS):
            elf = firmware(build, cpu, ["tools/size/step_count.c"], "step_profile%d" % last,
                           ["-DSTEP_LAST=%du" % last, "-DCALIBRATION_SPINS=1000u"])
            runs.append(executed_by_function(cpu, elf))
        per_step = [(name, (n - runs[0].get(name, 0)) / PROFILE_STEPS) for name, n in runs[1].items()]
        result[cpu] = (PROFILE_STEPS, sorted((e for e in per_step if e[1] > 0), key=lambda e: (-e[1], e[0])))
    return result


def call_graph(out):
    """Frames and edges from the .ci files (gcc -fcallgraph-info=su)."""
    frames, edges, names, files = {}, {}, {}, {}
    node = re.compile(r'^node: \{ title: "([^"]+)" label: "([^\\"]+)\\n([^:"]*):[^"]*?\\n(\d+) bytes \(([^)]*)\)"')
    edge = re.compile(r'^edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
    for f in sorted(os.listdir(out)):
        if not f.endswith(".ci"):
            continue
        with open(os.path.join(out, f)) as fh:
            for line in fh:
                m = node.match(line)
                if m:
                    frames[m.group(1)] = (int(m.group(4)), m.group(5))
                    names[m.group(1)] = m.group(2)
                    files[m.group(1)] = os.path.basename(m.group(3))
                    continue
                m = edge.match(line)
                if m:
                    edges.setdefault(m.group(1), set()).add(m.group(2))
    return frames, edges, names, files


def deepest(root, frames, edges, memo, stack=()):
    """(bytes, chain, bounded) of the deepest call chain from root; recursion is cut and
    reported as not bounded."""
    if root in memo:
        return memo[root]
    if root in stack:
        return (0, [root + " (recursion)"], False)
    own, kind = frames.get(root, (0, "static"))
    best = (0, [], True)
    for callee in sorted(edges.get(root, ())):
        sub = deepest(callee, frames, edges, memo, stack + (root,))
        if sub[0] > best[0]:
            best = sub
    bounded = best[2] and kind.startswith("static") or kind == "dynamic,bounded"
    result = (own + best[0], [root] + best[1], bounded)
    memo[root] = result
    return result


def measure_stack(build):
    out = os.path.join(build, "M4")
    frames, edges, names, files = call_graph(out)
    memo = {}
    api = public_api()
    public = [t for t in frames if ":" not in t and t in api]
    per_public = sorted(((deepest(t, frames, edges, memo), t) for t in public), key=lambda x: -x[0][0])
    per_core = [p for p in per_public if files.get(p[1]) not in FILE_FORMATS]
    step = deepest("pg_world_step", frames, edges, memo)
    # which functions below pg_world_step call a 64-bit division helper
    seen, todo, dividers = set(), ["pg_world_step"], set()
    while todo:
        f = todo.pop()
        if f in seen:
            continue
        seen.add(f)
        for callee in edges.get(f, ()):
            if callee in ("__aeabi_ldivmod", "__aeabi_uldivmod", "__divdi3", "__udivdi3", "__moddi3", "__umoddi3"):
                dividers.add(names.get(f, f).split(".")[0])
            todo.append(callee)
    largest = sorted(((frames[t][0], names[t]) for t in frames), reverse=True)[:6]
    short = lambda chain: " > ".join(names.get(c, c) for c in chain)
    sites = division_sites(out)
    reach = set(names.get(f, f) for f in seen)
    step_sites = sorted((n, c) for n, c in sites.items() if n in reach)
    # a call deeper than 4 KiB whose work area can come from the caller names its small-stack
    # form (X_in, declared beside it), which the budget is for
    depth_of = dict((t, d[0]) for d, t in per_public)
    over = [(d[0], t) + ((t + "_in", depth_of[t + "_in"]) if t + "_in" in depth_of else ())
            for d, t in per_public if d[0] > 4096]
    return step, per_public[:3] + per_core[:3], largest, short, sorted(dividers), step_sites, over, len(public)


def over_text(entry):
    """One call of the "deeper than 4 KiB" line; a wrapper names its small-stack form."""
    if len(entry) > 2:
        return "%s %d B (its work area on its own stack; `%s` takes it from the caller: %d B)" % (
            entry[1], entry[0], entry[2], entry[3])
    return "%s %d B" % (entry[1], entry[0])


def report_stack(build, jobs):
    """--stack: the Cortex-M4 objects only, and the stack report of every public call."""
    out, _ = compile_all(build, "M4", jobs)
    stack = measure_stack(build)
    step, calls, largest, short, dividers, sites, over, n_public = stack
    frames, edges, names, files = call_graph(out)
    memo = {}
    api = public_api()
    print("stack pg_world_step %d: %s" % (step[0], short(step[1])))
    for t in sorted((t for t in frames if ":" not in t and t in api and files.get(t) in FILE_FORMATS),
                    key=lambda t: -deepest(t, frames, edges, memo)[0]):
        d = deepest(t, frames, edges, memo)
        print("stack %s %d: %s" % (t, d[0], short(d[1])))
    print("deeper than 4 KiB (of %d public calls): %s" % (n_public, ", ".join(over_text(e) for e in over) or "none"))
    print("largest frames: %s" % ", ".join("%s %d B" % (n, b) for b, n in largest))
    return 0


def division_sites(out):
    """{function: calls of __aeabi_ldivmod / __aeabi_uldivmod in its code} (relocations)."""
    sites = {}
    for f in sorted(os.listdir(out)):
        if not f.endswith(".o") or f in ("baseline.o",):
            continue
        fn = None
        for line in run(["arm-none-eabi-objdump", "-dr", os.path.join(out, f)]).splitlines():
            m = re.match(r"^[0-9a-f]+ <([^>]+)>:$", line)
            if m:
                fn = m.group(1)
            elif fn and re.search(r"R_ARM_THM_(CALL|JUMP24)\s+__aeabi_u?ldivmod$", line):
                sites[fn] = sites.get(fn, 0) + 1
    return sites


def kib(n):
    return "%.1f KiB" % (n / 1024.0)


def machine():
    cpu_model = platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            m = re.search(r"^model name\s*:\s*(.*)$", f.read(), re.M)
            if m:
                cpu_model += ", " + m.group(1).strip()
    except OSError:
        pass
    return cpu_model


def results_of(flash, effects, memory, stack, steps, divisions, profile, command):
    """Every figure the tables show, as JSON (what --results writes and --render reads),
    with when, where, at what load, with which toolchain and by which command."""
    sizes, parts = memory
    step, calls, largest, short, _, sites, over, n_public = stack
    entry = lambda d: {"bytes": d[0], "chain": short(d[1]).split(" > "), "bounded": bool(d[2])}
    return {
        "measured": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC"),
        "machine": machine(),
        "load": "%.2f %.2f %.2f" % os.getloadavg(),
        "compiler": run([CC, "--version"]).splitlines()[0],
        "qemu": run([QEMU, "--version"]).splitlines()[0],
        "command": command,
        "flash": [{"config": n, "cpu": c, "bytes": s, "parts": [list(x) for x in largest_parts]}
                  for (n, c), (s, largest_parts) in sorted(flash.items())],
        "effects": [{"effect": n, "config": m, "bytes": s} for n, m, s in effects[0]],
        "small_functions": [list(x) for x in effects[1]],
        "memory": [{"world": list(k), "bytes": v, "parts": parts.get(k, {})} for k, v in sizes.items()],
        "stack": {"step": entry(step), "calls": [entry(d) for d, _ in calls],
                  "largest_frames": [list(x) for x in largest], "over_4k": [list(x) for x in over],
                  "public_declared": n_public, "step_division_sites": [list(x) for x in sites]},
        "steps": {cpu: {"instructions": v[0], "per_tick": v[1], "rows": v[2], "first": v[3], "last": v[4], "instructions_o2": v[5]}
                  for cpu, v in steps.items()},
        "divisions": {cpu: list(v) for cpu, v in divisions.items()},
        "profile": {cpu: {"steps": n, "functions": [[k, v] for k, v in ranked]} for cpu, (n, ranked) in profile.items()},
    }


def from_results(r):
    """The arguments of markdown() from a results file's JSON."""
    flash = {(f["config"], f["cpu"]): (f["bytes"], [tuple(x) for x in f["parts"]]) for f in r["flash"]}
    memory = ({tuple(m["world"]): m["bytes"] for m in r["memory"]}, {tuple(m["world"]): m["parts"] for m in r["memory"]})
    s = r["stack"]
    entry = lambda d: (d["bytes"], d["chain"], d["bounded"])
    stack = (entry(s["step"]), [(entry(d), d["chain"][0]) for d in s["calls"]],
             [tuple(x) for x in s["largest_frames"]], lambda chain: " > ".join(chain), None,
             [tuple(x) for x in s["step_division_sites"]], [tuple(x) for x in s["over_4k"]], s["public_declared"])
    steps = {cpu: (v["instructions"], v["per_tick"], v["rows"], v["first"], v["last"], v.get("instructions_o2"))
             for cpu, v in r["steps"].items()}
    divisions = {cpu: tuple(v) for cpu, v in r["divisions"].items()}
    profile = {cpu: (v["steps"], [tuple(x) for x in v["functions"]]) for cpu, v in r.get("profile", {}).items()}
    return flash, memory, stack, steps, divisions, profile


def markdown(r, path):
    """The tables of the results r (read from path), as docs/embedded.md shows them."""
    flash, memory, stack, steps, divisions, profile = from_results(r)
    limits = read_limits()
    L = []
    L.append("Measured %s on %s (load average %s) by `%s`; %s, %s. Rendered from `%s` by "
             "`tools/size/size_table.py --render`." % (r["measured"], r["machine"], r["load"], r["command"],
                                                       r["compiler"], r["qemu"], path))
    L.append("")
    L.append("Flash: `-mthumb -Os -ffunction-sections -fdata-sections -mgeneral-regs-only`, newlib-nano, "
             "`--gc-sections`, 12-bit sine table, `PG_FAST_DIV64=0`; what pogon adds to a program "
             "without it (tools/size/baseline.c), libgcc helpers included.")
    L.append("")
    L.append("| configuration | budget | Cortex-M4 | Cortex-M0+ | status | largest parts (M4) |")
    L.append("| --- | --- | --- | --- | --- | --- |")
    for name in CONFIGS:
        m4, m0 = flash[(name, "M4")][0], flash[(name, "M0+")][0]
        parts = ", ".join("%s.c %s" % (o, kib(s)) for o, s in flash[(name, "M4")][1])
        if BUDGETS[name] is None:
            L.append("| %s | - | %s | %s | - | %s |" % (CONFIG_TEXT[name], kib(m4), kib(m0), parts))
            continue
        budget = BUDGETS[name] * 1024
        worst = max(m4, m0)
        if worst <= budget:
            status = "within budget"
        else:
            status = "over budget by %s (M0+: %s)" % (kib(m4 - budget), kib(m0 - budget)) if m4 > budget \
                else "M4 within, M0+ over by %s" % kib(m0 - budget)
        L.append("| %s | %d KiB | %s | %s | %s | %s |" % (CONFIG_TEXT[name], BUDGETS[name], kib(m4), kib(m0), status, parts))
    L.append("")
    if r.get("effects"):
        full = flash[("step-only", "M4")][0]
        L.append("Each effect left out on its own (`PG_CONFIG_EFFECTS`), the step-only program on the Cortex-M4: "
                 + ", ".join("%s %s (%s%s)" % (e["effect"], kib(e["bytes"]), "-" if e["bytes"] <= full else "+",
                                                kib(abs(full - e["bytes"]))) for e in r["effects"]) + ".")
        L.append("")
    if r.get("small_functions"):
        L.append("Largest functions and tables of the smallest step-only program (the `PG_CONFIG_JOINTS=0` row above, "
                 "Cortex-M4, from its link map): "
                 + ", ".join("%s `%s` %d B" % tuple(x) for x in r["small_functions"]) + ".")
        L.append("")
    if limits:
        L.append("The cortex_m_size_and_no_float test holds each figure under its limit in tools/size/flash_limits.txt "
                 "(+2 %%): %s." % ", ".join("%s %s %d B" % (n, c, v) for (n, c), v in sorted(limits.items())))
        L.append("")
    if memory:
        memory, parts = memory
        base = (1024, 1024, 4096)
        more = {"body": (1032, 1024, 4096), "shape": (1024, 1032, 4096), "contact": (1024, 1024, 4104)}
        pyr = [k for k in memory if len(k) == 3 and k != (32, 32, 128) and k != base and k not in more.values()]
        L.append("RAM (`pg_world_memory_size` on the Cortex-M4, 32-bit pointers):")
        L.append("")
        L.append("| world | bytes |")
        L.append("| --- | --- |")
        L.append("| 32 bodies, 32 shapes, 128 contacts | %d (%s) |" % (memory[(32, 32, 128)], kib(memory[(32, 32, 128)])))
        for k in pyr:
            L.append("| pyramid of 20 rows: %d bodies, %d shapes, %d contacts | %d (%s) |" % (k + (memory[k], kib(memory[k]))))
        L.append("| 1024 bodies, 1024 shapes, 4096 contacts (the defaults) | %d (%s) |" % (memory[base], kib(memory[base])))
        L.append("")
        L.append("What one more slot costs, by part of the world's memory block (src/core/world.c, from 8 more slots "
                 "at the defaults; the scratch area serves the broadphase, then the next step's contact list, then the solver, then a body's mass, "
                 "and is as large as the largest of them: here the solver's):")
        L.append("")
        L.append("| slot | budget | bytes | parts |")
        L.append("| --- | --- | --- | --- |")
        slot_budget = {"body": "256", "shape": "-", "contact": "192"}
        for kind, key in more.items():
            total = (memory[key] - memory[base]) / 8.0
            split = sorted(((parts[key][n] - parts[base][n]) / 8.0, n) for n in parts[key] if parts[key][n] != parts[base][n])
            L.append("| %s | %s | %g | %s |" % (kind, slot_budget[kind], total,
                                              ", ".join("%s %g" % (n, b) for b, n in reversed(split))))
        L.append("")
        lean = lambda k: k + ("lean",)
        if all(lean(k) in memory for k in (base, more["body"], more["contact"])):
            per = lambda kind: (memory[lean(more[kind])] - memory[lean(base)]) / 8.0
            L.append("The same in a world made with `max_joints` 0 and `max_contact_events` 0 (a program without "
                     "joints that reads no events): body %g bytes, contact %g (a shape slot does not change)."
                     % (per("body"), per("contact")))
            L.append("")
    if stack:
        step, public, largest, short, dividers, step_sites, over, n_public = stack
        L.append("Stack (Cortex-M4 -Os, deepest call chain from the .su frame sizes; library helpers count 0): "
                 "pg_world_step, the three deepest public calls, and the three deepest outside the file formats.")
        L.append("")
        L.append("| entry | bytes | chain |")
        L.append("| --- | --- | --- |")
        L.append("| pg_world_step | %d%s | %s |" % (step[0], "" if step[2] else " (not bounded)", short(step[1])))
        for (depth, chain, bounded), _ in public:
            L.append("| %s | %d%s | %s |" % (chain[0], depth, "" if bounded else " (not bounded)", short(chain)))
        L.append("")
        L.append("Public calls (of %d declared in include/pogon/) deeper than 4 KiB: %s." % (
            n_public, ", ".join(over_text(e) for e in over) if over else "none"))
        L.append("")
        L.append("Largest frames: %s." % ", ".join("%s %d B" % (n, b) for b, n in largest))
        L.append("")
        L.append("64-bit divisions (`__aeabi_ldivmod`, `__aeabi_uldivmod`) below pg_world_step, with "
                 "`PG_FAST_DIV64=0`: %d call sites in %d functions (%s)." % (
                     sum(c for _, c in step_sites), len(step_sites),
                     ", ".join("%s %d" % (n, c) for n, c in step_sites) if step_sites else "none"))
        L.append("")
    if steps:
        L.append("Step cost: the pyramid of %s rows (210 boxes, all awake), steps %s to %s, under "
                 "`qemu-system-arm -icount shift=0` (tools/size/step_count.c; instructions, not cycles):"
                 % (steps["M4"][2], steps["M4"][3], steps["M4"][4]))
        L.append("")
        L.append("| CPU | instructions per step | the same built with -O2 | instructions per SysTick tick (calibrated) |")
        L.append("| --- | --- | --- | --- |")
        for cpu in CPUS:
            o2 = steps[cpu][5]
            L.append("| Cortex-%s | %.2f M | %s | %.1f |" % (cpu, steps[cpu][0] / 1e6, "%.2f M" % (o2 / 1e6) if o2 else "-",
                                                       steps[cpu][1]))
        L.append("")
    if divisions:
        L.append("64-bit division calls per pyramid step (the same steps, step_count.c counting them through "
                 "tools/size/count_divisions.S): %s." % "; ".join(
                     "Cortex-%s %.0f (`__aeabi_ldivmod` %.0f, `__aeabi_uldivmod` %.0f)" % (cpu, a + b, a, b)
                     for cpu, (a, b) in divisions.items()))
        L.append("")
    if profile:
        L.extend(profile_table(profile))
    return "\n".join(L)


def profile_table(profile):
    """Markdown lines: the functions that run most of a pyramid step's instructions."""
    L = ["Where a pyramid step's instructions go (the same steps; step_count.c run under "
         "`qemu-system-arm -d in_asm,exec,nochain`, the run without steps subtracted; a function's own "
         "instructions, not its callees'; `static` functions that gcc inlined count in their caller):", ""]
    cpus = list(profile)
    L.append("| rank | " + " | ".join("Cortex-%s | share" % cpu for cpu in cpus) + " |")
    L.append("| --- | " + " | ".join("--- | ---:" for _ in cpus) + " |")
    totals = {cpu: sum(n for _, n in profile[cpu][1]) for cpu in cpus}
    for i in range(PROFILE_TOP):
        cells = []
        for cpu in cpus:
            ranked = profile[cpu][1]
            if i < len(ranked):
                cells.append("`%s` | %.1f %%" % (ranked[i][0], 100.0 * ranked[i][1] / totals[cpu]))
            else:
                cells.append("- | -")
        L.append("| %d | %s |" % (i + 1, " | ".join(cells)))
    L.append("")
    return L


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--results", metavar="JSON", help="write the figures to this file (with --render: read them)")
    ap.add_argument("--render", action="store_true", help="print the tables from --results FILE; measures nothing")
    ap.add_argument("--build", default=os.path.join(ROOT, "build", "size"), help="work directory")
    ap.add_argument("--check", action="store_true", help="flash only: fail above the limits")
    ap.add_argument("--update-limits", action="store_true", help="write today's flash as the limits")
    ap.add_argument("--stack", action="store_true", help="the stack report only (Cortex-M4 objects; writes no results)")
    ap.add_argument("--profile", action="store_true", help="the step's instructions by function only (writes no results)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--one", metavar="CONFIG", choices=CONFIGS,
                    help="measure only this configuration's flash and print its largest functions; writes nothing")
    ap.add_argument("--cpu", choices=("m4", "m0plus"), default="m4", help="the CPU of --one")
    args = ap.parse_args()
    if args.one and (args.render or args.check or args.update_limits or args.results or args.stack):
        ap.error("--one measures and prints only: not with --render, --check, --update-limits, --results or --stack")
    if args.profile and (args.render or args.check or args.update_limits or args.results or args.stack or args.one):
        ap.error("--profile measures and prints only: not with another mode or --results")
    if args.stack:
        if shutil.which(CC) is None:
            print("size_table: %s not found (scripts/setup-deps.sh cortex-m installs it): skipped" % CC)
            return 77
        return report_stack(os.path.abspath(args.build), args.jobs)
    if args.render:
        if not args.results:
            ap.error("--render needs --results FILE")
        path = args.results if os.path.isabs(args.results) else os.path.join(ROOT, args.results)
        try:
            with open(path) as f:
                results = json.load(f)
            print(markdown(results, args.results))
        except (OSError, ValueError, KeyError, TypeError, IndexError) as e:
            raise SystemExit("size_table: %s: not a results file of size_table.py (%s: %s)" % (args.results, type(e).__name__, e))
        return 0
    for tool in (CC, QEMU) if not (args.check or args.one) else (CC,):
        if shutil.which(tool) is None:
            print("size_table: %s not found (scripts/setup-deps.sh cortex-m installs it): skipped" % tool)
            return 77
    build = os.path.abspath(args.build)
    if args.profile:
        print("\n".join(profile_table(measure_profile(build))))
        return 0
    if args.one:
        cpu = {"m4": "M4", "m0plus": "M0+"}[args.cpu]
        size, parts, functions = measure_one(build, args.one, cpu, args.jobs)
        print("flash %s %s %d B (%s)  budget %s KiB  largest: %s" % (
            args.one, cpu, size, kib(size), BUDGETS[args.one] or "-", ", ".join("%s %d" % p for p in parts)))
        for f, n, b in functions:
            print("  %6d B  %s %s" % (b, f, n))
        return 0
    flash = measure_flash(build, args.jobs)
    for (name, cpu), (size, parts) in sorted(flash.items()):
        print("flash %-11s %-4s %7d B  budget %s KiB  largest: %s" % (
            name, cpu, size, BUDGETS[name] or "-", ", ".join("%s %d" % p for p in parts)))
    if args.update_limits:
        write_limits(flash)
        print("size_table: wrote %s" % LIMITS)
    if args.check:
        limits = read_limits()
        status = 0
        for key, (size, _) in sorted(flash.items()):
            if key not in limits:
                print("FAIL: no limit for %s %s in %s" % (key + (LIMITS,)))
                status = 1
                continue
            allowed = int(limits[key] * GROWTH)
            verdict = "ok" if size <= allowed else "FAIL"
            print("%s: %s %s %d B, limit %d B (%d + 2 %%), budget %s" % (
                verdict, key[0], key[1], size, allowed, limits[key],
                "%d B" % (BUDGETS[key[0]] * 1024) if BUDGETS[key[0]] else "none"))
            if size > allowed:
                status = 1
        # the stack budgets, met: 2 KiB in pg_world_step, 4 KiB in every public call (a plain
        # reader that puts its work area on its own stack counts by its _in form)
        step, _, _, short, _, _, over, _ = measure_stack(build)
        too_deep = [e for e in over if len(e) <= 2 or e[3] > 4096]
        step_ok = step[2] and step[0] <= 2048
        print("%s: stack pg_world_step %d B (budget 2048 B): %s" % ("ok" if step_ok else "FAIL", step[0], short(step[1])))
        print("%s: public calls deeper than 4 KiB without a small-stack form: %s" % (
            "ok" if not too_deep else "FAIL", ", ".join(over_text(e) for e in too_deep) or "none"))
        if not step_ok or too_deep:
            status = 1
        for cpu in CPUS:
            lib = os.path.join(build, cpu.replace("+", "plus"), "libpogon.a")
            check = subprocess.run(["sh", os.path.join(ROOT, "scripts", "check-no-float.sh"), lib, "arm-none-eabi-objdump"],
                                   cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
            print("Cortex-%s: %s" % (cpu, check.stdout.strip().replace("\n", "\n  ")))
            if check.returncode != 0:
                status = 1
        return status
    effects = measure_effects(build, args.jobs)
    for name, mask, size in effects[0]:
        print("flash step-only M4 without %s (PG_CONFIG_EFFECTS=0x%02X): %d B" % (name, mask, size))
    memory = measure_memory(build)
    for k, v in sorted(memory[0].items()):
        print("memory %s %d" % (k, v))
    stack = measure_stack(build)
    print("stack pg_world_step %d: %s" % (stack[0][0], stack[3](stack[0][1])))
    steps = measure_steps(build)
    for cpu, v in steps.items():
        print("pyramid step %s: %.0f instructions (%.2f per tick)" % (cpu, v[0], v[1]))
    divisions = measure_divisions(build)
    for cpu, (a, b) in divisions.items():
        print("pyramid step %s: %.1f __aeabi_ldivmod, %.1f __aeabi_uldivmod calls" % (cpu, a, b))
    profile = measure_profile(build)
    results = results_of(flash, effects, memory, stack, steps, divisions, profile,
                         "tools/size/size_table.py" + (" --results " + args.results if args.results else ""))
    if args.results:
        with open(os.path.join(ROOT, args.results) if not os.path.isabs(args.results) else args.results, "w") as f:
            json.dump(results, f, indent=1)
            f.write("\n")
        print("size_table: wrote %s; render the documents with node tools/docs/regions.js --update" % args.results)
    print(markdown(results, args.results or "(not written)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())

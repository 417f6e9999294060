#!/usr/bin/env node
// harness.js — the pogon-bench scenes in matter.js (npm matter-js, the version pinned in
// package.json; `npm ci` here installs it), for comparison. Run by tools/bench/peers.
//
// Usage: node harness.js SCENE [--count N] [--steps N] [--repeat R] [--warmup-runs K]
//                        [--warmup-seconds S] [--json]
//                        [--variant defaults|best] [--sleep|--no-sleep]
//                        [--position-iterations N] [--velocity-iterations N]
//        node harness.js all [options]
//
// Same scenes as tools/scenes/scenes.c: a static ground 100 x 2 m whose top is at y = 0,
// 1 m boxes (pyramid: `count` rows centred on x = 0; stack: `count` boxes in a column),
// and rain: a 42 x 2 m floor, side walls 0.5 m thick in 100 m pieces at x = +-20.25 up to
// 500 m, and `count` circles whose radii (0.25 .. 0.5 m) and positions come from the same
// xorshift32 sequence (seed 12345) in the same order, converted from the same Q16.16
// integers.
//
// Units: matter.js is tuned for pixels (its slop, sleeping and other thresholds are in
// pixels), so 1 m = 100 units here: boxes are 100 units, circles 25..50 units. Its y axis
// points down; positions are mirrored (y_matter = -100 y) and the reported dy and angle
// are turned back to y-up. Gravity: matter's default {x: 0, y: 1, scale: 0.001} is
// 1000 units/s^2 = 10 m/s^2, as in the other engines. One Engine.update(engine, 1000/60)
// per step (60 Hz). Friction 0.6 on every body (matter takes the smaller of the two; its
// frictionStatic stays at the default 0.5), restitution 0, frictionAir 0 (the other
// engines have no damping; matter's default is 0.01), the default density everywhere
// (masses are proportional to area, as in the others). Circles are matter's circles:
// polygons of up to 25 sides (its default maxSides).
//
// Variants (--variant, default "defaults"):
//   defaults  positionIterations 6, velocityIterations 4, constraintIterations 2,
//             enableSleeping false (matter's Engine.create defaults).
//   best      enableSleeping true, default iterations: the fastest setting tried that keeps
//             the pyramid upright (more iterations sink it less: 20/20 halves the sinking
//             but costs 2.3 x; see tools/bench/peers.md). In rain matter puts most of the
//             pile to sleep within the 5 s measured.
//
// Method (as pogon-bench): build `repeat` times (default 3), time `steps` steps (default
// 600 for pyramid/stack, 300 for rain) with process.hrtime.bigint() around the stepping
// only, report the median of the per-run mean ms per step. The same JSON keys as
// pogon-bench, with "engine":"matter-js-<version>".
'use strict';

const Matter = require('matter-js');
const { Engine, Bodies, Composite } = Matter;

const SCALE = 100; // units per metre
const FRICTION = 0.6;

function usage(stream) {
    stream.write('usage: node harness.js pyramid|stack|rain|all [--count N] [--steps N] [--repeat R] [--warmup-runs K]\n' +
                 '         [--warmup-seconds S] [--json]\n' +
                 '         [--variant defaults|best] [--sleep|--no-sleep] [--position-iterations N] [--velocity-iterations N]\n');
}

function parseArgs(argv) {
    const o = { mode: null, count: 0, steps: 0, repeat: 3, warmupRuns: 0, warmupSeconds: 0, json: false, variant: 'defaults', sleep: null,
                positionIterations: 0, velocityIterations: 0 };
    for (let i = 0; i < argv.length; ++i) {
        const a = argv[i];
        if (a === '--json') o.json = true;
        else if (a === '--sleep') o.sleep = true;
        else if (a === '--no-sleep') o.sleep = false;
        else if (a === '--variant') {
            const v = argv[++i];
            if (v !== 'defaults' && v !== 'best') throw new Error('--variant takes defaults or best');
            o.variant = v;
        } else if (['--count', '--steps', '--repeat', '--position-iterations', '--velocity-iterations'].includes(a)) {
            const v = Number(argv[++i]);
            if (!Number.isInteger(v) || v <= 0) throw new Error(a + ' needs a positive integer');
            if (a === '--count') o.count = v;
            else if (a === '--steps') o.steps = v;
            else if (a === '--repeat') o.repeat = Math.min(v, 101);
            else if (a === '--position-iterations') o.positionIterations = v;
            else o.velocityIterations = v;
        } else if (a === '--warmup-runs') {
            // whole untimed runs first: V8 optimises hot code while it runs, so the first
            // runs of a short scene measure the compiler as much as the engine
            const v = Number(argv[++i]);
            if (!Number.isInteger(v) || v < 0 || v > 100) throw new Error('--warmup-runs needs an integer from 0 to 100');
            o.warmupRuns = v;
        } else if (a === '--warmup-seconds') {
            // and untimed runs until this much time has passed: V8 compiles in the
            // background, and a time says when a scene is warm whatever it costs
            const v = Number(argv[++i]);
            if (!Number.isInteger(v) || v < 0 || v > 60) throw new Error('--warmup-seconds needs an integer from 0 to 60');
            o.warmupSeconds = v;
        } else if (a === '--help' || a === '-h') {
            usage(process.stdout);
            process.exit(0);
        } else if (a[0] !== '-' && o.mode === null) o.mode = a;
        else throw new Error('unexpected argument ' + a);
    }
    if (o.mode === null) throw new Error('no scene');
    return o;
}

function settingsFor(scene, o) {
    const best = o.variant === 'best';
    const s = { positionIterations: 6, velocityIterations: 4, constraintIterations: 2, enableSleeping: best };
    if (o.positionIterations) s.positionIterations = o.positionIterations;
    if (o.velocityIterations) s.velocityIterations = o.velocityIterations;
    if (o.sleep !== null) s.enableSleeping = o.sleep;
    return s;
}

const q16 = (v) => v / 65536;

function nextRandom(state) {
    let x = state.s;
    x = (x ^ (x << 13)) >>> 0;
    x = (x ^ (x >>> 17)) >>> 0;
    x = (x ^ (x << 5)) >>> 0;
    state.s = x;
    return x;
}

const material = { friction: FRICTION, restitution: 0, frictionAir: 0 };

// a static box centred at (cx, cy) m, y up
function wall(cx, cy, w, h) {
    return Bodies.rectangle(cx * SCALE, -cy * SCALE, w * SCALE, h * SCALE, Object.assign({ isStatic: true }, material));
}

// Builds the scene; returns { bodies, top }.
function build(scene, count) {
    const all = [];
    let top = null, n = 0;
    if (scene === 'pyramid' || scene === 'stack') {
        const pyramid = scene === 'pyramid';
        all.push(wall(0, -1, 100, 2));
        for (let row = 0; row < (pyramid ? count : 1); ++row) {
            const m = pyramid ? count - row : count;
            for (let i = 0; i < m; ++i) {
                const x = pyramid ? q16((2 * i + 1) * 32768 - m * 32768) : 0;
                const y = pyramid ? 0.5 + row : 0.5 + i;
                top = Bodies.rectangle(x * SCALE, -y * SCALE, SCALE, SCALE, material);
                all.push(top);
                ++n;
            }
        }
    } else if (scene === 'rain') {
        all.push(wall(0, -1, 42, 2));
        for (let i = 0; i < 10; ++i) all.push(wall((i & 1) ? 20.25 : -20.25, 50 + 100 * Math.floor(i / 2), 0.5, 100));
        const seed = { s: 12345 };
        for (let i = 0; i < count; ++i) {
            const radius = 16384 + (nextRandom(seed) % 16385);
            const column = i % 39, layer = Math.floor(i / 39);
            const jitter = (nextRandom(seed) % 8193) - 4096;
            const x = column * 65536 - 19 * 65536 + jitter;
            const y = 2 * 65536 + layer * 65536;
            top = Bodies.circle(q16(x) * SCALE, -q16(y) * SCALE, q16(radius) * SCALE, material);
            all.push(top);
            ++n;
        }
    } else {
        throw new Error('unknown scene ' + scene);
    }
    return { all, top, n };
}

function run(scene, o, countOverride) {
    const rain = scene === 'rain';
    const count = countOverride || o.count || (rain ? 1000 : 20);
    const steps = o.steps || (rain ? 300 : 600);
    const repeat = o.repeat || 3;
    const s = settingsFor(scene, o);
    const runs = [];
    const res = { scene, count, steps, repeat, s, stands: !rain };
    const warmRuns = o.warmupRuns || 0, warmNs = BigInt(o.warmupSeconds || 0) * 1000000000n;
    const warmStart = process.hrtime.bigint();
    let warm = 0;
    res.warmupSeconds = o.warmupSeconds || 0;
    while (runs.length < repeat) {
        // untimed until both the runs and the time of the warm-up are done
        const warming = warm < warmRuns || process.hrtime.bigint() - warmStart < warmNs;
        const engine = Engine.create({
            positionIterations: s.positionIterations,
            velocityIterations: s.velocityIterations,
            constraintIterations: s.constraintIterations,
            enableSleeping: s.enableSleeping,
        });
        engine.gravity.x = 0;
        engine.gravity.y = 1;
        engine.gravity.scale = 0.001;
        const { all, top, n } = build(scene, count);
        Composite.add(engine.world, all);
        res.bodies = n;
        const x0 = top.position.x, y0 = top.position.y;
        const dt = 1000 / 60;
        const t0 = process.hrtime.bigint();
        for (let i = 0; i < steps; ++i) Engine.update(engine, dt);
        const t1 = process.hrtime.bigint();
        if (warming) {
            ++warm;
            continue;
        }
        runs.push(Number(t1 - t0) / 1e6 / steps);
        res.dx = (top.position.x - x0) / SCALE;
        res.dy = -(top.position.y - y0) / SCALE;
        res.disp = Math.hypot(res.dx, res.dy);
        res.angle = -top.angle * 180 / Math.PI;
        res.awake = all.filter((b) => !b.isStatic && !b.isSleeping).length;
        res.contacts = engine.pairs.list.length;
        res.touching = engine.pairs.list.filter((p) => p.isActive).length;
    }
    res.warmupRuns = warm;
    runs.sort((a, b) => a - b);
    const k = runs.length;
    res.ms = (k & 1) ? runs[k >> 1] : 0.5 * (runs[k / 2 - 1] + runs[k / 2]);
    res.msMin = runs[0];
    res.msMax = runs[k - 1];
    res.sps = res.ms > 0 ? 1000 / res.ms : 0;
    return res;
}

function printJson(r, variant) {
    const f = (v, d) => v.toFixed(d);
    let line = `{"engine":"matter-js-${Matter.version}","variant":"${variant}","scene":"${r.scene}","count":${r.count},` +
        `"bodies":${r.bodies},"steps":${r.steps},"warmup":0,"warmup_runs":${r.warmupRuns},"warmup_seconds":${r.warmupSeconds},` +
        `"repeat":${r.repeat},` +
        `"position_iterations":${r.s.positionIterations},"velocity_iterations":${r.s.velocityIterations},` +
        `"sleeping":${r.s.enableSleeping},"node":"${process.version}",` +
        `"ms_per_step":${f(r.ms, 6)},"ms_min":${f(r.msMin, 6)},"ms_max":${f(r.msMax, 6)},"steps_per_second":${f(r.sps, 2)},`;
    if (r.stands)
        line += `"top_displacement_m":${f(r.disp, 6)},"dx_m":${f(r.dx, 6)},"dy_m":${f(r.dy, 6)},"angle_deg":${f(r.angle, 4)},`;
    line += `"awake_bodies":${r.awake},"contacts":${r.contacts},"touching":${r.touching}}`;
    process.stdout.write(line + '\n');
}

function printRow(r, variant) {
    const f = (v, d) => v.toFixed(d);
    const disp = r.stands ? `${f(r.disp, 5)} | ${f(r.dx, 5)} | ${f(r.dy, 5)} | ${f(r.angle, 3)}` : '- | - | - | -';
    process.stdout.write(`| matter-js-${Matter.version} | ${variant} | ${r.scene} | ${r.count} | ${r.steps} | ` +
        `${r.s.positionIterations}/${r.s.velocityIterations} | ${r.s.enableSleeping ? 'on' : 'off'} | ${f(r.ms, 4)} | ` +
        `${disp} | ${r.awake} |\n`);
}

function main() {
    let o;
    try {
        o = parseArgs(process.argv.slice(2));
    } catch (e) {
        process.stderr.write('matter harness: ' + e.message + '\n');
        usage(process.stderr);
        process.exit(2);
    }
    const todo = o.mode === 'all'
        ? [['pyramid', 20], ['stack', 20], ['rain', 1000], ['rain', 2000], ['rain', 4000], ['rain', 8000], ['rain', 16000]]
        : [[o.mode, 0]];
    if (!['pyramid', 'stack', 'rain', 'all'].includes(o.mode)) {
        process.stderr.write('matter harness: unknown scene ' + o.mode + '\n');
        process.exit(2);
    }
    if (!o.json) {
        process.stdout.write('| engine | variant | scene | count | steps | iterations (pos/vel) | sleeping | ms/step | ' +
                             'top disp m | dx m | dy m | angle deg | awake at end |\n');
        process.stdout.write('| --- | --- | --- | ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n');
    }
    for (const [scene, count] of todo) {
        const r = run(scene, o, count);
        if (o.json) printJson(r, o.variant); else printRow(r, o.variant);
    }
}

main();

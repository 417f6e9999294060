#!/usr/bin/env node
// web_demo_table.js — the browser demo's figures (docs/web-demo.md) as markdown, from the
// committed results file (it never measures).
//
//   tools/docs/web_demo_table.js --results docs/results/web_demo.json
//
// The results file is what tools/bench/web_bench.mjs writes: date, machine, load average,
// Chromium version, command, one run per scene (means of one-second readouts of the page)
// and the download size in KiB. docs/generated.md says how regions are kept.
'use strict';
const fs = require('fs');
const path = require('path');

function usage(msg) {
  process.stderr.write(`web_demo_table: ${msg}\nusage: tools/docs/web_demo_table.js --results FILE\n`);
  process.exit(2);
}

let results = null;
const args = process.argv.slice(2);
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--results') results = args[++i];
  else usage(`unknown argument ${args[i]}`);
}
if (!results) usage('--results is required');

const ROOT = path.resolve(__dirname, '..', '..');
let r;
try {
  r = JSON.parse(fs.readFileSync(path.resolve(ROOT, results), 'utf8'));
} catch (err) {
  usage(`${results}: ${err.message}`);
}
for (const key of ['date', 'machine', 'load', 'chromium', 'command', 'runs', 'download_kib']) {
  if (r[key] === undefined) usage(`${results}: no field "${key}"`);
}
const SCENES = ['demo', 'pyramid', 'bench_circles_1000', 'bench_awake_500'];
const byName = {};
for (const run of r.runs) byName[run.scene.replace(/^scenes\//, '').replace(/\.scene$/, '')] = run;
const [demo, pyramid, circles, awake] = SCENES.map((s) => byName[s] || usage(`${results}: no run of scenes/${s}.scene`));
const kib = (n) => `${Number(n).toFixed(1)} KiB`;
// 500 of the awake scene's bodies are balls; the other 3 are its walls
const holds = awake.fps_min >= 58 ? 'yes' : 'no';

const out = [
  `Measured ${r.date} on ${r.machine}, load average ${r.load} at the start, headless Chromium ${r.chromium}, ` +
    `with \`${r.command}\` (site from \`scripts/build-web.sh\`). Each figure is the mean of ${pyramid.seconds} ` +
    'one-second readouts of the page (ms per step: pga_frame; ms per frame: steps, drawing and readout of one display frame).',
  '',
  '| scene | bodies | sleeping | ms per step | ms per frame | display frames/s (mean, lowest) |',
  '| --- | --- | --- | --- | --- | --- |',
  ...[demo, pyramid, circles, awake].map((x) => `| ${x.scene.replace('scenes/', '')} | ${x.bodies} (awake at least ` +
    `${x.awake_min}) | ${x.sleeping ? 'on' : 'off'} | ${x.ms_per_step} | ${x.ms_per_frame} | ${x.fps_mean}, ${x.fps_min} |`),
  '',
  `Holds 60 frames per second with ${awake.bodies - 3} bodies awake: **${holds}** (lowest one-second count ` +
    `${awake.fps_min}; the demo scene's ${demo.bodies} bodies drew ${demo.fps_mean} frames per second in the same run, ` +
    'which is what the browser\'s display clock gave at that load). The page\'s own work for a frame with those ' +
    `${awake.bodies - 3} bodies took ${awake.ms_per_frame} ms of the 16.7 ms a 60 Hz frame allows.`,
  '',
  `Download (wasm + JS + HTML + CSS): ${kib(r.download_kib.total)}, gzipped ${kib(r.download_kib.total_gzip)} ` +
    `(pogon_web.wasm ${kib(r.download_kib.wasm_gzip)} gzipped).`,
  '',
  `Rendered from \`${results}\` by \`tools/docs/web_demo_table.js\`.`,
];
process.stdout.write(out.join('\n') + '\n');

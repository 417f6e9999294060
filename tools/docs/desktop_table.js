#!/usr/bin/env node
// desktop_table.js — pogon-desktop's figures (docs/desktop.md) as markdown, from the
// committed results file (it never measures).
//
//   tools/docs/desktop_table.js --results docs/results/desktop.tsv
//
// The results file is what scripts/desktop-figures.sh writes: '# KEY: value' lines (when,
// on what machine at what load, by which command), then one figure a line, tab-separated:
// its name and its value as pogon-desktop printed it. docs/generated.md says how regions
// are kept.
'use strict';
const fs = require('fs');
const path = require('path');

function usage(msg) {
  process.stderr.write(`desktop_table: ${msg}\nusage: tools/docs/desktop_table.js --results FILE\n`);
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
let text;
try {
  text = fs.readFileSync(path.resolve(ROOT, results), 'utf8');
} catch (err) {
  usage(`${results}: ${err.message}`);
}
const meta = {};
const fig = {};
text.split('\n').forEach((line, n) => {
  if (line === '') return;
  const m = /^# (\w+): (.*)$/.exec(line);
  if (m) { meta[m[1]] = m[2]; return; }
  if (line.startsWith('#')) return;
  const f = line.split('\t');
  if (f.length !== 2) usage(`${results}:${n + 1}: want 2 tab-separated fields (figure, value), got ${f.length}`);
  fig[f[0]] = f[1];
});
for (const key of ['measured', 'machine', 'load', 'command']) {
  if (!meta[key]) usage(`${results}: no '# ${key}: ...' line`);
}
const FIGURES = ['window_pyramid', 'window_circles', 'minute_bytes', 'minute_frames', 'ten_minutes_bytes',
  'jump_fresh', 'jumps_played'];
for (const key of FIGURES) {
  if (fig[key] === undefined) usage(`${results}: no figure '${key}'`);
}
const cell = (s) => s.replace(/\|/g, '\\|');

const out = [
  `Measured ${meta.measured} on ${meta.machine}; load average ${meta.load} at the start, by \`${meta.command}\` ` +
    '(pogon-desktop of the release',
  'preset; the window under `xvfb-run` with SDL\'s **software renderer**, 960x600, one physics step',
  'per drawn frame, no vsync; the machine is shared, so frame rates vary with its load).',
  '',
  '| figure | value |',
  '| --- | --- |',
  `| window, pyramid awake (210 boxes, sleeping off) | ${cell(fig.window_pyramid)} |`,
  `| window, 2 000 circles | ${cell(fig.window_circles)} |`,
  '| replay bytes per minute, typical session (`minute.script`: an add, key pushes, a drag, two gravity toggles ' +
    `every 10 s, on scenes/demo.scene) | ${cell(fig.minute_bytes)} bytes for ${cell(fig.minute_frames)} frames |`,
  `| 10-minute replay (36 000 frames, the same pattern) | ${cell(fig.ten_minutes_bytes)} bytes |`,
  `| jump to frame 36 000, fresh player (straight from frame 0) | ${cell(fig.jump_fresh)} |`,
  `| jumps after playing through once | ${cell(fig.jumps_played)} |`,
  '',
  `Rendered from \`${results}\` by \`tools/docs/desktop_table.js\`.`,
];
process.stdout.write(out.join('\n') + '\n');

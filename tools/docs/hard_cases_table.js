#!/usr/bin/env node
// hard_cases_table.js — the hard-case suite's figures as a markdown table, from the
// committed results file (it never measures).
//
//   tools/docs/hard_cases_table.js --results docs/results/hard_cases.tsv [--functions F1,F2,...]
//
// The results file is what scripts/hard-case-figures.sh writes: '#' lines (what was run,
// when, where), then one figure a line, tab-separated: program, function, figure, value,
// bound ('-': printed, not asserted). --functions keeps the figures checked by those C
// functions (a test or its helper), in the file's order; without it, every figure. The
// table ends with the line saying when, where and by which command the figures were
// measured. docs/hard-cases.md holds its regions (docs/generated.md).
'use strict';
const fs = require('fs');
const path = require('path');

function usage(msg) {
  process.stderr.write(`hard_cases_table: ${msg}\n` +
    'usage: tools/docs/hard_cases_table.js --results FILE [--functions F1,F2,...]\n');
  process.exit(2);
}

let results = null;
let functions = null;
const args = process.argv.slice(2);
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--results') results = args[++i];
  else if (args[i] === '--functions') functions = (args[++i] || '').split(',').filter((f) => f.length);
  else usage(`unknown argument ${args[i]}`);
}
if (!results) usage('--results is required');

const ROOT = path.resolve(__dirname, '..', '..');
const text = fs.readFileSync(path.resolve(ROOT, results), 'utf8');
const meta = {};
const rows = [];
text.split('\n').forEach((line, n) => {
  if (line === '') return;
  const m = /^# (\w+): (.*)$/.exec(line);
  if (m) { meta[m[1]] = m[2]; return; }
  if (line.startsWith('#')) return;
  const f = line.split('\t');
  if (f.length !== 5) usage(`${results}:${n + 1}: want 5 tab-separated fields, got ${f.length}`);
  rows.push({ program: f[0], fn: f[1], figure: f[2], value: Number(f[3]), bound: f[4] });
});
for (const key of ['measured', 'machine', 'command']) {
  if (!meta[key]) usage(`${results}: no '# ${key}: ...' line`);
}
const chosen = functions ? rows.filter((r) => functions.includes(r.fn)) : rows;
if (functions) {
  for (const fn of functions) {
    if (!rows.some((r) => r.fn === fn)) usage(`${results}: no figure checked by ${fn}`);
  }
}

// 4 significant digits, plain notation between 1e-4 and 1e6.
function num(v) {
  if (!Number.isFinite(v)) return String(v);
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e-4 && a < 1e6) return String(Number(v.toPrecision(4)));
  return v.toExponential(2).replace(/e([+-])(\d)$/, 'e$1$2');
}
const cell = (s) => s.replace(/\|/g, '\\|');

const out = ['| figure | measured | bound | checked in |', '| --- | ---: | ---: | --- |'];
for (const r of chosen) {
  const bound = r.bound === '-' ? 'not asserted' : num(Number(r.bound));
  out.push(`| ${cell(r.figure)} | ${num(r.value)} | ${bound} | \`${r.fn}\` |`);
}
out.push('');
out.push(`Measured ${meta.measured} on ${meta.machine} by \`${meta.command}\`; ` +
  `rendered from \`${results}\` by \`tools/docs/hard_cases_table.js\`.`);
process.stdout.write(out.join('\n') + '\n');

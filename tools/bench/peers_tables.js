// peers_tables.js — the markdown tables of a tools/bench/peers run, from its results file
// (one JSON object a line). Renders only; never runs a benchmark.
//   node tools/bench/peers_tables.js RESULTS.jsonl [BUDGET] [--section headline|pyramid|scaling|joints]
// Each section ends with the date, machine and command of the run, so a table copied into
// a document (tools/docs/regions.js) carries them.
'use strict';
const fs = require('fs');
const argv = process.argv.slice(2);
let section = '';
const si = argv.indexOf('--section');
if (si >= 0) { section = argv[si + 1] || ''; argv.splice(si, 2); }
if (!['', 'headline', 'pyramid', 'scaling', 'joints'].includes(section)) {
  process.stderr.write(`peers_tables: unknown section '${section}' (headline, pyramid, scaling or joints)\n`);
  process.exit(2);
}
const [file] = argv;
const rows = fs.readFileSync(file, 'utf8').split('\n').filter((l) => l.startsWith('{')).map((l) => JSON.parse(l));
const runInfo = (rows.find((r) => r.peers_run) || {}).peers_run || {};
const endInfo = (rows.find((r) => r.peers_end) || {}).peers_end || {};
// the rounds of a cell (same engine, variant, scene, count and steps): keep the fastest,
// and count them for the note under the table
const roundsOf = {};
const res = [];
for (const r of rows.filter((x) => x.peer && !x.failed)) {
  const k = [r.peer, r.peer_variant, r.scene, r.count, r.steps, r.capped].join('|');
  roundsOf[k] = (roundsOf[k] || 0) + 1;
  const i = res.findIndex((x) => [x.peer, x.peer_variant, x.scene, x.count, x.steps, x.capped].join('|') === k);
  if (i < 0) res.push(r);
  else if (r.ms_per_step < res[i].ms_per_step) res[i] = r;
}
const maxRounds = Math.max(1, ...Object.values(roundsOf));
const failed = rows.filter((r) => r.failed);

const engineName = (r) => ({
  'pogon-native': 'pogon (native)', 'pogon-wasm': 'pogon (wasm, node)',
}[r.peer] || r.engine);
const variantName = (r) => r.peer_variant === 'sleeping-off' ? 'sleeping off' : r.peer_variant;
function settings(r) {
  if (r.peer === 'pogon-native' || r.peer === 'pogon-wasm')
    return `4 substeps, sleeping ${(r.effects & 32) ? 'on' : 'off'}, continuous on`;
  if (r.peer === 'box2d')
    return `${r.velocity_iterations} vel / ${r.position_iterations} pos it, sleeping ${r.sleeping ? 'on' : 'off'}, continuous ${r.continuous ? 'on' : 'off'}`;
  if (r.peer === 'chipmunk')
    return `${r.iterations} it, ${r.broadphase === 'spatial-hash' ? `spatial hash ${r.hash_dim_m} m` : 'bbtree'}, sleeping ${r.sleeping ? 'on' : 'off'}`;
  if (r.peer === 'matter')
    return `${r.position_iterations} pos / ${r.velocity_iterations} vel it, sleeping ${r.sleeping ? 'on' : 'off'}`;
  return '';
}
const fmtMs = (v) => v >= 100 ? v.toFixed(0) : v >= 10 ? v.toFixed(1) : v >= 1 ? v.toFixed(2) : v.toFixed(3);
const fmtRatio = (v) => v >= 100 ? v.toFixed(0) : v >= 10 ? v.toFixed(1) : v.toFixed(2);
const signed = (v, d) => (v >= 0 ? '+' : '') + v.toFixed(d);
function stands(r) {
  if (r.top_displacement_m === undefined) return '';
  if (r.top_displacement_m < 0.1) return 'yes';
  if (Math.abs(r.dx_m) < 0.1 && Math.abs(r.angle_deg) < 5 && Math.abs(r.dy_m) < 0.5)
    return `upright, ${r.dy_m < 0 ? 'sank' : 'rose'} ${Math.abs(r.dy_m).toFixed(2)} m`;
  return 'no (fell)';
}
// pogon native, defaults, same scene, count and steps
function base(r) {
  return res.find((b) => b.peer === 'pogon-native' && b.peer_variant === 'defaults' && b.scene === r.scene &&
                         b.count === r.count && b.steps === r.steps);
}
const budget = runInfo.budget_s !== undefined ? runInfo.budget_s : argv[1];
const out = [];
const p = (s) => out.push(s);
const measured = () => `Measured ${runInfo.date || '?'} on ${runInfo.cpu || '?'} (${runInfo.nproc || '?'} CPUs, node ` +
  `${runInfo.node || '?'}) by \`${runInfo.command || 'tools/bench/peers'}\`` +
  (runInfo.load_start !== undefined ? `; load average ${runInfo.load_start} at the start, ${endInfo.load_end ?? '?'} at the end` +
    (Math.max(runInfo.load_start, endInfo.load_end || 0) > (runInfo.nproc || 1e9)
      ? ' (more than the CPUs: the machine was shared, times are inflated and noisy)' : '') : '') + '.';
const roundsNote = () => (maxRounds > 1 ? `The pyramid and rain 1 000 ran ${maxRounds} rounds round every engine; each cell ` +
  'is the fastest of its rounds. ' : '');

// headline: the README's table, pyramid and rain 1 000 for each engine's best setting
if (section === 'headline') {
  const pick = (peer, variant) => res.filter((x) => x.peer === peer && x.peer_variant === variant && !x.capped &&
    (x.scene === 'pyramid' || (x.scene === 'rain' && x.count === 1000)));
  const lines = [['pogon-native', 'defaults'], ['pogon-wasm', 'defaults'], ['box2d', 'best'], ['chipmunk', 'best'],
    ['matter', 'best']];
  p('| engine | settings | pyramid ms/step | × pogon native | pyramid stands? | rain 1 000 ms/step | × pogon native |');
  p('| --- | --- | ---: | ---: | --- | ---: | ---: |');
  for (const [peer, variant] of lines) {
    const mine = pick(peer, variant);
    const py = mine.find((x) => x.scene === 'pyramid'), ra = mine.find((x) => x.scene === 'rain');
    if (!py && !ra) continue;
    const cell = (r) => { const b = r && base(r); return r ? `${fmtMs(r.ms_per_step)} | ${b ? fmtRatio(r.ms_per_step / b.ms_per_step) : '-'}` : '- | -'; };
    p(`| ${engineName(py || ra)} | ${settings(py || ra)} | ${cell(py)} | ${py ? stands(py) : ''} | ${cell(ra)} |`);
  }
  p('');
  p(`Each engine with its best setting (pogon: its defaults). ${roundsNote()}The full tables, the defaults of each ` +
    'peer and the scaling series are in [docs/performance.md](docs/performance.md).');
  p(measured());
  process.stdout.write(out.join('\n') + '\n');
  process.exit(0);
}

if (section === '') {
  p('');
  p(`### pyramid (20 rows, 210 boxes, 600 steps) and rain (1 000 circles, 300 steps)`);
  p('');
}
if (section === '' || section === 'pyramid') {
p('| engine | variant | settings | scene | ms/step | × pogon native | stands? | top dx m | top dy m | top angle ° | awake at end |');
p('| --- | --- | --- | --- | ---: | ---: | --- | ---: | ---: | ---: | ---: |');
for (const scene of ['pyramid', 'rain']) {
  for (const r of res.filter((x) => x.scene === scene && (scene === 'pyramid' || x.count === 1000) && !x.capped)) {
    const b = base(r);
    const disp = r.top_displacement_m !== undefined
      ? `${stands(r)} | ${signed(r.dx_m, 3)} | ${signed(r.dy_m, 3)} | ${signed(r.angle_deg, 2)}` : '| | |';
    p(`| ${engineName(r)} | ${variantName(r)} | ${settings(r)} | ${scene}${scene === 'rain' ? ' 1 000' : ''} | ` +
      `${fmtMs(r.ms_per_step)} | ${b ? fmtRatio(r.ms_per_step / b.ms_per_step) : '-'} | ${disp} | ${r.awake_bodies} |`);
  }
}

p('');
p(`Median of ${runInfo.quick ? '3' : '5'} runs (pyramid), ${runInfo.quick ? '1' : '3'} (rain 1 000). ${roundsNote()}` +
  'Top box: "yes" when it moved less than 0.1 m; "upright" when it stayed within 0.1 m sideways and 5° but ' +
  'sank or rose more (Box2D keeps a 0.01 m skin round every polygon, so its pyramid stands taller; matter.js ' +
  'rests with its boxes overlapping). dx, dy, angle: the top box at the end against where it started.');
p(measured());
}
const counts = [...new Set(res.filter((r) => r.scene === 'rain').map((r) => r.count))].sort((a, b) => a - b);
const keys = [];
for (const r of res) {
  if (r.scene !== 'rain' || r.peer_variant === 'sleeping-off') continue;
  const k = r.peer + '|' + r.peer_variant;
  if (!keys.includes(k)) keys.push(k);
}
if (section === '') {
  p('');
  p('### rain scaling: ms per step (× pogon native over the same steps)');
  p('');
}
if (section === '' || section === 'scaling') {
p(`| engine | variant | settings | ${counts.map((c) => c.toLocaleString('en').replace(/,/g, ' ')).join(' | ')} | exponent |`);
p(`| --- | --- | --- | ${counts.map(() => '---:').join(' | ')} | ---: |`);
const notes = [];
for (const k of keys) {
  const [peer, variant] = k.split('|');
  const mine = res.filter((r) => r.scene === 'rain' && r.peer === peer && r.peer_variant === variant &&
                                 !(peer === 'pogon-native' && r.capped));
  if (mine.length === 0) continue;
  const cells = counts.map((c) => {
    const r = mine.find((x) => x.count === c);
    if (!r) return '-';
    const b = base(r);
    const extra = [];
    if (peer !== 'pogon-native' && b) extra.push(`${fmtRatio(r.ms_per_step / b.ms_per_step)}×`);
    if (r.capped) extra.push(`${r.steps} steps`);
    return fmtMs(r.ms_per_step) + (extra.length ? ` (${extra.join(', ')})` : '');
  });
  // least-squares exponent over the points run for the full 300 steps
  const full = mine.filter((r) => !r.capped);
  let expo = '-';
  if (full.length >= 3) {
    let sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const r of full) {
      const x = Math.log(r.count), y = Math.log(r.ms_per_step);
      sx += x; sy += y; sxx += x * x; sxy += x * y;
    }
    const n = full.length;
    expo = ((n * sxy - sx * sy) / (n * sxx - sx * sx)).toFixed(2) + (full.length < mine.length ? ` (${full.length} points)` : '');
  }
  p(`| ${engineName(mine[0])} | ${variant} | ${settings(mine[mine.length - 1])} | ${cells.join(' | ')} | ${expo} |`);
}
p('');
p(`All runs from the drop; rain runs 300 steps unless a cell says fewer: a run predicted to take more than ${budget} s ` +
  'was cut to the steps that fit, and its ratio is to pogon native over those same first steps (still mostly the ' +
  'fall, before the pile forms, so such cells are cheaper per step than a full run). Exponent: least-squares fit of ' +
  'log ms against log N over the full-length points.');
p(`One run per cell from 2 000 circles on, so single cells are noisy.`);
p(measured());
}
if (section === '') {
  p('');
  p('### joint scenes: joint_grid (40 × 40) and chain (20 chains of 40 links)');
  p('');
}
if (section === '' || section === 'joints') {
  // the sanity figures of tools/scenes/joint_scenes.h: a rigid solver keeps both near 0
  const holds = (r) => {
    const figure = r.scene === 'joint_grid' ? r.sag_m : r.stretch_m;
    if (figure === undefined || r.worst_gap_m === undefined) return '';
    if (Math.abs(figure) < 1 && r.worst_gap_m < 0.1) return 'yes';
    return r.worst_gap_m >= 1 ? 'no, blew apart' : 'no';
  };
  const fmtM = (v) => (v === undefined ? '' : Math.abs(v) >= 100 ? v.toExponential(1) : Math.abs(v) >= 0.01 || v === 0
    ? v.toFixed(3) : v.toExponential(1));
  const joints = res.filter((x) => x.scene === 'joint_grid' || x.scene === 'chain');
  if (joints.length === 0) {
    p('No joint scenes in this results file: `tools/bench/peers` (or `tools/bench/peers --joints-only`) runs them.');
  } else {
    p('| engine | variant | settings | scene | bodies | joints | ms/step | × pogon native | holds? | sag or stretch m | worst joint gap m |');
    p('| --- | --- | --- | --- | ---: | ---: | ---: | ---: | --- | ---: | ---: |');
    for (const scene of ['joint_grid', 'chain']) {
      for (const r of joints.filter((x) => x.scene === scene)) {
        const b = base(r);
        p(`| ${engineName(r)} | ${variantName(r)} | ${settings(r)} | ${scene} | ${r.bodies} | ${r.joints ?? ''} | ` +
          `${fmtMs(r.ms_per_step)} | ${b ? fmtRatio(r.ms_per_step / b.ms_per_step) : '-'} | ${holds(r)} | ` +
          `${fmtM(scene === 'joint_grid' ? r.sag_m : r.stretch_m)} | ${fmtM(r.worst_gap_m)} |`);
      }
    }
    const reps = joints.find((x) => x.peer === 'pogon-native');
    p('');
    p(`600 steps (10 s), sleeping off in every engine, nothing collides; median of ${reps ? reps.repeat : '?'} ` +
      `run${reps && reps.repeat === 1 ? '' : 's'}. ` +
      (maxRounds > 1 ? `The joint scenes ran ${maxRounds} rounds round every engine; each cell is the fastest of its rounds. ` : '') +
      'Sag: how far the grid\'s bottom row came down (mean); stretch: the largest over the chains of the sum of the ' +
      'distances between each joint\'s two anchors; worst joint gap: the largest such distance in the scene, all at the ' +
      'end of the run. "Holds" when the figure is under 1 m and no joint is 0.1 m apart.');
    p(measured());
  }
}
if (failed.length)
  p('Failed: ' + failed.map((f) => `${f.peer} ${f.peer_variant} ${f.scene} ${f.count}`).join('; '));
process.stdout.write(out.join('\n') + '\n');

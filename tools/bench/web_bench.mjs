// web_bench.mjs — the browser demo's figures, measured in headless Chromium, written
// to a results file (docs/results/web_demo.json) with date, machine, load and command.
// tools/docs/web_demo_table.js renders docs/web-demo.md's figures from that file
// (node tools/docs/regions.js --update; docs/generated.md).
//
// Usage: node tools/bench/web_bench.mjs [--site build/web/site] [--results docs/results/web_demo.json]
//                                       [--seconds 5] [--no-write]
//   Build the site first: scripts/build-web.sh. Prints the figures as JSON either way
//   (with each file's download size in bytes, which the results file sums up in KiB).
//
// What it measures, each in the page as a visitor runs it (the scene picker, the effect
// switches), reading the page's own readouts (window.pogon: mean over the last second):
//   - the demo scene first, as the baseline of display frames per second at this load;
//   - ms per step and ms per display frame (steps + drawing) for the pyramid scene and
//     for 1 000 circles falling into a box, both with sleeping off;
//   - display frames per second with 500 bodies kept awake (sleeping off);
//   - the download size of the page (wasm + JS + HTML + CSS), raw and gzipped.
// The two generated scenes are served to the page in place of files it would fetch
// (its manifest gains them), so the page itself is unchanged.
import { readFileSync, readdirSync, statSync, writeFileSync } from 'node:fs';
import { cpus, loadavg, platform, release, totalmem } from 'node:os';
import { join, relative } from 'node:path';
import { parseArgs } from 'node:util';
import { gzipSync } from 'node:zlib';
import { serveSite, openBrowser, openPage } from '../../tests/web/browser.mjs';

const { values: opt } = parseArgs({
  options: {
    site: { type: 'string', default: 'build/web/site' },
    results: { type: 'string', default: 'docs/results/web_demo.json' },
    seconds: { type: 'string', default: '5' },
    'no-write': { type: 'boolean', default: false },
  },
});
const seconds = Number(opt.seconds);

// n balls of radius 0.25 m on a grid above the ground of a 40 m box, sleeping as asked.
function circlesScene(n, effects) {
  const lines = ['pogon-scene 1', `# ${n} circles falling into a box (tools/bench/web_bench.mjs)`, 'step_hz 60',
    'substeps 4', 'gravity 0 -10', `effects ${effects}`, `max_bodies ${n + 64}`, `max_shapes ${n + 64}`,
    `max_contacts ${8 * n + 256}`, 'wall 42 1 position 0 -0.5', 'wall 1 40 position -20.5 20',
    'wall 1 40 position 20.5 20'];
  const columns = 50;
  for (let i = 0; i < n; ++i) {
    const x = -14.7 + (i % columns) * 0.6 + (Math.floor(i / columns) % 2) * 0.3;
    const y = 1 + Math.floor(i / columns) * 0.6;
    lines.push(`ball 0.25 position ${x.toFixed(2)} ${y.toFixed(2)}`);
  }
  return lines.join('\n') + '\n';
}

const EXTRA = {
  'scenes/bench_circles_1000.scene': circlesScene(1000, 'all'), // sleeping switched off in the page
  'scenes/bench_awake_500.scene': circlesScene(500, 'gravity rotation friction restitution damping continuous'),
};

async function measureScene(page, path, { sleeping }) {
  await page.locator('#scene').selectOption(path);
  await page.waitForFunction((p) => window.pogon.sceneName() === p.split('/').pop().replace('.scene', ''), path);
  const box = page.locator('#effects input[data-effect="32"]');
  if ((await box.isChecked()) !== sleeping) await box.setChecked(sleeping);
  await page.waitForTimeout(1500); // settle into the run; the readouts cover the last second
  const samples = [];
  for (let i = 0; i < seconds; ++i) {
    await page.waitForTimeout(1000);
    samples.push(await page.evaluate(() => ({
      msPerStep: window.pogon.msPerStep(), msPerFrame: window.pogon.msPerFrame(),
      fps: window.pogon.framesPerSecond(), bodies: window.pogon.bodyCount(), awake: window.pogon.awakeCount(),
    })));
  }
  const mean = (key) => samples.reduce((s, x) => s + x[key], 0) / samples.length;
  return {
    scene: path, sleeping, seconds, bodies: samples.at(-1).bodies, awake_min: Math.min(...samples.map((s) => s.awake)),
    ms_per_step: +mean('msPerStep').toFixed(3), ms_per_frame: +mean('msPerFrame').toFixed(3),
    fps_mean: +mean('fps').toFixed(1), fps_min: Math.min(...samples.map((s) => s.fps)),
  };
}

function downloadSize(site) {
  const files = [];
  const walk = (dir) => {
    for (const name of readdirSync(dir)) {
      const path = join(dir, name);
      if (statSync(path).isDirectory()) {
        if (name === 'js') walk(path);
      } else if (/\.(wasm|js|html|css)$/.test(name)) files.push(path);
    }
  };
  walk(site);
  let raw = 0, gzip = 0;
  const perFile = {};
  for (const path of files.sort()) {
    const bytes = readFileSync(path);
    const z = gzipSync(bytes, { level: 9 }).length;
    raw += bytes.length;
    gzip += z;
    perFile[relative(site, path)] = { bytes: bytes.length, gzip: z };
  }
  return { raw, gzip, files: perFile };
}

async function main() {
  const site = await serveSite(opt.site);
  const browser = await openBrowser();
  const errors = [];
  try {
    await browser.context.route('**/manifest.json', async (route) => {
      const response = await route.fetch();
      const manifest = await response.json();
      manifest.scenes.push(...Object.keys(EXTRA));
      await route.fulfill({ response, json: manifest });
    });
    for (const [path, text] of Object.entries(EXTRA)) {
      await browser.context.route(`**/${path}`, (route) => route.fulfill({ body: text, contentType: 'text/plain' }));
    }
    const page = await openPage(browser.context, site.url, errors);
    const runs = [
      await measureScene(page, 'scenes/demo.scene', { sleeping: true }),
      await measureScene(page, 'scenes/pyramid.scene', { sleeping: false }),
      await measureScene(page, 'scenes/bench_circles_1000.scene', { sleeping: false }),
      await measureScene(page, 'scenes/bench_awake_500.scene', { sleeping: false }),
    ];
    const chromium = browser.context.browser()?.version() ?? 'unknown';
    const download = downloadSize(opt.site);
    const result = {
      date: new Date().toISOString().slice(0, 10), machine: machine(), load: +loadavg()[0].toFixed(1), chromium,
      command: `node tools/bench/web_bench.mjs --seconds ${seconds}`, runs, download, errors,
    };
    console.log(JSON.stringify(result, null, 2));
    // A page that threw while it was measured did not run what the figures say it ran.
    if (errors.length > 0) {
      console.error(`web_bench: the page reported ${errors.length} error(s); nothing written:\n  ${errors.join('\n  ')}`);
      process.exitCode = 1;
    } else if (!opt['no-write']) writeResults(result);
  } finally {
    await browser.close();
    await site.close();
  }
}

function machine() {
  const cpu = cpus();
  return `${cpu[0]?.model ?? 'cpu'} (${cpu.length} cores seen, shared), ${(totalmem() / 2 ** 30).toFixed(0)} GiB, ` +
    `${platform()} ${release()}`;
}

// The results file keeps what the documents show: the runs, and the download in KiB.
function writeResults(r) {
  const kib = (n) => +(n / 1024).toFixed(1);
  const { download, errors, ...kept } = r;
  const results = {
    ...kept,
    download_kib: {
      total: kib(download.raw), total_gzip: kib(download.gzip), wasm_gzip: kib(download.files['pogon_web.wasm'].gzip),
    },
  };
  writeFileSync(opt.results, JSON.stringify(results, null, 2) + '\n');
  console.error(`web_bench: wrote ${opt.results}; render the documents with node tools/docs/regions.js --update`);
}

main().catch((err) => {
  console.error(err);
  process.exit(1);
});

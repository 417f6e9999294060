// e2e.test.mjs — the browser demo end to end, in headless Chromium (web_e2e, label web).
//
// Usage: node tests/web/e2e.test.mjs --site DIR --replay-tool PATH --out DIR [--screenshot PATH]
//   --site         the built site (scripts/build-web.sh writes build/web/site)
//   --replay-tool  the native pogon-replay, which verifies the recording made in the page
//   --out          where the downloaded recording and the screenshot are written
//   --screenshot   also write the screenshot here (docs/images/demo.png for the README)
//
// The test drives the page as a visitor does: clicks on the buttons and the canvas, keys,
// sliders, file inputs. It reads the outcome from window.pogon (read-only) and from the
// canvas pixels. Bodies are added with gravity off so that they stay where they are put.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdirSync, readdirSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { serveSite, openBrowser, openPage } from './browser.mjs';
import {
  usePage, hook, frame, bodies, dist, frames, pagePoint, clickWorld, button, tool, bodyCountIs, newBodies, add, pixel,
  hexColor, BACKGROUND, message, shownAsRefusal, chooseReplayFile, sampleVelocities, clearColumn, startShipped, playToEnd,
} from './page_driver.mjs';

const { values: opt } = parseArgs({
  options: {
    site: { type: 'string' }, 'replay-tool': { type: 'string' }, out: { type: 'string' }, screenshot: { type: 'string' },
  },
});
for (const name of ['site', 'replay-tool', 'out']) {
  if (!opt[name]) throw new Error(`e2e.test.mjs: --${name} is required`);
}
const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
mkdirSync(opt.out, { recursive: true });

const PX_TOLERANCE_M = 0.08; // a click lands within a pixel (1/22 m in the demo scene) of its point
let site, browser, page;
const errors = [];

// ---- set up --------------------------------------------------------------------------------
before(async () => {
  site = await serveSite(opt.site);
  browser = await openBrowser();
  page = await openPage(browser.context, site.url, errors);
  page.setDefaultTimeout(10000);
  usePage(page);
});

after(async () => {
  if (browser) await browser.close();
  if (site) await site.close();
});

// ---- the tests, in order: each starts from the state the one before left ----------------
test('the page starts with the demo scene: static walls along the canvas edges', async () => {
  assert.equal(await hook(() => window.pogon.sceneName()), 'demo');
  const list = await bodies();
  const statics = list.filter((b) => b.type === 'static');
  assert.ok(statics.length >= 3, `static walls: ${statics.length}`);
  // the walls' outer corners are within the canvas and near its edges (the view fits them)
  const corners = statics.flatMap((b) => b.shapes.flatMap((s) => s.vertices));
  const screen = await Promise.all(corners.map((v) => hook(([x, y]) => window.pogon.toScreen(x, y), v)));
  const xs = screen.map((p) => p[0]);
  const ys = screen.map((p) => p[1]);
  assert.ok(Math.min(...xs) >= 0 && Math.min(...xs) < 40, `left wall at x ${Math.min(...xs)} px`);
  assert.ok(Math.max(...xs) <= 960 && Math.max(...xs) > 920, `right wall at x ${Math.max(...xs)} px`);
  assert.ok(Math.max(...ys) <= 540 && Math.max(...ys) > 500, `ground at y ${Math.max(...ys)} px`);
  assert.equal(await hook(() => window.pogon.stepHz()), 60);
  assert.deepEqual(await hook(() => window.pogon.gravity()), [0, -10]);
});

test('the world steps at 60 Hz whatever the display does', async () => {
  const f0 = await frame();
  const t0 = Date.now();
  await page.waitForTimeout(2000);
  const f1 = await frame();
  const seconds = (Date.now() - t0) / 1000;
  const rate = (f1 - f0) / seconds;
  assert.ok(rate > 50 && rate < 66, `${rate.toFixed(1)} steps per second`);
});

test('toggle gravity: off', async () => {
  await button('Toggle gravity').click();
  await page.waitForFunction(() => window.pogon.gravity()[1] === 0);
  assert.deepEqual(await hook(() => window.pogon.gravity()), [0, 0]);
});

const placed = {};
test('adds a ball, a capsule, a box and a star with one click each', async () => {
  const cases = [['Ball', [-15, 12], '#e03131'], ['Capsule', [-9, 12], '#2f9e44'], ['Box', [-3, 12], '#1971c2'],
    ['Star', [3, 12], '#f08c00']];
  for (const [name, point, color] of cases) {
    const body = await add(name, [point], color);
    assert.equal(body.type, 'dynamic', name);
    assert.ok(dist(body.center, point) < PX_TOLERANCE_M, `${name} at ${body.center} for a click at ${point}`);
    assert.equal(hexColor(body.color), color, `${name} colour`);
    placed[name] = body;
  }
  // nothing moves without gravity or a push: bit for bit the same centre 30 frames on
  await frames(30);
  const now = await bodies();
  for (const body of Object.values(placed)) {
    const again = now.find((b) => b.index === body.index && b.generation === body.generation);
    assert.deepEqual(again.center, body.center);
  }
});

test('a triangle by three clicks, the pending clicks highlighted', async () => {
  await tool('Triangle');
  await page.locator('#p-color').fill('#9c36b5');
  const before = await bodies();
  const corners = [[8, 11], [11, 11], [9.5, 13.5]];
  await clickWorld(corners[0]);
  await clickWorld(corners[1]);
  await page.waitForFunction(() => window.pogon.pending().length === 2);
  const pending = await hook(() => window.pogon.pending());
  assert.ok(dist(pending[0], corners[0]) < PX_TOLERANCE_M && dist(pending[1], corners[1]) < PX_TOLERANCE_M);
  // drawn: the highlight's colour at a pending click
  assert.equal(hexColor(await pixel(corners[0])), '#d9480f');
  assert.equal((await bodies()).length, before.length, 'no body before the third click');
  await clickWorld(corners[2]);
  await bodyCountIs(before.length + 1);
  const [triangle] = await newBodies(before);
  const vertices = triangle.shapes[0].vertices;
  assert.equal(vertices.length, 3);
  for (const c of corners) {
    assert.ok(vertices.some((v) => dist(v, c) < PX_TOLERANCE_M), `a vertex at ${c}: ${JSON.stringify(vertices)}`);
  }
  assert.equal((await hook(() => window.pogon.pending())).length, 0);
  placed.Triangle = triangle;
});

test('a wall by two clicks: static, from the first point to the second', async () => {
  await tool('Wall');
  await page.locator('#p-color').fill('#495057');
  const before = await bodies();
  const ends = [[13, 6], [18, 9]];
  await clickWorld(ends[0]);
  await page.waitForFunction(() => window.pogon.pending().length === 1);
  assert.equal(hexColor(await pixel(ends[0])), '#d9480f');
  await clickWorld(ends[1]);
  await bodyCountIs(before.length + 1);
  const [wall] = await newBodies(before);
  assert.equal(wall.type, 'static');
  const mid = [(ends[0][0] + ends[1][0]) / 2, (ends[0][1] + ends[1][1]) / 2];
  assert.ok(dist(wall.center, mid) < PX_TOLERANCE_M, `wall centre ${wall.center}, clicks' middle ${mid}`);
  // its long sides are as long as the clicks are apart
  const v = wall.shapes[0].vertices;
  const sides = v.map((p, i) => dist(p, v[(i + 1) % v.length]));
  assert.ok(Math.abs(Math.max(...sides) - dist(ends[0], ends[1])) < 2 * PX_TOLERANCE_M, `sides ${sides}`);
  placed.Wall = wall;
});

test('an add that would overlap is refused with a message; with the switch it goes to the nearest free spot', async () => {
  await tool('Box');
  const count = await hook(() => window.pogon.bodyCount());
  await frames(2); // the wall's add has been applied and announced
  await clickWorld(placed.Box.center);
  try {
    await page.waitForFunction(() => /^Refused/.test(window.pogon.message()));
  } catch {
    assert.fail(`no refusal: ${await message()}`);
  }
  assert.ok(await shownAsRefusal(), 'shown as a refusal');
  assert.match(await message(), /overlap/i);
  await frames(5);
  assert.equal(await hook(() => window.pogon.bodyCount()), count);

  await tool('Box');
  await page.locator('#p-nudge').check();
  const before = await bodies();
  await clickWorld(placed.Box.center);
  await bodyCountIs(count + 1);
  const [nudged] = await newBodies(before);
  const moved = dist(nudged.center, placed.Box.center);
  assert.ok(moved >= 0.99 && moved < 3, `placed ${moved.toFixed(3)} m from the click (boxes 1 m wide)`);
  await page.locator('#p-nudge').uncheck();
  placed.Nudged = nudged;
});

test('bodies are drawn where the engine says they are (canvas pixels)', async () => {
  await button('Pause').click();
  await page.waitForFunction(() => window.pogon.paused());
  await page.waitForTimeout(100); // a display frame draws the paused state
  for (const [name, b] of Object.entries(placed)) {
    const now = (await bodies()).find((x) => x.index === b.index && x.generation === b.generation);
    assert.equal(hexColor(await pixel(now.center)), hexColor(now.color), `${name}: its colour at its centre`);
  }
  // and nothing is drawn beside the ball: 0.3 m outside its rim is background
  const ball = (await bodies()).find((x) => x.index === placed.Ball.index);
  const r = ball.shapes[0].radius;
  assert.equal(await pixel([ball.center[0] - r - 0.3, ball.center[1]]), BACKGROUND);
  await button('Start').click();
});

test('the selected body\'s material can be edited (its mass follows the density)', async () => {
  await tool('Move');
  await clickWorld((await bodies()).find((b) => b.index === placed.Box.index).center);
  await page.waitForFunction((i) => (window.pogon.selected() || {}).index === i, placed.Box.index);
  const before = (await bodies()).find((b) => b.index === placed.Box.index).mass;
  await page.locator('#s-density').fill('4');
  await page.locator('#s-friction').fill('1.2');
  await page.locator('#s-restitution').fill('0.5');
  await button('Apply to selected').click();
  await frames(2);
  const after = (await bodies()).find((b) => b.index === placed.Box.index).mass;
  assert.ok(Math.abs(after - 4 * before) < 1e-3 * after, `mass ${before} -> ${after} kg for density 1 -> 4`);
});

test('Move: drag a body with the mouse', async () => {
  const star = (await bodies()).find((b) => b.index === placed.Star.index);
  const [x0, y0] = await pagePoint(star.center);
  const target = [star.center[0], star.center[1] - 4];
  const [x1, y1] = await pagePoint(target);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move(x1, y1, { steps: 10 });
  await frames(60);
  const held = (await bodies()).find((b) => b.index === placed.Star.index);
  // a dynamic body is held by a mouse joint at the pressed point, whose target is the pointer
  const joints = await hook(() => window.pogon.joints());
  await page.mouse.up();
  assert.ok(dist(held.center, target) < 0.5, `dragged to ${held.center}, pointer at ${target}`);
  assert.equal(joints.length, 1, 'one joint while dragging');
  assert.equal(joints[0].type, 4, 'a mouse joint');
  assert.ok(dist(joints[0].a, target) < PX_TOLERANCE_M, `its target ${joints[0].a}, the pointer ${target}`);
  await page.waitForFunction(() => window.pogon.jointCount() === 0); // released: gone
});

test('Pin, Rod and Spring: two clicks make each joint, drawn on the canvas; Delete removes one', async () => {
  await button('Pause').click(); // no gravity and paused: the bodies stay where the clicks find them
  await page.waitForFunction(() => window.pogon.paused());
  const centre = async (name) => (await bodies()).find((b) => b.index === placed[name].index).center;
  const join = async (name, first, second, count) => {
    await tool(name);
    await clickWorld(first);
    await page.waitForFunction(() => window.pogon.pending().length === 1);
    await clickWorld(second);
    try {
      await page.waitForFunction((n) => window.pogon.jointCount() === n, count);
    } catch {
      assert.fail(`${name} from ${first} to ${second} not made: ${await message()}`);
    }
  };
  const triangle = await centre('Triangle'), capsule = await centre('Capsule'), box = await centre('Box');
  const pivot = [triangle[0], triangle[1] + 2], anchorPoint = [capsule[0], capsule[1] + 3];
  await join('Pin', triangle, pivot, 1); // a pendulum: the triangle pinned to the world 2 m up
  await join('Rod', capsule, box, 2);
  await tool('Spring');
  await page.locator('#j-hertz').fill('2');
  await page.waitForFunction(() => window.pogon.spring().hertz === 2);
  await join('Spring', capsule, anchorPoint, 3); // the capsule hung from the world by a 2 Hz spring
  const joints = await hook(() => window.pogon.joints());
  const pin = joints.find((j) => j.type === 1), rod = joints.find((j) => j.type === 0 && !j.spring);
  const spring = joints.find((j) => j.spring);
  assert.ok(pin && rod && spring, JSON.stringify(joints));
  assert.ok(dist(pin.b, pivot) < PX_TOLERANCE_M, `the pin at ${pin.b}, clicked at ${pivot}`);
  assert.ok(dist(rod.a, capsule) < PX_TOLERANCE_M && dist(rod.b, box) < PX_TOLERANCE_M, `the rod ${rod.a} ${rod.b}`);
  assert.ok(dist(spring.a, anchorPoint) < PX_TOLERANCE_M && dist(spring.b, capsule) < PX_TOLERANCE_M, 'the spring');
  assert.equal(await page.locator('#stat-joints').textContent(), '3');
  // drawn: the rod's colour halfway between the capsule and the box, where no body is
  const middle = [(capsule[0] + box[0]) / 2, (capsule[1] + box[1]) / 2];
  assert.equal(hexColor(await pixel(middle)), hexColor(rod.color));
  await tool('Delete');
  await clickWorld([middle[0], middle[1] + 0.1]); // near the rod: the joint goes, not a body
  await page.waitForFunction(() => window.pogon.jointCount() === 2);
  assert.match(await message(), /^Deleted joint \d+ \(a rod\)/);
  await button('Start').click();
});

test('new bodies take the restitution slider: a bouncy ball bounces, a dead one does not', async () => {
  await button('Toggle gravity').click();
  await page.waitForFunction(() => window.pogon.gravity()[1] === -10);
  // dropped from 4.5 m above the ground: 9.5 m/s at impact
  // each ball falls where nothing else is or comes within the 1.5 s sampled (the bodies
  // added, dragged and jointed by the tests before are falling and swinging now)
  const drop = async (restitution) => {
    const { x, clearance } = await clearColumn(-18.5, 18.5, 1.5);
    assert.ok(clearance > 1, `no clear column to drop a ball in: the best, at x=${x}, is ${clearance.toFixed(2)} m clear`);
    await tool('Ball');
    await page.locator('#p-restitution').fill(String(restitution));
    await page.locator('#p-friction').fill('0.6');
    const ball = await add('Ball', [[x, 5]], '#0b7285');
    const vys = await sampleVelocities(ball, 90);
    const impact = vys.indexOf(Math.min(...vys));
    return { x, impact: -vys[impact], rebound: Math.max(0, ...vys.slice(impact)) };
  };
  const bouncy = await drop(0.9);
  const dead = await drop(0);
  assert.ok(bouncy.impact > 8, `x=${bouncy.x}: impact at ${bouncy.impact.toFixed(2)} m/s`);
  assert.ok(bouncy.rebound > 0.6 * bouncy.impact, `restitution 0.9 at x=${bouncy.x}: up at ${bouncy.rebound.toFixed(2)} m/s after ${bouncy.impact.toFixed(2)}`);
  // restitution 0 may leave a slow lift as the soft contact pushes the impact's overlap back out
  assert.ok(dead.rebound < 0.1 * dead.impact, `restitution 0 at x=${dead.x}: up at ${dead.rebound.toFixed(2)} m/s after ${dead.impact.toFixed(2)}`);
  await tool('Ball');
  await page.locator('#p-restitution').fill('0');
});

test('Move: a click selects the body; keys push and spin it right after a button press', async () => {
  // the ball has fallen to the ground (gravity is back on) and may be rolling: paused, a
  // click at its centre cannot miss (a press selects at once, without a step)
  const ballNow = async () => (await bodies()).find((b) => b.index === placed.Ball.index);
  await tool('Move');
  await button('Pause').click();
  await page.waitForFunction(() => window.pogon.paused());
  await clickWorld((await ballNow()).center);
  await page.waitForFunction((i) => (window.pogon.selected() || {}).index === i, placed.Ball.index);
  await page.waitForTimeout(100); // a display frame draws the selection
  assert.ok((await ballNow()).flags & 1, 'drawn as selected');
  assert.equal(hexColor(await pixel((await ballNow()).center)), hexColor(placed.Ball.color));
  await button('Start').click(); // the last thing used is a button: keys must still reach the app
  // a held key is a force of mass x 20 m/s^2 (up: 25) or a torque of inertia x 30 rad/s^2,
  // each while the body is slower than the app's limit (6 m/s, 10 rad/s) that way
  const before = await ballNow();
  await page.keyboard.down('d');
  await frames(30);
  await page.keyboard.up('d');
  const pushed = await ballNow();
  assert.ok(pushed.velocity[0] > before.velocity[0] + 1 && pushed.velocity[0] > 0,
    `D pushes right: vx ${before.velocity[0].toFixed(2)} -> ${pushed.velocity[0].toFixed(2)} m/s`);
  await page.keyboard.down('ArrowUp');
  await frames(20);
  await page.keyboard.up('ArrowUp');
  const lifted = await ballNow();
  assert.ok(lifted.velocity[1] > 0.5, `arrow up lifts it against gravity: vy ${lifted.velocity[1].toFixed(2)} m/s`);
  await page.keyboard.down('q');
  await frames(20);
  await page.keyboard.up('q');
  const spun = await ballNow();
  assert.ok(spun.angularVelocity > lifted.angularVelocity + 3,
    `Q spins it counter-clockwise: w ${lifted.angularVelocity.toFixed(2)} -> ${spun.angularVelocity.toFixed(2)} rad/s`);
});

test('pause, then Step advances exactly one frame', async () => {
  await button('Pause').click();
  await page.waitForFunction(() => window.pogon.paused());
  const f0 = await frame();
  await page.waitForTimeout(300);
  assert.equal(await frame(), f0, 'paused: no frames');
  await button('Step').click();
  await page.waitForFunction((f) => window.pogon.frame() === f + 1, f0);
  await page.waitForTimeout(300);
  assert.equal(await frame(), f0 + 1, 'one step, then paused again');
  assert.equal(await page.locator('#stat-frame').textContent(), String(f0 + 1));
  await button('Start').click();
});

test('Delete removes the body clicked', async () => {
  await tool('Delete');
  const count = await hook(() => window.pogon.bodyCount());
  const star = (await bodies()).find((b) => b.index === placed.Star.index);
  await clickWorld(star.center);
  await bodyCountIs(count - 1);
  assert.ok(!(await bodies()).some((b) => b.index === star.index && b.generation === star.generation));
});

test('the numbers on screen: bodies, ms per step, state hash', async () => {
  await frames(70);
  const stats = await page.evaluate(() => ({
    bodies: document.getElementById('stat-bodies').textContent,
    ms: document.getElementById('stat-ms').textContent,
    hash: document.getElementById('stat-hash').textContent,
  }));
  assert.equal(stats.bodies, String(await hook(() => window.pogon.bodyCount())));
  assert.ok(Number(stats.ms) > 0, `ms per step ${stats.ms}`);
  assert.match(stats.hash, /^[0-9a-f]{16}$/);
});

test('effect switches: each sets its bit of the world\'s effects', async () => {
  const all = await hook(() => window.pogon.effects());
  assert.equal(all, 0x7f);
  for (const bit of [1, 2, 4, 8, 16, 32, 64]) {
    await page.locator(`#effects input[data-effect="${bit}"]`).uncheck();
    await page.waitForFunction((b) => (window.pogon.effects() & b) === 0, bit);
    await page.locator(`#effects input[data-effect="${bit}"]`).check();
    await page.waitForFunction((b) => (window.pogon.effects() & b) !== 0, bit);
  }
});

let recordingPath;
test('the recorded session downloads and passes the native pogon-replay verify', async () => {
  await frames(10);
  const [download] = await Promise.all([page.waitForEvent('download'), button('Download recording').click()]);
  recordingPath = join(opt.out, 'web_session.pgr');
  await download.saveAs(recordingPath);
  const out = execFileSync(opt['replay-tool'], ['verify', recordingPath], { encoding: 'utf8' });
  assert.match(out, /: OK \d+ frames/, out);
});

test('the accuracy presets: fast, balanced and accurate are 2, 4 and 8 substeps', async () => {
  // (after the download: a preset restarts the world and the recording)
  for (const [value, name, substeps] of [['2', 'accurate', 8], ['0', 'fast', 2], ['1', 'balanced', 4]]) {
    await page.locator('#preset').selectOption(value);
    await page.waitForFunction((v) => window.pogon.preset() === v, Number(value));
    assert.match(await message(), new RegExp(`^Accuracy ${name} \\(${substeps} substeps\\)`));
  }
});

test('the page plays its own recording back and every checkpoint matches', async () => {
  await chooseReplayFile(recordingPath);
  await playToEnd('web_session.pgr');
});

test('playback: pause and single step move the frame counter by one', async () => {
  await page.locator('#pb-speed').selectOption('1');
  await startShipped('replays/demo.pgr');
  await page.waitForFunction(() => window.pogon.playback().frame > 0);
  // the panel says what recorded the file: the engine version and numeric configuration
  // of its header (u16 major, minor, patch at byte 10; docs/formats.md)
  const header = readFileSync(join(root, 'tests/replays/demo.pgr'));
  const [major, minor, patch] = [10, 12, 14].map((at) => header.readUInt16LE(at));
  const recordedWith = `pogon ${major}.${minor}.${patch}, a 12-bit sine table`;
  await page.waitForFunction((want) => document.getElementById('pb-recorded').textContent === want, recordedWith)
    .catch(() => {});
  assert.equal(await page.locator('#pb-recorded').textContent(), recordedWith);
  await page.locator('#pb-run').click();
  await page.waitForFunction(() => window.pogon.paused());
  const f0 = (await hook(() => window.pogon.playback())).frame;
  await page.waitForTimeout(200);
  assert.equal((await hook(() => window.pogon.playback())).frame, f0);
  await page.locator('#pb-step').click();
  await page.waitForFunction((f) => window.pogon.playback().frame === f + 1, f0);
  await page.waitForFunction((f) => document.getElementById('pb-frame').textContent === String(f + 1), f0)
    .catch(() => {});
  assert.equal(await page.locator('#pb-frame').textContent(), String(f0 + 1));
  await page.locator('#pb-run').click();
});

test('every shipped replay (tests/replays, tests/replays/recorded) plays with every checkpoint matching', async () => {
  const shipped = readdirSync(join(root, 'tests/replays')).filter((f) => f.endsWith('.pgr')).map((f) => `replays/${f}`);
  let recorded = [];
  try {
    recorded = readdirSync(join(root, 'tests/replays/recorded')).filter((f) => f.endsWith('.pgr'))
      .map((f) => `replays/recorded/${f}`);
  } catch { /* no recorded replays yet */ }
  const offered = await page.$$eval('#replay-shipped option', (os) => os.map((o) => o.value));
  for (const file of [...shipped, ...recorded]) {
    assert.ok(offered.includes(file), `${file} is offered by the page`);
    await startShipped(file);
    await playToEnd(file);
  }
});

// FNV-1a 64 (pg_hash_bytes), to seal a header edited here as a writer would.
function fnv1a64(bytes) {
  let h = 0xcbf29ce484222325n;
  for (const b of bytes) h = ((h ^ BigInt(b)) * 0x100000001b3n) & 0xffffffffffffffffn;
  return h;
}
function reseal(buffer, headerHashAt) {
  buffer.writeBigUInt64LE(fnv1a64(buffer.subarray(0, headerHashAt)), headerHashAt);
  buffer.writeBigUInt64LE(fnv1a64(buffer.subarray(0, buffer.length - 8)), buffer.length - 8);
  return buffer;
}

test('a corrupt, truncated, old or other-numerics file shows the reader\'s error (offset and field) and the page keeps working', async () => {
  const good = readFileSync(join(root, 'tests/replays/commands.pgr'));
  const flipped = Buffer.from(good);
  flipped[200] ^= 0x10;
  const truncated = good.subarray(0, Math.floor(good.length / 2));
  // recorded with an 8-bit sine table (the numeric configuration, header bytes 20..23)
  const otherTable = Buffer.from(good);
  otherTable.writeUInt32LE(8, 20);
  reseal(otherTable, 36);
  // format 1: the same file without the numeric configuration
  const format1 = Buffer.concat([good.subarray(0, 20), good.subarray(24)]);
  format1.writeUInt16LE(1, 8);
  reseal(format1, 32);
  const expected = {
    'other-table.pgr': /numeric_config: recorded with an 8-bit sine table; this build has a 12-bit sine table/,
    'format1.pgr': /format_version: format version 1 is older than this build's 4: convert it with `pogon-replay upgrade IN OUT`/,
  };
  for (const [name, buffer] of [['flipped.pgr', flipped], ['truncated.pgr', truncated], ['other-table.pgr', otherTable],
    ['format1.pgr', format1]]) {
    const playing = await hook(() => window.pogon.playback());
    await chooseReplayFile({ name, mimeType: 'application/octet-stream', buffer });
    try {
      await page.waitForFunction(() => /^Replay refused: offset \d+/.test(window.pogon.message()));
    } catch {
      assert.fail(`${name}: ${await message()}`);
    }
    const text = await message();
    assert.match(text, /offset \d+, \w+ field \w+/, `${name}: ${text}`);
    if (expected[name]) assert.match(text, expected[name], `${name}: ${text}`);
    assert.ok(await shownAsRefusal(), 'shown as an error');
    // nothing changed: the replay that was playing is still the one shown
    const still = await hook(() => window.pogon.playback());
    assert.equal(still.frameCount, playing.frameCount);
  }
  // still working: back to live, the frame advances and a click adds a body
  if ((await hook(() => window.pogon.playback())).active) await button('Back to live').click();
  await page.waitForFunction(() => !window.pogon.playback().active);
  if (await hook(() => window.pogon.paused())) await button('Start').click();
  await frames(10);
  await page.locator('#scene').selectOption('scenes/demo.scene');
  await page.waitForFunction(() => window.pogon.sceneName() === 'demo' && window.pogon.bodyCount() === 9);
  const ball = await add('Ball', [[0, 8]], '#e8590c');
  assert.equal(ball.type, 'dynamic');
});

test('the scene picker offers every file of scenes/ and loads each', async () => {
  const files = readdirSync(join(root, 'scenes')).filter((f) => f.endsWith('.scene')).sort();
  const offered = await page.$$eval('#scene option', (os) => os.map((o) => o.value));
  assert.deepEqual(offered, files.map((f) => `scenes/${f}`));
  // the scene shown now last, so that choosing each one is a change
  const current = `${await hook(() => window.pogon.sceneName())}.scene`;
  for (const f of [...files.filter((x) => x !== current), current]) {
    const name = f.replace(/\.scene$/, '');
    await page.locator('#scene').selectOption(`scenes/${f}`);
    await page.waitForFunction((n) => window.pogon.sceneName() === n, name);
    assert.match(await message(), new RegExp(`^Loaded scene ${name}: \\d+ bodies`));
    assert.ok((await hook(() => window.pogon.bodyCount())) > 0, name);
  }
});

test('the screenshot for the README', async () => {
  // the pile scene with a body of each one-click kind dropped on it, two of them on joints
  await page.locator('#scene').selectOption('scenes/pile.scene');
  await page.waitForFunction(() => window.pogon.sceneName() === 'pile');
  await frames(90);
  const colors = { Box: '#1c7ed6', Star: '#f59f00', Capsule: '#37b24d', Ball: '#e03131' };
  await page.locator('#p-nudge').check();
  const dropped = {};
  for (const [i, name] of ['Box', 'Star', 'Capsule', 'Ball'].entries()) {
    dropped[name] = await add(name, [[-4.5 + 3 * i, 13]], colors[name]);
  }
  await page.locator('#p-nudge').uncheck();
  // and joints: the ball on a pin 3 m to its left (a pendulum), the box hung from a spring
  await button('Pause').click();
  await page.waitForFunction(() => window.pogon.paused());
  const now = async (name) => (await bodies()).find((b) => b.index === dropped[name].index).center;
  const joints = await hook(() => window.pogon.jointCount());
  const ball = await now('Ball'), box = await now('Box');
  for (const [name, from, to] of [['Pin', ball, [ball[0] - 3, ball[1]]], ['Spring', box, [box[0], box[1] + 3]]]) {
    await tool(name);
    await clickWorld(from);
    await clickWorld(to);
  }
  await page.waitForFunction((n) => window.pogon.jointCount() === n + 2, joints);
  await button('Start').click();
  await tool('Move');
  await frames(40);
  const path = join(opt.out, 'demo.png');
  await page.screenshot({ path, clip: { x: 0, y: 0, width: 1320, height: 700 } }); // the page without the empty space below
  if (opt.screenshot) {
    mkdirSync(dirname(opt.screenshot), { recursive: true });
    copyFileSync(path, opt.screenshot);
  }
  assert.deepEqual(errors, [], 'no errors in the page');
});

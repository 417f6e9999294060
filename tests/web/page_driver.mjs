// page_driver.mjs — how tests/web/e2e.test.mjs works the page: clicks at world points,
// the tools, adds, canvas pixels, messages, files and playback, each waiting for what the
// page shows (its readouts follow the app by a display frame). usePage() names the page.
import assert from 'node:assert/strict';

let page;
export function usePage(p) { page = p; }

export const hook = (fn, arg) => page.evaluate(fn, arg);
export const frame = () => hook(() => window.pogon.frame());
export const bodies = () => hook(() => window.pogon.bodies());
export const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);

export async function frames(n) {
  const target = (await frame()) + n;
  await page.waitForFunction((t) => window.pogon.frame() >= t, target, { timeout: 20000 });
}

// The page point (CSS pixels of the viewport) of a world point.
export async function pagePoint([x, y]) {
  const [sx, sy] = await hook(([px, py]) => window.pogon.toScreen(px, py), [x, y]);
  const box = await page.locator('#canvas').boundingBox();
  const border = await hook(() => document.getElementById('canvas').clientLeft);
  return [box.x + border + sx, box.y + border + sy];
}

export async function clickWorld(point) {
  const [px, py] = await pagePoint(point);
  await page.mouse.click(px, py);
}

export const button = (name) => page.getByRole('button', { name, exact: true });

export async function tool(name) { await button(name).click(); }

// Wait until the body count is `n` (adds are applied at the start of the next frame).
export async function bodyCountIs(n) {
  await page.waitForFunction((k) => window.pogon.bodyCount() === k, n, { timeout: 5000 });
}

// The bodies present now that were not in `before`.
export async function newBodies(beforeList) {
  const known = new Set(beforeList.map((b) => `${b.index}:${b.generation}`));
  return (await bodies()).filter((b) => !known.has(`${b.index}:${b.generation}`));
}

// Add by clicking `points` with tool `name` and colour `color`: the one new body.
export async function add(name, points, color) {
  await tool(name);
  await page.locator('#p-color').fill(color);
  const before = await bodies();
  for (const p of points) await clickWorld(p);
  try {
    await bodyCountIs(before.length + 1);
  } catch {
    assert.fail(`${name} at ${JSON.stringify(points)} not added: ${await message()}`);
  }
  const added = await newBodies(before);
  assert.equal(added.length, 1, `${name}: one new body`);
  return added[0];
}

// The canvas pixel at a world point, as 0xRRGGBB, once two more display frames have drawn.
export async function pixel([x, y]) {
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  return hook(([px, py]) => {
    const canvas = document.getElementById('canvas');
    const [sx, sy] = window.pogon.toScreen(px, py);
    const ratio = canvas.width / canvas.clientWidth;
    const d = canvas.getContext('2d').getImageData(Math.floor(sx * ratio), Math.floor(sy * ratio), 1, 1).data;
    return (d[0] << 16) | (d[1] << 8) | d[2];
  }, [x, y]);
}

export const hexColor = (c) => '#' + c.toString(16).padStart(6, '0');
export const BACKGROUND = 0xfbfaf7;

// The message the page shows, once it shows the app's latest (the readout follows a display frame later).
export async function message() {
  await page.waitForFunction(() => document.getElementById('message').textContent === window.pogon.message())
    .catch(() => {});
  return (await page.locator('#message').textContent()).trim();
}

// Whether the page shows its message in the refusal style (a display frame after the app says it).
export async function shownAsRefusal() {
  return page.waitForFunction(() => document.getElementById('message').classList.contains('refused'), null,
    { timeout: 3000 }).then(() => true, () => false);
}

// Choose a file in the page's "load a file" input, through the browser's file chooser.
export async function chooseReplayFile(files) {
  const [chooser] = await Promise.all([page.waitForEvent('filechooser'), page.locator('#replay-file').click()]);
  await chooser.setFiles(files);
}

// Sample a body every display frame for `n` frames, in the page: its vertical velocities.
export const sampleVelocities = (id, n) => page.evaluate(([index, generation, count]) => new Promise((done) => {
  const vys = [];
  const sample = () => {
    const b = window.pogon.bodies().find((x) => x.index === index && x.generation === generation);
    vys.push(b ? b.velocity[1] : 0);
    if (vys.length < count) requestAnimationFrame(sample); else done(vys);
  };
  requestAnimationFrame(sample);
}), [id.index, id.generation, n]);

// The x in [lo, hi] (a 0.25 m grid) farthest from every body that could come near a ball
// dropped there within `seconds`: each body's horizontal extent now, widened by the distance
// its horizontal speed covers in that time. A body spanning most of the range (the ground)
// is left out. {x, clearance} in metres.
export async function clearColumn(lo, hi, seconds) {
  const spans = (await bodies()).map((b) => {
    const xs = b.shapes.flatMap((s) => s.vertices.flatMap((v) => [v[0] - s.radius, v[0] + s.radius]));
    const reach = b.type === 'static' ? 0 : Math.abs(b.velocity[0]) * seconds;
    return [Math.min(...xs) - reach, Math.max(...xs) + reach];
  }).filter(([left, right]) => right - left < 0.75 * (hi - lo));
  let best = { x: lo, clearance: -Infinity };
  for (let x = lo; x <= hi; x += 0.25) {
    const clearance = Math.min(...spans.map(([left, right]) => Math.max(left - x, x - right, 0)));
    if (clearance > best.clearance) best = { x, clearance };
  }
  return best;
}

// Choose a shipped replay and start it: the app says so in a new message.
export async function startShipped(file) {
  const serial = await hook(() => window.pogon.messageSerial());
  await page.locator('#replay-shipped').selectOption(file);
  await button('Play selected').click();
  await page.waitForFunction((s) => window.pogon.messageSerial() !== s && window.pogon.playback().active, serial);
}

// Play a replay already chosen in the page to its end at full speed.
export async function playToEnd(label) {
  await page.waitForFunction(() => window.pogon.playback().active, null, { timeout: 5000 });
  await page.locator('#pb-speed').selectOption('0');
  await page.waitForFunction(() => { const p = window.pogon.playback(); return p.frame === p.frameCount; }, null,
    { timeout: 120000 });
  // the app announces the end once it is reached
  await page.waitForFunction(() => /^Replay finished/.test(window.pogon.message()));
  assert.match(await message(), /^Replay finished: \d+ frames, (\d+) of \1 checkpoints matched/, label);
  const p = await hook(() => window.pogon.playback());
  assert.equal(p.failed, 0, `${label}: ${p.failed} checkpoints diverged`);
  assert.ok(p.checked >= 2, `${label}: ${p.checked} checkpoints compared`);
  assert.equal(p.lastMatch, 1, `${label}: the last checkpoint matches`);
  await page.waitForFunction((n) => document.getElementById('pb-checked').textContent === String(n), p.checked)
    .catch(() => {});
  assert.equal(await page.locator('#pb-failed').textContent(), '0');
  // the readout follows a display frame later
  await page.waitForFunction((n) => document.getElementById('pb-strip').textContent.length >= n, p.checked)
    .catch(() => {});
  const strip = await page.locator('#pb-strip').textContent();
  assert.equal(strip, '✓'.repeat(p.checked), `${label}: one ✓ per checkpoint`);
  return p;
}

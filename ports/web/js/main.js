// main.js — puts the page together: the wasm app, the view, the renderer, the fixed
// step loop, the controls, the file pickers, the status readout and the test hook.
//
// Per display frame (loop.js): ticks at the world's step rate, each one pga_frame (or,
// in fast playback, several), then one drawing of what the app says.
import { loadEngine } from './engine.js';
import { View } from './view.js';
import { Renderer } from './render.js';
import { FixedStepLoop } from './loop.js';
import { bindControls, showParams } from './controls.js';
import { Files } from './files.js';
import { Status } from './status.js';
import { installTestHook } from './test_hook.js';

const FAST_PLAYBACK_BUDGET_MS = 12;

async function main() {
  const canvas = document.getElementById('canvas');
  const engine = await loadEngine();
  const view = new View(canvas);
  const renderer = new Renderer(canvas, view);
  const notes = { localMessage: null, world: null }; // the page's own message; the pointer in metres

  let files = null;
  let readout = null;
  const tick = () => {
    const playing = engine.playback().active;
    const perTick = playing ? files.playbackSpeed : 1;
    const t0 = performance.now();
    let steps = 0;
    if (perTick === 0) {
      while (performance.now() - t0 < FAST_PLAYBACK_BUDGET_MS && engine.frame()) steps += 1;
    } else {
      for (let i = 0; i < perTick; ++i) if (engine.frame()) steps += 1;
    }
    return { steps, ms: performance.now() - t0 };
  };
  const loop = new FixedStepLoop({
    stepHz: () => engine.stepHz(),
    tick,
    draw: () => {
      renderer.draw(engine.drawList(), (s) => engine.bodyAngle(s), engine.pendingPoints(), notes.world, engine.jointList());
      readout.update();
    },
  });
  files = new Files(engine, view, canvas, loop, notes);
  readout = new Status(engine, loop, notes);

  bindControls(engine, view, canvas, notes);
  showParams(engine);
  await files.init();
  installTestHook(engine, view, loop);
  canvas.focus({ preventScroll: true });
  loop.start();
}

main().catch((err) => {
  const message = document.getElementById('message');
  message.textContent = `The page could not start: ${err.message || err}`;
  message.classList.add('refused');
  console.error(err);
});

// controls.js — DOM events to app calls: tool buttons, sliders (new bodies, new springs),
// the simulation buttons,
// effect switches, keys and the pointer on the canvas. Nothing here decides what an
// input means; the app does (ports/app). What the page shows of the outcome is
// refreshed from the app each display frame by status.js.
import { KEY, POINTER } from './engine.js';

const $ = (id) => document.getElementById(id);

const KEYS = {
  KeyA: KEY.LEFT, ArrowLeft: KEY.LEFT, KeyD: KEY.RIGHT, ArrowRight: KEY.RIGHT,
  KeyW: KEY.UP, ArrowUp: KEY.UP, KeyS: KEY.DOWN, ArrowDown: KEY.DOWN,
  KeyQ: KEY.SPIN_CCW, KeyE: KEY.SPIN_CW,
};
const PARAMS = ['radius', 'width', 'height', 'density', 'friction', 'restitution'];
const rgbToInt = (hex) => parseInt(hex.slice(1), 16);
const intToRgb = (c) => '#' + (c & 0xffffff).toString(16).padStart(6, '0');

// Text fields and pickers keep their keys; everything else hands them to the app.
function keepsKeys(target) {
  if (target instanceof HTMLSelectElement || target instanceof HTMLTextAreaElement) return true;
  return target instanceof HTMLInputElement && !['checkbox', 'range', 'color', 'button'].includes(target.type);
}

// After a button or a switch is used, the canvas takes focus back, so W A S D work at once.
export function refocus(canvas, element) {
  if (element && element.blur) element.blur();
  canvas.focus({ preventScroll: true });
}

function showValue(input) {
  const out = input.parentElement.querySelector('output');
  if (out) out.textContent = Number(input.value).toFixed(2).replace(/\.?0+$/, '') || '0';
}

// Put the app's parameters into the sliders (after a refusal they snap back).
export function showParams(engine) {
  const spring = engine.spring();
  $('j-hertz').value = spring.hertz;
  $('j-damping').value = spring.damping;
  showValue($('j-hertz'));
  showValue($('j-damping'));
  const p = engine.params();
  for (const name of PARAMS) {
    const input = $(`p-${name}`);
    input.value = p[name];
    showValue(input);
  }
  $('p-color').value = intToRgb(p.color);
  $('p-nudge').checked = p.nudge;
}

export function bindControls(engine, view, canvas, pointerState) {
  const say = (text) => { pointerState.localMessage = text; };

  // ---- tools ----
  for (const button of document.querySelectorAll('#tools button[data-tool]')) {
    button.addEventListener('click', () => {
      engine.setTool(Number(button.dataset.tool));
      refocus(canvas, button);
    });
  }

  // ---- parameters of new bodies: all sent together, as the app validates them together ----
  const sendParams = () => {
    const p = { color: rgbToInt($('p-color').value), nudge: $('p-nudge').checked };
    for (const name of PARAMS) p[name] = Number($(`p-${name}`).value);
    const r = engine.setParams(p);
    if (r !== 0) say(engine.message() || `${engine.resultName(r)}: the value was refused`);
    showParams(engine);
  };
  for (const name of PARAMS) {
    const input = $(`p-${name}`);
    input.addEventListener('input', () => { showValue(input); sendParams(); });
    input.addEventListener('change', () => refocus(canvas, input));
  }
  $('p-color').addEventListener('change', (e) => { sendParams(); refocus(canvas, e.target); });
  $('p-nudge').addEventListener('change', (e) => { sendParams(); refocus(canvas, e.target); });

  // ---- the spring tool's frequency and damping ratio ----
  for (const id of ['j-hertz', 'j-damping']) {
    const input = $(id);
    input.addEventListener('input', () => {
      const r = engine.setSpring(Number($('j-hertz').value), Number($('j-damping').value));
      if (r !== 0) say(engine.message() || engine.resultName(r));
      showParams(engine);
    });
    input.addEventListener('change', () => refocus(canvas, input));
  }

  // ---- the selected body's material ----
  for (const name of ['density', 'friction', 'restitution']) {
    const input = $(`s-${name}`);
    input.addEventListener('input', () => showValue(input));
    input.addEventListener('change', () => refocus(canvas, input));
  }
  $('s-apply').addEventListener('click', (e) => {
    const r = engine.setSelectedMaterial(Number($('s-density').value), Number($('s-friction').value),
      Number($('s-restitution').value));
    if (r !== 0) say(engine.message() || engine.resultName(r));
    refocus(canvas, e.target);
  });

  $('s-color').addEventListener('change', (e) => {
    const r = engine.setSelectedColor(rgbToInt(e.target.value));
    if (r !== 0) say(engine.message() || engine.resultName(r));
    refocus(canvas, e.target);
  });

  // ---- simulation ----
  $('run').addEventListener('click', (e) => { engine.setPaused(!engine.paused()); refocus(canvas, e.target); });
  $('step').addEventListener('click', (e) => {
    if (!engine.paused()) engine.setPaused(true);
    engine.stepOnce();
    refocus(canvas, e.target);
  });
  $('gravity').addEventListener('click', (e) => { engine.toggleGravity(); refocus(canvas, e.target); });
  $('preset').addEventListener('change', (e) => {
    const r = engine.setPreset(Number(e.target.value));
    if (r !== 0) say(engine.message() || engine.resultName(r));
    refocus(canvas, e.target);
  });
  for (const box of document.querySelectorAll('#effects input[data-effect]')) {
    box.addEventListener('change', () => {
      const bit = Number(box.dataset.effect);
      const effects = box.checked ? engine.effects() | bit : engine.effects() & ~bit;
      engine.setEffects(effects);
      refocus(canvas, box);
    });
  }

  // ---- keys: held keys push or spin the selected body ----
  const held = new Set();
  window.addEventListener('keydown', (e) => {
    const key = KEYS[e.code];
    if (key === undefined || keepsKeys(e.target) || e.ctrlKey || e.metaKey || e.altKey) return;
    e.preventDefault(); // arrows would scroll the page or move a slider
    if (held.has(e.code)) return;
    held.add(e.code);
    engine.key(key, true);
  });
  window.addEventListener('keyup', (e) => {
    if (!held.delete(e.code)) return;
    engine.key(KEYS[e.code], false);
  });
  window.addEventListener('blur', () => {
    for (const code of held) engine.key(KEYS[code], false);
    held.clear();
  });

  // ---- the pointer, in world metres ----
  const world = (e) => {
    const r = canvas.getBoundingClientRect();
    return view.toWorld(e.clientX - r.left - canvas.clientLeft, e.clientY - r.top - canvas.clientTop);
  };
  canvas.addEventListener('pointerdown', (e) => {
    if (e.button !== 0) return;
    canvas.setPointerCapture(e.pointerId);
    canvas.focus({ preventScroll: true });
    const [x, y] = world(e);
    pointerState.world = [x, y];
    pointerState.localMessage = null;
    engine.pointer(POINTER.DOWN, x, y);
  });
  canvas.addEventListener('pointermove', (e) => {
    const [x, y] = world(e);
    pointerState.world = [x, y];
    engine.pointer(POINTER.MOVE, x, y);
  });
  const up = (e) => {
    const [x, y] = world(e);
    engine.pointer(POINTER.UP, x, y);
  };
  canvas.addEventListener('pointerup', up);
  canvas.addEventListener('pointercancel', up);
  canvas.addEventListener('pointerleave', () => { pointerState.world = null; });
}

// Selected-body sliders start from the new-body values (the core has no material
// getters, so the app cannot say a body's friction); the colour is the body's own.
export function showSelected(engine, body) {
  $('s-color').value = intToRgb(body.color);
  const p = engine.params();
  for (const name of ['density', 'friction', 'restitution']) {
    const input = $(`s-${name}`);
    input.value = p[name];
    showValue(input);
  }
}

// status.js — what the page shows of the app's state, refreshed each display frame:
// the numbers (bodies, joints, ms per step, frame, state hash, gravity), the active tool and
// the panels it uses, the effect switches, the run button, the selected body, the
// message, and the playback panel. Reads only; never calls into the app's input.
import { showSelected } from './controls.js';

const $ = (id) => document.getElementById(id);
const fmt = (v, digits = 2) => (Math.abs(v) < 0.5 * 10 ** -digits ? 0 : v).toFixed(digits);

const TOOL_HINTS = [
  'Click a body to select it; drag it; W A S D / arrows push, Q E spin.',
  'Click a body to remove it, or near a joint to remove the joint.',
  'Click to place a ball.',
  'Click to place a capsule.',
  'Click to place a box.',
  'Click three times: the triangle\'s corners.',
  'Click to place a star.',
  'Click twice: the wall\'s two ends.',
  'Click the body to pin, then where the pin goes: on another body, or anywhere else for the world.',
  'Click two points: a rigid rod between them (on two bodies, or a body and the world).',
  'Click two points: a spring between them (on two bodies, or a body and the world).',
];

function setText(id, text) {
  const el = $(id);
  if (el.textContent !== text) el.textContent = text;
}

export class Status {
  constructor(engine, loop, notes) {
    this.engine = engine;
    this.loop = loop;
    this.notes = notes;
    this.lastSerial = -1;
    this.lastSelected = '';
    this.lastTool = -1;
    this.hashFrame = -1;
    this.hashTime = -Infinity;
  }

  update() {
    const { engine } = this;
    const ms = this.loop.msPerStep();
    setText('stat-bodies', String(engine.bodyCount()));
    setText('stat-joints', String(engine.jointCount()));
    setText('stat-awake', String(engine.awakeCount()));
    setText('stat-ms', ms === null ? '–' : ms.toFixed(3));
    setText('effects-ms', ms === null ? '–' : ms.toFixed(3));
    setText('stat-frame', String(engine.frameNumber()));
    // the hash costs a pass over the whole state: refreshed when the frame moved, 5 times a second
    const now = performance.now();
    const frame = engine.frameNumber();
    if (frame !== this.hashFrame && now - this.hashTime >= 200) {
      this.hashFrame = frame;
      this.hashTime = now;
      setText('stat-hash', engine.stateHash());
    }
    const [gx, gy] = engine.gravity();
    setText('stat-gravity', engine.gravityEnabled() ? `${fmt(gx, 1)}, ${fmt(gy, 1)} m/s²` : 'off');
    this.message();
    this.tool();
    this.effects();
    this.selected();
    this.playback();
  }

  // The app's latest message, unless the page has a newer one of its own.
  message() {
    const serial = this.engine.messageSerial();
    if (serial !== this.lastSerial) {
      this.lastSerial = serial;
      this.notes.localMessage = null;
    }
    const text = this.notes.localMessage ?? this.engine.message();
    setText('message', text);
    const level = this.notes.localMessage ? 'error' : this.engine.messageLevel();
    $('message').classList.toggle('refused', level !== 'info');
  }

  tool() {
    const tool = this.engine.tool();
    if (tool === this.lastTool) return;
    this.lastTool = tool;
    for (const b of document.querySelectorAll('#tools button[data-tool]')) {
      b.classList.toggle('active', Number(b.dataset.tool) === tool);
    }
    for (const el of document.querySelectorAll('[data-for-tools]')) {
      el.hidden = !el.dataset.forTools.split(' ').map(Number).includes(tool);
    }
    setText('tool-hint', TOOL_HINTS[tool] || '');
  }

  effects() {
    const bits = this.engine.effects();
    for (const box of document.querySelectorAll('#effects input[data-effect]')) {
      const on = (bits & Number(box.dataset.effect)) !== 0;
      if (box.checked !== on) box.checked = on;
    }
    const preset = String(this.engine.preset());
    if ($('preset').value !== preset) $('preset').value = preset;
    const paused = this.engine.paused();
    setText('run', paused ? 'Start' : 'Pause');
    setText('pb-run', paused ? 'Play' : 'Pause');
  }

  selected() {
    const id = this.engine.selected();
    const key = id ? `${id.index}:${id.generation}` : '';
    if (!id) {
      this.lastSelected = '';
      setText('sel-info', 'none: click a body with Move');
      return;
    }
    const b = this.engine.body(id);
    if (key !== this.lastSelected) {
      this.lastSelected = key;
      showSelected(this.engine, b);
    }
    setText('sel-info', `#${id.index} ${b.type}, ${fmt(b.mass)} kg at (${fmt(b.center[0])}, ${fmt(b.center[1])}) m, ` +
      `v (${fmt(b.velocity[0])}, ${fmt(b.velocity[1])}) m/s, ω ${fmt(b.angularVelocity)} rad/s`);
  }

  // One mark per checkpoint compared, in order. Several may be compared between two
  // display frames (fast playback): the app counts them, and those that diverged are
  // the latest of them, since a run that diverged stays diverged.
  checkpointMarks(p) {
    const strip = $('pb-strip');
    if (!this.marks || p.checked < this.marks.checked) {
      this.marks = { checked: 0, failed: 0 };
      strip.textContent = '';
    }
    const added = p.checked - this.marks.checked;
    const failed = Math.min(added, p.failed - this.marks.failed);
    if (added > failed) strip.append('✓'.repeat(added - failed));
    if (failed > 0) {
      const bad = document.createElement('span');
      bad.className = 'diverged';
      bad.textContent = '✗'.repeat(failed);
      strip.append(bad);
    }
    this.marks = { checked: p.checked, failed: p.failed };
  }

  playback() {
    const p = this.engine.playback();
    $('playback').hidden = !p.active;
    for (const id of ['tools', 'params', 'spring', 'selected', 'sim', 'effects']) $(id).disabled = p.active;
    if (!p.active) {
      this.marks = null;
      return;
    }
    this.checkpointMarks(p);
    setText('pb-recorded', this.engine.replayRecordedWith() || '–');
    setText('pb-frame', String(p.frame));
    setText('pb-frames', String(p.frameCount));
    setText('pb-checked', String(p.checked));
    setText('pb-failed', String(p.failed));
    setText('pb-last', p.lastMatch === 1 ? 'matches' : p.lastMatch === 0
      ? `DIVERGED (sections 0x${p.sectionMismatch.toString(16)})` : '–');
  }
}

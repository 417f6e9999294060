// engine.js — the wasm module (pogon_web.c over ports/app) as a JavaScript object.
//
// Converts at the edge and nowhere else: metres in, Q16.16 out (toFix), strings and
// byte arrays copied into and out of wasm memory. Every method forwards to one pgw_*
// export; the interaction logic is the C app's.
import createPogon from '../pogon_web.js';

const FIX_ONE = 65536;
export const toFix = (metres) => Math.round(metres * FIX_ONE);
export const fromFix = (fix) => fix / FIX_ONE;
const TURN = 4294967296;

export const TOOL = Object.freeze({
  MOVE: 0, DELETE: 1, BALL: 2, CAPSULE: 3, BOX: 4, TRIANGLE: 5, STAR: 6, WALL: 7, PIN: 8, ROD: 9, SPRING: 10,
});
export const JOINT = Object.freeze({ DISTANCE: 0, REVOLUTE: 1, WELD: 2, PRISMATIC: 3, MOUSE: 4 });
export const KEY = Object.freeze({ LEFT: 0, RIGHT: 1, UP: 2, DOWN: 3, SPIN_CCW: 4, SPIN_CW: 5 });
export const SHAPE = Object.freeze({ CIRCLE: 0, SEGMENT: 1, CAPSULE: 2, POLYGON: 3 });
export const DRAW = Object.freeze({ SELECTED: 1, STATIC: 2, ASLEEP: 4, KINEMATIC: 8 });
export const POINTER = Object.freeze({ DOWN: 0, MOVE: 1, UP: 2 });
const PARAM_NAMES = ['radius', 'width', 'height', 'density', 'friction', 'restitution'];

export async function loadEngine() {
  const module = await createPogon();
  if (!module._pgw_create()) throw new Error('the app could not be created (out of memory)');
  return new Engine(module);
}

class Engine {
  constructor(module) {
    this.m = module;
    const L = (i) => module._pgw_draw_layout(i);
    this.layout = {
      size: L(0), index: L(1), generation: L(2), kind: L(3), count: L(4),
      vertices: L(5), radius: L(6), color: L(7), flags: L(8), vec2: L(9),
    };
    const J = (i) => module._pgw_joint_layout(i);
    this.jointLayout = { size: J(0), type: J(1), spring: J(2), a: J(3), b: J(4), originA: J(5), originB: J(6), color: J(7) };
  }

  // ---- strings and bytes across the boundary ----
  withString(text, fn) {
    const size = this.m.lengthBytesUTF8(text) + 1;
    const ptr = this.m._malloc(size);
    try {
      this.m.stringToUTF8(text, ptr, size);
      return fn(ptr, size - 1);
    } finally {
      this.m._free(ptr);
    }
  }
  text(ptr) { return ptr ? this.m.UTF8ToString(ptr) : ''; }

  // ---- life ----
  loadScene(name, text) {
    return this.withString(name, (namePtr) => this.withString(text, (textPtr, length) =>
      this.m._pgw_load_scene(namePtr, textPtr, length)));
  }
  sceneName() { return this.text(this.m._pgw_scene_name()); }

  // ---- tools and parameters ----
  setTool(tool) { return this.m._pgw_set_tool(tool); }
  tool() { return this.m._pgw_get_tool(); }
  toolName(tool) { return this.text(this.m._pgw_tool_name(tool)); }
  // {radius, width, height, density, friction, restitution} in SI units, colour 0xRRGGBB, nudge bool
  params(defaults = false) {
    const p = {};
    PARAM_NAMES.forEach((name, i) => { p[name] = fromFix(this.m._pgw_param(i, defaults ? 1 : 0)); });
    p.color = this.m._pgw_param(6, defaults ? 1 : 0) >>> 0;
    p.nudge = this.m._pgw_param(7, defaults ? 1 : 0) !== 0;
    return p;
  }
  // the spring tool's {hertz, damping}
  spring(defaults = false) {
    return { hertz: fromFix(this.m._pgw_param(8, defaults ? 1 : 0)), damping: fromFix(this.m._pgw_param(9, defaults ? 1 : 0)) };
  }
  setSpring(hertz, damping) { return this.m._pgw_set_spring(toFix(hertz), toFix(damping)); }
  setParams(p) {
    return this.m._pgw_set_params(toFix(p.radius), toFix(p.width), toFix(p.height), toFix(p.density),
      toFix(p.friction), toFix(p.restitution), p.color >>> 0, p.nudge ? 1 : 0);
  }

  // ---- input (world metres) ----
  pointer(phase, x, y) { this.m._pgw_pointer(phase, toFix(x), toFix(y)); }
  key(key, down) { this.m._pgw_key(key, down ? 1 : 0); }

  // ---- actions ----
  toggleGravity() { return this.m._pgw_toggle_gravity(); }
  setEffects(bits) { return this.m._pgw_set_effects(bits >>> 0); }
  effects() { return this.m._pgw_effects() >>> 0; }
  gravityEnabled() { return this.m._pgw_gravity_enabled() !== 0; }
  gravity() { return [fromFix(this.m._pgw_gravity(0)), fromFix(this.m._pgw_gravity(1))]; }
  setPaused(paused) { this.m._pgw_set_paused(paused ? 1 : 0); }
  paused() { return this.m._pgw_paused() !== 0; }
  stepOnce() { this.m._pgw_step_once(); }
  setPreset(preset) { return this.m._pgw_set_preset(preset); }
  preset() { return this.m._pgw_get_preset(); }
  selected() {
    const index = this.m._pgw_selected_index() >>> 0;
    const generation = this.m._pgw_selected_generation() >>> 0;
    return index === 0 && generation === 0 ? null : { index, generation };
  }
  select(id) { return this.m._pgw_select(id.index, id.generation); }
  setSelectedColor(color) { return this.m._pgw_set_selected_color(color >>> 0); }
  setSelectedMaterial(density, friction, restitution) {
    return this.m._pgw_set_selected_material(toFix(density), toFix(friction), toFix(restitution));
  }

  // ---- time ----
  frame() { return this.m._pgw_frame() !== 0; }
  frameNumber() { return this.m._pgw_frame_number() >>> 0; }
  stepHz() { return this.m._pgw_step_hz() >>> 0; }

  // ---- the world, read only ----
  body(id) {
    const b = (what) => this.m._pgw_body(id.index, id.generation, what);
    return {
      center: [fromFix(b(0)), fromFix(b(1))],
      position: [fromFix(b(2)), fromFix(b(3))],
      velocity: [fromFix(b(4)), fromFix(b(5))],
      angle: ((b(6) >>> 0) / TURN) * 2 * Math.PI,
      angularVelocity: fromFix(b(7)),
      type: ['static', 'kinematic', 'dynamic'][b(8)] ?? 'static',
      awake: b(9) !== 0,
      mass: fromFix(this.m._pgw_body_info(id.index, id.generation, 0)),
      color: this.m._pgw_body_info(id.index, id.generation, 1) >>> 0,
    };
  }
  bodyAngle(id) { return ((this.m._pgw_body(id.index, id.generation, 6) >>> 0) / TURN) * 2 * Math.PI; }
  bodyCount() { return this.m._pgw_body_count() >>> 0; }
  awakeCount() { return this.m._pgw_awake_count() >>> 0; }
  stateHash() { return this.text(this.m._pgw_state_hash()); }

  // Every shape of every body: {index, generation, kind, vertices [[x, y]...], radius, color, flags}
  drawList() {
    const base = this.m._pgw_draw_list();
    const count = this.m._pgw_draw_count() >>> 0;
    const L = this.layout;
    const heap = this.m.HEAP32;
    const shapes = new Array(count);
    for (let i = 0; i < count; ++i) {
      const s = (base + i * L.size) >> 2;
      const n = heap[s + (L.count >> 2)];
      const vertices = new Array(n);
      for (let v = 0; v < n; ++v) {
        const at = s + ((L.vertices + v * L.vec2) >> 2);
        vertices[v] = [heap[at] / FIX_ONE, heap[at + 1] / FIX_ONE];
      }
      shapes[i] = {
        index: heap[s + (L.index >> 2)] >>> 0,
        generation: heap[s + (L.generation >> 2)] >>> 0,
        kind: heap[s + (L.kind >> 2)],
        vertices,
        radius: heap[s + (L.radius >> 2)] / FIX_ONE,
        color: heap[s + (L.color >> 2)] >>> 0,
        flags: heap[s + (L.flags >> 2)] >>> 0,
      };
    }
    return shapes;
  }
  // Every joint: {type, spring, a, b, originA, originB: [x, y] metres, color}
  jointList() {
    const base = this.m._pgw_draw_joints();
    const count = this.m._pgw_joint_draw_count() >>> 0;
    const L = this.jointLayout;
    const heap = this.m.HEAP32;
    const point = (s, offset) => [heap[s + (offset >> 2)] / FIX_ONE, heap[s + (offset >> 2) + 1] / FIX_ONE];
    const joints = new Array(count);
    for (let i = 0; i < count; ++i) {
      const s = (base + i * L.size) >> 2;
      joints[i] = {
        type: heap[s + (L.type >> 2)],
        spring: heap[s + (L.spring >> 2)] !== 0,
        a: point(s, L.a), b: point(s, L.b), originA: point(s, L.originA), originB: point(s, L.originB),
        color: heap[s + (L.color >> 2)] >>> 0,
      };
    }
    return joints;
  }
  jointCount() { return this.m._pgw_joint_count() >>> 0; }
  pendingPoints() {
    const base = this.m._pgw_pending_points();
    const count = this.m._pgw_pending_count() >>> 0;
    const heap = this.m.HEAP32;
    const points = [];
    for (let i = 0; i < count; ++i) points.push([heap[(base >> 2) + 2 * i] / FIX_ONE, heap[(base >> 2) + 2 * i + 1] / FIX_ONE]);
    return points;
  }
  message() { return this.text(this.m._pgw_message()); }
  messageSerial() { return this.m._pgw_message_serial() >>> 0; }
  // 'info', 'refused' or 'error'
  messageLevel() { return ['info', 'refused', 'error'][this.m._pgw_message_level()] ?? 'info'; }
  resultName(code) { return this.text(this.m._pgw_result_name(code)); }

  // ---- recording and playback ----
  recording() {
    const ptr = this.m._pgw_recording();
    const size = this.m._pgw_recording_size() >>> 0;
    return ptr ? this.m.HEAPU8.slice(ptr, ptr + size) : null;
  }
  playReplay(bytes) {
    const ptr = this.m._malloc(Math.max(1, bytes.length));
    if (!ptr) return 5; // PG_ERR_MEMORY
    this.m.HEAPU8.set(bytes, ptr);
    return this.m._pgw_play_replay(ptr, bytes.length); // the binding keeps or frees ptr
  }
  playback() {
    const p = (i) => this.m._pgw_playback(i);
    return {
      active: p(0) !== 0, frame: p(1) >>> 0, frameCount: p(2) >>> 0,
      checked: p(3) >>> 0, failed: p(4) >>> 0, lastMatch: p(5), sectionMismatch: p(6) >>> 0,
    };
  }
  stopPlayback() { return this.m._pgw_stop_playback(); }
  // "pogon 0.2.0, a 12-bit sine table": the engine version and numeric configuration
  // that recorded the replay being played ('' when none).
  replayRecordedWith() { return this.text(this.m._pgw_replay_recorded_with()); }
}

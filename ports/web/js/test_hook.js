// test_hook.js — window.pogon: a read-only view of the page for tests and benchmarks
// (tests/web, tools/bench/web_bench.mjs). It changes nothing: tests drive the page
// through its controls, as a visitor does, and read the outcome here.
export function installTestHook(engine, view, loop) {
  const bodies = () => {
    const seen = new Map();
    for (const s of engine.drawList()) {
      const key = `${s.index}:${s.generation}`;
      if (!seen.has(key)) {
        const id = { index: s.index, generation: s.generation };
        seen.set(key, { ...id, ...engine.body(id), color: s.color, flags: s.flags, shapes: [] });
      }
      seen.get(key).shapes.push({ kind: s.kind, vertices: s.vertices, radius: s.radius });
    }
    return [...seen.values()];
  };
  window.pogon = Object.freeze({
    bodies,
    bodyCount: () => engine.bodyCount(),
    jointCount: () => engine.jointCount(),
    joints: () => engine.jointList(),
    spring: () => engine.spring(),
    awakeCount: () => engine.awakeCount(),
    frame: () => engine.frameNumber(),
    hash: () => engine.stateHash(),
    message: () => engine.message(),
    messageSerial: () => engine.messageSerial(),
    paused: () => engine.paused(),
    gravity: () => engine.gravity(),
    effects: () => engine.effects(),
    preset: () => engine.preset(),
    tool: () => engine.tool(),
    selected: () => engine.selected(),
    pending: () => engine.pendingPoints(),
    playback: () => engine.playback(),
    sceneName: () => engine.sceneName(),
    stepHz: () => engine.stepHz(),
    msPerStep: () => loop.msPerStep(),
    framesPerSecond: () => loop.framesPerSecond(),
    msPerFrame: () => loop.msPerFrame(),
    pixelsPerMetre: () => view.pixelsPerMetre,
    toScreen: (x, y) => view.toScreen(x, y),   // CSS pixels of the canvas
    toWorld: (sx, sy) => view.toWorld(sx, sy),
  });
}

// loop.js — a fixed-timestep accumulator on requestAnimationFrame.
//
// The world steps at its own rate (step_hz, 60 in the shipped scenes) whatever the
// display's refresh rate: each display frame adds the elapsed milliseconds times
// step_hz to an accumulator and takes one tick per 1000 it holds. Counting in
// (milliseconds x step_hz) keeps 60 Hz exact, where a 16.666... ms step would drift.
// A stall (a hidden tab) is capped at MAX_CATCH_UP_MS so the page never runs a burst.
const MAX_CATCH_UP_MS = 250;
const STATS_WINDOW_MS = 1000;

export class FixedStepLoop {
  // stepHz(): ticks per second; tick(): runs one tick and returns {steps, ms}: how many
  // steps the world took (0 while paused; several in fast playback) and the ms they
  // took; draw(): after the ticks of a display frame.
  constructor({ stepHz, tick, draw }) {
    this.stepHz = stepHz;
    this.tick = tick;
    this.draw = draw;
    this.accumulator = 0;
    this.last = null;
    this.costs = [];        // [time, steps, ms] of the ticks of the last second that stepped
    this.frameTimes = [];   // [time, ms of work] of the display frames of the last second
    this.onFrame = this.onFrame.bind(this);
  }

  start() { requestAnimationFrame(this.onFrame); }

  // Start the accumulator afresh (after a pause in input, a scene load): no burst.
  reset() { this.accumulator = 0; }

  onFrame(now) {
    const workStart = performance.now();
    const elapsed = this.last === null ? 0 : Math.min(now - this.last, MAX_CATCH_UP_MS);
    this.last = now;
    this.accumulator += elapsed * this.stepHz();
    while (this.accumulator >= 1000) {
      this.accumulator -= 1000;
      const { steps, ms } = this.tick();
      if (steps > 0) this.costs.push([now, steps, ms]);
    }
    this.draw();
    this.frameTimes.push([now, performance.now() - workStart]);
    this.trim(now);
    requestAnimationFrame(this.onFrame);
  }

  trim(now) {
    while (this.costs.length && now - this.costs[0][0] > STATS_WINDOW_MS) this.costs.shift();
    while (this.frameTimes.length && now - this.frameTimes[0][0] > STATS_WINDOW_MS) this.frameTimes.shift();
  }

  // Mean ms per step over the last second, or null when nothing stepped.
  msPerStep() {
    let steps = 0, ms = 0;
    for (const [, n, t] of this.costs) { steps += n; ms += t; }
    return steps ? ms / steps : null;
  }

  // Display frames drawn in the last second.
  framesPerSecond() { return this.frameTimes.length; }

  // Mean ms of work per display frame (steps, drawing, readout) over the last second.
  msPerFrame() {
    if (!this.frameTimes.length) return null;
    return this.frameTimes.reduce((sum, [, ms]) => sum + ms, 0) / this.frameTimes.length;
  }
}

// view.js — world metres (y up) to canvas pixels (y down) and back.
//
// One uniform scale, in pixels per metre, for both axes: a metre is the same length
// across and up, and stays that length until another scene is fitted. Coordinates
// returned are CSS pixels of the canvas; drawing multiplies by the backing store's
// ratio (devicePixelRatio) itself.
export class View {
  constructor(canvas) {
    this.canvas = canvas;
    this.pixelsPerMetre = 20;
    this.origin = [0, 0]; // the world point drawn at the canvas's top-left corner
  }

  get width() { return this.canvas.clientWidth; }
  get height() { return this.canvas.clientHeight; }

  // Fit the world box {minX, minY, maxX, maxY} (metres) into the canvas, centred, with a margin.
  fit(box, marginMetres = 0.5) {
    const w = Math.max(1, box.maxX - box.minX + 2 * marginMetres);
    const h = Math.max(1, box.maxY - box.minY + 2 * marginMetres);
    this.pixelsPerMetre = Math.min(this.width / w, this.height / h);
    const cx = (box.minX + box.maxX) / 2;
    const cy = (box.minY + box.maxY) / 2;
    this.origin = [cx - this.width / 2 / this.pixelsPerMetre, cy + this.height / 2 / this.pixelsPerMetre];
  }

  toScreen(x, y) {
    return [(x - this.origin[0]) * this.pixelsPerMetre, (this.origin[1] - y) * this.pixelsPerMetre];
  }

  toWorld(sx, sy) {
    return [this.origin[0] + sx / this.pixelsPerMetre, this.origin[1] - sy / this.pixelsPerMetre];
  }
}

// The box around every vertex (and radius) of a draw list: what a scene occupies.
export function boundsOf(shapes) {
  const box = { minX: Infinity, minY: Infinity, maxX: -Infinity, maxY: -Infinity };
  for (const s of shapes) {
    for (const [x, y] of s.vertices) {
      box.minX = Math.min(box.minX, x - s.radius);
      box.maxX = Math.max(box.maxX, x + s.radius);
      box.minY = Math.min(box.minY, y - s.radius);
      box.maxY = Math.max(box.maxY, y + s.radius);
    }
  }
  if (!Number.isFinite(box.minX)) return { minX: -20, minY: -1, maxX: 20, maxY: 20 };
  return box;
}

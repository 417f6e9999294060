// render.js — draws what the app says (its draw list, joints and pending clicks) on a 2D canvas.
//
// Fills carry each body's own colour unchanged, whatever its state, so a pixel inside a
// body is that body's colour (the end-to-end test reads them); state shows in outlines:
// the selected body thick and orange, sleeping bodies dashed, static ones dark.
import { SHAPE, DRAW, JOINT } from './engine.js';

export const BACKGROUND = '#fbfaf7';
const SELECTED = '#d9480f';
const OUTLINE = '#3a3a3a';
const ASLEEP = '#9a9a9a';

const hex = (c) => '#' + (c & 0xffffff).toString(16).padStart(6, '0');

export class Renderer {
  constructor(canvas, view) {
    this.canvas = canvas;
    this.view = view;
    this.ctx = canvas.getContext('2d');
  }

  // Match the backing store to the CSS size times devicePixelRatio, once per change.
  resize() {
    const ratio = window.devicePixelRatio || 1;
    const w = Math.round(this.canvas.clientWidth * ratio);
    const h = Math.round(this.canvas.clientHeight * ratio);
    if (this.canvas.width !== w || this.canvas.height !== h) {
      this.canvas.width = w;
      this.canvas.height = h;
    }
    this.ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  }

  // shapes: engine.drawList(); angleOf(shape): a circle's angle (radians) for its spoke;
  // pending: points of an unfinished triangle, wall or joint; pointer: the world point under
  // the mouse or null; joints: engine.jointList().
  draw(shapes, angleOf, pending, pointer, joints = []) {
    const { ctx, view } = this;
    this.resize();
    ctx.fillStyle = BACKGROUND;
    ctx.fillRect(0, 0, view.width, view.height);
    const px = view.pixelsPerMetre;
    // Shapes of one look (colour and outline) share one path: one fill and one stroke for
    // all of them, in list order, with the selected body last so its outline is on top.
    const groups = new Map();
    const selected = [];
    for (const s of shapes) {
      if (s.flags & DRAW.SELECTED) { selected.push(s); continue; }
      const key = s.color * 16 + (s.flags & DRAW.ASLEEP ? 1 : 0) + (s.kind === SHAPE.SEGMENT ? 2 : 0);
      if (!groups.has(key)) groups.set(key, []);
      groups.get(key).push(s);
    }
    for (const group of groups.values()) this.fillAndStroke(group, px, false);
    if (selected.length) this.fillAndStroke(selected, px, true);
    // the balls' spokes, all in one stroke
    ctx.beginPath();
    for (const s of shapes) if (s.kind === SHAPE.CIRCLE) this.spoke(s, angleOf(s), px);
    ctx.setLineDash([]);
    ctx.lineWidth = 1;
    ctx.strokeStyle = OUTLINE;
    ctx.stroke();
    for (const j of joints) this.joint(j);
    this.pending(pending, pointer);
  }

  // Over the bodies, in the app's colour by kind: a pin a ringed dot with thin arms from
  // the bodies' origins, a rod a line, a spring a zigzag, a drag a thin line to a ring at
  // the pointer; a rod's and a spring's ends are dots.
  joint(j) {
    const { ctx, view } = this;
    const colour = hex(j.color);
    const [ax, ay] = view.toScreen(...j.a);
    const [bx, by] = view.toScreen(...j.b);
    const dot = (x, y, r, fill) => { ctx.beginPath(); ctx.arc(x, y, r, 0, 2 * Math.PI); ctx.fillStyle = fill; ctx.fill(); };
    ctx.setLineDash([]);
    ctx.strokeStyle = colour;
    ctx.beginPath();
    if (j.type === JOINT.REVOLUTE) {
      for (const o of [j.originA, j.originB]) {
        const [ox, oy] = view.toScreen(...o);
        ctx.moveTo(ox, oy);
        ctx.lineTo(bx, by);
      }
      ctx.lineWidth = 1;
      ctx.stroke();
      dot(bx, by, 5, colour);
      dot(bx, by, 2, '#ffffff');
    } else if (j.type === JOINT.MOUSE) {
      ctx.moveTo(bx, by);
      ctx.lineTo(ax, ay);
      ctx.lineWidth = 1;
      ctx.stroke();
      ctx.beginPath();
      ctx.arc(ax, ay, 4, 0, 2 * Math.PI);
      ctx.stroke();
      dot(bx, by, 2, colour);
    } else {
      if (j.type === JOINT.DISTANCE && j.spring) this.zigzag(ax, ay, bx, by);
      else { ctx.moveTo(ax, ay); ctx.lineTo(bx, by); }
      ctx.lineWidth = j.type === JOINT.DISTANCE && !j.spring ? 3 : 2;
      ctx.stroke();
      dot(ax, ay, 3, colour);
      dot(bx, by, 3, colour);
    }
  }

  // Teeth 5 px to each side, about one per 6 px of length; added to the current path.
  zigzag(ax, ay, bx, by) {
    const { ctx } = this;
    const dx = bx - ax, dy = by - ay, len = Math.hypot(dx, dy);
    ctx.moveTo(ax, ay);
    if (len >= 1) {
      const n = Math.min(60, Math.max(4, Math.floor(len / 6)));
      const nx = (-dy / len) * 5, ny = (dx / len) * 5;
      for (let i = 1; i <= n; ++i) {
        const t = i / (n + 1), side = i % 2 ? 1 : -1;
        ctx.lineTo(ax + dx * t + nx * side, ay + dy * t + ny * side);
      }
    }
    ctx.lineTo(bx, by);
  }

  fillAndStroke(group, px, selected) {
    const { ctx } = this;
    const first = group[0];
    ctx.beginPath();
    for (const s of group) this.path(s, px);
    if (first.kind !== SHAPE.SEGMENT) {
      ctx.fillStyle = hex(first.color);
      ctx.fill();
    }
    ctx.setLineDash(!selected && first.flags & DRAW.ASLEEP ? [4, 3] : []);
    ctx.lineWidth = selected ? 3 : 1;
    ctx.strokeStyle = selected ? SELECTED : first.kind === SHAPE.SEGMENT ? hex(first.color)
      : first.flags & DRAW.ASLEEP ? ASLEEP : OUTLINE;
    ctx.stroke();
  }

  // Adds the shape as a subpath of the current path.
  path(s, px) {
    const { ctx, view } = this;
    if (s.kind === SHAPE.CIRCLE) {
      const [x, y] = view.toScreen(...s.vertices[0]);
      ctx.moveTo(x + s.radius * px, y);
      ctx.arc(x, y, s.radius * px, 0, 2 * Math.PI);
    } else if (s.kind === SHAPE.CAPSULE) {
      const [ax, ay] = view.toScreen(...s.vertices[0]);
      const [bx, by] = view.toScreen(...s.vertices[1]);
      const a = Math.atan2(by - ay, bx - ax);
      ctx.moveTo(bx + s.radius * px * Math.cos(a - Math.PI / 2), by + s.radius * px * Math.sin(a - Math.PI / 2));
      ctx.arc(bx, by, s.radius * px, a - Math.PI / 2, a + Math.PI / 2);
      ctx.arc(ax, ay, s.radius * px, a + Math.PI / 2, a + 1.5 * Math.PI);
      ctx.closePath();
    } else {
      s.vertices.forEach((v, i) => {
        const [x, y] = view.toScreen(...v);
        if (i === 0) ctx.moveTo(x, y); else ctx.lineTo(x, y);
      });
      if (s.kind === SHAPE.POLYGON) ctx.closePath();
    }
  }

  // A spoke from half the radius to the rim shows a ball's turning (and leaves its centre
  // clear); added to the current path.
  spoke(s, angle, px) {
    const { ctx, view } = this;
    const [x, y] = view.toScreen(...s.vertices[0]);
    const r = s.radius * px;
    const c = Math.cos(angle), n = -Math.sin(angle);
    ctx.moveTo(x + 0.5 * r * c, y + 0.5 * r * n);
    ctx.lineTo(x + r * c, y + r * n);
  }

  // The clicks collected for a triangle or a wall, joined, with a line on to the pointer.
  pending(points, pointer) {
    if (!points.length) return;
    const { ctx, view } = this;
    const screen = points.map((p) => view.toScreen(...p));
    if (pointer) screen.push(view.toScreen(...pointer));
    ctx.beginPath();
    screen.forEach(([x, y], i) => (i === 0 ? ctx.moveTo(x, y) : ctx.lineTo(x, y)));
    ctx.setLineDash([6, 4]);
    ctx.lineWidth = 2;
    ctx.strokeStyle = SELECTED;
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = SELECTED;
    for (const [x, y] of screen.slice(0, points.length)) {
      ctx.beginPath();
      ctx.arc(x, y, 5, 0, 2 * Math.PI);
      ctx.fill();
    }
  }
}

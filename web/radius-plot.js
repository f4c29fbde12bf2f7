// A small two-series plot on a <canvas>: mean gather radius (left axis) and photons traced
// (right axis) against elapsed seconds. Each series has its own vertical scale starting at
// zero. Points are appended as passes finish; the canvas redraws itself on resize.

import { formatCount, formatDuration, formatRadius } from './format.js';

// Series colours: the canvas's --plot-radius and --plot-photons (style.css), else these.
const RADIUS_COLOR = '#c2410c';
const PHOTONS_COLOR = '#1d4ed8';
const MARGIN = { left: 58, right: 58, top: 26, bottom: 30 };
const TICKS = 4;

// The smallest "round" number (1, 2, 2.5 or 5 times a power of ten) >= value.
function niceCeiling(value) {
  if (!(value > 0)) return 1;
  const power = 10 ** Math.floor(Math.log10(value));
  for (const step of [1, 2, 2.5, 5, 10]) {
    if (step * power >= value * (1 - 1e-9)) return step * power;
  }
  return 10 * power;
}

export class RadiusPlot {
  constructor(canvas) {
    this.canvas = canvas;
    this.points = []; // { t, radius, photons }
    if (typeof ResizeObserver === 'function') {
      this.observer = new ResizeObserver(() => this.draw());
      this.observer.observe(canvas);
    }
    this.draw();
  }

  clear() {
    this.points = [];
    this.draw();
  }

  // Appends a point; a point at the same time as the last one replaces it.
  add({ t, radius, photons }) {
    if (!Number.isFinite(t)) return;
    const point = { t, radius: Number.isFinite(radius) ? radius : null, photons: Number.isFinite(photons) ? photons : null };
    const last = this.points[this.points.length - 1];
    if (last && last.t === t) this.points[this.points.length - 1] = point;
    else if (!last || t > last.t) this.points.push(point);
    else return; // out of order (a replayed event): already plotted
    this.draw();
  }

  describe() {
    const last = this.points[this.points.length - 1];
    if (!last) return 'No passes finished yet.';
    return (
      `${this.points.length} point(s). Latest at ${formatDuration(last.t)}: ` +
      `mean radius ${formatRadius(last.radius)}, photons traced ${formatCount(last.photons)}.`
    );
  }

  draw() {
    const canvas = this.canvas;
    const cssWidth = canvas.clientWidth || canvas.width;
    const cssHeight = canvas.clientHeight || canvas.height;
    const ratio = window.devicePixelRatio || 1;
    if (canvas.width !== Math.round(cssWidth * ratio) || canvas.height !== Math.round(cssHeight * ratio)) {
      canvas.width = Math.round(cssWidth * ratio);
      canvas.height = Math.round(cssHeight * ratio);
    }
    const ctx = canvas.getContext('2d');
    if (!ctx) return;
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, cssWidth, cssHeight);
    canvas.setAttribute('aria-label', `Mean radius and photons traced over time. ${this.describe()}`);

    const style = getComputedStyle(canvas);
    const ink = style.color || '#222';
    this.colors = {
      radius: style.getPropertyValue('--plot-radius').trim() || RADIUS_COLOR,
      photons: style.getPropertyValue('--plot-photons').trim() || PHOTONS_COLOR,
    };
    const box = {
      x: MARGIN.left,
      y: MARGIN.top,
      w: Math.max(10, cssWidth - MARGIN.left - MARGIN.right),
      h: Math.max(10, cssHeight - MARGIN.top - MARGIN.bottom),
    };
    const tMax = niceCeiling(Math.max(1, ...this.points.map((p) => p.t)));
    const rMax = niceCeiling(Math.max(0, ...this.points.map((p) => p.radius ?? 0)));
    const nMax = niceCeiling(Math.max(0, ...this.points.map((p) => p.photons ?? 0)));

    ctx.font = '11px system-ui, sans-serif';
    this.drawAxes(ctx, box, ink, { tMax, rMax, nMax });
    this.drawLegend(ctx, box);
    if (this.points.length === 0) {
      ctx.fillStyle = ink;
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      ctx.fillText('Points appear as passes finish', box.x + box.w / 2, box.y + box.h / 2);
      return;
    }
    const x = (t) => box.x + (t / tMax) * box.w;
    this.drawSeries(ctx, x, (r) => box.y + box.h - (r / rMax) * box.h, 'radius', this.colors.radius);
    this.drawSeries(ctx, x, (n) => box.y + box.h - (n / nMax) * box.h, 'photons', this.colors.photons);
  }

  drawAxes(ctx, box, ink, { tMax, rMax, nMax }) {
    ctx.strokeStyle = 'rgba(128, 128, 128, 0.35)';
    ctx.lineWidth = 1;
    ctx.textBaseline = 'middle';
    for (let i = 0; i <= TICKS; i++) {
      const y = Math.round(box.y + box.h - (i / TICKS) * box.h) + 0.5;
      ctx.beginPath();
      ctx.moveTo(box.x, y);
      ctx.lineTo(box.x + box.w, y);
      ctx.stroke();
      ctx.fillStyle = this.colors.radius;
      ctx.textAlign = 'right';
      ctx.fillText(String(Number(((rMax * i) / TICKS).toPrecision(3))), box.x - 6, y);
      ctx.fillStyle = this.colors.photons;
      ctx.textAlign = 'left';
      ctx.fillText(formatCount((nMax * i) / TICKS), box.x + box.w + 6, y);
    }
    ctx.fillStyle = ink;
    ctx.textBaseline = 'top';
    for (let i = 0; i <= TICKS; i++) {
      const t = (tMax * i) / TICKS;
      ctx.textAlign = i === 0 ? 'left' : i === TICKS ? 'right' : 'center';
      const label = tMax < 10 ? `${t.toFixed(tMax < 4 ? 2 : 1)} s` : formatDuration(t);
      ctx.fillText(label, box.x + (i / TICKS) * box.w, box.y + box.h + 6);
    }
    ctx.strokeStyle = ink;
    ctx.strokeRect(box.x + 0.5, box.y + 0.5, box.w, box.h);
  }

  drawLegend(ctx, box) {
    const entries = [
      ['mean radius (left)', this.colors.radius],
      ['photons traced (right)', this.colors.photons],
    ];
    ctx.textBaseline = 'middle';
    ctx.textAlign = 'left';
    let x = box.x;
    for (const [label, color] of entries) {
      ctx.fillStyle = color;
      ctx.fillRect(x, 8, 14, 3);
      ctx.fillText(label, x + 18, 10);
      x += 26 + ctx.measureText(label).width;
    }
  }

  drawSeries(ctx, x, y, key, color) {
    const points = this.points.filter((p) => p[key] !== null);
    if (points.length === 0) return;
    ctx.strokeStyle = color;
    ctx.fillStyle = color;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    points.forEach((p, i) => (i === 0 ? ctx.moveTo(x(p.t), y(p[key])) : ctx.lineTo(x(p.t), y(p[key]))));
    ctx.stroke();
    for (const p of points) {
      ctx.beginPath();
      ctx.arc(x(p.t), y(p[key]), 2.5, 0, 2 * Math.PI);
      ctx.fill();
    }
  }
}

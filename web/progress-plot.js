// The job's progress over time on a <canvas>: one panel per series, stacked, sharing the
// time axis (elapsed seconds), each with its own vertical scale from zero. Which series
// depends on the method: passes per second for every method, and for SPPM also the mean
// gather radius and the photons traced (the other methods have no radius, and the path
// tracer and radiosity trace no photons), and the image's estimated relative error for the
// methods that keep one (all but photon mapping). Points are keyed by pass, so a history read
// after a reload and the live passes merge in any order; the canvas redraws on resize.

import { formatCount, formatDuration, formatRadius, formatRelativeError } from './format.js';

// Series: key, label, colour (a CSS custom property of the canvas, else the fallback).
const SERIES = {
  rate: { label: 'passes per second', color: ['--plot-rate', '#15803d'], describe: (v) => `${formatTick(v, v / 10)}/s` },
  radius: { label: 'mean radius', color: ['--plot-radius', '#c2410c'], describe: formatRadius },
  photons: { label: 'photons traced', color: ['--plot-photons', '#1d4ed8'], describe: formatCount },
  error: { label: 'relative error', color: ['--plot-error', '#7e22ce'], describe: (v) => formatRelativeError(v) },
};
const MARGIN = { left: 62, right: 14, top: 8, bottom: 26 };
const PANEL_HEIGHT = 92; // CSS pixels per series
const TICKS = 4;

// The series a method has.
export function seriesFor(integrator) {
  if (integrator === 'sppm') return ['rate', 'radius', 'photons', 'error'];
  return integrator === 'photonmap' ? ['rate'] : ['rate', 'error'];
}

// The smallest "round" number (1, 2, 2.5 or 5 times a power of ten) >= value; 1 for none.
export function niceCeiling(value) {
  if (!(value > 0)) return 1;
  const power = 10 ** Math.floor(Math.log10(value));
  for (const step of [1, 2, 2.5, 5, 10]) {
    if (step * power >= value * (1 - 1e-9)) return step * power;
  }
  return 10 * power;
}

// A tick's label with the decimals the step between ticks needs (three significant digits
// of the step: 0.0125 steps keep four), large values as counts ("12.5 k"), so that no two
// ticks read the same. Without a step: two decimals.
export function formatTick(value, step) {
  if (value === 0) return '0';
  if (Math.abs(step) >= 1000) return formatCount(value);
  const decimals = step > 0 ? Math.max(0, 2 - Math.floor(Math.log10(step))) : 2;
  return String(Number(value.toFixed(Math.min(decimals, 12))));
}

// The labels of an axis from 0 to max in TICKS steps.
export function tickLabels(max, ticks = TICKS) {
  return Array.from({ length: ticks + 1 }, (_, i) => formatTick((max * i) / ticks, max / ticks));
}

export class ProgressPlot {
  constructor(canvas) {
    this.canvas = canvas;
    this.series = ['rate'];
    this.byPass = new Map(); // pass -> { pass, t, radius, photons, error }
    if (typeof ResizeObserver === 'function') {
      this.observer = new ResizeObserver(() => this.draw());
      this.observer.observe(canvas);
    }
    this.draw();
  }

  clear() {
    this.byPass.clear();
    this.draw();
  }

  setSeries(keys) {
    if (keys.join() === this.series.join()) return;
    this.series = keys;
    this.draw();
  }

  // The job's state after a pass (a job record of api.js); a pass already plotted is kept.
  add(job, { redraw = true } = {}) {
    const pass = job.passesDone;
    const t = job.elapsedSeconds;
    if (!(pass > 0) || !Number.isFinite(t) || this.byPass.has(pass)) return;
    const finite = (v) => (Number.isFinite(v) ? v : null);
    this.byPass.set(pass, {
      pass, t, radius: finite(job.meanRadius), photons: finite(job.photonsTraced), error: finite(job.relativeError),
    });
    if (redraw) this.draw();
  }

  addAll(jobs) {
    for (const job of jobs) this.add(job, { redraw: false });
    this.draw();
  }

  // Points in pass order, with passes per second since the previous point plotted.
  points() {
    const sorted = [...this.byPass.values()].sort((a, b) => a.pass - b.pass);
    let previous = { pass: 0, t: 0 };
    return sorted.map((p) => {
      const dt = p.t - previous.t;
      const rate = dt > 0 ? (p.pass - previous.pass) / dt : null;
      previous = p;
      return { ...p, rate };
    });
  }

  describe(points) {
    const names = this.series.map((key) => SERIES[key].label);
    const title = `${names.join(', ').replace(/, ([^,]*)$/, ' and $1')} over time`;
    const last = points[points.length - 1];
    if (!last) return `${title[0].toUpperCase()}${title.slice(1)}. No passes finished yet.`;
    const values = this.series
      .filter((key) => last[key] !== null)
      .map((key) => `${SERIES[key].label} ${SERIES[key].describe(last[key])}`);
    return (
      `${title[0].toUpperCase()}${title.slice(1)}. ${points.length} pass${points.length === 1 ? '' : 'es'} plotted. ` +
      `Latest, pass ${last.pass} at ${formatDuration(last.t)}: ${values.join(', ')}.`
    );
  }

  draw() {
    const canvas = this.canvas;
    const points = this.points();
    canvas.dataset.series = this.series.map((key) => SERIES[key].label).join(', ');
    canvas.dataset.points = String(points.length);
    canvas.setAttribute('aria-label', this.describe(points));
    const cssHeight = MARGIN.top + MARGIN.bottom + PANEL_HEIGHT * this.series.length;
    canvas.style.height = `${cssHeight}px`;
    const cssWidth = canvas.clientWidth || canvas.width;
    const ratio = window.devicePixelRatio || 1;
    if (canvas.width !== Math.round(cssWidth * ratio) || canvas.height !== Math.round(cssHeight * ratio)) {
      canvas.width = Math.round(cssWidth * ratio);
      canvas.height = Math.round(cssHeight * ratio);
    }
    const ctx = canvas.getContext('2d');
    if (!ctx) return;
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, cssWidth, cssHeight);
    const style = getComputedStyle(canvas);
    const ink = style.color || '#222';
    ctx.font = '11px system-ui, sans-serif';

    const width = Math.max(10, cssWidth - MARGIN.left - MARGIN.right);
    const tMax = niceCeiling(Math.max(0, ...points.map((p) => p.t)));
    const x = (t) => MARGIN.left + (t / tMax) * width;
    this.series.forEach((key, index) => {
      const box = { x: MARGIN.left, y: MARGIN.top + index * PANEL_HEIGHT, w: width, h: PANEL_HEIGHT - 18 };
      const color = style.getPropertyValue(SERIES[key].color[0]).trim() || SERIES[key].color[1];
      const values = points.filter((p) => p[key] !== null);
      const max = niceCeiling(Math.max(0, ...values.map((p) => p[key])));
      this.drawPanel(ctx, box, { ink, color, label: SERIES[key].label, max });
      const y = (v) => box.y + box.h - (v / max) * box.h;
      this.drawSeries(ctx, values.map((p) => [x(p.t), y(p[key])]), color);
    });
    this.drawTimeAxis(ctx, MARGIN.top + this.series.length * PANEL_HEIGHT - 18, width, tMax, ink);
    if (points.length === 0) {
      ctx.fillStyle = ink;
      ctx.textAlign = 'center';
      ctx.textBaseline = 'middle';
      ctx.fillText('Points appear as passes finish', MARGIN.left + width / 2, MARGIN.top + PANEL_HEIGHT / 2);
    }
  }

  drawPanel(ctx, box, { ink, color, label, max }) {
    ctx.lineWidth = 1;
    ctx.textBaseline = 'middle';
    ctx.textAlign = 'right';
    const labels = tickLabels(max, 2); // 0, half, max: enough for a panel this small
    labels.forEach((text, i) => {
      const y = Math.round(box.y + box.h - (i / 2) * box.h) + 0.5;
      ctx.strokeStyle = 'rgba(128, 128, 128, 0.35)';
      ctx.beginPath();
      ctx.moveTo(box.x, y);
      ctx.lineTo(box.x + box.w, y);
      ctx.stroke();
      ctx.fillStyle = color;
      ctx.fillText(text, box.x - 6, y);
    });
    ctx.strokeStyle = ink;
    ctx.strokeRect(box.x + 0.5, box.y + 0.5, box.w, box.h);
    ctx.fillStyle = color;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'top';
    ctx.fillText(label, box.x + 6, box.y + 4);
  }

  drawTimeAxis(ctx, bottom, width, tMax, ink) {
    ctx.fillStyle = ink;
    ctx.textBaseline = 'top';
    for (let i = 0; i <= TICKS; i++) {
      const t = (tMax * i) / TICKS;
      ctx.textAlign = i === 0 ? 'left' : i === TICKS ? 'right' : 'center';
      const label = tMax < 10 ? `${formatTick(t, tMax / TICKS)} s` : formatDuration(t);
      ctx.fillText(label, MARGIN.left + (i / TICKS) * width, bottom + 6);
    }
  }

  drawSeries(ctx, xy, color) {
    if (xy.length === 0) return;
    ctx.strokeStyle = color;
    ctx.fillStyle = color;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    xy.forEach(([px, py], i) => (i === 0 ? ctx.moveTo(px, py) : ctx.lineTo(px, py)));
    ctx.stroke();
    if (xy.length > 200) return; // a line is enough: dots would merge
    for (const [px, py] of xy) {
      ctx.beginPath();
      ctx.arc(px, py, 2.5, 0, 2 * Math.PI);
      ctx.fill();
    }
  }
}

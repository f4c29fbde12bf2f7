// Numbers and times as the page shows them. Every function takes null/undefined/NaN and
// returns a dash, so callers can pass fields the server did not send.

const DASH = '—';

function ok(value) {
  return typeof value === 'number' && Number.isFinite(value);
}

// 3725.4 -> "1:02:05"
export function formatDuration(seconds) {
  if (!ok(seconds) || seconds < 0) return DASH;
  const total = Math.round(seconds);
  const h = Math.floor(total / 3600);
  const m = Math.floor((total % 3600) / 60);
  const s = total % 60;
  return `${h}:${String(m).padStart(2, '0')}:${String(s).padStart(2, '0')}`;
}

// 1234567 -> "1.23 M"; 950 -> "950"
export function formatCount(value) {
  if (!ok(value)) return DASH;
  const units = [
    [1e9, 'G'],
    [1e6, 'M'],
    [1e3, 'k'],
  ];
  for (const [size, unit] of units) {
    if (Math.abs(value) >= size) return `${(value / size).toPrecision(3)} ${unit}`;
  }
  return String(Math.round(value));
}

// The photons a pass traces now. SPPM's adaptive counts (render.adaptive_photons) change
// it after passes 4, 8, 16, ..., so the record's photons_per_pass is only where the render
// started; the job's progress points ({ pass, photons }: photons traced after that pass, in
// any order, as the plot keeps them) tell the latest passes' count: the photons between the
// last two over the passes between them. null until two passes with photons are known.
export function currentPhotonsPerPass(points) {
  const known = (points || []).filter((p) => p && Number.isInteger(p.pass) && p.pass > 0 && ok(p.photons));
  if (known.length < 2) return null;
  known.sort((a, b) => a.pass - b.pass);
  const [before, last] = known.slice(-2);
  const photons = last.photons - before.photons;
  return last.pass > before.pass && photons > 0 ? Math.round(photons / (last.pass - before.pass)) : null;
}

// SPPM's photons per pass as the job view shows them: the count now, with where the render
// started once it has moved ("800 k (started at 200 k)"); the start alone until the points
// tell. Counts that read the same are shown once: "200 k (started at 200 k)" would say a
// change that the figures cannot show.
export function formatPhotonsPerPass(start, points) {
  const now = currentPhotonsPerPass(points);
  if (now === null) return formatCount(start);
  if (!ok(start) || formatCount(now) === formatCount(start)) return formatCount(now);
  return `${formatCount(now)} (started at ${formatCount(start)})`;
}

export function formatRate(perSecond) {
  return ok(perSecond) ? `${formatCount(perSecond)}/s` : DASH;
}

// Gather radius in scene units, three significant digits.
export function formatRadius(radius) {
  if (!ok(radius)) return DASH;
  if (radius === 0) return '0';
  return radius >= 0.01 && radius < 1000 ? radius.toPrecision(3) : radius.toExponential(2);
}

// The estimated relative error against its target: 0.0312, 0.02 -> "3.12% (target 2%)".
export function formatRelativeError(error, target) {
  if (!ok(error)) return DASH;
  const percent = (v) => `${Number((100 * v).toPrecision(3))}%`;
  return ok(target) && target > 0 ? `${percent(error)} (target ${percent(target)})` : percent(error);
}

export function formatPasses(done, total) {
  const d = ok(done) ? done : 0;
  return ok(total) ? `${d} / ${total}` : String(d);
}

// ISO timestamp -> local "2024-05-01 14:03:12"; anything else -> dash.
export function formatTime(iso) {
  if (!iso) return DASH;
  const date = new Date(iso);
  if (Number.isNaN(date.getTime())) return DASH;
  const pad = (n) => String(n).padStart(2, '0');
  return (
    `${date.getFullYear()}-${pad(date.getMonth() + 1)}-${pad(date.getDate())} ` +
    `${pad(date.getHours())}:${pad(date.getMinutes())}:${pad(date.getSeconds())}`
  );
}

// Passes done as a fraction in [0, 1] for progress bars.
export function progressFraction(done, total) {
  if (!ok(done) || !ok(total) || total <= 0) return 0;
  return Math.min(1, Math.max(0, done / total));
}

// JSON text for people: two-space indents, but arrays of plain values (vectors, colours,
// index lists) on one line.
export function formatJson(value, indent = '') {
  const inner = `${indent}  `;
  if (Array.isArray(value)) {
    if (value.length === 0) return '[]';
    if (value.every((v) => v === null || typeof v !== 'object')) return `[${value.map((v) => JSON.stringify(v)).join(', ')}]`;
    return `[\n${value.map((v) => inner + formatJson(v, inner)).join(',\n')}\n${indent}]`;
  }
  if (value && typeof value === 'object') {
    const entries = Object.entries(value);
    if (entries.length === 0) return '{}';
    return `{\n${entries.map(([k, v]) => `${inner}${JSON.stringify(k)}: ${formatJson(v, inner)}`).join(',\n')}\n${indent}}`;
  }
  return JSON.stringify(value) ?? 'null';
}

// A job's method (settings.integrator) in words.
const METHOD_NAMES = { sppm: 'SPPM', photonmap: 'photon map', radiosity: 'radiosity', path: 'path tracing' };

export function methodName(integrator) {
  return METHOD_NAMES[integrator] ?? integrator ?? DASH;
}

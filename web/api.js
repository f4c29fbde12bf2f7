// The photon REST API (/api/v1) as plain functions. Every call goes through request(),
// which adds the bearer token when one is set, asks for a token on a 401 and retries once,
// and turns failures into ApiError with a message in plain words. normalizeJob() is the one
// place that knows the server's field names for a job record.

const BASE = '/api/v1';
const TOKEN_KEY = 'photon.token';

export class ApiError extends Error {
  // status: the HTTP status (0 when the server could not be reached); path: the JSON path
  // into the scene for scene errors ('' for the document as a whole), else undefined;
  // pointer: the same place as a JSON Pointer (JSON scenes only), else undefined.
  constructor(message, { status = 0, path, pointer } = {}) {
    super(message);
    this.name = 'ApiError';
    this.status = status;
    this.path = path;
    this.pointer = pointer;
  }
}

// ---- Token ---------------------------------------------------------------------------

let askForToken = null; // (refused: boolean) => Promise<string|null>, set by main.js
let pendingAsk = null;  // one question at a time, however many requests got a 401
let declined = false;   // the user closed the question: do not ask again by ourselves

export function getToken() {
  try {
    return sessionStorage.getItem(TOKEN_KEY) || '';
  } catch {
    return '';
  }
}

export function setToken(token) {
  try {
    if (token) sessionStorage.setItem(TOKEN_KEY, token);
    else sessionStorage.removeItem(TOKEN_KEY);
  } catch {
    // Storage refused (private mode): the token lasts until the page is reloaded.
  }
}

export function hasToken() {
  return getToken() !== '';
}

export function onTokenNeeded(ask) {
  askForToken = ask;
}

// After the user declined: ask again on the next 401 (the "Enter access token" button).
export function allowTokenQuestion() {
  declined = false;
}

function authHeaders() {
  const token = getToken();
  return token ? { Authorization: `Bearer ${token}` } : {};
}

async function tokenAfter401() {
  if (!askForToken || declined) return null;
  if (!pendingAsk) {
    pendingAsk = Promise.resolve(askForToken(hasToken())).then(async (token) => {
      if (token) {
        setToken(token);
        sessionStarted = null;
        await ensureSession();
      } else {
        declined = true;
      }
      return token;
    }).finally(() => {
      pendingAsk = null;
    });
  }
  return pendingAsk;
}

// With a token, the page trades it for a session cookie (HttpOnly, so no script here sees
// it): an EventSource stream cannot send the token, the cookie goes with it by itself.
// Resolves to whether a session was started; one attempt per token.
let sessionStarted = null;

export function ensureSession() {
  if (!hasToken()) return Promise.resolve(false);
  if (!sessionStarted) {
    sessionStarted = fetch(BASE + '/session', { method: 'POST', headers: authHeaders() })
      .then((res) => res.ok)
      .catch(() => false);
  }
  return sessionStarted;
}

// A stream was refused: the session may have ended (a server restart); the next
// ensureSession() asks for a new one.
export function sessionLost() {
  sessionStarted = null;
}

// ---- Requests ------------------------------------------------------------------------

async function errorFrom(res) {
  let body = null;
  try {
    body = await res.json();
  } catch {
    // Not JSON (a proxy's page, say): fall back to the status line.
  }
  const serverMessage = body && typeof body.error === 'string' ? body.error : '';
  const path = body && typeof body.path === 'string' ? body.path : undefined;
  const pointer = body && typeof body.pointer === 'string' ? body.pointer : undefined;
  let message = serverMessage || `The server answered ${res.status} ${res.statusText}`.trim();
  if (res.status === 413) {
    message = 'The upload is too large for the server' + (serverMessage ? ` (${serverMessage}).` : '.');
  } else if (res.status === 401) {
    message = 'The server needs an access token' + (hasToken() ? ', and the one given was refused.' : '.');
  } else if (path && !message.startsWith(path)) {
    message = `${path}: ${message}`;
  }
  return new ApiError(message, { status: res.status, path, pointer });
}

async function request(method, url, { body, headers = {} } = {}) {
  for (let attempt = 0; ; attempt++) {
    let res;
    try {
      res = await fetch(BASE + url, { method, body, headers: { ...headers, ...authHeaders() } });
    } catch {
      throw new ApiError("The server can't be reached. Check that photon-server is running and try again.");
    }
    if (res.status === 401 && attempt === 0 && (await tokenAfter401())) continue;
    if (!res.ok) throw await errorFrom(res);
    return res;
  }
}

async function requestJson(method, url, options) {
  const res = await request(method, url, options);
  return res.status === 204 ? null : res.json();
}

function query(params) {
  const q = new URLSearchParams();
  for (const [key, value] of Object.entries(params)) {
    if (value !== undefined && value !== null && value !== '') q.set(key, String(value));
  }
  const text = q.toString();
  return text ? `?${text}` : '';
}

// ---- Job records ---------------------------------------------------------------------

function first(...values) {
  return values.find((v) => v !== undefined && v !== null);
}

function num(...values) {
  const v = first(...values);
  return typeof v === 'number' && Number.isFinite(v) ? v : null;
}

// The server's job record -> the names the page uses. Missing fields become null.
export function normalizeJob(raw) {
  const r = raw || {};
  const s = r.settings || {};
  const resolution = Array.isArray(s.resolution) ? s.resolution : [];
  const photonsTraced = num(r.photons_traced);
  const elapsedSeconds = num(r.elapsed_seconds, r.elapsed);
  let photonsPerSecond = num(r.photons_per_second);
  if (photonsPerSecond === null && photonsTraced !== null && elapsedSeconds > 0) {
    photonsPerSecond = photonsTraced / elapsedSeconds;
  }
  return {
    id: String(first(r.id, '')),
    name: typeof r.name === 'string' ? r.name : '',
    labels: Array.isArray(r.labels) ? r.labels.map(String) : [],
    status: String(first(r.status, 'unknown')),
    priority: num(r.priority),
    createdAt: first(r.created_at, null),
    updatedAt: first(r.updated_at, null),
    startedAt: first(r.started_at, null),
    finishedAt: first(r.finished_at, null),
    passesDone: num(r.pass, r.passes_done) ?? 0,
    passes: num(r.total_passes, s.passes, r.passes),
    photonsPerPass: num(s.photons_per_pass, r.photons_per_pass),
    seed: num(s.seed, r.seed),
    integrator: first(s.integrator, r.integrator, null),
    // Whether the scene asks for the denoiser, so its images have a raw layer; null from a
    // server whose record does not say (GET /jobs/{id}/scene has it).
    denoise: typeof s.denoise === 'boolean' ? s.denoise : null,
    // The earlier passes the server keeps images of (1, 2, 4, 8, ... and the latest),
    // ascending; null from a server that keeps none.
    keptPasses: Array.isArray(r.kept_passes) ? r.kept_passes.filter((p) => Number.isInteger(p) && p > 0) : null,
    width: num(resolution[0], r.width),
    height: num(resolution[1], r.height),
    photonsTraced,
    photonsPerSecond,
    meanRadius: num(r.mean_radius),
    elapsedSeconds,
    etaSeconds: num(r.eta_seconds, r.eta),
    // The image's estimated relative error and the scene's target (null: none).
    relativeError: num(r.relative_error),
    targetError: num(r.target_error),
    error: first(r.error, null),
    warnings: Array.isArray(r.warnings) ? r.warnings.map(String) : [],
    // The method's own figures (null where the method has none).
    figures: {
      samplesPerPixel: num(r.figures?.samples_per_pixel),
      patches: num(r.figures?.patches),
      solverIterations: num(r.figures?.solver_iterations),
      solverResidual: num(r.figures?.solver_residual),
      globalMapPhotons: num(r.figures?.global_map_photons),
      causticMapPhotons: num(r.figures?.caustic_map_photons),
    },
  };
}

export const FINAL_STATUSES = ['completed', 'failed', 'cancelled'];

export function isFinished(job) {
  return FINAL_STATUSES.includes(job.status);
}

// ---- Endpoints -----------------------------------------------------------------------

// status: statuses, comma-separated; name: a part of the name, in any case.
export async function listJobs({ status, name, limit = 50, offset } = {}) {
  const body = await requestJson('GET', `/jobs${query({ status, name, limit, offset })}`);
  const jobs = Array.isArray(body && body.jobs) ? body.jobs.map(normalizeJob) : [];
  return { jobs, total: num(body && body.total) ?? jobs.length };
}

// The render farm: { farm, queueDepth, workers: [{ name, host, threads, busy,
// passesPerSecond, batches, redeliveries }] }; farm is false when the server renders alone.
export async function getWorkers() {
  const body = await requestJson('GET', '/workers');
  const workers = Array.isArray(body && body.workers) ? body.workers : [];
  return {
    farm: Boolean(body && body.farm),
    queueDepth: num(body && body.queue_depth) ?? 0,
    workers: workers.map((w) => ({
      name: String(w.name ?? ''),
      host: String(w.host ?? ''),
      threads: num(w.threads) ?? 0,
      busy: Boolean(w.busy),
      job: w.job == null ? null : String(w.job),
      passesPerSecond: num(w.passes_per_second) ?? 0,
      batches: num(w.batches) ?? 0,
      redeliveries: num(w.redeliveries) ?? 0,
    })),
  };
}

export async function getJob(id) {
  return normalizeJob(await requestJson('GET', `/jobs/${encodeURIComponent(id)}`));
}

// sceneText: the scene JSON as text. assets: [{ file: File, path: 'meshes/x.obj' }].
// params: { passes, photons_per_pass, seed, target_error, priority }; empty values are left out.
// sceneFile: a scene file sent as it is (a .pbrt, .gltf or .glb the server imports) instead
// of sceneText; its name's extension tells the server its kind.
export async function submitJob({ sceneText, sceneFile = null, assets = [], params = {} }) {
  const url = `/jobs${query(params)}`;
  if (assets.length === 0 && !sceneFile) {
    const headers = { 'Content-Type': 'application/json' };
    return normalizeJob(await requestJson('POST', url, { body: sceneText, headers }));
  }
  const form = new FormData();
  if (sceneFile) form.append('scene', sceneFile, sceneFile.name);
  else form.append('scene', new Blob([sceneText], { type: 'application/json' }), 'scene.json');
  // The part name is fixed ('scene' is reserved); the filename carries the asset's path.
  for (const { file, path } of assets) form.append('asset', file, path);
  return normalizeJob(await requestJson('POST', url, { body: form }));
}

// The scene as submitted: { type (its Content-Type), text }.
export async function getScene(id) {
  const res = await request('GET', `/jobs/${encodeURIComponent(id)}/scene`);
  return { type: res.headers.get('Content-Type') || '', text: await res.text() };
}

export async function cancelJob(id) {
  return normalizeJob(await requestJson('POST', `/jobs/${encodeURIComponent(id)}/cancel`));
}

export async function deleteJob(id) {
  await request('DELETE', `/jobs/${encodeURIComponent(id)}`);
}

// The URL of the job's latest image (always the same: the server answers no-cache with an
// ETag, so a fetch revalidates and gets the newest pass). Options: `pass`, a kept earlier
// pass (the record's keptPasses; the server has no other passes); `size` ('64x64'), a
// thumbnail that fits in that box; `layer: 'raw'`, the image before the denoiser (jobs that
// denoise only); `exposure` (stops, PNG only), tone-mapped at that exposure instead of the
// render's own (null: the render's).
export function imageUrl(id, format = 'png', { pass = null, size = null, layer = null, exposure = null } = {}) {
  return `${BASE}/jobs/${encodeURIComponent(id)}/image${query({ format, pass, size, layer, exposure })}`;
}

// The image as a Blob, with the bearer token when there is one (an <img> or <a> cannot
// send headers). Resolves once the whole body has arrived, to { blob, pass }: pass is the
// pass the server sent (X-Photon-Pass; the latest encoded one, which may be older than the
// job's record says: it encodes a running job's image at most every 250 ms); null if not
// named. Options as for imageUrl().
export async function fetchImage(id, format = 'png', options = {}) {
  const res = await request('GET', imageUrl(id, format, options).slice(BASE.length));
  const blob = await res.blob();
  const sent = Number.parseInt(res.headers.get('X-Photon-Pass') ?? '', 10);
  return { blob, pass: Number.isFinite(sent) ? sent : null };
}

// Every job's changes (GET /api/v1/events), for the job list.
export function serviceEventsUrl() {
  return `${BASE}/events`;
}

export function eventsUrl(id) {
  return `${BASE}/jobs/${encodeURIComponent(id)}/events`;
}

// The job's progress history as the server keeps it (GET /jobs/{id}/progress: at most 256
// points, thinned evenly, kept across restarts), as records with the fields the plot reads
// (passesDone, elapsedSeconds, photonsTraced, meanRadius, relativeError). null when it cannot be had: a
// server without the route answers 404, and progressHistory() below replays the events.
export async function progressPoints(id) {
  let body;
  try {
    body = await requestJson('GET', `/jobs/${encodeURIComponent(id)}/progress`);
  } catch {
    return null;
  }
  if (!Array.isArray(body?.points)) return null;
  return body.points.map((p) => ({
    passesDone: num(p.pass) ?? 0,
    elapsedSeconds: num(p.elapsed_seconds),
    photonsTraced: num(p.photons_traced),
    meanRadius: num(p.mean_radius),
    relativeError: num(p.relative_error),
  }));
}

// The job's progress so far, for a plot that outlives a reload: the job's event stream read
// from its start (Last-Event-ID: 0 replays the events the server still keeps), as job
// records, until `untilPass` has been seen, the job's final event, or `timeoutMs`. fetch()
// rather than EventSource, which cannot send Last-Event-ID on its first connection.
export async function progressHistory(id, { untilPass, timeoutMs = 5000 } = {}) {
  const controller = new AbortController();
  const timer = setTimeout(() => controller.abort(), timeoutMs);
  const records = [];
  try {
    const res = await fetch(eventsUrl(id), {
      headers: { 'Last-Event-ID': '0', Accept: 'text/event-stream', ...authHeaders() },
      signal: controller.signal,
    });
    if (!res.ok || !res.body) return records;
    const reader = res.body.pipeThrough(new TextDecoderStream()).getReader();
    let buffered = '';
    for (;;) {
      const { value, done } = await reader.read();
      if (done) break;
      buffered += value.replace(/\r\n?/g, '\n');
      let end;
      while ((end = buffered.indexOf('\n\n')) >= 0) {
        const block = buffered.slice(0, end);
        buffered = buffered.slice(end + 2);
        const type = /^event: ?(.*)$/m.exec(block)?.[1] ?? 'message';
        const data = block.split('\n').filter((l) => l.startsWith('data:')).map((l) => l.slice(5).replace(/^ /, '')).join('\n');
        if (!data) continue;
        const job = normalizeJob(JSON.parse(data));
        records.push(job);
        if (type !== 'progress' || job.passesDone >= untilPass) return records;
      }
    }
    return records;
  } catch {
    return records; // cut short (timeout, network): what arrived is still history
  } finally {
    clearTimeout(timer);
    controller.abort();
  }
}

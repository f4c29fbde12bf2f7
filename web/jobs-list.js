// The job list: each job with its name (or id), method, size, passes, a thumbnail of its
// latest pass, its status and a progress bar; filtered by status and by a part of the name
// (the server filters the listing, the same test keeps events in line), and sorted.
//
// It stays current from GET /api/v1/events (every job's changes, each with the job record):
// the jobs are listed once when the stream is ready (or reset), then every event updates the
// list by itself, without asking the server again. Only without that stream (an old
// browser, the stream refused) does it poll GET /api/v1/jobs every 2 s. refresh() lists at
// once (after a submit, cancel or delete, or a change of filter). Rows are updated in
// place, so focus and clicks survive.

import { ensureSession, fetchImage, hasToken, isFinished, listJobs, normalizeJob, serviceEventsUrl, sessionLost } from './api.js';
import { formatPasses, formatTime, methodName, progressFraction } from './format.js';

const POLL_MS = 2000;
// Events closer together than this are drawn once.
const DRAW_MS = 100;
// A running job's thumbnail is fetched again at most this often (and once more at its end).
const THUMBNAIL_MS = 3000;
const THUMBNAIL_BOX = '48x48';
const RECORD_EVENTS = ['changed', 'progress', 'done', 'failed', 'cancelled'];
const PAGE_SIZE = 100;

const STATUS_ORDER = ['running', 'paused', 'queued', 'failed', 'cancelled', 'completed'];

// How the list can be sorted: the select's values -> a comparison of two jobs.
const byCreated = (a, b) => String(b.createdAt ?? '').localeCompare(String(a.createdAt ?? '')) || b.id.localeCompare(a.id);
export const SORTS = {
  newest: byCreated,
  oldest: (a, b) => byCreated(b, a),
  name: (a, b) => (a.name || a.id).localeCompare(b.name || b.id, undefined, { sensitivity: 'base' }) || byCreated(a, b),
  status: (a, b) => STATUS_ORDER.indexOf(a.status) - STATUS_ORDER.indexOf(b.status) || byCreated(a, b),
  progress: (a, b) => progressFraction(b.passesDone, b.passes) - progressFraction(a.passesDone, a.passes) || byCreated(a, b),
};

export function createJobsList({ list, status, filters, onSelect, onConnection }) {
  const rows = new Map(); // id -> { item, button, parts, thumbPass, thumbAt, thumbTimer }
  const jobs = new Map(); // id -> job: the jobs that match the filter, as last heard of
  let total = 0; // jobs matching the filter on the server (the listing's total, kept up by events)
  let selectedId = null;
  let timer = null;
  let inFlight = null;
  let again = false;
  let streaming = false; // the event stream is open
  let heardDuringListing = null; // events that arrived while a listing was on its way
  let drawTimer = null;

  function filter() {
    return { status: filters.status.value, name: filters.name.value.trim() };
  }

  function matches(job) {
    const { status: wanted, name } = filter();
    return (!wanted || job.status === wanted) && (!name || job.name.toLowerCase().includes(name.toLowerCase()));
  }

  function makeRow(id) {
    const item = document.createElement('li');
    item.dataset.jobId = id;
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'job-row';
    button.dataset.jobId = id;
    const thumb = document.createElement('img');
    thumb.className = 'job-thumb';
    thumb.alt = '';
    thumb.width = 48;
    thumb.height = 48;
    thumb.hidden = true;
    // A thumbnail that cannot be had (no session for a token) is left out, not shown broken.
    thumb.addEventListener('error', () => {
      thumb.hidden = true;
    });
    const title = document.createElement('span');
    title.className = 'job-row-title';
    const badge = document.createElement('span');
    badge.className = 'status-badge';
    const detail = document.createElement('span');
    detail.className = 'job-row-detail';
    const bar = document.createElement('progress');
    bar.max = 1;
    bar.setAttribute('aria-label', `Passes done, job ${id}`);
    button.append(thumb, title, badge, detail, bar);
    button.addEventListener('click', () => onSelect(id));
    item.append(button);
    return { item, button, parts: { thumb, title, badge, detail, bar }, thumbPass: 0, thumbAt: 0, thumbTimer: null, thumbUrl: null };
  }

  // The thumbnail follows the passes, but a running job's at most every THUMBNAIL_MS.
  function updateThumbnail(row, job) {
    const { thumb } = row.parts;
    clearTimeout(row.thumbTimer);
    if (job.passesDone <= 0 || job.passesDone === row.thumbPass) return;
    const wait = isFinished(job) ? 0 : row.thumbAt + THUMBNAIL_MS - Date.now();
    if (wait > 0) {
      row.thumbTimer = setTimeout(() => updateThumbnail(row, jobs.get(job.id) ?? job), wait);
      return;
    }
    row.thumbPass = job.passesDone;
    row.thumbAt = Date.now();
    loadThumbnail(row, job);
  }

  // Fetched (the latest image's URL stays the same from pass to pass, and an <img> would not
  // load it again), with the token when there is one, and shown once whole.
  async function loadThumbnail(row, job) {
    const { thumb } = row.parts;
    try {
      const { blob, pass } = await fetchImage(job.id, 'png', { size: THUMBNAIL_BOX });
      if (rows.get(job.id) !== row) return; // the row was removed meanwhile
      const url = URL.createObjectURL(blob);
      if (row.thumbUrl) URL.revokeObjectURL(row.thumbUrl);
      row.thumbUrl = url;
      thumb.dataset.pass = String(pass ?? job.passesDone);
      thumb.src = url;
      thumb.alt = `Job ${job.name || job.id} after pass ${pass ?? job.passesDone}`;
      thumb.hidden = false;
    } catch {
      // Left out, not shown broken (no token, the job deleted meanwhile); the next pass retries.
    }
  }

  function updateRow(row, job) {
    const { title, badge, detail, bar } = row.parts;
    title.textContent = job.name || job.id;
    title.title = job.name ? `${job.name} (${job.id})` : job.id;
    badge.textContent = job.status;
    badge.dataset.status = job.status;
    row.item.dataset.status = job.status;
    const parts = [methodName(job.integrator)];
    if (job.denoise) parts.push('denoised');
    if (job.width && job.height) parts.push(`${job.width}×${job.height}`);
    parts.push(`pass ${formatPasses(job.passesDone, job.passes)}`);
    parts.push(formatTime(job.createdAt));
    detail.textContent = parts.join(' · ');
    bar.value = progressFraction(job.passesDone, job.passes);
    row.button.setAttribute('aria-current', job.id === selectedId ? 'true' : 'false');
    updateThumbnail(row, job);
  }

  function draw() {
    clearTimeout(drawTimer);
    drawTimer = null;
    const sorted = [...jobs.values()].sort(SORTS[filters.sort.value] ?? SORTS.newest).slice(0, PAGE_SIZE);
    const seen = new Set();
    sorted.forEach((job, index) => {
      seen.add(job.id);
      let row = rows.get(job.id);
      if (!row) {
        row = makeRow(job.id);
        rows.set(job.id, row);
      }
      updateRow(row, job);
      if (list.children[index] !== row.item) list.insertBefore(row.item, list.children[index] || null);
    });
    for (const [id, row] of rows) {
      if (!seen.has(id)) {
        clearTimeout(row.thumbTimer);
        if (row.thumbUrl) URL.revokeObjectURL(row.thumbUrl);
        row.item.remove();
        rows.delete(id);
      }
    }
    const filtered = filter().status !== '' || filter().name !== '';
    if (sorted.length === 0) status.textContent = filtered ? 'No jobs match.' : 'No jobs yet.';
    else if (total > sorted.length) status.textContent = `Showing ${sorted.length} of ${total} jobs.`;
    else status.textContent = `${total} job${total === 1 ? '' : 's'}${filtered ? ' match' + (total === 1 ? 'es' : '') : ''}.`;
  }

  function drawSoon() {
    if (!drawTimer) drawTimer = setTimeout(draw, DRAW_MS);
  }

  // One event of the stream: a job record (or { id } for a deletion) put into the list.
  function hear(type, data) {
    if (type === 'deleted') {
      if (jobs.delete(data.id)) total = Math.max(0, total - 1);
      return;
    }
    const job = normalizeJob(data);
    if (!job.id) return;
    const known = jobs.get(job.id);
    // Events and a listing can cross: never step back to an older state.
    if (known && known.updatedAt && job.updatedAt && job.updatedAt < known.updatedAt) return;
    if (matches(job)) {
      if (!known) total++;
      jobs.set(job.id, job);
    } else if (known) {
      jobs.delete(job.id);
      total = Math.max(0, total - 1);
    }
  }

  async function fetchList() {
    clearTimeout(timer);
    heardDuringListing = [];
    try {
      const answer = await listJobs({ ...filter(), limit: PAGE_SIZE });
      jobs.clear();
      for (const job of answer.jobs) jobs.set(job.id, job);
      total = answer.total;
      // What the stream said meanwhile may be newer than the listing.
      for (const [type, data] of heardDuringListing) hear(type, data);
      draw();
      onConnection(null);
    } catch (error) {
      onConnection(error);
    } finally {
      heardDuringListing = null;
    }
    if (!streaming) timer = setTimeout(refresh, POLL_MS);
  }

  function onEvent(event) {
    let data;
    try {
      data = JSON.parse(event.data);
    } catch {
      refresh(); // a malformed event: list again
      return;
    }
    if (heardDuringListing) heardDuringListing.push([event.type, data]);
    hear(event.type, data);
    drawSoon();
  }

  async function subscribe() {
    if (typeof EventSource !== 'function') return;
    // With a token the stream is authorised by the session cookie the token was traded for.
    if (hasToken() && !(await ensureSession())) return;
    const source = new EventSource(serviceEventsUrl());
    for (const type of [...RECORD_EVENTS, 'deleted']) source.addEventListener(type, onEvent);
    // Connected (or reconnected too late for the changes missed): list, then follow events.
    // data-following on the list says how it stays current ("events" or "polling").
    for (const type of ['ready', 'reset']) {
      source.addEventListener(type, () => refresh().then(() => {
        if (streaming) list.dataset.following = 'events';
      }));
    }
    source.addEventListener('open', () => {
      streaming = true;
      clearTimeout(timer);
    });
    source.addEventListener('error', () => {
      // CONNECTING: the browser retries by itself (and 'ready' lists again). CLOSED: refused
      // (a 401, 503): poll, and try the stream again later.
      if (source.readyState !== EventSource.CLOSED) return;
      streaming = false;
      list.dataset.following = 'polling';
      sessionLost();
      setTimeout(subscribe, 30_000);
      refresh();
    });
  }

  // Fetch now; a call during a fetch queues exactly one more.
  function refresh() {
    if (inFlight) {
      again = true;
      return inFlight;
    }
    inFlight = fetchList().finally(() => {
      inFlight = null;
      if (again) {
        again = false;
        refresh();
      }
    });
    return inFlight;
  }

  // A job changed through this page (submitted, finished, cancelled, deleted). The event
  // stream brings the change to the list by itself; a listing then would only repeat it.
  // Without a stream, list again now.
  function changed() {
    if (!streaming) refresh();
  }

  function setSelected(id) {
    selectedId = id;
    for (const [rowId, row] of rows) row.button.setAttribute('aria-current', rowId === id ? 'true' : 'false');
  }

  let typing = null;
  filters.name.addEventListener('input', () => {
    clearTimeout(typing);
    typing = setTimeout(refresh, 250);
  });
  filters.status.addEventListener('change', () => {
    clearTimeout(typing); // this listing has the name typed so far as well
    refresh();
  });
  filters.sort.addEventListener('change', () => draw());

  subscribe();
  return { refresh, changed, setSelected };
}

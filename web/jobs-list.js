// The job list: newest first, each job with its status and a progress bar (passes done /
// passes). Follows GET /api/v1/events (every job's changes) and lists the jobs again after
// each burst of changes; without that stream (an old browser, the stream refused) it polls
// GET /api/v1/jobs every 2 s. It also lists at once when refresh() is called (after a
// submit, cancel or delete). Rows are updated in place, so focus and clicks survive.

import { ensureSession, hasToken, listJobs, serviceEventsUrl, sessionLost } from './api.js';
import { formatPasses, formatTime, progressFraction } from './format.js';

const POLL_MS = 2000;
// With the event stream open, polling is only a safety net.
const SAFETY_POLL_MS = 30_000;
// Changes closer together than this are listed once.
const BURST_MS = 250;
const EVENT_TYPES = ['ready', 'changed', 'progress', 'done', 'failed', 'cancelled', 'deleted', 'reset'];
const PAGE_SIZE = 100;

export function createJobsList({ list, status, onSelect, onConnection }) {
  const rows = new Map(); // id -> { item, button, parts }
  let selectedId = null;
  let timer = null;
  let inFlight = null;
  let again = false;
  let streaming = false; // the event stream is open
  let burst = null;

  function makeRow(id) {
    const item = document.createElement('li');
    item.dataset.jobId = id;
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'job-row';
    button.dataset.jobId = id;
    const title = document.createElement('span');
    title.className = 'job-row-title';
    const badge = document.createElement('span');
    badge.className = 'status-badge';
    const detail = document.createElement('span');
    detail.className = 'job-row-detail';
    const bar = document.createElement('progress');
    bar.max = 1;
    bar.setAttribute('aria-label', `Passes done, job ${id}`);
    button.append(title, badge, detail, bar);
    button.addEventListener('click', () => onSelect(id));
    item.append(button);
    return { item, button, parts: { title, badge, detail, bar } };
  }

  function updateRow(row, job) {
    const { title, badge, detail, bar } = row.parts;
    title.textContent = job.id;
    badge.textContent = job.status;
    badge.dataset.status = job.status;
    row.item.dataset.status = job.status;
    const size = job.width && job.height ? `${job.width}×${job.height}, ` : '';
    detail.textContent = `${size}pass ${formatPasses(job.passesDone, job.passes)} · ${formatTime(job.createdAt)}`;
    bar.value = progressFraction(job.passesDone, job.passes);
    row.button.setAttribute('aria-current', job.id === selectedId ? 'true' : 'false');
  }

  function render({ jobs, total }) {
    const seen = new Set();
    jobs.forEach((job, index) => {
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
        row.item.remove();
        rows.delete(id);
      }
    }
    if (jobs.length === 0) status.textContent = 'No jobs yet.';
    else if (total > jobs.length) status.textContent = `Showing the newest ${jobs.length} of ${total} jobs.`;
    else status.textContent = `${total} job${total === 1 ? '' : 's'}.`;
  }

  async function poll() {
    clearTimeout(timer);
    try {
      render(await listJobs({ limit: PAGE_SIZE }));
      onConnection(null);
    } catch (error) {
      onConnection(error);
    }
    timer = setTimeout(refresh, streaming ? SAFETY_POLL_MS : POLL_MS);
  }

  function onChange() {
    if (burst) return;
    burst = setTimeout(() => {
      burst = null;
      refresh();
    }, BURST_MS);
  }

  async function subscribe() {
    if (typeof EventSource !== 'function') return;
    // With a token the stream is authorised by the session cookie the token was traded for.
    if (hasToken() && !(await ensureSession())) return;
    const source = new EventSource(serviceEventsUrl());
    for (const type of EVENT_TYPES) source.addEventListener(type, onChange);
    source.addEventListener('open', () => {
      streaming = true;
    });
    source.addEventListener('error', () => {
      // CONNECTING: the browser retries by itself. CLOSED: refused (a 401, 503): poll, and
      // try the stream again later.
      if (source.readyState !== EventSource.CLOSED) return;
      streaming = false;
      sessionLost();
      setTimeout(subscribe, SAFETY_POLL_MS);
      refresh();
    });
  }

  // Fetch now; a call during a fetch queues exactly one more.
  function refresh() {
    if (inFlight) {
      again = true;
      return inFlight;
    }
    inFlight = poll().finally(() => {
      inFlight = null;
      if (again) {
        again = false;
        refresh();
      }
    });
    return inFlight;
  }

  function setSelected(id) {
    selectedId = id;
    for (const [rowId, row] of rows) row.button.setAttribute('aria-current', rowId === id ? 'true' : 'false');
  }

  subscribe();
  return { refresh, setSelected };
}

// The render farm's workers (photon-server --redis): who is alive, what each is doing and how
// fast, and the farm's queue. Polled every few seconds; the panel stays hidden when the
// server renders alone or cannot be asked.

import { getWorkers } from './api.js';

const POLL_MS = 5000;

function cell(text) {
  const td = document.createElement('td');
  td.textContent = text;
  return td;
}

export function createWorkersPanel({ section, summary, rows }) {
  async function refresh() {
    let farm;
    try {
      farm = await getWorkers();
    } catch {
      section.hidden = true;
      return;
    }
    section.hidden = !farm.farm;
    if (!farm.farm) return;
    const busy = farm.workers.filter((w) => w.busy).length;
    summary.textContent = `${farm.workers.length} worker${farm.workers.length === 1 ? '' : 's'}, ${busy} rendering; ` +
      `${farm.queueDepth} item${farm.queueDepth === 1 ? '' : 's'} queued or in progress.`;
    rows.replaceChildren(...farm.workers.map((w) => {
      const tr = document.createElement('tr');
      tr.append(cell(w.name), cell(w.host), cell(String(w.threads)), cell(w.busy ? (w.job ? `job ${w.job}` : 'rendering') : 'idle'),
        cell(w.passesPerSecond.toFixed(2)), cell(String(w.batches)), cell(String(w.redeliveries)));
      return tr;
    }));
  }
  refresh();
  const timer = setInterval(refresh, POLL_MS);
  return { refresh, stop: () => clearInterval(timer) };
}

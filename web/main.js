// Wires the page together: the submit form, the job list and the job view, the token
// question, and the address bar (#job=<id> opens that job, so a reload keeps the view).

import { allowTokenQuestion, onTokenNeeded } from './api.js';
import { createJobView } from './job-view.js';
import { createJobsList } from './jobs-list.js';
import { createSubmitForm } from './submit-form.js';
import { createTokenForm } from './token-form.js';
import { createWorkersPanel } from './workers-panel.js';

const $ = (id) => document.getElementById(id);

function jobIdFromHash() {
  const match = /^#job=([^&]+)$/.exec(window.location.hash);
  return match ? decodeURIComponent(match[1]) : null;
}

function start() {
  onTokenNeeded(createTokenForm($('token-dialog')));
  const serverStatus = $('server-status');
  const tokenButton = $('token-button');

  const jobs = createJobsList({
    list: $('job-list'),
    status: $('job-list-status'),
    filters: { name: $('job-search'), status: $('job-status-filter'), sort: $('job-sort') },
    onSelect: (id) => openJob(id),
    onConnection: (error) => {
      serverStatus.textContent = error ? error.message : '';
      serverStatus.classList.toggle('error', Boolean(error));
      tokenButton.hidden = !(error && error.status === 401);
    },
  });
  tokenButton.addEventListener('click', () => {
    allowTokenQuestion();
    jobs.refresh();
  });

  const view = createJobView({
    onChanged: () => jobs.changed(),
    onDeleted: (id) => {
      jobs.setSelected(null);
      if (jobIdFromHash() === id) history.replaceState(null, '', window.location.pathname);
    },
  });

  function openJob(id) {
    jobs.setSelected(id);
    if (jobIdFromHash() !== id) history.pushState(null, '', `#job=${encodeURIComponent(id)}`);
    if (view.currentId() !== id) view.open(id);
  }

  createSubmitForm({
    onSubmitted: (job) => {
      openJob(job.id);
      // On a phone the job view is below the form: bring it up to follow the new job.
      if (window.matchMedia('(max-width: 700px)').matches) $('job-view').scrollIntoView({ block: 'start' });
      jobs.changed();
    },
  });

  window.addEventListener('popstate', () => {
    const id = jobIdFromHash();
    if (id) openJob(id);
  });

  const initial = jobIdFromHash();
  if (initial) openJob(initial);
  jobs.refresh();
  createWorkersPanel({ section: $('workers-panel'), summary: $('workers-summary'), rows: $('workers-rows') });
}

start();

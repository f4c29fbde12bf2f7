// The compare view of the job's image: another image of the same size laid over it, shown
// right of a vertical divider that can be dragged (or moved with the arrow keys), the job's
// own image left of it. The other image is an earlier pass the server kept of this job
// (GET /jobs/{id}/image?pass=N, listed by the record's kept_passes) or another job of the
// same resolution. It is zoomed and panned with the job's image (the viewport transforms
// both) and asked for with the same settings (exposure), loaded whole like the preview.
//
// createCompareView({ frame, select, layer, image, divider, leftLabel, rightLabel, settings,
//   onError }):
//   settings()  -> the options of fetchImage (api.js) the job's image is shown with.
// Returns { open(job), update(job), reload(), refreshChoices(), choice(), split(), setSplit(f) }.

import { fetchImage, listJobs } from './api.js';
import { formatPasses } from './format.js';
import { createPreviewLoader } from './preview-loader.js';

const KEY_STEP = 0.01;
const PAGE_STEP = 0.1;
const MAX_OTHER_JOBS = 100;

export function createCompareView({ frame, select, layer, image, divider, leftLabel, rightLabel, settings, onError }) {
  let job = null; // the job on show
  let others = []; // other jobs of its size: [{ id, name, passesDone }]
  let chosen = ''; // the select's value: '', 'pass:N' or 'job:ID'
  let loader = null; // loads the chosen image
  let split = 0.5; // the divider's place, a fraction of the frame's width
  let listing = 0; // counts listings, so that an old answer does not overwrite a newer one

  // The clip and the divider follow the frame's width (a resized window keeps the fraction),
  // on a whole device pixel: a sharp edge between the two images.
  function place() {
    const dpr = window.devicePixelRatio || 1;
    const at = Math.round(split * frame.clientWidth * dpr) / dpr;
    layer.style.clipPath = `inset(0px 0px 0px ${at}px)`;
    divider.style.left = `${at}px`;
    divider.setAttribute('aria-valuenow', String(Math.round(split * 100)));
    divider.dataset.split = String(split);
  }

  function setSplit(fraction) {
    split = Math.min(1, Math.max(0, fraction));
    place();
  }

  function option(value, text) {
    const item = document.createElement('option');
    item.value = value;
    item.textContent = text;
    return item;
  }

  function group(label, items) {
    const g = document.createElement('optgroup');
    g.label = label;
    g.append(...items);
    return g;
  }

  // The choices: the passes the server kept of this job, and the other jobs of its size.
  function fillSelect() {
    const kept = (job?.keptPasses ?? []).map((pass) => option(`pass:${pass}`, `pass ${pass}`));
    const jobs = others.map((other) =>
      option(`job:${other.id}`, `${other.name || other.id} (${formatPasses(other.passesDone, other.passes)})`));
    const groups = [];
    if (kept.length) groups.push(group('Passes of this job', kept));
    if (jobs.length) groups.push(group(`Other jobs of ${job.width} × ${job.height}`, jobs));
    select.replaceChildren(option('', 'nothing'), ...groups);
    // A choice that is gone (a job deleted) is let go.
    if (chosen && ![...select.options].some((o) => o.value === chosen)) choose('');
    select.value = chosen;
  }

  async function refreshChoices() {
    if (!job) return;
    const asked = ++listing;
    const forJob = job;
    try {
      const { jobs } = await listJobs({ limit: MAX_OTHER_JOBS });
      if (asked !== listing || job !== forJob) return;
      others = jobs.filter((other) => other.id !== forJob.id && other.passesDone > 0 &&
        other.width === forJob.width && other.height === forJob.height);
    } catch {
      // The list stays as it was; the next focus asks again.
    }
    if (asked === listing && job === forJob) fillSelect();
  }

  // What each side shows, with "raw" where the raw layer is shown and "error" where the
  // error map is.
  function labels() {
    const layer = settings().layer;
    const suffix = (j) => (layer === 'raw' && j?.denoise ? ', raw' : layer === 'error' && j?.relativeError != null ? ', error' : '');
    leftLabel.textContent = job ? `this job, pass ${job.passesDone}${suffix(job)}` : '';
    if (chosen.startsWith('pass:')) {
      rightLabel.textContent = `pass ${chosen.slice(5)}${suffix(job)}`;
    } else if (chosen.startsWith('job:')) {
      const other = others.find((o) => o.id === chosen.slice(4));
      rightLabel.textContent = (other ? other.name || other.id : chosen.slice(4)) + suffix(other);
    }
  }

  function choose(value) {
    chosen = value;
    if (loader) loader.stop();
    loader = null;
    const on = Boolean(chosen);
    for (const element of [layer, divider, leftLabel, rightLabel]) element.hidden = !on;
    frame.classList.toggle('comparing', on);
    image.removeAttribute('src');
    delete image.dataset.pass;
    delete image.dataset.job;
    if (!on) return;
    const [kind, key] = [chosen.slice(0, chosen.indexOf(':')), chosen.slice(chosen.indexOf(':') + 1)];
    const id = kind === 'pass' ? job.id : key;
    const target = kind === 'pass' ? job : others.find((o) => o.id === key);
    const pass = kind === 'pass' ? Number(key) : target?.passesDone ?? 1;
    image.dataset.job = id;
    // The raw layer of a job that has none would be refused (400), the error map of a job
    // without an estimate too (404): its image instead. A kept first pass has no error map
    // either, and says so.
    const optionsFor = () => {
      const options = settings();
      if (options.layer === 'error') return target?.relativeError != null ? options : { ...options, layer: null };
      return target?.denoise === true ? options : { ...options, layer: null };
    };
    loader = createPreviewLoader({
      img: image,
      // A kept pass by its number; another job's latest image (the pass its record named).
      load: () => fetchImage(id, 'png', kind === 'pass' ? { ...optionsFor(), pass } : optionsFor()),
      onShown: () => labels(),
      onError,
    });
    loader.want(pass);
    labels();
    place();
  }

  select.addEventListener('change', () => choose(select.value));
  // Jobs finish and come while the page is open: the list is made anew when it is opened
  // (so the select stays enabled with "nothing" alone: it can be opened and refilled).
  select.addEventListener('focus', () => refreshChoices());
  select.addEventListener('pointerdown', () => refreshChoices());

  let dragging = null;
  divider.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    event.preventDefault();
    event.stopPropagation(); // the divider moves; the image does not pan
    dragging = event.pointerId;
    divider.setPointerCapture(event.pointerId);
    divider.focus({ preventScroll: true });
  });
  divider.addEventListener('pointermove', (event) => {
    if (event.pointerId !== dragging) return;
    const rect = frame.getBoundingClientRect();
    setSplit((event.clientX - rect.left - frame.clientLeft) / frame.clientWidth);
  });
  const stop = (event) => {
    if (event.pointerId === dragging) dragging = null;
  };
  divider.addEventListener('pointerup', stop);
  divider.addEventListener('pointercancel', stop);
  divider.addEventListener('keydown', (event) => {
    const moves = {
      ArrowLeft: split - KEY_STEP, ArrowRight: split + KEY_STEP,
      PageDown: split - PAGE_STEP, PageUp: split + PAGE_STEP, Home: 0, End: 1,
    };
    if (!(event.key in moves)) return;
    event.preventDefault();
    event.stopPropagation(); // not the frame's keys (arrows pan there)
    // Whole percents, so that steps do not gather rounding errors.
    setSplit(Math.round(moves[event.key] * 100) / 100);
  });
  new ResizeObserver(place).observe(frame);

  return {
    // Another job: nothing compared, its own choices.
    open(next) {
      job = next;
      others = [];
      choose('');
      split = 0.5;
      fillSelect();
      refreshChoices();
    },
    // A new state of the same job: its kept passes may have grown.
    update(next) {
      const before = (job?.keptPasses ?? []).join();
      job = next;
      if ((next.keptPasses ?? []).join() !== before) fillSelect();
      if (chosen) labels();
    },
    // The settings changed (exposure): the chosen image again, with them.
    reload() {
      if (loader) loader.reload();
      if (chosen) labels();
    },
    refreshChoices,
    choice: () => chosen,
    split: () => split,
    setSplit,
    select: (value) => {
      select.value = value;
      choose(select.value);
    },
  };
}

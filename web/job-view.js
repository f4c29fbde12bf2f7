// The job view: latest image (preview-loader.js: whole images only, one load at a time),
// zoomed and panned in its frame (image-viewport.js), at the exposure chosen
// (exposure-control.js), raw or denoised, compared with a kept pass or another job
// (compare-view.js); progress numbers (those the job's method has), the progress plot
// (progress-plot.js, with the passes before a reload from the server's progress history or
// its kept events), Cancel, Delete and downloads. Follows the job with Server-Sent Events (with a token, authorised by the session
// cookie the token was traded for: EventSource cannot send headers); when the stream fails
// for good, it polls GET /jobs/{id} every second.

import {
  cancelJob,
  deleteJob,
  ensureSession,
  eventsUrl,
  fetchImage,
  getJob,
  getScene,
  hasToken,
  imageUrl,
  isFinished,
  normalizeJob,
  progressHistory,
  progressPoints,
  sessionLost,
} from './api.js';
import {
  formatCount,
  formatDuration,
  formatPasses,
  formatPhotonsPerPass,
  formatRadius,
  formatRelativeError,
  formatRate,
  formatTime,
  methodName,
  progressFraction,
} from './format.js';
import { createCompareView } from './compare-view.js';
import { createExposureControl } from './exposure-control.js';
import { createImageViewport } from './image-viewport.js';
import { createPreviewLoader } from './preview-loader.js';
import { formatTick, ProgressPlot, seriesFor } from './progress-plot.js';

const POLL_MS = 1000;
const EVENT_TYPES = ['progress', 'done', 'failed', 'cancelled'];

const $ = (id) => document.getElementById(id);

export function createJobView({ onChanged, onDeleted }) {
  const el = {
    empty: $('job-empty'),
    details: $('job-details'),
    id: $('job-id'),
    image: $('job-image'),
    frame: $('image-frame'),
    placeholder: $('job-image-placeholder'),
    status: $('job-status'),
    pass: $('job-pass'),
    rate: $('job-rate'),
    radius: $('job-radius'),
    photons: $('job-photons'),
    elapsed: $('job-elapsed'),
    eta: $('job-eta'),
    resolution: $('job-resolution'),
    photonsPerPass: $('job-photons-per-pass'),
    seed: $('job-seed'),
    integrator: $('job-integrator'),
    denoise: $('job-denoise'),
    passRate: $('job-pass-rate'),
    statRate: $('stat-rate'),
    statRadius: $('stat-radius'),
    statPhotons: $('stat-photons'),
    statPhotonsPerPass: $('stat-photons-per-pass'),
    statSamples: $('stat-samples'),
    samples: $('job-samples'),
    statPatches: $('stat-patches'),
    patches: $('job-patches'),
    statResidual: $('stat-residual'),
    residual: $('job-residual'),
    statMaps: $('stat-maps'),
    statRelativeError: $('stat-relative-error'),
    relativeError: $('job-relative-error'),
    maps: $('job-maps'),
    created: $('job-created'),
    progress: $('job-progress'),
    error: $('job-error'),
    warnings: $('job-warnings'),
    warningList: $('job-warning-list'),
    actionError: $('job-action-error'),
    cancel: $('cancel-button'),
    remove: $('delete-button'),
    png: $('download-png'),
    exr: $('download-exr'),
  };
  const plot = new ProgressPlot($('progress-plot'));
  let session = null; // the job on show: { id, job, source, timer, preview }

  const viewport = createImageViewport({ frame: el.frame, images: [el.image, $('compare-image')], zoomLabel: $('zoom-level') });
  $('zoom-in').addEventListener('click', () => viewport.zoomIn());
  $('zoom-out').addEventListener('click', () => viewport.zoomOut());
  $('zoom-fit').addEventListener('click', () => viewport.fit());
  $('zoom-one').addEventListener('click', () => viewport.oneToOne());
  // A new pass has the size of the last one, so the zoom stays; another job's may differ.
  el.image.addEventListener('load', () => viewport.setImageSize(el.image.naturalWidth, el.image.naturalHeight));

  // The image at another exposure: the pass on show is loaded again, once, with it.
  const exposure = createExposureControl({
    slider: $('exposure'),
    label: $('exposure-value'),
    reset: $('exposure-reset'),
    onChange: () => settingsChanged(),
  });

  // Another image over the job's, split by a divider: an earlier pass, another job.
  const compare = createCompareView({
    frame: el.frame,
    select: $('compare-select'),
    layer: $('compare-layer'),
    image: $('compare-image'),
    divider: $('compare-divider'),
    leftLabel: $('compare-left-label'),
    rightLabel: $('compare-right-label'),
    settings: () => imageSettings(),
    onError: (error) => {
      if (session) el.actionError.textContent = `The image to compare with could not be loaded: ${error.message}`;
    },
  });

  // A job that denoises has a raw layer too: the image before the denoiser; a job whose
  // method estimates its error has the error heat map (from pass 2 on).
  const layerChoice = $('layer-choice');
  const rawLayer = $('layer-raw');
  const errorLayer = $('layer-error');
  for (const radio of layerChoice.querySelectorAll('input')) {
    radio.addEventListener('change', () => settingsChanged());
  }

  function showLayerChoice(job) {
    const raw = job.denoise === true;
    const error = job.relativeError !== null;
    $('layer-raw-choice').hidden = !raw;
    $('layer-error-choice').hidden = !error;
    $('layer-denoised-label').textContent = raw ? 'Denoised' : 'Image';
    layerChoice.hidden = !raw && !error;
    if ((rawLayer.checked && !raw) || (errorLayer.checked && !error)) $('layer-denoised').checked = true;
  }

  // Another exposure or layer: the images on show are loaded again with it (the frame says it
  // is busy until the job's is in), and the PNG download follows.
  function settingsChanged() {
    if (!session) return;
    if (session.preview.shownPass() > 0) el.frame.setAttribute('aria-busy', 'true');
    session.preview.reload();
    compare.reload();
    if (session.job) setDownload(el.png, session.id, 'png', session.job.passesDone > 0);
  }

  // What the job's image is asked for with: the layer (raw, error, or null for the image
  // itself) and the exposure chosen (null: the render's; the error map has none, its
  // colours are a scale).
  function imageSettings() {
    if (!layerChoice.hidden && errorLayer.checked) return { layer: 'error', exposure: null };
    return { layer: !layerChoice.hidden && rawLayer.checked ? 'raw' : null, exposure: exposure.value() };
  }

  function showMessage(text) {
    el.details.hidden = true;
    el.empty.hidden = false;
    el.empty.textContent = text;
    el.id.textContent = '';
  }

  // What the server accepted with a change (an import's approximations, unused files).
  function showWarnings(warnings) {
    el.warnings.hidden = warnings.length === 0;
    el.warningList.replaceChildren(
      ...warnings.map((text) => {
        const item = document.createElement('li');
        item.textContent = text;
        return item;
      }),
    );
  }

  function setDownload(link, id, format, ready) {
    if (ready) {
      // The PNG as shown: at the exposure chosen.
      link.href = imageUrl(id, format, format === 'png' ? imageSettings() : {});
      link.download = `photon-${id}.${format}`;
      link.removeAttribute('aria-disabled');
    } else {
      link.removeAttribute('href');
      link.setAttribute('aria-disabled', 'true');
    }
  }

  // The preview of a session's job: images follow the passes one complete image at a time.
  function previewFor(s) {
    return createPreviewLoader({
      img: el.image,
      // The latest image: the loader asks again while the server's is older than `pass`.
      load: () => fetchImage(s.id, 'png', imageSettings()),
      onShown: (pass) => {
        if (session !== s) return;
        el.image.alt = `Image of job ${s.id} after pass ${pass}`;
        el.image.hidden = false;
        el.frame.hidden = false;
        el.frame.removeAttribute('aria-busy');
        el.placeholder.hidden = true;
      },
      onError: (error) => {
        if (session !== s) return;
        el.frame.removeAttribute('aria-busy');
        el.actionError.textContent = `The image could not be loaded: ${error.message}`;
      },
    });
  }

  function render(job) {
    el.status.textContent = job.status;
    el.status.dataset.status = job.status;
    el.pass.textContent = formatPasses(job.passesDone, job.passes);
    el.rate.textContent = formatRate(job.photonsPerSecond);
    el.radius.textContent = formatRadius(job.meanRadius);
    el.statRelativeError.hidden = job.relativeError === null;
    el.relativeError.textContent = formatRelativeError(job.relativeError, job.targetError);
    el.photons.textContent = formatCount(job.photonsTraced);
    el.elapsed.textContent = formatDuration(job.elapsedSeconds);
    el.eta.textContent = job.status === 'running' && job.passesDone > 0 ? formatDuration(job.etaSeconds) : '—';
    el.resolution.textContent = job.width && job.height ? `${job.width} × ${job.height}` : '—';
    el.seed.textContent = job.seed ?? '—';
    el.integrator.textContent = methodName(job.integrator);
    if (job.denoise !== null) el.denoise.textContent = job.denoise ? 'on' : 'off';
    el.passRate.textContent = job.elapsedSeconds > 0 && job.passesDone > 0
      ? `${formatTick(job.passesDone / job.elapsedSeconds)}/s` : '—';
    // Only the figures the method has: the path tracer and radiosity trace no photons (the
    // record says 0), and only SPPM has a gather radius and a photon count per pass.
    const photons = job.integrator === 'sppm' || job.integrator === 'photonmap';
    el.statRate.hidden = !photons;
    el.statPhotons.hidden = !photons;
    el.statRadius.hidden = job.integrator !== 'sppm';
    el.statPhotonsPerPass.hidden = job.integrator !== 'sppm';
    // The method's own figures, as the record gives them (absent: hidden).
    const f = job.figures;
    el.statSamples.hidden = f.samplesPerPixel === null;
    el.samples.textContent = f.samplesPerPixel ?? '—';
    el.statPatches.hidden = f.patches === null;
    el.patches.textContent = f.patches ? formatCount(f.patches) : '—';
    el.statResidual.hidden = f.solverResidual === null;
    el.residual.textContent = f.patches ? `${f.solverResidual.toExponential(1)} after ${f.solverIterations} sweeps` : '—';
    el.statMaps.hidden = f.globalMapPhotons === null;
    el.maps.textContent = f.globalMapPhotons || f.causticMapPhotons
      ? `${formatCount(f.globalMapPhotons)} global, ${formatCount(f.causticMapPhotons)} caustic` : '—';
    plot.setSeries(seriesFor(job.integrator));
    el.created.textContent = formatTime(job.createdAt);
    el.progress.value = progressFraction(job.passesDone, job.passes);
    el.error.hidden = !job.error;
    el.error.textContent = job.error ? `The render failed: ${job.error}` : '';
    showWarnings(job.warnings || []);
    el.cancel.disabled = job.status !== 'queued' && job.status !== 'running';
    el.remove.disabled = !isFinished(job);
    setDownload(el.png, job.id, 'png', job.passesDone > 0);
    setDownload(el.exr, job.id, 'exr', job.passesDone > 0);
  }

  // SPPM's adaptive photon counts move away from the record's photons_per_pass (where the
  // render started): the count now is read off the passes the plot holds (its history and
  // the live passes), so no request of its own. The other methods show the record's.
  function showPhotonsPerPass(job) {
    el.photonsPerPass.textContent = job.integrator === 'sppm'
      ? formatPhotonsPerPass(job.photonsPerPass, plot.points()) : formatCount(job.photonsPerPass);
  }

  // A new state of the job on show, from an event, a poll or a button's answer.
  function apply(s, job) {
    if (session !== s) return;
    const previous = s.job;
    // Answers can cross (a slow GET after a newer event): never step back.
    if (previous && isFinished(previous) && !isFinished(job)) return;
    if (previous && job.passesDone < previous.passesDone) return;
    s.job = job;
    render(job);
    showLayerChoice(job);
    if (previous) compare.update(job);
    else compare.open(job);
    if (job.passesDone > 0) s.preview.want(job.passesDone);
    plot.add(job);
    showPhotonsPerPass(job);
    if (isFinished(job)) {
      stopFollowing(s);
      if (!previous || !isFinished(previous)) onChanged();
    }
  }

  function stopFollowing(s) {
    if (s.source) s.source.close();
    s.source = null;
    clearTimeout(s.timer);
    s.timer = null;
  }

  function poll(s) {
    s.timer = setTimeout(async () => {
      if (session !== s) return;
      try {
        apply(s, await getJob(s.id));
      } catch (error) {
        if (session !== s) return;
        if (error.status === 404) {
          close();
          showMessage(`Job ${s.id} no longer exists.`);
          return;
        }
        el.actionError.textContent = error.message; // keep trying: the server may come back
      }
      if (session === s && !(s.job && isFinished(s.job))) poll(s);
    }, POLL_MS);
  }

  async function follow(s) {
    if (typeof EventSource !== 'function') return poll(s);
    // With a token the stream is authorised by the session cookie; without one, polling.
    if (hasToken() && !(await ensureSession())) return poll(s);
    if (session !== s) return;
    const source = new EventSource(eventsUrl(s.id));
    s.source = source;
    for (const type of EVENT_TYPES) {
      source.addEventListener(type, (event) => {
        el.actionError.textContent = '';
        try {
          apply(s, normalizeJob(JSON.parse(event.data)));
        } catch {
          // A malformed event: the next one or the final state will correct the view.
        }
      });
    }
    source.addEventListener('error', () => {
      // CONNECTING: the browser retries by itself. CLOSED: it gave up (an HTTP error such
      // as 401 or 404), so fall back to polling, which reports the reason.
      if (session === s && source.readyState === EventSource.CLOSED && !(s.job && isFinished(s.job))) {
        s.source = null;
        sessionLost();
        poll(s);
      }
    });
  }

  // Whether the job denoises and at which exposure it renders: the record does not say;
  // its scene's render.denoise and render.exposure (default 0) do.
  async function showSceneSettings(s) {
    let text = '—';
    let stops = null;
    try {
      const scene = await getScene(s.id);
      if (scene.type.startsWith('application/json')) {
        const render = JSON.parse(scene.text)?.render ?? {};
        text = render.denoise === true ? 'on' : 'off';
        stops = typeof render.exposure === 'number' ? render.exposure : 0;
      }
    } catch {
      // An imported scene, or the scene could not be read: not known.
    }
    if (session !== s) return;
    if (!(s.job && s.job.denoise !== null)) el.denoise.textContent = text; // the record, when it says, wins
    exposure.setRenderExposure(stops);
  }

  function close() {
    if (!session) return;
    stopFollowing(session);
    session.preview.stop();
    session = null;
  }

  function open(id) {
    close();
    const s = { id, job: null, source: null, timer: null, preview: null };
    s.preview = previewFor(s);
    session = s;
    el.empty.hidden = true;
    el.details.hidden = false;
    el.id.textContent = id;
    el.image.hidden = true;
    el.frame.hidden = true;
    el.frame.removeAttribute('aria-busy');
    el.image.removeAttribute('src');
    exposure.clear();
    viewport.clear();
    layerChoice.hidden = true;
    $('layer-denoised').checked = true;
    compare.open(null);
    delete el.image.dataset.pass;
    el.placeholder.hidden = false;
    el.actionError.textContent = '';
    for (const key of ['status', 'pass', 'rate', 'radius', 'photons', 'elapsed', 'eta']) el[key].textContent = '…';
    el.cancel.disabled = true;
    el.remove.disabled = true;
    setDownload(el.png, id, 'png', false);
    setDownload(el.exr, id, 'exr', false);
    plot.clear();
    follow(s); // first, so no pass is missed while the GET is on its way
    el.denoise.textContent = '…';
    showSceneSettings(s);
    getJob(id)
      .then((job) => {
        apply(s, job);
        // The passes before this moment (a reload, a job opened late), for the plot: the
        // server's kept history, or from a server without it the events it still keeps.
        if (job.passesDone > 0) {
          progressPoints(id)
            .then((points) => points ?? progressHistory(id, { untilPass: job.passesDone }))
            .then((records) => {
              if (session !== s) return;
              plot.addAll(records);
              showPhotonsPerPass(s.job); // the passes before the latest may tell the count now
            });
        }
      })
      .catch((error) => {
        if (session !== s) return;
        close();
        showMessage(error.status === 404 ? `There is no job ${id}.` : error.message);
      });
  }

  el.cancel.addEventListener('click', async () => {
    const s = session;
    if (!s) return;
    el.cancel.disabled = true;
    el.actionError.textContent = '';
    try {
      apply(s, await cancelJob(s.id));
      // 202: still running until the pass ends; events bring the final state, and a poll
      // as well, so that a stream that is reconnecting (or gone) cannot leave it unseen.
      if (session === s && !(s.job && isFinished(s.job)) && !s.timer) poll(s);
    } catch (error) {
      if (session === s) el.actionError.textContent = error.message;
    }
    onChanged();
  });

  el.remove.addEventListener('click', async () => {
    const s = session;
    if (!s) return;
    const name = s.job && s.job.name ? `"${s.job.name}" (${s.id})` : s.id;
    if (!window.confirm(`Delete job ${name}? Its images, scene and log are removed from the server.`)) return;
    el.remove.disabled = true;
    el.actionError.textContent = '';
    try {
      await deleteJob(s.id);
      close();
      showMessage(`Job ${s.id} was deleted.`);
      onDeleted(s.id);
    } catch (error) {
      if (session === s) {
        el.actionError.textContent = error.message;
        el.remove.disabled = false;
      }
    }
    onChanged();
  });

  // With a token, plain links would be refused: fetch the file and save it from memory.
  for (const [link, format] of [
    [el.png, 'png'],
    [el.exr, 'exr'],
  ]) {
    link.addEventListener('click', async (event) => {
      if (!session || !hasToken() || !link.href) return;
      event.preventDefault();
      try {
        const url = URL.createObjectURL((await fetchImage(session.id, format, format === 'png' ? imageSettings() : {})).blob);
        const save = document.createElement('a');
        save.href = url;
        save.download = link.download;
        save.click();
        setTimeout(() => URL.revokeObjectURL(url), 10000);
      } catch (error) {
        el.actionError.textContent = error.message;
      }
    });
  }

  return { open, close, currentId: () => (session ? session.id : null) };
}

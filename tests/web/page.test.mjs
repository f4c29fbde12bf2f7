// Browser test of the web page (web/) against a real photon-server, with Debian's Chromium
// driven by playwright-core (no browser download).
//
//   npm ci --prefix tests/web
//   PHOTON_SERVER_BIN=build/app/photon-server PHOTON_WEB_SCREENSHOT=out/web.png \
//     node --test tests/web/page.test.mjs
//
// Starts the server on a free port with a fresh data folder, opens the page and checks: the
// render farm panel; a Cornell box render followed to completion, whole preview images only,
// its error estimate, the plot's history kept across a reload; the preview on a link
// throttled to 30 KB/s (CDP) and the photons per pass its adaptive count moved to; method
// and denoise choices; cancel and delete (with its confirmation); an imported pbrt file's
// warnings; the job list (names, methods, thumbnails, search, status filter, sort, events
// without polling); each method's figures; the phone-width layout. Screenshots of each state
// go beside PHOTON_WEB_SCREENSHOT. The form (examples, placeholders, memory, errors) is
// checked in page-form.test.mjs, the image's zoom, exposure, layers and compare view in
// page-image.test.mjs. The server and the browser (page-session.mjs) are stopped at the end,
// also when a check fails; the helpers that talk to the server from Node are in harness.mjs.

import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { dirname } from 'node:path';
import { test } from 'node:test';
import { formatCount } from '../../web/format.js';
import {
  countEventStreams,
  occupyWorker,
  readScene,
  releaseWorker,
  submitScene,
  waitForStatus,
} from './harness.mjs';
import {
  assertWholeImages,
  chooseExample,
  markScreenshotTaken,
  page,
  pageErrors,
  RENDER_TIMEOUT_MS,
  saveScreenshot,
  SCREENSHOT,
  server,
  shownImages,
  textOf,
  usePageSession,
  watchShownImages,
} from './page-session.mjs';

usePageSession();

const namedJobs = {}; // name -> id: the jobs the job list's test submits, one per method

// ---- Helpers -----------------------------------------------------------------------

async function submittedJobId() {
  await page.waitForFunction(() => /^Submitted job \S+\.$/.test(document.querySelector('#form-status').textContent));
  return /^Submitted job (\S+)\.$/.exec(await textOf('#form-status'))[1];
}

// ---- Tests -------------------------------------------------------------------------

test('the render farm panel stays hidden when the server renders alone', async () => {
  // The server here runs without --redis: /api/v1/workers says farm: false.
  await page.waitForResponse((r) => r.url().endsWith('/api/v1/workers'), { timeout: 10_000 }).catch(() => {});
  const workers = await page.evaluate(async () => (await fetch('/api/v1/workers')).json());
  assert.deepEqual(workers, { farm: false, queue_depth: 0, workers: [] });
  assert.equal(await page.locator('#workers-panel').isHidden(), true);
});

test('the render farm panel lists the workers a farm reports', async () => {
  // The answer a server started with --redis gives (its shape is held to api/openapi.yaml by
  // the server's own tests), served here by the browser's request interception.
  const farm = {
    farm: true,
    queue_depth: 3,
    workers: [
      { name: 'node-1', host: 'render-a', threads: 16, busy: true, job: '0123456789abcdef', passes_per_second: 2.5, batches: 12, redeliveries: 1 },
      { name: 'node-2', host: 'render-b', threads: 8, busy: false, job: null, passes_per_second: 1.25, batches: 7, redeliveries: 0 },
    ],
  };
  await page.route('**/api/v1/workers', (route) => route.fulfill({ json: farm }));
  try {
    await page.locator('#workers-panel').waitFor({ state: 'visible', timeout: 10_000 });
    assert.equal(await textOf('#workers-summary'), '2 workers, 1 rendering; 3 items queued or in progress.');
    const rows = await page.locator('#workers-rows tr').evaluateAll((trs) =>
      trs.map((tr) => [...tr.children].map((td) => td.textContent)));
    assert.deepEqual(rows, [
      ['node-1', 'render-a', '16', 'job 0123456789abcdef', '2.50', '12', '1'],
      ['node-2', 'render-b', '8', 'idle', '1.25', '7', '0'],
    ]);
  } finally {
    await page.unroute('**/api/v1/workers');
  }
  await page.locator('#workers-panel').waitFor({ state: 'hidden', timeout: 10_000 });
});

test('a Cornell box render follows its passes to completion', { timeout: RENDER_TIMEOUT_MS + 30_000 }, async (t) => {
  await watchShownImages();
  const loadedPasses = new Set(); // image responses that arrived (200)
  page.on('response', (response) => {
    // The latest image (one URL for every pass): the pass is the one the server names.
    if (/\/api\/v1\/jobs\/[^/]+\/image\?format=png$/.test(response.url()) && response.status() === 200) {
      loadedPasses.add(response.headers()['x-photon-pass']);
    }
  });

  // The event streams the page has open: the job view must be following the job before
  // its first pass, or a fast machine finishes it before the page connects.
  await countEventStreams(page);
  const blocker = await occupyWorker(server);

  await chooseExample('cornell-box');
  await page.fill('#passes', '4');
  await page.fill('#photons-per-pass', '20000');
  await page.fill('#seed', '');
  await page.fill('#target-error', '0.001'); // 0.001%: far below what 4 passes reach
  await page.click('#submit-button');
  const id = await submittedJobId();
  assert.equal(await textOf('#job-id'), id, 'the job view opens the submitted job');
  await page.waitForFunction(
    () => document.querySelector('#job-status').textContent === 'queued' && window.__openEventStreams >= 1,
  );
  await releaseWorker(server, blocker);

  await page.waitForFunction(
    () => document.querySelector('#job-status').textContent === 'completed' && window.__shown.length >= 1 &&
      window.__shown.at(-1).pass === 4,
    null,
    { timeout: RENDER_TIMEOUT_MS },
  );
  const shown = await shownImages();
  const passes = shown.map((image) => image.pass);
  t.diagnostic(`image passes shown: ${passes.join(', ')}`);
  assertWholeImages(shown, 256, 256);
  assert.equal(passes.at(-1), 4, 'the last image is of pass 4');
  assert.equal(await textOf('#job-pass'), '4 / 4');

  // The final image is really shown, at the scene's resolution.
  await page.waitForFunction(() => {
    const img = document.querySelector('#job-image');
    return !img.hidden && img.complete && img.naturalWidth === 256 && img.naturalHeight === 256 && img.dataset.pass === '4';
  });
  assert.ok(loadedPasses.has('4'), 'the image of pass 4 was fetched');

  // Numbers and controls of a completed job.
  assert.match(await textOf('#job-elapsed'), /^\d+:\d\d:\d\d$/);
  assert.match(await textOf('#job-rate'), /\/s$/);
  assert.match(await textOf('#job-radius'), /^\d/);
  // Adaptive counts change after pass 4 at the earliest: all 4 passes traced the start count.
  assert.equal(await textOf('#job-photons-per-pass'), '20.0 k');
  assert.equal(await page.isDisabled('#cancel-button'), true);
  assert.equal(await page.isDisabled('#delete-button'), false);
  for (const format of ['png', 'exr']) {
    const link = page.locator(`#download-${format}`);
    assert.equal(await link.getAttribute('href'), `/api/v1/jobs/${id}/image?format=${format}`);
    assert.equal(await link.getAttribute('download'), `photon-${id}.${format}`);
  }
  assert.equal(await page.getAttribute('#progress-plot', 'data-points'), '4');
  assert.equal(await page.getAttribute('#progress-plot', 'data-series'),
    'passes per second, mean radius, photons traced, relative error');
  // The estimated error from pass 2 on, as the record has it.
  const done = await (await fetch(`${server.baseUrl}api/v1/jobs/${id}`)).json();
  assert.ok(done.relative_error > 0 && done.relative_error < 1, `relative error ${done.relative_error}`);
  assert.equal(done.target_error, 0.00001);
  assert.equal(done.settings.target_error, 0.00001);
  assert.equal(await textOf('#job-relative-error'), `${Number((100 * done.relative_error).toPrecision(3))}% (target 0.001%)`);
  await page.fill('#target-error', '');

  // The list shows the job as completed with a full progress bar (it polls every 2 s).
  const row = page.locator(`#job-list li[data-job-id="${id}"]`);
  await page.waitForFunction(
    (jobId) => document.querySelector(`#job-list li[data-job-id="${jobId}"]`)?.dataset.status === 'completed',
    id,
    { timeout: 10_000 },
  );
  assert.equal(await row.locator('progress').evaluate((bar) => bar.value), 1);

  mkdirSync(dirname(SCREENSHOT), { recursive: true });
  await page.screenshot({ path: SCREENSHOT, fullPage: true });
  markScreenshotTaken();

  // After a reload the plot still has every pass: read back from the job's kept events.
  await page.reload();
  await waitForStatus(page, server, id, 'completed', 10_000);
  await page.waitForFunction(() => document.querySelector('#progress-plot').dataset.points === '4');
  assert.match(await page.getAttribute('#progress-plot', 'aria-label'),
    /^Passes per second, mean radius, photons traced and relative error over time\. 4 passes plotted\. Latest, pass 4 at \d+:\d\d:\d\d: passes per second [\d.]+\/s, mean radius [\d.e+-]+, photons traced 80\.0 k, relative error [\d.]+%\.$/);
});

test('on a slow link the preview shows only whole images and ends on the final pass', { timeout: RENDER_TIMEOUT_MS + 30_000 }, async (t) => {
  const blocker = await occupyWorker(server);
  const scene = readScene('cornell-box');
  scene.camera.resolution = [64, 64];
  scene.render = { ...scene.render, passes: 12, photons_per_pass: 100000 };
  const id = await submitScene(server, scene);
  await countEventStreams(page);
  await page.evaluate((jobId) => {
    window.location.hash = `job=${jobId}`;
  }, id);
  await page.waitForFunction(
    (jobId) => document.querySelector('#job-id').textContent === jobId &&
      document.querySelector('#job-status').textContent === 'queued' && window.__openEventStreams >= 1,
    id,
  );
  await watchShownImages();
  const failedImages = []; // image requests that did not finish: aborted or cut off
  const onFailed = (request) => {
    if (request.url().includes(`/api/v1/jobs/${id}/image`)) failedImages.push(request.url());
  };
  page.on('requestfailed', onFailed);
  // 30 KB/s down and up, 150 ms latency: a 64x64 PNG takes about half a second.
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Network.enable');
  await cdp.send('Network.emulateNetworkConditions', {
    offline: false, latency: 150, downloadThroughput: 30 * 1024, uploadThroughput: 30 * 1024,
  });
  try {
    const started = Date.now();
    await releaseWorker(server, blocker);
    await waitForStatus(page, server, id, 'completed', RENDER_TIMEOUT_MS);
    await page.waitForFunction(() => window.__shown.at(-1)?.pass === 12, null, { timeout: 30_000 });
    t.diagnostic(`completed and final preview shown after ${Date.now() - started} ms`);
  } finally {
    await cdp.send('Network.emulateNetworkConditions', { offline: false, latency: 0, downloadThroughput: -1, uploadThroughput: -1 });
    await cdp.detach();
    page.off('requestfailed', onFailed);
  }
  const shown = await shownImages();
  t.diagnostic(`passes shown on the slow link: ${shown.map((image) => image.pass).join(', ')}`);
  assertWholeImages(shown, 64, 64);
  const record = await (await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl))).json();
  assert.equal(record.total_passes, 12);
  assert.equal(shown.at(-1).pass, record.total_passes, "the last image shown is the job's final pass");
  assert.equal(await page.getAttribute('#job-image', 'data-pass'), '12');
  // 100k photons a pass is far more than 64x64 pixels need: the adaptive count moved after
  // pass 4 (and 8), and the view shows the latest passes' count with where it started.
  const points = (await (await fetch(new URL(`api/v1/jobs/${id}/progress`, server.baseUrl))).json()).points;
  assert.deepEqual(points.slice(-2).map((p) => p.pass), [11, 12]);
  const latest = points.at(-1).photons_traced - points.at(-2).photons_traced;
  t.diagnostic(`photons per pass: ${points.map((p, i) => p.photons_traced - (points[i - 1]?.photons_traced ?? 0)).join(', ')}`);
  assert.notEqual(formatCount(latest), formatCount(100000), 'the render changed its photons per pass');
  assert.equal(await textOf('#job-photons-per-pass'), `${formatCount(latest)} (started at 100 k)`);
  assert.deepEqual(failedImages, [], 'no image load was aborted');
  await saveScreenshot('throttled-preview');
});

test('the method and denoising chosen on the form reach the job', { timeout: RENDER_TIMEOUT_MS + 30_000 }, async () => {
  await chooseExample('cornell-box');
  await page.fill('#passes', '2');
  await page.fill('#photons-per-pass', '');
  await page.selectOption('#integrator', 'radiosity');
  await page.check('#denoise');
  await page.click('#submit-button');
  const id = await submittedJobId();
  await page.waitForFunction(() => document.querySelector('#job-status').textContent === 'completed', null, {
    timeout: RENDER_TIMEOUT_MS,
  });
  assert.equal(await textOf('#job-integrator'), 'radiosity');
  const record = await (await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl))).json();
  assert.equal(record.settings?.integrator ?? record.integrator, 'radiosity');
  // Denoised: the EXR carries the raw image as extra channels beside R, G, B.
  const exr = Buffer.from(await (await fetch(new URL(`api/v1/jobs/${id}/image?format=exr`, server.baseUrl))).arrayBuffer());
  assert.ok(exr.includes(Buffer.from('raw.R')), 'the EXR has the raw layer');
  await page.selectOption('#integrator', '');
  await page.uncheck('#denoise');
});

test('a running job can be cancelled and a finished one deleted', async () => {
  await chooseExample('cornell-glass');
  await page.fill('#passes', '100000');
  await page.fill('#photons-per-pass', '20000');
  await page.click('#submit-button');
  const id = await submittedJobId();
  await waitForStatus(page, server, id, 'running', 30_000);
  await page.waitForFunction(() => Number(document.querySelector('#job-image').dataset.pass) >= 1);
  await saveScreenshot('running-job');
  await page.click('#cancel-button');
  await waitForStatus(page, server, id, 'cancelled', 30_000);
  await page.waitForFunction(() => !document.querySelector('#delete-button').disabled);
  // Delete asks first; declined, nothing happens.
  const question = `Delete job ${id}? Its images, scene and log are removed from the server.`;
  const answer = (accept) => new Promise((resolveDialog) => {
    page.once('dialog', async (dialog) => {
      resolveDialog([dialog.type(), dialog.message()]);
      await (accept ? dialog.accept() : dialog.dismiss());
    });
  });
  let asked = answer(false);
  await page.click('#delete-button');
  assert.deepEqual(await asked, ['confirm', question]);
  assert.equal(await page.isDisabled('#delete-button'), false);
  assert.equal((await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl))).status, 200, 'still there');
  asked = answer(true);
  await page.click('#delete-button');
  assert.deepEqual(await asked, ['confirm', question]);
  await page.waitForFunction(
    (jobId) => !document.querySelector(`#job-list li[data-job-id="${jobId}"]`),
    id,
    { timeout: 10_000 },
  );
  assert.equal(await textOf('#job-empty'), `Job ${id} was deleted.`);
  const gone = await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl));
  assert.equal(gone.status, 404);
});

test('an imported pbrt file is sent as it is and its warnings are shown', { timeout: RENDER_TIMEOUT_MS + 30_000 }, async () => {
  const pbrt = [
    'LookAt 0 1 4  0 1 0  0 1 0',
    'Camera "perspective" "float fov" [45]',
    'Film "rgb" "integer xresolution" [16] "integer yresolution" [16]',
    'PixelFilter "mitchell"',
    'WorldBegin',
    'AreaLightSource "diffuse" "rgb L" [4 4 4]',
    'Shape "trianglemesh" "integer indices" [0 1 2 0 2 3] "point3 P" [-1 2 -1  1 2 -1  1 2 1  -1 2 1]',
    '',
  ].join('\n');
  await page.setInputFiles('#scene-file', { name: 'room.pbrt', mimeType: 'text/plain', buffer: Buffer.from(pbrt) });
  await page.waitForFunction(() => document.querySelector('#scene-text').placeholder.includes('room.pbrt'));
  await page.fill('#passes', '1');
  await page.fill('#photons-per-pass', '1000');
  await page.click('#submit-button');
  const id = await submittedJobId();
  const record = await (await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl))).json();
  assert.equal(record.name, 'room');
  assert.deepEqual(record.warnings, [
    'scene.pbrt:4: PixelFilter "mitchell": its negative lobes are left out (photon\'s pixel estimates are not negative)',
  ]);
  const warnings = page.locator('#job-warnings');
  await warnings.waitFor({ state: 'visible' });
  assert.deepEqual(await page.locator('#job-warning-list li').allTextContents(), record.warnings);
  await waitForStatus(page, server, id, 'completed', RENDER_TIMEOUT_MS);
  await page.fill('#passes', '');
  await page.fill('#photons-per-pass', '');
});

test('the job list tells jobs apart, filters, sorts and follows events without polling', { timeout: RENDER_TIMEOUT_MS + 30_000 }, async () => {
  // The list has listed the jobs and follows the event stream.
  await page.waitForFunction(() => document.querySelector('#job-list').dataset.following === 'events');
  const listings = []; // the page's GET /api/v1/jobs requests (listings), by query
  const thumbnails = new Set(); // the page's requests for thumbnails: "<id><query>"
  const onRequest = (request) => {
    const url = new URL(request.url());
    if (request.method() === 'GET' && url.pathname === '/api/v1/jobs') listings.push(url.search);
    const image = /^\/api\/v1\/jobs\/([^/]+)\/image$/.exec(url.pathname);
    if (image && url.searchParams.has('size')) thumbnails.add(image[1] + url.search);
  };
  page.on('request', onRequest);
  try {
    // Three small jobs, named, one per method, submitted from outside the page.
    const submitted = {};
    for (const [name, integrator] of [['kitchen', 'sppm'], ['hall', 'path'], ['attic', 'radiosity']]) {
      const scene = readScene('cornell-box');
      scene.camera.resolution = [64, 64];
      scene.render = { ...scene.render, integrator, passes: 2, photons_per_pass: 2000 };
      const response = await fetch(new URL(`api/v1/jobs?name=${name}`, server.baseUrl), {
        method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(scene),
      });
      assert.equal(response.status, 201);
      submitted[name] = (await response.json()).id;
    }
    Object.assign(namedJobs, submitted);
    await page.waitForFunction((ids) => ids.every((id) => {
      const row = document.querySelector(`#job-list li[data-job-id="${id}"]`);
      return row?.dataset.status === 'completed' && row.querySelector('.job-thumb').naturalWidth > 0;
    }), Object.values(submitted), { timeout: RENDER_TIMEOUT_MS });
    assert.deepEqual(listings, [], 'the list followed the events and never asked for the jobs');

    const row = (name) => page.locator(`#job-list li[data-job-id="${submitted[name]}"]`);
    const detail = async (name) => (await row(name).locator('.job-row-detail').textContent()).replace(/ · \d{4}-.*$/, '');
    assert.equal(await row('kitchen').locator('.job-row-title').textContent(), 'kitchen');
    assert.equal(await row('kitchen').locator('.status-badge').textContent(), 'completed');
    assert.equal(await detail('kitchen'), 'SPPM · 64×64 · pass 2 / 2');
    assert.equal(await detail('hall'), 'path tracing · 64×64 · pass 2 / 2');
    assert.equal(await detail('attic'), 'radiosity · 64×64 · pass 2 / 2');
    // The thumbnail: the image endpoint's 48x48 box of the latest image, here the last pass,
    // fetched whole (the latest image's URL is the same for every pass).
    const thumb = await row('hall').locator('.job-thumb').evaluate((img) =>
      ({ blob: img.src.startsWith('blob:'), pass: img.dataset.pass, width: img.naturalWidth, height: img.naturalHeight, alt: img.alt }));
    assert.deepEqual(thumb, { blob: true, pass: '2', width: 48, height: 48, alt: 'Job hall after pass 2' });
    assert.ok(thumbnails.has(`${submitted.hall}?format=png&size=48x48`), [...thumbnails].join(', '));

    const titles = () => page.locator('#job-list .job-row-title').allTextContents();
    // Search by name: the server filters the listing.
    await page.fill('#job-search', 'AL');
    await page.waitForFunction(() => document.querySelector('#job-list-status').textContent === '1 job matches.');
    assert.deepEqual(await titles(), ['hall']);
    assert.deepEqual(listings, ['?name=AL&limit=100']);
    await page.fill('#job-search', 't');
    await page.waitForFunction(() => document.querySelector('#job-list-status').textContent === '2 jobs match.');
    assert.deepEqual(await titles(), ['attic', 'kitchen'], 'newest first');
    await page.selectOption('#job-sort', 'name');
    assert.deepEqual(await titles(), ['attic', 'kitchen']);
    await page.selectOption('#job-sort', 'oldest');
    assert.deepEqual(await titles(), ['kitchen', 'attic']);
    // Filter by status: a job that starts running joins the "running" list from its event.
    await page.fill('#job-search', '');
    await page.selectOption('#job-status-filter', 'running');
    await page.waitForFunction(() => document.querySelector('#job-list-status').textContent === 'No jobs match.');
    const blocker = await occupyWorker(server);
    await page.waitForFunction((id) => document.querySelector(`#job-list li[data-job-id="${id}"]`), blocker);
    assert.deepEqual(await page.locator('#job-list li').evaluateAll((items) => items.map((li) => li.dataset.jobId)), [blocker]);
    await saveScreenshot('list-filtered');
    await releaseWorker(server, blocker);
    // Cancelled: it leaves the "running" list, again from its event.
    await page.waitForFunction(() => document.querySelector('#job-list-status').textContent === 'No jobs match.');
    assert.deepEqual(listings, ['?name=AL&limit=100', '?name=t&limit=100', '?status=running&limit=100']);
  } finally {
    page.off('request', onRequest);
    await page.fill('#job-search', '');
    await page.selectOption('#job-status-filter', '');
    await page.selectOption('#job-sort', 'newest');
  }
  await page.waitForFunction(() => /^\d+ jobs\.$/.test(document.querySelector('#job-list-status').textContent));
  await saveScreenshot('list');
});

test("the job view shows only the figures of the job's method", async () => {
  const common = ['Status', 'Pass', 'Method', 'Denoise', 'Passes/s'];
  const times = ['Error', 'Elapsed', 'ETA', 'Resolution', 'Seed', 'Created'];
  const expected = {
    kitchen: { method: 'SPPM', figures: [...common, 'Photons/s', 'Mean radius', 'Photons traced', 'Photons per pass', ...times],
      series: 'passes per second, mean radius, photons traced, relative error' },
    hall: { method: 'path tracing', figures: [...common, 'Samples/pixel', ...times], series: 'passes per second, relative error' },
    attic: { method: 'radiosity', figures: [...common, 'Samples/pixel', 'Patches', 'Solver residual', ...times],
      series: 'passes per second, relative error' },
  };
  assert.deepEqual(Object.keys(namedJobs), Object.keys(expected), 'the job list test submitted the jobs');
  for (const [name, want] of Object.entries(expected)) {
    const id = namedJobs[name];
    await page.click(`#job-list li[data-job-id="${id}"] button`);
    await waitForStatus(page, server, id, 'completed', 10_000);
    // Two passes: the first read back from the job's events, the last from the live view.
    await page.waitForFunction(() => document.querySelector('#progress-plot').dataset.points === '2');
    await page.waitForFunction(() => document.querySelector('#job-denoise').textContent === 'off');
    const figures = await page.locator('#job-details .stats > div:not([hidden]) dt').allTextContents();
    assert.deepEqual(figures, want.figures, `${name}: figures`);
    assert.equal(await textOf('#job-integrator'), want.method);
    assert.equal(await page.getAttribute('#progress-plot', 'data-series'), want.series);
    assert.match(await textOf('#job-pass-rate'), /^[\d.]+\/s$/);
    // The method's own figures, as the record gives them.
    const record = await (await fetch(`${server.baseUrl}api/v1/jobs/${id}`)).json();
    if (name !== 'kitchen') assert.equal(await textOf('#job-samples'), String(record.figures.samples_per_pixel));
    if (name === 'attic') {
      assert.ok(record.figures.patches > 0);
      assert.equal(await textOf('#job-residual'),
        `${record.figures.solver_residual.toExponential(1)} after ${record.figures.solver_iterations} sweeps`);
    }
    if (name === 'hall') await saveScreenshot('path-tracing-job');
  }
  // Axis labels step in as many decimals as they need: none repeat.
  const ticks = await page.evaluate(async () => {
    const { tickLabels } = await import('/progress-plot.js');
    return [tickLabels(1), tickLabels(0.02), tickLabels(250000), tickLabels(5, 2), tickLabels(0.025, 2)];
  });
  assert.deepEqual(ticks, [
    ['0', '0.25', '0.5', '0.75', '1'],
    ['0', '0.005', '0.01', '0.015', '0.02'],
    ['0', '62.5 k', '125 k', '188 k', '250 k'],
    ['0', '2.5', '5'],
    ['0', '0.0125', '0.025'],
  ]);
});

test('on a phone-width screen the form and the job come before the job list', async () => {
  await page.setViewportSize({ width: 390, height: 844 });
  try {
    await page.reload(); // the address bar keeps the job on show (#job=<id>)
    await page.waitForFunction(() => !document.querySelector('#job-details').hidden);
    const tops = await page.evaluate(() =>
      Object.fromEntries(['submit-panel', 'job-view', 'jobs-panel'].map((id) => [id, document.getElementById(id).getBoundingClientRect().top])));
    assert.ok(tops['submit-panel'] < tops['job-view'] && tops['job-view'] < tops['jobs-panel'], JSON.stringify(tops));
    const width = await page.evaluate(() => document.documentElement.scrollWidth);
    assert.equal(width, 390, 'nothing sticks out sideways');
    await saveScreenshot('phone');
  } finally {
    await page.setViewportSize({ width: 1440, height: 1000 });
  }
});

test('the page raised no script errors', () => {
  assert.deepEqual(pageErrors, []);
});

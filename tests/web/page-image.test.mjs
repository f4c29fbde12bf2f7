// Browser test of the job view's image (web/image-viewport.js, exposure-control.js,
// compare-view.js) against a real photon-server, with Debian's Chromium driven by
// playwright-core:
//
//   PHOTON_SERVER_BIN=build/app/photon-server PHOTON_WEB_SCREENSHOT=out/web.png \
//     node --test tests/web/page-image.test.mjs
//
// Zoom and pan (exact transforms after the wheel, buttons, keys, a drag, a pinch and a double
// click, 1:1 at devicePixelRatio 1 and 2, kept across passes), exposure (exact requests, the
// server's pixels, 4 times the light at +2 stops), the compare view (divider place -> clip)
// and a denoised job's raw layer, kept passes and progress history. Screenshots beside
// PHOTON_WEB_SCREENSHOT; what the checks read of the page is in image-checks.mjs.

import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { test } from 'node:test';
import { readScene, REPO, submitScene, waitForStatus } from './harness.mjs';
import { compareState, expectedView, imageView, linear, shownAndServedPixels, viewOf } from './image-checks.mjs';
import {
  markScreenshotTaken,
  page,
  pageErrors,
  saveScreenshot,
  server,
  shownImages,
  textOf,
  usePageSession,
  watchShownImages,
} from './page-session.mjs';

usePageSession();
markScreenshotTaken(); // the main screenshot is page.test.mjs's; this file saves its own states

// ---- The image: zoom, pan, exposure --------------------------------------------------

// A job of 64 x 64 pixels that keeps rendering until cancelled, opened in the job view.
async function openLongJob() {
  const scene = readScene('cornell-box');
  scene.camera.resolution = [64, 64];
  scene.render = { ...scene.render, passes: 100000, photons_per_pass: 20000 };
  const id = await submitScene(server, scene);
  await page.evaluate((jobId) => {
    window.location.hash = `job=${jobId}`;
  }, id);
  await page.waitForFunction(() => Number(document.querySelector('#job-image').dataset.pass) >= 1 &&
    document.querySelector('#job-image').naturalWidth === 64 && !document.querySelector('#image-frame').hidden, null, { timeout: 30_000 });
  return id;
}

let inspectedJob = null; // the 64 x 64 job the zoom test renders (cancelled), for the exposure test

test('the image zooms around the cursor, pans, fits, shows 1:1 and keeps its zoom across passes', { timeout: 60_000 }, async () => {
  const id = await openLongJob();
  inspectedJob = id;
  try {
    // Fit: the whole image, centred in the frame.
    let view = await imageView(page);
    const [w, h] = view.frame;
    const fitScale = Math.min(w / 64, h / 64);
    assert.deepEqual(viewOf(view), expectedView(fitScale, (w - 64 * fitScale) / 2, (h - 64 * fitScale) / 2));
    assert.equal(view.mode, 'fit');
    assert.deepEqual(view.box, [...view.drawn, 64 * fitScale, 64 * fitScale]);

    // 1:1: one image pixel per CSS pixel on this screen (devicePixelRatio 1), centred.
    await page.click('#zoom-one');
    view = await imageView(page);
    assert.equal(view.scale, 1);
    assert.deepEqual(view.box.slice(2), [64, 64], 'a 64 x 64 image is 64 x 64 CSS px at 1:1');
    assert.equal(view.zoom, '100%');
    assert.equal(view.pixelated, false, 'not magnified: not pixelated');

    // + and −: steps of √2 through 1:1, 2:1, 4:1, around the frame's centre.
    await page.click('#zoom-in');
    await page.click('#zoom-in');
    view = await imageView(page);
    assert.deepEqual(viewOf(view), expectedView(2, w / 2 - 64, h / 2 - 64));
    assert.equal(view.zoom, '200%');
    assert.equal(view.pixelated, true, 'magnified: crisp pixels');
    await page.click('#zoom-out');
    assert.equal((await imageView(page)).scale, 2 ** 0.5);
    await page.click('#zoom-in');

    // The wheel zooms around the cursor: one notch (100 px) in is √2 more, and the image
    // point under the cursor stays under it.
    // Where the wheel event is, in the frame's content box (the page rounds mouse positions).
    await page.evaluate(() => document.querySelector('#image-frame').addEventListener('wheel', (event) => {
      const frame = event.currentTarget;
      const rect = frame.getBoundingClientRect();
      window.__wheelAt = [event.clientX - rect.left - frame.clientLeft, event.clientY - rect.top - frame.clientTop];
    }, { once: true, capture: true }));
    const frameBox = await page.locator('#image-frame').boundingBox();
    await page.mouse.move(frameBox.x + w / 2 + 20, frameBox.y + h / 2 - 12);
    const before = await imageView(page);
    await page.mouse.wheel(0, -100);
    await page.waitForFunction((old) => Number(document.querySelector('#image-frame').dataset.scale) !== old, before.scale);
    view = await imageView(page);
    const [cx, cy] = await page.evaluate(() => window.__wheelAt);
    const s = 2 * 2 ** 0.5;
    const u = (cx - before.x) / 2; // the image point under the cursor
    const v = (cy - before.y) / 2;
    assert.deepEqual(viewOf(view), expectedView(s, cx - u * s, cy - v * s));
    // The box is laid out in single precision, hence "within 1/1000 px" for its size.
    assert.deepEqual(view.box.slice(0, 2), view.drawn);
    assert.ok(view.box.slice(2).every((side) => Math.abs(side - 64 * s) < 1e-3), `${view.box} is ${64 * s} px wide`);

    // Dragging pans by exactly the pointer's travel.
    await page.mouse.down();
    await page.mouse.move(frameBox.x + w / 2 + 20 - 30, frameBox.y + h / 2 - 12 + 17, { steps: 3 });
    await page.mouse.up();
    const dragged = await imageView(page);
    assert.deepEqual(viewOf(dragged), expectedView(s, view.x - 30, view.y + 17));
    assert.equal(dragged.mode, 'free');

    // New passes replace the image but not the view.
    const pass = Number(await page.getAttribute('#job-image', 'data-pass'));
    await page.waitForFunction((p) => Number(document.querySelector('#job-image').dataset.pass) >= p + 2, pass, { timeout: 20_000 });
    const later = await imageView(page);
    assert.deepEqual(later, dragged, 'a new pass keeps the zoom and the pan');
    await saveScreenshot('zoomed-image');

    // Keys on the focused frame: + zooms in, an arrow pans, 0 fits, 1 is 1:1.
    await page.focus('#image-frame');
    await page.keyboard.press('Minus');
    assert.equal((await imageView(page)).scale, 2);
    const zoomedOut = await imageView(page);
    await page.keyboard.press('ArrowLeft');
    assert.equal((await imageView(page)).x, Math.min(w - 128, zoomedOut.x + 40), 'the image moves right, inside the frame');
    await page.keyboard.press('0');
    const fitted = await imageView(page);
    assert.deepEqual([fitted.mode, fitted.scale], ['fit', fitScale]);
    // A double click goes from Fit to 1:1 around the point clicked, and back to Fit.
    const frameAt = await page.locator('#image-frame').boundingBox();
    await page.mouse.dblclick(frameAt.x + w / 2, frameAt.y + h / 2);
    assert.equal((await imageView(page)).scale, 1);
    await page.mouse.dblclick(frameAt.x + w / 2, frameAt.y + h / 2);
    assert.deepEqual(viewOf(await imageView(page)), viewOf(fitted));
    await page.keyboard.press('1');
    const single = await imageView(page);
    assert.equal(single.scale, 1);

    // Two fingers pinching apart from 100 to 200 px: twice the zoom around their first
    // midpoint, then panned by the midpoint's travel (50 px right).
    await page.evaluate(() => {
      const frame = document.querySelector('#image-frame');
      const rect = frame.getBoundingClientRect();
      const at = (id, type, x, y) => frame.dispatchEvent(new PointerEvent(type, {
        pointerId: id, pointerType: 'touch', isPrimary: id === 11, button: type === 'pointermove' ? -1 : 0, bubbles: true,
        clientX: rect.left + frame.clientLeft + x, clientY: rect.top + frame.clientTop + y,
      }));
      at(11, 'pointerdown', 100, 100);
      at(12, 'pointerdown', 200, 100);
      at(12, 'pointermove', 300, 100);
      at(11, 'pointerup', 100, 100);
      at(12, 'pointerup', 300, 100);
    });
    const pinched = await imageView(page);
    assert.deepEqual(viewOf(pinched), expectedView(2, 150 - (150 - single.x) * 2 + 50, 100 - (100 - single.y) * 2));
    await page.keyboard.press('1');

    // On a screen of devicePixelRatio 2, 1:1 is one image pixel per device pixel: 32 CSS px.
    const cdp = await page.context().newCDPSession(page);
    try {
      await cdp.send('Emulation.setDeviceMetricsOverride', { width: 1440, height: 1000, deviceScaleFactor: 2, mobile: false });
      await page.click('#zoom-one');
      view = await imageView(page);
      assert.deepEqual({ scale: view.scale, size: view.box.slice(2), zoom: view.zoom }, { scale: 0.5, size: [32, 32], zoom: '100%' });
      await page.click('#zoom-in');
      assert.equal((await imageView(page)).scale, 2 ** 0.5 / 2);
      assert.equal((await imageView(page)).pixelated, false, '√2 device px per image pixel: smooth, not squares of 1 and 2');
      await page.click('#zoom-in');
      view = await imageView(page);
      assert.deepEqual({ scale: view.scale, size: view.box.slice(2), pixelated: view.pixelated }, { scale: 1, size: [64, 64], pixelated: true });
      assert.deepEqual(view.drawn, view.drawn.map((c) => Math.round(c * 2) / 2), 'the corner is on the device pixel grid');
      assert.deepEqual(view.box, [...view.drawn, 64, 64]);
    } finally {
      await cdp.send('Emulation.clearDeviceMetricsOverride');
      await cdp.detach();
    }
    await page.click('#zoom-fit');
  } finally {
    await fetch(new URL(`api/v1/jobs/${id}/cancel`, server.baseUrl), { method: 'POST' });
  }
  await waitForStatus(page, server, id, 'cancelled', 30_000);
});

test('the exposure slider reloads the pass on show once, at the exposure chosen', { timeout: 60_000 }, async () => {
  const id = inspectedJob;
  assert.ok(id, 'the zoom test rendered a job');
  if ((await textOf('#job-id')) !== id) {
    await page.evaluate((jobId) => {
      window.location.hash = `job=${jobId}`;
    }, id);
  }
  await waitForStatus(page, server, id, 'cancelled', 10_000);
  const record = await (await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl))).json();
  const pass = record.pass;
  await page.waitForFunction((p) => document.querySelector('#job-image').dataset.pass === String(p), pass);
  await page.waitForFunction(() => document.querySelector('#exposure-value').textContent === "±0 EV (render's)");
  assert.equal(await page.isDisabled('#exposure-reset'), true);
  // The render's own exposure (the Cornell box's is 0): the plain PNG, same pixels as exposure=0.
  const plain = await shownAndServedPixels(page, id, '?format=png&exposure=0');
  assert.deepEqual(plain.shown, plain.served);

  await page.click('#zoom-in');
  const zoom = await page.getAttribute('#image-frame', 'data-scale');
  const requests = []; // the image requests the page makes, by query
  const onRequest = (request) => {
    const url = new URL(request.url());
    if (url.pathname === `/api/v1/jobs/${id}/image` && !request.headers()['x-test-check']) requests.push(url.search);
  };
  page.on('request', onRequest);
  try {
    // +2 stops: the pass on show, loaded once more at exposure 2, swapped in whole.
    await watchShownImages();
    const busy = await page.locator('#exposure').evaluate((slider) => {
      slider.value = '2';
      slider.dispatchEvent(new Event('input', { bubbles: true }));
      return document.querySelector('#image-frame').getAttribute('aria-busy');
    });
    assert.equal(busy, 'true', 'the frame says it is loading');
    await page.waitForFunction(() => window.__shown.length === 1);
    assert.equal(await page.getAttribute('#image-frame', 'aria-busy'), null, 'and stops saying so once the image is in');
    assert.deepEqual(await shownImages(), [{ pass, blob: true, loaded: true, width: 64, height: 64 }]);
    assert.deepEqual(requests, [`?format=png&exposure=2`]);
    assert.equal(await textOf('#exposure-value'), '+2 EV');
    assert.equal(await page.isDisabled('#exposure-reset'), false);
    assert.equal(await page.getAttribute('#download-png', 'href'), `/api/v1/jobs/${id}/image?format=png&exposure=2`);
    assert.equal(await page.getAttribute('#image-frame', 'data-scale'), zoom, 'the zoom stays');

    // What is shown is the server's PNG at exposure 2, pixel for pixel, and 4 times as bright
    // in linear light wherever neither image is clipped (nor too dark for 8 bits to tell).
    const bright = await shownAndServedPixels(page, id, '?format=png&exposure=2');
    assert.deepEqual(bright.shown, bright.served);
    let [sumDark, sumBright, used] = [0, 0, 0];
    plain.shown.forEach((dark, i) => {
      if (dark < 40 || bright.shown[i] > 250) return;
      sumDark += linear(dark);
      sumBright += linear(bright.shown[i]);
      used++;
    });
    assert.ok(used > 1000, `enough unclipped values: ${used}`);
    const ratio = sumBright / sumDark;
    assert.ok(Math.abs(ratio - 4) < 0.04, `+2 stops is 4 times the light: ${ratio} over ${used} values`);
    await saveScreenshot('exposure');

    // The keyboard steps half stops: one more reload, at 1.5.
    await page.focus('#exposure');
    await page.keyboard.press('ArrowLeft');
    await page.waitForFunction(() => window.__shown.length === 2);
    assert.deepEqual(requests.slice(1), [`?format=png&exposure=1.5`]);
    assert.equal(await textOf('#exposure-value'), '+1.5 EV');
    const half = await shownAndServedPixels(page, id, '?format=png&exposure=1.5');
    assert.deepEqual(half.shown, half.served);

    // Reset: the render's own again, the plain PNG.
    await page.click('#exposure-reset');
    await page.waitForFunction(() => window.__shown.length === 3);
    assert.deepEqual(requests.slice(2), [`?format=png`]);
    assert.equal(await textOf('#exposure-value'), "±0 EV (render's)");
    assert.equal(await page.inputValue('#exposure'), '0');
    assert.deepEqual((await shownAndServedPixels(page, id, '?format=png')).shown, plain.shown);
    // Each a whole image of the same pass.
    assert.deepEqual(await shownImages(), [1, 2, 3].map(() => ({ pass, blob: true, loaded: true, width: 64, height: 64 })));
  } finally {
    page.off('request', onRequest);
  }
  await page.click('#zoom-fit');
});

test('the compare view splits the image and another job of its size at a divider', { timeout: 60_000 }, async () => {
  const id = inspectedJob;
  assert.ok(id, 'the zoom test rendered a job');
  // Another 64 x 64 job, and one of another size that is not offered.
  const submit = async (name, resolution) => {
    const scene = readScene('cornell-box');
    scene.camera.resolution = resolution;
    scene.render = { ...scene.render, passes: 2, photons_per_pass: 5000, seed: 9 };
    const response = await fetch(new URL(`api/v1/jobs?name=${name}`, server.baseUrl), {
      method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(scene),
    });
    assert.equal(response.status, 201);
    return (await response.json()).id;
  };
  const other = await submit('porch', [64, 64]);
  const wider = await submit('wide-porch', [96, 64]);
  for (const job of [other, wider]) {
    for (let waited = 0; ; waited += 100) {
      const record = await (await fetch(new URL(`api/v1/jobs/${job}`, server.baseUrl))).json();
      if (record.status === 'completed') break;
      assert.ok(waited < 30_000, `job ${job} did not complete: ${JSON.stringify(record)}`);
      await new Promise((r) => setTimeout(r, 100));
    }
  }
  await page.evaluate((jobId) => {
    window.location.hash = `job=${jobId}`;
  }, id);
  await waitForStatus(page, server, id, 'cancelled', 10_000);
  await page.focus('#compare-select'); // the choices are listed anew when the select is opened
  await page.waitForFunction((o) => document.querySelector(`#compare-select option[value="job:${o}"]`), other);
  const options = await page.locator('#compare-select option').evaluateAll((items) => items.map((o) => [o.value, o.textContent]));
  assert.ok(options.some(([value, text]) => value === `job:${other}` && text === 'porch (2 / 2)'), JSON.stringify(options));
  assert.ok(!options.some(([value]) => value === `job:${wider}`), 'a job of another size is not offered');
  assert.deepEqual(options[0], ['', 'nothing']);

  const requests = [];
  const onRequest = (request) => {
    const url = new URL(request.url());
    if (url.pathname.endsWith('/image') && !request.headers()['x-test-check']) requests.push(url.pathname.split('/')[4] + url.search);
  };
  page.on('request', onRequest);
  try {
    await page.selectOption('#compare-select', `job:${other}`);
    await page.waitForFunction(() => document.querySelector('#compare-image').naturalWidth === 64);
    assert.deepEqual(requests, [`${other}?format=png`]);
    let state = await compareState(page);
    const w = state.width;
    assert.deepEqual(state, {
      choice: `job:${other}`, hidden: false, split: 0.5, valuenow: '50',
      clip: [0, 0, 0, Math.round(w / 2)], left: `${Math.round(w / 2)}px`,
      width: w, sameTransform: true, other: { job: other, pass: '2', width: 64 }, labels: [`this job, pass ${await textOf('#job-pass').then((t) => t.split(' ')[0])}`, 'porch'],
    });

    // Dragging the divider: the clip follows it exactly (to the nearest pixel).
    const box = await page.locator('#image-frame').boundingBox();
    await page.evaluate(() => document.querySelector('#compare-divider').addEventListener('pointermove', (event) => {
      const frame = document.querySelector('#image-frame');
      window.__dividerAt = (event.clientX - frame.getBoundingClientRect().left - frame.clientLeft) / frame.clientWidth;
    }));
    await page.mouse.move(box.x + 1 + w / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + 1 + w / 4, box.y + box.height / 3, { steps: 4 });
    await page.mouse.up();
    const at = await page.evaluate(() => window.__dividerAt);
    assert.ok(Math.abs(at - 0.25) < 2 / w, `the divider is where it was dropped: ${at}`);
    state = await compareState(page);
    assert.deepEqual([state.split, state.clip, state.left, state.valuenow],
      [at, [0, 0, 0, Math.round(at * w)], `${Math.round(at * w)}px`, String(Math.round(at * 100))]);
    assert.equal(await page.getAttribute('#image-frame', 'data-mode'), 'fit', 'dragging the divider does not pan the image');

    // Keys on the divider: Home, End, arrows by 1 %, Page Up/Down by 10 %.
    const keys = [['Home', 0], ['ArrowRight', 0.01], ['ArrowRight', 0.02], ['End', 1], ['PageDown', 0.9], ['ArrowLeft', 0.89]];
    for (const [key, split] of keys) {
      await page.keyboard.press(key);
      state = await compareState(page);
      assert.deepEqual([key, state.split, state.clip], [key, split, [0, 0, 0, Math.round(split * w)]]);
    }

    // Zoom applies to both images; another exposure reloads both, once each.
    await page.click('#zoom-in');
    assert.equal((await compareState(page)).sameTransform, true);
    requests.length = 0;
    await page.locator('#exposure').evaluate((slider) => {
      slider.value = '1';
      slider.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await page.waitForFunction(() => document.querySelector('#compare-image').src && document.querySelector('#job-image').src);
    await page.waitForFunction(() => performance.getEntriesByType('resource').filter((e) => e.name.includes('exposure=1')).length >= 2);
    const pass = await page.getAttribute('#job-image', 'data-pass');
    assert.deepEqual(requests.sort(), [`${id}?format=png&exposure=1`, `${other}?format=png&exposure=1`].sort());
    await page.focus('#compare-divider');
    for (const key of ['Home', 'PageUp', 'PageUp', 'PageUp', 'PageUp', 'PageUp']) await page.keyboard.press(key);
    assert.equal((await compareState(page)).split, 0.5);
    await page.click('#zoom-fit');
    await saveScreenshot('compare');

    // Nothing: back to the job's image alone.
    await page.selectOption('#compare-select', '');
    state = await compareState(page);
    assert.deepEqual([state.choice, state.hidden, state.other.job], ['', true, undefined]);
    await page.click('#exposure-reset');
  } finally {
    page.off('request', onRequest);
  }
});

// The raw layer, kept passes and the progress history come with the API that describes them
// (api/openapi.yaml of this checkout): with it, the server built beside it serves them.
const API_KEEPS_PASSES = readFileSync(join(REPO, 'api', 'openapi.yaml'), 'utf8').includes('/api/v1/jobs/{id}/progress:');

// Submits a Cornell box of `size` pixels from Node and waits for it to complete.
async function renderJob(name, size, render) {
  const scene = readScene('cornell-box');
  scene.camera.resolution = [size, size];
  scene.render = { ...scene.render, ...render };
  const response = await fetch(new URL(`api/v1/jobs?name=${name}`, server.baseUrl), {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(scene),
  });
  assert.equal(response.status, 201);
  const { id } = await response.json();
  for (let waited = 0; ; waited += 100) {
    const record = await (await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl))).json();
    if (record.status === 'completed') return record;
    assert.ok(waited < 60_000, `job ${name} did not complete: ${JSON.stringify(record)}`);
    await new Promise((r) => setTimeout(r, 100));
  }
}

test("a denoised job: raw or denoised, its kept passes compared, its plot from the server's history",
  { timeout: 90_000, skip: !API_KEEPS_PASSES && 'api/openapi.yaml has no kept passes yet' }, async () => {
    const record = await renderJob('cellar', 32, { passes: 9, photons_per_pass: 2000, denoise: true, seed: 3 });
    const plain = await renderJob('shed', 32, { passes: 2, photons_per_pass: 2000 });
    const id = record.id;
    assert.deepEqual([record.settings.denoise, record.kept_passes, plain.settings.denoise], [true, [1, 2, 4, 8], false]);

    const requests = []; // the page's image and history requests: "<id><query>" or "<id> progress"
    const onRequest = (request) => {
      const url = new URL(request.url());
      const image = /^\/api\/v1\/jobs\/([^/]+)\/(image|progress|events)$/.exec(url.pathname);
      if (!image || request.headers()['x-test-check']) return;
      if (image[2] === 'image') requests.push(image[1] + url.search);
      else if (image[2] === 'progress') requests.push(`${image[1]} progress`);
      else if (request.headers()['last-event-id'] === '0') requests.push(`${image[1]} events replayed`);
    };
    page.on('request', onRequest);
    try {
      await page.evaluate((jobId) => {
        window.location.hash = `job=${jobId}`;
      }, id);
      await waitForStatus(page, server, id, 'completed', 10_000);
      await page.waitForFunction(() => document.querySelector('#job-image').dataset.pass === '9');
      // The plot's nine passes come from GET /progress, not from replaying the events.
      await page.waitForFunction(() => document.querySelector('#progress-plot').dataset.points === '9');
      assert.deepEqual(requests.filter((r) => r.endsWith(' progress') || r.endsWith(' replayed')), [`${id} progress`]);
      // The list and the figures say it denoises; the choice of layer is there.
      const detail = await page.locator(`#job-list li[data-job-id="${id}"] .job-row-detail`).textContent();
      assert.equal(detail.replace(/ · \d{4}-.*$/, ''), 'SPPM · denoised · 32×32 · pass 9 / 9');
      assert.equal(await textOf('#job-denoise'), 'on');
      assert.equal(await page.isVisible('#layer-choice'), true);
      assert.equal(await page.isChecked('#layer-denoised'), true);

      // Raw: the pass on show once more, its raw layer, pixel for pixel the server's.
      requests.length = 0;
      await watchShownImages();
      const denoised = await shownAndServedPixels(page, id, '?format=png');
      assert.deepEqual(denoised.shown, denoised.served);
      await page.check('#layer-raw');
      await page.waitForFunction(() => window.__shown.length === 1);
      assert.deepEqual(requests, [`${id}?format=png&layer=raw`]);
      const raw = await shownAndServedPixels(page, id, '?format=png&layer=raw');
      assert.deepEqual(raw.shown, raw.served);
      assert.notDeepEqual(raw.shown, denoised.shown, 'the raw layer is not the denoised image');
      // With an exposure: both in the request, and in the PNG download.
      await page.locator('#exposure').evaluate((slider) => {
        slider.value = '1';
        slider.dispatchEvent(new Event('input', { bubbles: true }));
      });
      await page.waitForFunction(() => window.__shown.length === 2);
      assert.deepEqual(requests.slice(1), [`${id}?format=png&layer=raw&exposure=1`]);
      assert.equal(await page.getAttribute('#download-png', 'href'), `/api/v1/jobs/${id}/image?format=png&layer=raw&exposure=1`);

      // Compare with pass 4, kept by the server: its raw layer at the same exposure.
      requests.length = 0;
      const kept = await page.locator('#compare-select optgroup[label="Passes of this job"] option').evaluateAll((items) =>
        items.map((o) => [o.value, o.textContent]));
      assert.deepEqual(kept, [['pass:1', 'pass 1'], ['pass:2', 'pass 2'], ['pass:4', 'pass 4'], ['pass:8', 'pass 8']]);
      await page.selectOption('#compare-select', 'pass:4');
      await page.waitForFunction(() => document.querySelector('#compare-image').dataset.pass === '4' &&
        document.querySelector('#compare-image').complete);
      assert.deepEqual(requests, [`${id}?format=png&pass=4&layer=raw&exposure=1`]);
      assert.deepEqual((await compareState(page)).labels, ['this job, pass 9, raw', 'pass 4, raw']);
      await page.click('#zoom-in');
      await saveScreenshot('compare-kept-pass');

      // Back to the denoised layer: both images again, without layer=raw.
      requests.length = 0;
      await page.check('#layer-denoised');
      await page.waitForFunction(() => window.__shown.length === 3);
      await page.waitForFunction(() => document.querySelector('#compare-image').complete);
      await page.waitForFunction(() => performance.getEntriesByType('resource')
        .filter((e) => e.name.endsWith('pass=4&exposure=1')).length >= 1);
      assert.deepEqual(requests.sort(), [`${id}?format=png&exposure=1`, `${id}?format=png&pass=4&exposure=1`].sort());

      // Another 32 x 32 job, which has no raw layer: asked for without one, also under Raw.
      await page.check('#layer-raw');
      await page.focus('#compare-select');
      await page.waitForFunction((o) => document.querySelector(`#compare-select option[value="job:${o}"]`), plain.id);
      requests.length = 0;
      await page.selectOption('#compare-select', `job:${plain.id}`);
      await page.waitForFunction((o) => document.querySelector('#compare-image').dataset.job === o &&
        document.querySelector('#compare-image').dataset.pass === '2', plain.id);
      assert.deepEqual(requests.filter((r) => r.startsWith(plain.id)), [`${plain.id}?format=png&exposure=1`]);
      assert.deepEqual((await compareState(page)).labels, ['this job, pass 9, raw', 'shed']);
      assert.equal(await textOf('#job-action-error'), '');
      await page.selectOption('#compare-select', '');
      await page.click('#exposure-reset');
      await page.check('#layer-denoised');
      await page.click('#zoom-fit');
    } finally {
      page.off('request', onRequest);
    }
  });

test("the error map: each pixel's estimated error, the server's heat map pixel for pixel", { timeout: 60_000 }, async () => {
  const record = await renderJob('porch', 32, { passes: 4, photons_per_pass: 2000, seed: 5 });
  const id = record.id;
  assert.ok(record.relative_error > 0, `relative error ${record.relative_error}`);
  const requests = [];
  const onRequest = (request) => {
    const url = new URL(request.url());
    if (url.pathname === `/api/v1/jobs/${id}/image` && !request.headers()['x-test-check']) requests.push(url.search);
  };
  page.on('request', onRequest);
  try {
    await page.evaluate((jobId) => {
      window.location.hash = `job=${jobId}`;
    }, id);
    await page.waitForFunction(() => document.querySelector('#job-image').dataset.pass === '4');
    // Not denoised: the image and its error map, no raw layer.
    assert.equal(await page.isVisible('#layer-choice'), true);
    assert.equal(await page.isVisible('#layer-raw-choice'), false);
    assert.equal(await page.isVisible('#layer-error-choice'), true);
    assert.equal(await textOf('#layer-denoised-label'), 'Image');
    assert.equal(await textOf('#job-relative-error'), `${Number((100 * record.relative_error).toPrecision(3))}%`);
    requests.length = 0;
    await watchShownImages();
    await page.check('#layer-error');
    await page.waitForFunction(() => window.__shown.length === 1);
    assert.deepEqual(requests, ['?format=png&layer=error']);
    const map = await shownAndServedPixels(page, id, '?format=png&layer=error');
    assert.deepEqual(map.shown, map.served);
    const image = await shownAndServedPixels(page, id, '?format=png');
    assert.notDeepEqual(map.shown, image.served, 'the error map is not the image');
    assert.equal(await page.getAttribute('#download-png', 'href'), `/api/v1/jobs/${id}/image?format=png&layer=error`);
    await saveScreenshot('error-map');
    await page.check('#layer-denoised');
    await page.waitForFunction(() => window.__shown.length === 2);
    assert.deepEqual(requests.slice(1), ['?format=png']);
  } finally {
    page.off('request', onRequest);
  }
});

test('the page raised no script errors', () => {
  assert.deepEqual(pageErrors, []);
});

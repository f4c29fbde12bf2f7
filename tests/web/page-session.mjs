// The page test's session, shared by the test files that drive the page (page-form.test.mjs,
// page.test.mjs, page-image.test.mjs): one photon-server on a free port with a fresh data folder and one
// Chromium page on it, started before a file's tests and stopped after them (also when a
// check fails), the page's script errors and 404s recorded, and the helpers those files share.
// Each test file runs in a process of its own, so each has a session of its own.

import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { after, before } from 'node:test';
import { assertPrerequisites, launchBrowser, startServer, stopServer, textOf as textIn } from './harness.mjs';

export const SCREENSHOT = resolve(process.env.PHOTON_WEB_SCREENSHOT || join(tmpdir(), 'photon-web.png'));
export const RENDER_TIMEOUT_MS = 120_000;

export let server = null; // { proc, baseUrl, stderr }
export let page = null;
let context = null; // Playwright persistent browser context
let scratch = null; // temp folder: server data + browser profile
let screenshotTaken = false;
export const pageErrors = [];
export const notFound = []; // URLs the page asked for and got a 404 for

// The main screenshot (PHOTON_WEB_SCREENSHOT) was taken: none is needed for diagnosis.
export function markScreenshotTaken() {
  screenshotTaken = true;
}

// Registers the file's before and after hooks.
export function usePageSession() {
  before(async () => {
    assertPrerequisites();
    scratch = mkdtempSync(join(tmpdir(), 'photon-web-test-'));
    server = await startServer(join(scratch, 'data'));
    context = await launchBrowser(join(scratch, 'profile'));
    page = context.pages()[0] || (await context.newPage());
    page.on('pageerror', (error) => pageErrors.push(String(error)));
    page.on('response', (response) => {
      if (response.status() === 404) notFound.push(response.url());
    });
    const response = await page.goto(server.baseUrl);
    assert.equal(response.status(), 200, 'GET / should serve web/index.html');
  });

  after(async () => {
    try {
      if (page && !screenshotTaken) {
        // A check failed before the screenshot: keep what the page showed, for diagnosis.
        mkdirSync(dirname(SCREENSHOT), { recursive: true });
        await page.screenshot({ path: SCREENSHOT, fullPage: true }).catch(() => {});
      }
      if (context) await context.close().catch(() => {});
    } finally {
      await stopServer(server);
      if (scratch) rmSync(scratch, { recursive: true, force: true });
    }
  });
}

// Screenshots of each state, beside PHOTON_WEB_SCREENSHOT: web-page.png -> web-page-<state>.png.
export async function saveScreenshot(state, options = {}) {
  const path = SCREENSHOT.replace(/(\.png)?$/, `-${state}.png`);
  mkdirSync(dirname(path), { recursive: true });
  await page.screenshot({ path, fullPage: true, ...options });
}

export async function textOf(selector) {
  return textIn(page, selector);
}

// Records, in window.__shown, every image the job view puts on show: its pass, whether its
// src is a blob: URL (whole bytes held in memory), and what its load gave.
export async function watchShownImages() {
  await page.evaluate(() => {
    window.__shown = [];
    const img = document.querySelector('#job-image');
    if (window.__shownObserver) window.__shownObserver.disconnect();
    window.__shownObserver = new MutationObserver(() => {
      if (!img.getAttribute('src')) return;
      window.__shown.push({ pass: Number(img.dataset.pass), blob: img.src.startsWith('blob:'), loaded: null });
    });
    window.__shownObserver.observe(img, { attributes: true, attributeFilter: ['src'] });
    if (!window.__shownListening) {
      window.__shownListening = true;
      const settle = (entry) => {
        const last = window.__shown.at(-1);
        if (last && last.loaded === null) Object.assign(last, entry);
      };
      img.addEventListener('load', () => settle({ loaded: true, width: img.naturalWidth, height: img.naturalHeight }));
      img.addEventListener('error', () => settle({ loaded: false }));
    }
  });
}

export async function shownImages() {
  // The last src set may still be loading (from memory: a moment).
  await page.waitForFunction(() => window.__shown.every((image) => image.loaded !== null));
  return page.evaluate(() => window.__shown);
}

// Each image shown was whole: a blob: URL that loaded at the render's size; passes only go up.
export function assertWholeImages(shown, width, height) {
  assert.ok(shown.length >= 1, 'an image was shown');
  for (const image of shown) {
    assert.deepEqual(image, { pass: image.pass, blob: true, loaded: true, width, height });
  }
  const passes = shown.map((image) => image.pass);
  assert.deepEqual([...new Set(passes)].sort((a, b) => a - b), passes, `passes only go up: ${passes}`);
}

// ---- The form ----------------------------------------------------------------------

export async function chooseExample(name) {
  await page.selectOption('#example-select', name);
  await page.waitForFunction(() => document.querySelector('#scene-text').value.trim().startsWith('{'));
}

export async function clearOverrides() {
  for (const id of ['#passes', '#photons-per-pass', '#seed', '#target-error']) await page.fill(id, '');
}

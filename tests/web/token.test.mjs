// Browser test of the web page (web/) against a photon-server that needs an access token
// (--token), with Debian's Chromium driven by playwright-core.
//
//   npm ci --prefix tests/web
//   PHOTON_SERVER_BIN=build/app/photon-server node --test tests/web/token.test.mjs
//
// Starts the server with a random token and one render worker, opens the page and answers
// the token question the job list's first 401 brings up. The page trades the token for a
// session cookie that no script can read, and follows a job with Server-Sent Events
// authorised by that cookie (an EventSource cannot send the token) instead of polling. The
// checks read the server's access log (stderr, one line per answered request), so they see
// what reached the server rather than what the page says it did. The server and the browser
// are stopped at the end, also when a check fails.

import assert from 'node:assert/strict';
import { randomBytes } from 'node:crypto';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import {
  assertPrerequisites,
  countEventStreams,
  launchBrowser,
  occupyWorker,
  readScene,
  releaseWorker,
  startServer,
  stopServer,
  submitScene,
  textOf,
  waitForStatus,
} from './harness.mjs';

const TOKEN = randomBytes(24).toString('hex');
const AUTH = { Authorization: `Bearer ${TOKEN}` };
const RENDER_TIMEOUT_MS = 60_000;
const POLL_MS = 1000; // how often the job view would ask for GET /jobs/{id} if it polled

let server = null; // { proc, baseUrl, stderr }
let context = null; // Playwright persistent browser context
let page = null;
let scratch = null; // temp folder: server data + browser profile
const pageErrors = [];

// ---- Setup -------------------------------------------------------------------------

before(async () => {
  assertPrerequisites();
  scratch = mkdtempSync(join(tmpdir(), 'photon-web-token-test-'));
  // One worker: a job submitted behind the blocking job of occupyWorker() waits in the queue.
  server = await startServer(join(scratch, 'data'), ['--token', TOKEN, '--workers', '1']);
  context = await launchBrowser(join(scratch, 'profile'));
  page = context.pages()[0] || (await context.newPage());
  page.on('pageerror', (error) => pageErrors.push(String(error)));
  const response = await page.goto(server.baseUrl);
  assert.equal(response.status(), 200, 'GET / should serve web/index.html without a token');
});

after(async () => {
  try {
    if (context) await context.close().catch(() => {});
  } finally {
    await stopServer(server);
    if (scratch) rmSync(scratch, { recursive: true, force: true });
  }
});

// ---- Helpers -----------------------------------------------------------------------

function escapeRegExp(text) {
  return text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}

// The server's access log lines for `method path status`, e.g. ('GET', '/api/v1/jobs', 401);
// status undefined matches any status. The log leaves out query strings.
function accessLines(method, path, status) {
  const pattern = new RegExp(` ${method} ${escapeRegExp(path)} ${status ?? '\\d{3}'}( |$)`);
  return server.stderr.split('\n').filter((line) => pattern.test(line));
}

// A stream's line is written when the stream ends, a moment after the page has seen its end.
async function waitForAccessLine(method, path, status, timeout) {
  for (let waited = 0; accessLines(method, path, status).length === 0; waited += 50) {
    assert.ok(
      waited < timeout,
      `no "${method} ${path} ${status}" in the server's access log within ${timeout} ms; server log:\n` +
        server.stderr.slice(-2000),
    );
    await new Promise((r) => setTimeout(r, 50));
  }
}

// ---- Tests -------------------------------------------------------------------------

test('the first 401 asks for the token, which is traded for an HttpOnly session cookie', async () => {
  const dialog = page.locator('#token-dialog');
  await dialog.waitFor({ state: 'visible' });
  assert.match(await textOf(page, '#token-message'), /needs an access token/);
  assert.ok(accessLines('GET', '/api/v1/jobs', 401).length >= 1, 'the job list was refused before the question');

  await page.fill('#token-input', TOKEN);
  await page.getByRole('button', { name: 'Use token' }).click();
  await dialog.waitFor({ state: 'hidden' });
  // The job list's retry, with the token, went through.
  await page.waitForFunction(() => document.querySelector('#job-list-status').textContent === 'No jobs yet.');
  assert.equal(await textOf(page, '#server-status'), '');

  await waitForAccessLine('POST', '/api/v1/session', 204, 5_000);
  assert.equal(accessLines('POST', '/api/v1/session').length, 1, 'one session per token');

  // The browser holds the cookie, as the server set it...
  const cookie = (await context.cookies(server.baseUrl)).find((c) => c.name === 'photon_session');
  assert.ok(cookie, 'the browser stored the photon_session cookie');
  assert.match(cookie.value, /^[0-9a-f]{64}$/);
  assert.equal(cookie.httpOnly, true);
  assert.equal(cookie.sameSite, 'Strict');
  // ...but HttpOnly keeps it from the page's scripts.
  const visible = await page.evaluate(() => document.cookie);
  assert.doesNotMatch(visible, /photon_session/, 'document.cookie must not show the session cookie');
});

test('a job is followed with events authorised by the cookie, not polled', { timeout: RENDER_TIMEOUT_MS + 60_000 }, async (t) => {
  await countEventStreams(page);
  const blocker = await occupyWorker(server, AUTH);

  const scene = readScene('cornell-box');
  scene.camera.resolution = [16, 16];
  scene.render = { ...scene.render, passes: 6, photons_per_pass: 2000 };
  const id = await submitScene(server, scene, AUTH);
  const jobPath = `/api/v1/jobs/${id}`;

  // The address bar opens the job, as a link or a reload would.
  await page.goto(`${server.baseUrl}#job=${encodeURIComponent(id)}`);
  // 'open' fires only on a 200: the stream got past the server's authorisation, which
  // the page can only have passed with the cookie.
  await page.waitForFunction(
    (jobId) =>
      document.querySelector('#job-id').textContent === jobId &&
      document.querySelector('#job-status').textContent === 'queued' &&
      window.__openEventStreams >= 1,
    id,
  );
  // Held in the queue for longer than two poll periods: a view that polled beside (or
  // instead of) its stream would have asked for the job again by now.
  await new Promise((r) => setTimeout(r, 2 * POLL_MS + 500));
  await releaseWorker(server, blocker, AUTH);

  await waitForStatus(page, server, id, 'completed', RENDER_TIMEOUT_MS, AUTH);
  assert.equal(await textOf(page, '#job-pass'), '6 / 6');
  // With a token the view fetches the image with the bearer header and shows it from memory
  // (a blob: URL); it labels it with the last pass.
  await page.waitForFunction(() => {
    const img = document.querySelector('#job-image');
    return (
      !img.hidden &&
      img.src.startsWith('blob:') &&
      img.complete &&
      img.naturalWidth === 16 &&
      img.naturalHeight === 16 &&
      img.dataset.pass === '6'
    );
  });

  await waitForAccessLine('GET', `${jobPath}/events`, 200, 5_000);
  assert.deepEqual(accessLines('GET', `${jobPath}/events`, 401), [], 'no event stream was refused');
  const gets = accessLines('GET', jobPath);
  t.diagnostic(`GET ${jobPath}: ${gets.length} request(s)`);
  assert.ok(gets.length <= 2, `the job view polled the job instead of following its events:\n${gets.join('\n')}`);
});

test('the page raised no script errors', () => {
  assert.deepEqual(pageErrors, []);
});

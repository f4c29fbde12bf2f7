// What the browser tests of the web page (page.test.mjs, token.test.mjs) share: a real
// photon-server on a free port serving this checkout's web/, Debian's Chromium driven by
// playwright-core (no browser download), and helpers that talk to the server from Node.
//
// PHOTON_SERVER_BIN names the photon-server binary to test.

import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';

let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch (error) {
  throw new Error(`playwright-core is not installed: run \`npm ci --prefix tests/web\` first (${error.message})`);
}

export const REPO = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const WEB_ROOT = join(REPO, 'web');
export const CHROMIUM = '/usr/bin/chromium';
export const SERVER_BIN = process.env.PHOTON_SERVER_BIN ? resolve(process.env.PHOTON_SERVER_BIN) : '';

// Fails with what to do when the server binary or the browser is missing.
export function assertPrerequisites() {
  assert.ok(SERVER_BIN, 'set PHOTON_SERVER_BIN to the photon-server binary');
  assert.ok(existsSync(SERVER_BIN), `PHOTON_SERVER_BIN does not exist: ${SERVER_BIN}`);
  assert.ok(existsSync(CHROMIUM), `${CHROMIUM} is missing: apt-get install -y chromium`);
}

// ---- Server ------------------------------------------------------------------------

const running = new Set(); // server processes not yet seen to exit

function isRunning(proc) {
  return proc.exitCode === null && proc.signalCode === null;
}

function serverArgs(dataDir, extraArgs) {
  // The server serves its --web-root at "/": this checkout's web/.
  return ['--host', '127.0.0.1', '--port', '0', '--data', dataDir, '--web-root', WEB_ROOT, ...extraArgs];
}

// Starts photon-server with a data folder of its own and waits for the address it prints.
// Resolves to { proc, baseUrl, stderr }: stderr holds everything the server has written to
// it so far (its log, one access line per answered request) and keeps growing. A server
// that does not come up is stopped before the promise rejects.
export function startServer(dataDir, extraArgs = []) {
  return new Promise((resolvePromise, reject) => {
    const proc = spawn(SERVER_BIN, serverArgs(dataDir, extraArgs), { cwd: REPO, stdio: ['ignore', 'pipe', 'pipe'] });
    const state = { proc, baseUrl: null, stderr: '' };
    running.add(proc);
    const fail = (error) => {
      clearTimeout(timer);
      if (isRunning(proc)) proc.kill('SIGKILL');
      reject(error);
    };
    proc.stderr.on('data', (chunk) => {
      state.stderr += chunk;
    });
    const timer = setTimeout(() => fail(new Error(`photon-server did not print its address within 30 s\n${state.stderr}`)), 30_000);
    const lines = createInterface({ input: proc.stdout });
    lines.once('line', (line) => {
      clearTimeout(timer);
      const match = /^photon-server listening on (http:\/\/127\.0\.0\.1:\d+\/)$/.exec(line.trim());
      if (!match) return fail(new Error(`unexpected first line from photon-server: ${JSON.stringify(line)}`));
      state.baseUrl = match[1];
      lines.on('line', () => {}); // keep draining stdout
      resolvePromise(state);
    });
    proc.once('error', fail);
    proc.once('exit', (code, signal) => {
      running.delete(proc);
      if (!state.baseUrl) fail(new Error(`photon-server exited (${code ?? signal}) before listening\n${state.stderr}`));
    });
  });
}

// SIGTERM, then SIGKILL if the server has not exited after 10 s. Does nothing for a server
// that never started or has already exited.
export async function stopServer(state) {
  if (!state || !isRunning(state.proc)) return;
  const { proc } = state;
  const exited = new Promise((r) => proc.once('exit', r));
  proc.kill('SIGTERM');
  let timer;
  const timeout = new Promise((r) => {
    timer = setTimeout(() => r('timeout'), 10_000);
  });
  const outcome = await Promise.race([exited, timeout]);
  clearTimeout(timer);
  if (outcome === 'timeout') {
    proc.kill('SIGKILL');
    await exited;
  }
}

// If the test process itself is killed, do not leave a server behind.
process.on('exit', () => {
  for (const proc of running) if (isRunning(proc)) proc.kill('SIGKILL');
});

// ---- Browser -----------------------------------------------------------------------

// Chromium, headless, with its profile in profileDir: a Playwright persistent context whose
// pages()[0] is the first tab.
export function launchBrowser(profileDir) {
  return chromium.launchPersistentContext(profileDir, {
    executablePath: CHROMIUM,
    headless: true,
    args: [
      '--headless',
      '--no-sandbox',
      '--disable-gpu',
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
    ],
    viewport: { width: 1440, height: 1000 },
  });
}

export async function textOf(page, selector) {
  return (await page.locator(selector).textContent()).trim();
}

// Counts, in window.__openEventStreams, the event streams the page opens from now on: an
// EventSource's 'open' fires only once the server has answered 200, so a test can wait
// until the job view is really following its job.
export async function countEventStreams(page) {
  await page.evaluate(() => {
    window.__openEventStreams = 0;
    const Native = window.EventSource;
    window.EventSource = class extends Native {
      constructor(...args) {
        super(...args);
        this.addEventListener('open', () => window.__openEventStreams++);
      }
    };
  });
}

// Waits for the job view to show `status`; on a timeout the error says what the page, the
// server's record of the job and the server's log showed instead. `headers` go with the
// request for the record (the bearer token of a server that needs one).
export async function waitForStatus(page, server, id, status, timeout, headers = {}) {
  try {
    await page.waitForFunction((want) => document.querySelector('#job-status').textContent === want, status, {
      timeout,
    });
  } catch (error) {
    const record = await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl), { headers }).then(
      (r) => r.text(),
      (e) => String(e),
    );
    throw new Error(
      `job ${id} did not show "${status}" within ${timeout} ms: the page shows "${await textOf(page, '#job-status')}" ` +
        `(action error "${await textOf(page, '#job-action-error')}"), the server has ${record}; server log:\n` +
        server.stderr.slice(-2000),
      { cause: error },
    );
  }
}

// ---- Jobs from Node ----------------------------------------------------------------

// A scene of scenes/, parsed.
export function readScene(name) {
  return JSON.parse(readFileSync(join(REPO, 'scenes', `${name}.json`), 'utf8'));
}

// Submits a scene as JSON; resolves to the job's id.
export async function submitScene(server, scene, headers = {}) {
  const response = await fetch(new URL('api/v1/jobs', server.baseUrl), {
    method: 'POST',
    headers: { ...headers, 'Content-Type': 'application/json' },
    body: JSON.stringify(scene),
  });
  const text = await response.text();
  assert.equal(response.status, 201, text);
  return JSON.parse(text).id;
}

// Occupies the server's one render worker with a job that would run for hours, so that a job
// submitted next waits in the queue until releaseWorker() cancels it: a test can then watch
// that job from its first pass on, however fast the machine renders.
export async function occupyWorker(server, headers = {}) {
  const scene = readScene('cornell-box');
  scene.camera.resolution = [16, 16];
  scene.render = { ...scene.render, passes: 100000, photons_per_pass: 100000 };
  const id = await submitScene(server, scene, headers);
  for (let waited = 0; ; waited += 50) {
    const job = await (await fetch(new URL(`api/v1/jobs/${id}`, server.baseUrl), { headers })).json();
    if (job.status === 'running') return id;
    assert.ok(waited < 30_000, `the blocking job did not start: ${JSON.stringify(job)}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}

export async function releaseWorker(server, id, headers = {}) {
  const response = await fetch(new URL(`api/v1/jobs/${id}/cancel`, server.baseUrl), { method: 'POST', headers });
  assert.ok(response.ok, `cancel of the blocking job: ${response.status}`);
}

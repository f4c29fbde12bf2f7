// Browser test of the page's form (web/submit-form.js) against a real photon-server: the
// bundled examples and the icon, the number fields' placeholders from the scene, the form's
// contents kept across a reload, and errors: JSON syntax (caret, scrolling) and the server's
// scene errors (message, selection of the member it names, cleared on edit). Its own server
// and browser (page-session.mjs); renders and the job view are in page.test.mjs.

import assert from 'node:assert/strict';
import { test } from 'node:test';
import { readScene } from './harness.mjs';
import {
  chooseExample,
  clearOverrides,
  markScreenshotTaken,
  notFound,
  page,
  pageErrors,
  saveScreenshot,
  server,
  textOf,
  usePageSession,
} from './page-session.mjs';

usePageSession();
markScreenshotTaken(); // the main screenshot is page.test.mjs's; this file saves its own states

// The scene editor's selection, and whether it has the focus (a selection shows only then).
async function sceneSelection() {
  return page.locator('#scene-text').evaluate((area) =>
    ({ focused: document.activeElement === area, start: area.selectionStart, end: area.selectionEnd }));
}

test('the page loads with the bundled examples', async () => {
  assert.equal(await page.title(), 'photon render service');
  const options = await page.locator('#example-select option').evaluateAll((els) => els.map((e) => e.value));
  assert.deepEqual(options.filter(Boolean), ['cornell-box', 'cornell-glass', 'point-light-plane']);
  for (const id of ['#submit-button', '#job-list', '#scene-text', '#passes', '#photons-per-pass', '#seed']) {
    assert.equal(await page.locator(id).count(), 1, `${id} is on the page`);
  }
  // The icon: served from the web root as SVG, so the browser's request for it is no 404.
  assert.equal(await page.getAttribute('link[rel="icon"]', 'href'), 'favicon.svg');
  const icon = await page.evaluate(async () => {
    const res = await fetch('/favicon.svg');
    return { status: res.status, type: res.headers.get('Content-Type'), svg: (await res.text()).startsWith('<svg') };
  });
  assert.deepEqual(icon, { status: 200, type: 'image/svg+xml', svg: true });
  assert.deepEqual(notFound, []);
});

test("an example's passes, photons and seed are the number fields' placeholders", async () => {
  await chooseExample('cornell-box');
  const placeholders = () => page.locator('#passes, #photons-per-pass, #seed').evaluateAll((inputs) => inputs.map((i) => i.placeholder));
  assert.deepEqual(await placeholders(), ['16', '200000', '1']);
  // They follow the text: another seed typed into the scene.
  const text = (await page.inputValue('#scene-text')).replace('"seed": 1', '"seed": 42');
  await page.fill('#scene-text', text);
  assert.deepEqual(await placeholders(), ['16', '200000', '42']);
  await page.fill('#scene-text', '{');
  assert.deepEqual(await placeholders(), ['', '', '']);
});

test('the form keeps its contents across a reload', async () => {
  await chooseExample('point-light-plane');
  const scene = (await page.inputValue('#scene-text')).replace('"fov": 60', '"fov": 55');
  await page.fill('#scene-text', scene);
  await page.fill('#passes', '3');
  await page.fill('#photons-per-pass', '5000');
  await page.fill('#seed', '7');
  await page.selectOption('#integrator', 'photonmap');
  await page.check('#denoise');
  await page.reload();
  const form = await page.evaluate(() => ({
    example: document.querySelector('#example-select').value,
    scene: document.querySelector('#scene-text').value,
    numbers: ['passes', 'photons-per-pass', 'seed'].map((id) => document.getElementById(id).value),
    integrator: document.querySelector('#integrator').value,
    denoise: document.querySelector('#denoise').checked,
    placeholders: ['passes', 'photons-per-pass', 'seed'].map((id) => document.getElementById(id).placeholder),
  }));
  assert.deepEqual(form, {
    example: 'point-light-plane', scene, numbers: ['3', '5000', '7'], integrator: 'photonmap', denoise: true,
    placeholders: ['16', '200000', '1'],
  });
  await clearOverrides();
  await page.selectOption('#integrator', '');
  await page.uncheck('#denoise');
});

test('invalid JSON is explained next to the textarea and nothing is sent', async () => {
  let posted = 0;
  const onRequest = (request) => {
    if (request.method() === 'POST' && request.url().includes('/api/v1/jobs')) posted++;
  };
  page.on('request', onRequest);
  await page.fill('#scene-text', '{\n  "camera": {\n    "fov": 40,\n  }\n}');
  await page.click('#submit-button');
  const error = page.locator('#scene-error');
  await error.filter({ hasText: 'The scene is not valid JSON' }).waitFor();
  const message = (await error.textContent()).trim();
  assert.match(message, /^The scene is not valid JSON: .+ at line 4, column 3\.$/);
  assert.equal(await page.getAttribute('#scene-text', 'aria-invalid'), 'true');
  assert.equal(await page.getAttribute('#scene-text', 'aria-describedby'), 'scene-error');
  // Next to the textarea: its following sibling in the same field.
  assert.ok(await page.evaluate(() => document.querySelector('#scene-text').nextElementSibling.id === 'scene-error'));
  page.off('request', onRequest);
  assert.equal(posted, 0, 'an unparsable scene must not be sent to the server');
  // The caret is put where the error is: line 4, column 3 (the '}' after a trailing comma).
  assert.deepEqual(await sceneSelection(), { focused: true, start: 33, end: 33 });
  assert.equal('{\n  "camera": {\n    "fov": 40,\n  }\n}'.slice(31, 34), '  }', 'offset 33: line 4, column 3');
  // Editing the scene takes the error away.
  await page.press('#scene-text', 'Delete');
  assert.equal(await textOf('#scene-error'), '');
  assert.equal(await page.getAttribute('#scene-text', 'aria-invalid'), null);
});

test('a syntax error far down the scene is scrolled into sight with the caret on it', async () => {
  await chooseExample('cornell-glass');
  const good = await page.inputValue('#scene-text');
  const text = good.replace('"max_depth": 8,', '"max_depth": 8,,');
  assert.notEqual(text, good);
  await page.fill('#scene-text', text);
  await page.click('#submit-button');
  const offset = text.indexOf(',,') + 1;
  const lines = text.slice(0, offset).split('\n');
  const [line, column] = [lines.length, lines.at(-1).length + 1];
  assert.ok(line > 40, `the error is far down (line ${line})`);
  await page.locator('#scene-error').filter({ hasText: 'not valid JSON' }).waitFor();
  assert.equal(await textOf('#scene-error'),
    `The scene is not valid JSON: expected a property name in double quotes but found ',' at line ${line}, column ${column}.`);
  assert.deepEqual(await sceneSelection(), { focused: true, start: offset, end: offset });
  // The line is inside the textarea's visible part.
  const view = await page.locator('#scene-text').evaluate((area, at) => {
    const style = getComputedStyle(area);
    const lineHeight = Number.parseFloat(style.lineHeight);
    return { top: (at - 1) * lineHeight, lineHeight, scrollTop: area.scrollTop, height: area.clientHeight };
  }, line);
  assert.ok(view.scrollTop > 0, 'the textarea scrolled');
  assert.ok(view.top >= view.scrollTop && view.top + view.lineHeight <= view.scrollTop + view.height,
    `line ${line} is in sight: ${JSON.stringify(view)}`);
  await saveScreenshot('syntax-error');
});

test("a scene error shows the server's message with the JSON path", async () => {
  await chooseExample('cornell-glass');
  const scene = JSON.parse(await page.inputValue('#scene-text'));
  const sphere = scene.shapes.findIndex((s) => s.type === 'sphere');
  assert.ok(sphere >= 0, 'the example has a sphere');
  scene.shapes[sphere].radius = -1;
  const text = JSON.stringify(scene, null, 2);

  // What the server says about this scene, asked directly.
  const direct = await fetch(new URL('api/v1/jobs', server.baseUrl), {
    method: 'POST',
    headers: { 'Content-Type': 'application/json' },
    body: text,
  });
  assert.equal(direct.status, 400);
  const body = await direct.json();
  assert.equal(body.path, `shapes[${sphere}].radius`);
  assert.match(body.error, new RegExp(`^shapes\\[${sphere}\\]\\.radius: must be > 0`));

  await page.fill('#scene-text', text);
  await clearOverrides();
  await page.click('#submit-button');
  const error = page.locator('#scene-error');
  await error.filter({ hasText: 'radius' }).waitFor();
  assert.equal((await error.textContent()).trim(), body.error);
  assert.equal(await textOf('#form-error'), '', 'the scene error is shown by the scene, not at the bottom');
  // The member the error names is selected in the scene text.
  assert.equal(body.pointer, `/shapes/${sphere}/radius`);
  const start = text.indexOf('"radius": -1');
  assert.deepEqual(await sceneSelection(), { focused: true, start, end: start + '"radius": -1'.length });
  await saveScreenshot('error-highlight');
  // Editing takes the error away.
  await page.press('#scene-text', 'End');
  await page.keyboard.type('0');
  assert.equal(await textOf('#scene-error'), '');
  assert.equal(await page.getAttribute('#scene-text', 'aria-invalid'), null);
});

test('the page raised no script errors', () => {
  assert.deepEqual(pageErrors, []);
});

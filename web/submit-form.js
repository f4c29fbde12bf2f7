// The "New render" form: a scene from the bundled examples, a .json file or pasted text, or
// a .pbrt, .gltf or .glb file the server imports (sent as it is);
// asset files with editable relative paths; optional passes, photons per pass, seed and the
// error to stop at (a percentage, sent as target_error);
// the method (render.integrator) and denoising (render.denoise), written into the scene.
// Checks what it can before sending (JSON syntax, whole numbers) and shows every error,
// its own or the server's, next to the field at fault.

import { ApiError, submitJob } from './api.js';
import { EXAMPLES, exampleScene } from './examples.js';
import { rememberForm } from './form-memory.js';
import { formatJson } from './format.js';
import { describeJsonError, locateJsonError } from './json-error.js';
import { locateValue, pathKeys, pointerKeys } from './json-place.js';

const $ = (id) => document.getElementById(id);

// Query parameter -> its input, the input's error element and the words that point at it
// in a server message (first match wins, so "photons_per_pass" is not taken for passes).
const NUMBER_FIELDS = [
  { param: 'photons_per_pass', input: 'photons-per-pass', label: 'Photons per pass', min: 1, words: /photon/i },
  { param: 'passes', input: 'passes', label: 'Passes', min: 1, words: /\bpass(es)?\b/i },
  { param: 'seed', input: 'seed', label: 'Seed', min: 0, words: /\bseed\b/i },
];

// Every string in a parsed scene: candidates for an asset's path.
function sceneStrings(node, out = []) {
  if (typeof node === 'string') out.push(node);
  else if (node && typeof node === 'object') for (const v of Object.values(node)) sceneStrings(v, out);
  return out;
}

export function createSubmitForm({ onSubmitted }) {
  const form = $('submit-form');
  const select = $('example-select');
  const sceneFile = $('scene-file');
  const sceneText = $('scene-text');
  const assetInput = $('asset-files');
  const assetList = $('asset-list');
  const button = $('submit-button');
  const status = $('form-status');
  let assets = []; // { file, pathInput }
  let importedScene = null; // a chosen .pbrt/.gltf/.glb File: sent as it is, not as the text

  for (const example of EXAMPLES) select.add(new Option(example.title, example.name));
  // What was typed and chosen survives a reload (not the files: a page cannot set those).
  const memory = rememberForm(
    form,
    ['example-select', 'scene-text', 'passes', 'photons-per-pass', 'seed', 'target-error', 'integrator', 'denoise'],
    'photon.submit-form',
  );

  // The number fields' placeholders show the scene's own values: what an empty field means.
  function showSceneSettings() {
    let render = {};
    try {
      const scene = JSON.parse(sceneText.value);
      if (scene && typeof scene.render === 'object' && scene.render) render = scene.render;
    } catch {
      // Not JSON (yet): no values to show.
    }
    for (const field of NUMBER_FIELDS) {
      const value = render[field.param];
      $(field.input).placeholder = Number.isInteger(value) ? String(value) : '';
    }
    const target = render.target_error;
    $('target-error').placeholder = typeof target === 'number' && target > 0 ? String(Number((100 * target).toPrecision(6))) : '';
  }
  showSceneSettings();

  function showError(elementId, message, input) {
    $(elementId).textContent = message;
    if (input) input.setAttribute('aria-invalid', 'true');
  }

  // Selects text[start, end) in the scene editor and scrolls it into sight: a textarea does
  // not scroll to a selection made by a script, so the line's offset is worked out here.
  function showInScene(start, end = start) {
    sceneText.focus({ preventScroll: true });
    sceneText.setSelectionRange(start, end);
    const style = getComputedStyle(sceneText);
    const lineHeight = Number.parseFloat(style.lineHeight) || 1.2 * Number.parseFloat(style.fontSize);
    const line = sceneText.value.slice(0, start).split('\n').length - 1;
    const top = line * lineHeight;
    // The line a third of the way down, so what comes before it is in sight too.
    sceneText.scrollTop = Math.max(0, top - sceneText.clientHeight / 3);
    sceneText.scrollIntoView({ block: 'nearest' });
  }

  // The part of the scene a server error names (its JSON Pointer, else its path), selected.
  function selectErrorPlace(error) {
    const keys = error.pointer !== undefined ? pointerKeys(error.pointer) : pathKeys(error.path);
    if (!keys || importedScene) return;
    const place = locateValue(sceneText.value, keys);
    if (place) showInScene(place.start, place.end);
  }

  function clearErrors() {
    for (const el of form.querySelectorAll('.field-error, #form-error')) el.textContent = '';
    for (const el of form.querySelectorAll('[aria-invalid]')) el.removeAttribute('aria-invalid');
    status.textContent = '';
  }

  // The path the scene most likely names for this file: a string ending in "/<name>".
  function guessPath(fileName) {
    try {
      const named = sceneStrings(JSON.parse(sceneText.value));
      return named.find((s) => s === fileName || s.endsWith(`/${fileName}`)) || fileName;
    } catch {
      return fileName;
    }
  }

  function renderAssets() {
    assetList.replaceChildren();
    assets.forEach((asset, index) => {
      const item = document.createElement('li');
      const label = document.createElement('label');
      label.htmlFor = `asset-path-${index}`;
      label.textContent = `Path in the scene for ${asset.file.name}`;
      asset.pathInput.id = `asset-path-${index}`;
      const remove = document.createElement('button');
      remove.type = 'button';
      remove.textContent = 'Remove';
      remove.setAttribute('aria-label', `Remove ${asset.file.name}`);
      remove.addEventListener('click', () => {
        assets = assets.filter((a) => a !== asset);
        renderAssets();
      });
      item.append(label, asset.pathInput, remove);
      assetList.append(item);
    });
  }

  function useImported(file) {
    importedScene = file;
    if (file) sceneText.value = ''; // typing after choosing a file keeps what is typed
    sceneText.placeholder = file ? `${file.name} is sent as it is; the server imports it.` : '';
    showSceneSettings();
  }

  select.addEventListener('change', () => {
    const scene = exampleScene(select.value);
    if (!scene) return;
    useImported(null);
    sceneText.value = formatJson(scene);
    sceneFile.value = '';
    clearErrors();
    showSceneSettings();
    memory.save();
  });

  sceneText.addEventListener('input', () => {
    if (importedScene) useImported(null);
    showSceneSettings();
  });

  // An error goes as soon as the field it is about is edited: it may no longer hold.
  form.addEventListener('input', (event) => {
    const field = event.target;
    if (!field.hasAttribute('aria-invalid')) return;
    field.removeAttribute('aria-invalid');
    const errorId = field.getAttribute('aria-describedby');
    if (errorId && $(errorId)) $(errorId).textContent = '';
  });

  sceneFile.addEventListener('change', async () => {
    const file = sceneFile.files && sceneFile.files[0];
    if (!file) return;
    clearErrors();
    if (/\.(pbrt|gltf|glb)$/i.test(file.name)) {
      useImported(file);
      select.value = '';
      return;
    }
    useImported(null);
    try {
      sceneText.value = await file.text();
      select.value = '';
      showSceneSettings();
      memory.save();
    } catch {
      showError('scene-error', `Could not read ${file.name}.`, sceneText);
    }
  });

  assetInput.addEventListener('change', () => {
    for (const file of assetInput.files || []) {
      const pathInput = document.createElement('input');
      pathInput.type = 'text';
      pathInput.value = guessPath(file.name);
      pathInput.spellcheck = false;
      pathInput.setAttribute('aria-describedby', 'assets-error');
      assets.push({ file, pathInput });
    }
    assetInput.value = ''; // so the same file can be added again after removing it
    renderAssets();
  });

  // The overrides from the number inputs, or null after showing what is wrong.
  function readNumbers() {
    const params = {};
    let ok = true;
    for (const field of NUMBER_FIELDS) {
      const input = $(field.input);
      const text = input.value.trim();
      if (input.validity && input.validity.badInput) {
        showError(`${field.input}-error`, `${field.label} must be a whole number.`, input);
        ok = false;
      } else if (text !== '') {
        if (!/^\d+$/.test(text) || Number(text) < field.min) {
          showError(`${field.input}-error`, `${field.label} must be a whole number of at least ${field.min}.`, input);
          ok = false;
        } else {
          params[field.param] = text;
        }
      }
    }
    // The error to stop at, a percentage: 2 is target_error=0.02.
    const target = $('target-error');
    const percent = target.value.trim();
    if ((target.validity && target.validity.badInput) || (percent !== '' && !(Number(percent) >= 0))) {
      showError('target-error-error', 'Stop at error must be a percentage of at least 0.', target);
      ok = false;
    } else if (percent !== '') {
      params.target_error = String(Number(percent) / 100);
    }
    return ok ? params : null;
  }

  function readAssets() {
    const seen = new Set();
    for (const { file, pathInput } of assets) {
      const path = pathInput.value.trim();
      if (!path) {
        showError('assets-error', `Give the path the scene uses for ${file.name}.`, pathInput);
        return null;
      }
      if (seen.has(path)) {
        showError('assets-error', `Two files have the path ${path}.`, pathInput);
        return null;
      }
      seen.add(path);
    }
    return assets.map(({ file, pathInput }) => ({ file, path: pathInput.value.trim() }));
  }

  // Puts a server error next to the field it is about.
  function showServerError(error) {
    const message = error.message;
    if (!(error instanceof ApiError) || error.status === 0 || error.status === 413 || error.status >= 500) {
      showError('form-error', message);
      return;
    }
    if (error.path !== undefined) {
      showError('scene-error', message, sceneText);
      selectErrorPlace(error);
      return;
    }
    if (/target_error/.test(message) && $('target-error').value.trim() !== '') {
      showError('target-error-error', message, $('target-error'));
      return;
    }
    for (const field of NUMBER_FIELDS) {
      if (field.words.test(message) && $(field.input).value.trim() !== '') {
        showError(`${field.input}-error`, message, $(field.input));
        return;
      }
    }
    if (/\basset\b|\bform field\b|\bupload/i.test(message) && assets.length > 0) {
      showError('assets-error', message, assetInput);
    } else if (/photon|pass|pixel|resolution|width|height|scene|JSON/i.test(message)) {
      // A limit the scene itself exceeds (its own passes, resolution...).
      showError('scene-error', message, sceneText);
    } else {
      showError('form-error', message);
    }
  }

  // The scene as typed, or with the chosen method and denoising written into its "render"
  // block (only when one is chosen, so the server still sees the text itself otherwise).
  // Throws the parser's error for text that is not JSON.
  function sceneWithChoices(text) {
    const scene = JSON.parse(text);
    const integrator = $('integrator').value;
    const denoise = $('denoise').checked;
    if (!integrator && !denoise) return text;
    if (!scene || typeof scene !== 'object' || Array.isArray(scene)) return text; // the server says what is wrong
    const render = scene.render && typeof scene.render === 'object' ? scene.render : {};
    if (integrator) render.integrator = integrator;
    if (denoise) render.denoise = true;
    scene.render = render;
    return JSON.stringify(scene, null, 2);
  }

  form.addEventListener('submit', async (event) => {
    event.preventDefault();
    clearErrors();
    let text = sceneText.value;
    try {
      // An imported file's own settings stand; the overrides below still apply.
      if (!importedScene) text = sceneWithChoices(text);
    } catch (parseError) {
      showError('scene-error', describeJsonError(text, parseError), sceneText);
      const found = locateJsonError(text);
      showInScene(found ? found.offset : 0);
      return;
    }
    const params = readNumbers();
    const files = readAssets();
    if (!params || !files) return;

    button.disabled = true;
    button.textContent = 'Submitting…';
    try {
      const job = await submitJob({ sceneText: text, sceneFile: importedScene, assets: files, params });
      status.textContent = `Submitted job ${job.id}.`;
      onSubmitted(job);
    } catch (error) {
      showServerError(error);
    } finally {
      button.disabled = false;
      button.textContent = 'Submit render';
    }
  });

  return { clearErrors };
}

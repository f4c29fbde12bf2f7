// The page's bundled examples are the scenes in scenes/ at 256x256 with 16 passes, nothing
// else: a change to either side that the other does not follow fails here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { EXAMPLES, exampleScene } from '../../web/examples.js';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

for (const example of EXAMPLES) {
  test(`example ${example.name} is scenes/${example.name}.json at 256x256, 16 passes`, () => {
    const file = JSON.parse(fs.readFileSync(path.join(root, 'scenes', `${example.name}.json`), 'utf8'));
    file.camera.resolution = [256, 256];
    file.render.passes = 16;
    assert.deepStrictEqual(exampleScene(example.name), file);
  });
}

test('each example scene is a copy: changing one leaves the others and the next copy alone', () => {
  const box = exampleScene('cornell-box');
  box.shapes[0].material = 'red';
  box.camera.fov = 90;
  assert.equal(exampleScene('cornell-box').shapes[0].material, 'white');
  assert.equal(exampleScene('cornell-glass').camera.fov, 19.5);
  assert.equal(exampleScene('no-such-example'), null);
});

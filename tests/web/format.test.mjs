// SPPM's photons per pass as the job view shows them (web/format.js, Node alone, no
// browser): with adaptive photon counts the record's photons_per_pass is only where the
// render started, and the count now comes from the job's last two progress points.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { currentPhotonsPerPass, formatPhotonsPerPass } from '../../web/format.js';

// Progress points as the plot keeps them: photons traced after each pass.
const points = (...pairs) => pairs.map(([pass, photons]) => ({ pass, photons }));

test('a count the render changed shows with where it started', () => {
  // 200k for passes 1-4, then 800k (a decision after pass 4 moves it by up to 4x).
  const history = points([3, 600_000], [4, 800_000], [5, 1_600_000], [6, 2_400_000]);
  assert.equal(currentPhotonsPerPass(history), 800_000);
  assert.equal(formatPhotonsPerPass(200_000, history), '800 k (started at 200 k)');
  // Thinned history: the count over the passes between the last two points, in any order.
  assert.equal(formatPhotonsPerPass(200_000, points([16, 3_200_000], [8, 1_600_000], [12, 2_400_000])),
    '200 k');
  assert.equal(formatPhotonsPerPass(200_000, points([8, 1_600_000], [16, 2_000_000])), '50.0 k (started at 200 k)');
});

test('an unchanged count shows alone', () => {
  assert.equal(formatPhotonsPerPass(20_000, points([1, 20_000], [2, 40_000], [3, 60_000], [4, 80_000])), '20.0 k');
  // Counts that read the same are not a change worth showing.
  assert.equal(formatPhotonsPerPass(200_000, points([4, 800_000], [5, 1_000_300])), '200 k');
});

test('before two passes are known the start count shows', () => {
  assert.equal(currentPhotonsPerPass(points([1, 200_000])), null);
  assert.equal(formatPhotonsPerPass(200_000, points([1, 200_000])), '200 k');
  assert.equal(formatPhotonsPerPass(200_000, []), '200 k');
  assert.equal(formatPhotonsPerPass(200_000, undefined), '200 k');
  // Points without photons (a record that lacks them) do not count.
  assert.equal(formatPhotonsPerPass(1000, points([1, 1000], [2, null])), '1.00 k');
  // No start in the record: the count now, else a dash.
  assert.equal(formatPhotonsPerPass(null, points([1, 1000], [2, 5000])), '4.00 k');
  assert.equal(formatPhotonsPerPass(null, []), '—');
});

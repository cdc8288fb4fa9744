// sweep.test.mjs — the sweep view in the browser (issue 16): Ctrl+G shows the grid of renders of
// the default sweep (shininess against k_s), Save PNG downloads it as a PNG of the grid's size,
// and on a phone every part of the window is on the screen.
//
//   node --test --test-name-pattern="sweep" web/tests/
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { PNG } from 'pngjs';
import { withBrowser, newLabPage, settle, widgets } from './page.mjs';

const env = withBrowser();

async function openSweep(page) {
  await page.keyboard.down('Control');
  await page.keyboard.press('g');
  await page.keyboard.up('Control');
  await settle(page);
  return widgets(page);
}

test('sweep: Ctrl+G shows the grid and Save PNG downloads it', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base + '#preset=06-shininess-10', { width: 1024, height: 768 });
  const w = await openSweep(page);
  assert.ok(w['sweep.grid'], 'the grid should be shown');
  const save = w['sweep.save'];
  const [download] = await Promise.all([page.waitForEvent('download'), page.mouse.click(save.x + save.w / 2, save.y + save.h / 2)]);
  const png = PNG.sync.read(fs.readFileSync(await download.path()));
  // Four columns and three rows of 256-pixel cells, and the labels around them.
  assert.ok(png.width > 4 * 256 && png.width < 4 * 256 + 400, `width ${png.width}`);
  assert.ok(png.height > 3 * 256 && png.height < 3 * 256 + 300, `height ${png.height}`);
  const at = (x, y) => png.data[(y * png.width + x) * 4 + 2]; // blue
  assert.equal(at(2, png.height - 2), 255, 'the page is white');
  assert.deepEqual(problems, []);
  await context.close();
});

test('sweep: on a 390x844 phone the whole window is on the screen', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base + '#preset=06-shininess-10', { width: 390, height: 844, touch: true });
  const w = await openSweep(page);
  for (const name of ['sweep', 'sweep.key1', 'sweep.values1', 'sweep.key2', 'sweep.values2', 'sweep.save', 'sweep.grid']) {
    const r = w[name];
    assert.ok(r, `${name} should be shown`);
    assert.ok(r.x >= 0 && r.y >= 0 && r.x + r.w <= 390 && r.y + r.h <= 844, `${name} ${JSON.stringify(r)} is outside the screen`);
  }
  assert.deepEqual(problems, []);
  await context.close();
});

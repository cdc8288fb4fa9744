// moving-light.test.mjs — the moving light in the browser (issue 16): a preset whose light orbits
// keeps drawing (the highlight moves in the live view) at a steady rate, while the view's
// screenshot (F12) shows the preset's own light position, as the native golden does.
//
//   node --test --test-name-pattern="moving light" web/tests/
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { repo, withBrowser, newLabPage, frames, widgets, viewShot, compare, sizeModelViewport } from './page.mjs';

const env = withBrowser();

test('moving light: the orbiting preset moves its highlight over time, and its screenshot is the preset position', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base + '#preset=25-moving-light', { width: 1024, height: 640 });
  const view = (await widgets(page)).view;
  const clip = { x: view.x, y: view.y, width: view.w, height: view.h };
  const drawn = () => page.evaluate(() => Module.ccall('lab_frames', 'number', [], []));
  const first = PNG.sync.read(await page.screenshot({ clip }));
  const framesBefore = await drawn();
  await page.waitForTimeout(1000); // 30 degrees of orbit
  await frames(page, 2);
  const framesAfter = await drawn();
  const second = PNG.sync.read(await page.screenshot({ clip }));
  // The page keeps drawing by itself (60 a second asked for; SwiftShader may manage fewer, and a
  // loaded machine far fewer: 8 with a build beside it, so how many is the benchmark's question)...
  assert.ok(framesAfter - framesBefore >= 3, `frames drawn in 1 s of orbit: ${framesAfter - framesBefore}`);
  // ... and what it draws changes: the highlight has moved.
  const moved = compare(first, second, { pixel: 8 });
  assert.ok(moved.failingShare > 0.002, `the view should change as the light orbits: ${JSON.stringify(moved)}`);
  // The screenshot is the preset's position, whatever the orbit's angle: the native golden.
  const golden = PNG.sync.read(fs.readFileSync(path.join(repo, 'tests/golden/25-moving-light.png')));
  const shotCompare = await (async () => {
    await page.keyboard.press('h');
    await page.keyboard.press('h'); // the view alone, its model's viewport 512x512 as the golden
    await frames(page, 5);
    await sizeModelViewport(page, 512, 512);
    return compare(await viewShot(page), golden);
  })();
  assert.ok(shotCompare.passes, `F12 should show the preset's light position: ${JSON.stringify(shotCompare)}`);
  assert.deepEqual(problems, []);
  await context.close();
});

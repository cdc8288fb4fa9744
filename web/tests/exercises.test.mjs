// exercises.test.mjs — share links, QR codes and exercises in the browser: what `lab share` prints
// and encodes opens the same scene in the page as `lab render` draws, an exercise on a phone shows
// only its open field, its target below the attempt, hints, a live score and Solved, and the page's
// QR code window says the page's own link.
//
//   cd web && node --test --test-concurrency=1 tests/exercises.test.mjs      (after tools/dev web)
//
// Needs the native program (build/lab, or LAB_EXE) and zbarimg (zbar-tools, tools/dev deps).
// Widgets are found through the lab's rectangles (lab_widgets), input is real keys, mouse and touch
// events, QR codes are read back by a real decoder from PNGs. LAB_WEB_SHOTS=folder keeps the pictures.
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { PNG } from 'pngjs';
import { repo, withBrowser, newLabPage, settle, frames, widgets, press, viewShot, compare, finger } from './page.mjs';

const env = withBrowser();
const lab = process.env.LAB_EXE || path.join(repo, 'build/lab');
const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'lab-web-exercises-'));
const shots = process.env.LAB_WEB_SHOTS;
after(() => fs.rmSync(scratch, { recursive: true, force: true }));

const centre = (r) => [r.x + r.w / 2, r.y + r.h / 2];

// What `zbarimg --raw -q` reads in a PNG, without its final line feed.
function decodeQr(png) {
  return execFileSync('zbarimg', ['--raw', '-q', png], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] })
    .replace(/\n$/, '');
}

// `lab share FILE --base BASE --qr PNG`: the printed link and the link its QR code says.
function share(file, base) {
  const png = path.join(scratch, `${path.basename(file, '.json')}-qr.png`);
  const link = execFileSync(lab, ['share', file, '--base', base, '--qr', png], { encoding: 'utf8' }).trim();
  return { link, decoded: decodeQr(png), png };
}

function render(file, width, height) {
  const out = path.join(scratch, `${path.basename(file, '.json')}-${width}x${height}.png`);
  execFileSync(lab, ['render', file, '--out', out, '--size', `${width}x${height}`], { stdio: 'ignore' });
  return PNG.sync.read(fs.readFileSync(out));
}

// A copy of `file` in the scratch folder (so it is not a bundled one), edited by `edit`.
function editedCopy(file, name, edit) {
  const json = JSON.parse(fs.readFileSync(path.join(repo, file), 'utf8'));
  edit(json);
  const copy = path.join(scratch, name);
  fs.writeFileSync(copy, JSON.stringify(json, null, 2));
  return copy;
}

function keep(name, png) {
  if (shots) {
    fs.mkdirSync(shots, { recursive: true });
    fs.writeFileSync(path.join(shots, `exercises-${name}.png`), PNG.sync.write(png));
  }
}

function keepFile(file, name) {
  if (shots) {
    fs.mkdirSync(shots, { recursive: true });
    fs.copyFileSync(file, path.join(shots, name));
  }
}

// The page's own pixels of a rectangle (page units), device pixels in the PNG.
async function picture(page, r) {
  return PNG.sync.read(await page.screenshot({ clip: { x: r.x, y: r.y, width: r.w, height: r.h } }));
}

// The share of pixels that differ by more than 8 levels in a channel (same sizes).
function changedShare(a, b) {
  assert.deepEqual([a.width, a.height], [b.width, b.height]);
  let changed = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if (Math.max(Math.abs(a.data[i] - b.data[i]), Math.abs(a.data[i + 1] - b.data[i + 1]),
                 Math.abs(a.data[i + 2] - b.data[i + 2])) > 8) changed++;
  }
  return changed / (a.width * a.height);
}

// How far the exercise's progress bar is filled, 0..1: the share of a row near its top (above
// the percentage written over it) in the bar's colours (ImGui's yellow, the lab's green when
// solved). The panel is scrolled to the bar first (by `touch`).
async function scoreFill(page, touch) {
  const rects = await widgets(page);
  const name = rects['exercise.solved'] ? 'exercise.solved' : 'exercise.score';
  assert.ok(rects[name], 'the exercise has its score bar');
  const bar = await scrolledTo(page, touch, name);
  const png = await picture(page, bar);
  const y = Math.round(png.height * 0.2);
  let filled = 0;
  for (let x = 0; x < png.width; ++x) {
    const i = 4 * (y * png.width + x);
    const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
    if ((r > 150 && g > 110 && b < 80) || (g > 130 && r < 100 && b < 120)) filled++;
  }
  return filled / png.width;
}


// Scrolls the control panel by its scrollbar (dragged by the finger, as factor-views.test.mjs
// does) until widget `name` is whole inside it, down or up. Returns the widget's rectangle.
async function scrolledTo(page, touch, name) {
  let rects = await widgets(page);
  const panel = rects.panel, margin = 4;
  assert.ok(panel, 'the control panel is shown');
  assert.ok(rects[name], `the panel has ${name}`);
  const shows = (w) => w && w.y >= panel.y + margin && w.y + w.h <= panel.y + panel.h - margin;
  if (shows(rects[name])) return rects[name];
  const down = rects[name].y > panel.y;
  const x = panel.x + panel.w - 7;
  // On the scrollbar's grab: found by pressing where it must be at the top (or bottom) of the track.
  let y = down ? panel.y + 30 : panel.y + panel.h - 30;
  await touch.down(x, y);
  while (!shows(rects[name]) && y > panel.y && y < panel.y + panel.h) {
    y += down ? 6 : -6;
    await touch.move(x, y);
    rects = await widgets(page);
  }
  await touch.up();
  rects = await widgets(page);
  assert.ok(shows(rects[name]), `${name} ${JSON.stringify(rects[name])} never came into the panel ${JSON.stringify(panel)}`);
  return rects[name];
}

// The names the panel shows over the phone's three panel tabs.
async function panelNames(page, touch) {
  const names = new Set();
  for (const tab of ['model', 'material', 'lights']) {
    await touch.tap(...centre((await widgets(page))[`tab.${tab}`]));
    for (const name of Object.keys(await widgets(page))) names.add(`${tab}:${name}`);
  }
  return names;
}

//----------------------------------------------------------------------------------------
// lab share: the link, its QR code, and the scene the page opens at it
//----------------------------------------------------------------------------------------

test('lab share: the QR code says the printed link, and the page at that link draws what lab render draws', async () => {
  const bundled = path.join(repo, 'presets/05-full-phong.json');
  // Not a bundled preset (another folder, another exponent): the whole scene travels in a #z= link.
  const edited = editedCopy('presets/05-full-phong.json', 'my-phong.json', (p) => { p.material.shininess = 12; });
  const cases = [
    { file: bundled, link: /#preset=05-full-phong$/, title: /05-full-phong\.json/ },
    { file: edited, link: /#z=[A-Za-z0-9_-]+$/, title: /Full Phong/ },
  ];
  const shown = [];
  for (const c of cases) {
    const { link, decoded } = share(c.file, env.base);
    assert.ok(link.startsWith(env.base + '#'), `the link ${link} opens the page at ${env.base}`);
    assert.match(link, c.link);
    assert.equal(decoded, link, 'the QR code says the printed link');

    // The decoded link, as a phone's camera would hand it over, on a laptop-sized page.
    const { page, context, problems } = await newLabPage(env.browser, decoded, { width: 1280, height: 720 });
    assert.match(await page.title(), c.title);
    assert.equal(await page.evaluate(() => location.href), link, 'the page keeps the link it was opened at');
    const view = (await widgets(page)).view;
    const shot = await viewShot(page);
    assert.deepEqual([shot.width, shot.height], [view.w, view.h], 'F12 saves the model\'s viewport');
    // lab render at the page's viewport size, held to the screenshot tests' tolerance (page.mjs
    // compare(): the same one lab.test.mjs holds the page to the native goldens with).
    const native = render(c.file, shot.width, shot.height);
    keep(`share-${path.basename(c.file, '.json')}-page`, shot);
    keep(`share-${path.basename(c.file, '.json')}-native`, native);
    const result = compare(shot, native);
    assert.ok(result.passes, `${path.basename(c.file)}: the page at ${link} differs from lab render: ${JSON.stringify(result)}`);
    assert.deepEqual(problems, []);
    shown.push({ shot, native });
    await context.close();
  }
  // The two scenes differ visibly, so each page matched its own scene and not the other.
  for (const [i, j] of [[0, 1], [1, 0]]) {
    const cross = compare(shown[i].shot, shown[j].native);
    assert.ok(!cross.passes, `the page of ${path.basename(cases[i].file)} also matches the other scene: ${JSON.stringify(cross)}`);
  }
});

test('lab share: an exercise\'s link opens the exercise, a bundled one by name, an edited one whole (#x=)', async () => {
  const bundled = path.join(repo, 'presets/exercises/02-shininess.json');
  const edited = editedCopy('presets/exercises/02-shininess.json', 'my-shininess.json', (e) => {
    e.title = 'Find a softer shininess';
    e.instructions = 'Match the target\'s highlight.';
    delete e.hints; // a whole exercise with three hints is too long for a QR code (lab share says so)
    e.target.material.shininess = 20;
  });
  const targets = [];
  for (const [file, pattern, title] of [[bundled, /#exercise=02-shininess$/, /Find the shininess/],
                                        [edited, /#x=[A-Za-z0-9_-]+$/, /Find a softer shininess/]]) {
    const { link, decoded } = share(file, env.base);
    assert.match(link, pattern);
    assert.equal(decoded, link, 'the QR code says the printed link');
    const { page, context, problems } = await newLabPage(env.browser, decoded, { width: 1280, height: 720 });
    assert.match(await page.title(), title);
    const rects = await widgets(page);
    for (const name of ['exercise.title', 'exercise.score', 'view.a', 'view.b', 'view.label-b', 'material.shininess']) {
      assert.ok(rects[name], `the exercise shows ${name}`);
    }
    assert.equal(rects['material.diffuse'], undefined, 'the diffuse colour is not open');
    // Beside or below the attempt (compare mode's halves: a tall viewport stacks them), the same size.
    const [a, b] = [rects['view.a'], rects['view.b']];
    assert.ok(b.x >= a.x + a.w - 0.5 || b.y >= a.y + a.h - 0.5, `the target ${JSON.stringify(b)} is beside or below the attempt ${JSON.stringify(a)}`);
    assert.ok(Math.abs(a.w - b.w) < 1 && Math.abs(a.h - b.h) < 1, 'the attempt and the target have the same size');
    targets.push({ a: await picture(page, rects['view.a']), b: await picture(page, rects['view.b']) });
    assert.deepEqual(problems, []);
    await context.close();
  }
  assert.ok(changedShare(targets[0].a, targets[1].a) < 0.001, 'both start from the same scene');
  assert.ok(changedShare(targets[0].b, targets[1].b) > 0.001, 'the edited exercise has its own target (a wider highlight)');
});

//----------------------------------------------------------------------------------------
// An exercise on a phone
//----------------------------------------------------------------------------------------

test('phone: an exercise shows only its open field, the target below the attempt, hints, a live score, and Solved', async () => {
  const phone = { width: 390, height: 844, scale: 2, touch: true };
  // The names an exercise must hide, each shown on the same phone for an ordinary preset (so that
  // their absence below means something).
  const locked = ['material:material.diffuse', 'material:material.ambient', 'material:material.specular',
    'material:material.emissive', 'material:ambient_light', 'material:background', 'material:brdf.Phong',
    'material:shading.flat', 'material:terms.specular', 'material:normal_matrix', 'lights:lights.add',
    'lights:lights[0].position', 'model:model.builtin', 'model:compare'];
  {
    const { page, context } = await newLabPage(env.browser, `${env.base}#preset=05-full-phong`, phone);
    const names = await panelNames(page, await finger(page));
    assert.deepEqual(locked.filter((n) => !names.has(n)), [], 'an ordinary preset shows these');
    await context.close();
  }

  const { page, context, problems } = await newLabPage(env.browser, `${env.base}#exercise=02-shininess`, phone);
  const touch = await finger(page);
  assert.match(await page.title(), /Find the shininess/);
  let rects = await widgets(page);
  assert.ok(rects['tab.material'], 'the compact layout, with its tabs');
  // The target is drawn below the attempt (compare mode's second half, stacked), labelled.
  assert.ok(rects['view.a'] && rects['view.b'], 'the attempt and the target');
  assert.ok(rects['view.b'].y >= rects['view.a'].y + rects['view.a'].h - 0.5,
    `the target ${JSON.stringify(rects['view.b'])} is below the attempt ${JSON.stringify(rects['view.a'])}`);
  assert.ok(Math.abs(rects['view.b'].w - rects['view.a'].w) < 1, 'both across the page');
  assert.ok(rects['view.label-b'] && rects['view.label-b'].y < rects['view.b'].y, 'the target\'s label above it');

  const names = await panelNames(page, touch);
  for (const tab of ['model', 'material', 'lights']) {
    assert.ok(names.has(`${tab}:exercise.title`) && names.has(`${tab}:exercise.score`), `the ${tab} tab shows the exercise`);
  }
  assert.ok(names.has('material:material.shininess'), 'the open field has its slider');
  assert.deepEqual(locked.filter((n) => names.has(n)), [], 'no locked field has a widget');
  assert.ok(!names.has('material:exercise.solved'), 'the start does not solve it');

  await touch.tap(...centre((await widgets(page))['tab.material']));
  await frames(page, 2);
  const screenshot = path.join(os.tmpdir(), 'exercise-phone.png');
  await page.screenshot({ path: screenshot });
  keepFile(screenshot, 'exercises-phone.png');
  const targetRect = (await widgets(page))['view.b'];
  const targetBefore = await picture(page, targetRect);

  // Hints, one a tap: each adds its text above the buttons; the exercise has three.
  for (let i = 1; i <= 4; ++i) {
    const hint = await scrolledTo(page, touch, 'exercise.hint');
    const before = await widgets(page);
    const beforeShot = await picture(page, before.panel);
    await touch.tap(...centre(hint));
    const after = await widgets(page);
    const moved = (after['exercise.reset'].y - after['exercise.title'].y) - (before['exercise.reset'].y - before['exercise.title'].y);
    if (i <= 3) {
      assert.ok(moved > 15, `hint ${i}: its text takes room above the buttons (they moved ${moved})`);
      assert.ok(changedShare(beforeShot, await picture(page, after.panel)) > 0.01, `hint ${i} shows`);
    } else {
      assert.equal(moved, 0, 'there is no fourth hint');
    }
  }

  // The score is a progress (issue 38): the start scores 0%, and it follows the slider: a tap far
  // right on the slider (a tiny highlight) scores differently.
  const startFill = await scoreFill(page, touch);
  assert.ok(startFill < 0.02, `the start's bar is empty: ${startFill}`);
  assert.match(await page.evaluate(() => window.labPageModel.exercise.score), /^Score 0%/);
  let slider = await scrolledTo(page, touch, 'material.shininess');
  const left = slider.x, right = slider.x + slider.w;
  await touch.tap(slider.x + slider.w * 0.6, slider.y + slider.h / 2); // on the slider's frame (left of its label), far right of 80
  assert.ok((await widgets(page))['exercise.score'], 'not solved there');
  const percent = () => page.evaluate(() => +(/(\d+)%/.exec(window.labPageModel.exercise.score) || [0, 0])[1]);

  // A student's search: taps along the slider, 2 page units apart, until the lab says Solved (its
  // window is about 5 units wide here); the slider's row moves as the score's text changes, so it
  // is looked up before each tap.
  let solvedAt = null, nearest = 0;
  for (let x = left + (right - left) * 0.3; x < left + (right - left) * 0.7 && solvedAt === null; x += 2) {
    slider = await scrolledTo(page, touch, 'material.shininess');
    await touch.tap(x, slider.y + slider.h / 2);
    if ((await widgets(page))['exercise.solved']) solvedAt = x;
    else nearest = Math.max(nearest, await percent());
  }
  assert.ok(solvedAt !== null, 'some position of the shininess slider solves the exercise');
  assert.ok(nearest > 50 && nearest < 100, `the score rose on the way (a progress): at best ${nearest}% before Solved`);
  await frames(page, 3);
  rects = await widgets(page);
  assert.ok(rects['exercise.solved'] && !rects['exercise.score'], 'Solved stays after the finger is lifted');
  const solvedFill = await scoreFill(page, touch);
  assert.ok(solvedFill > 0.9, `the bar is (nearly) full: ${solvedFill}`);
  const solvedShot = path.join(os.tmpdir(), 'exercise-phone-solved.png');
  await page.screenshot({ path: solvedShot });
  keepFile(solvedShot, 'exercises-phone-solved.png');
  // The note "Solved! ..." takes a second line under the model for a few seconds: the target is
  // compared once its view has its size again.
  for (let waited = 0; waited < 15000 && JSON.stringify((await widgets(page))['view.b']) !== JSON.stringify(targetRect); waited += 250) {
    await page.waitForTimeout(250);
    await frames(page, 1);
  }
  assert.deepEqual((await widgets(page))['view.b'], targetRect, 'the target\'s view has its size again');
  assert.ok(changedShare(targetBefore, await picture(page, targetRect)) < 0.001, 'the target did not change');

  // Start again: back at the start's exponent, not solved.
  await touch.tap(...centre(await scrolledTo(page, touch, 'exercise.reset')));
  rects = await widgets(page);
  assert.ok(rects['exercise.score'] && !rects['exercise.solved'], 'Start again is the start: not solved');
  assert.ok(Math.abs(await scoreFill(page, touch) - startFill) < 0.02, 'with the start\'s score');
  assert.deepEqual(problems, []);
  await context.close();
});

//----------------------------------------------------------------------------------------
// The QR code window (Q)
//----------------------------------------------------------------------------------------

test('Q and the panel\'s QR code button show the page\'s own link as a QR code that a decoder reads', async () => {
  const { page, context, problems } = await newLabPage(env.browser, `${env.base}#preset=05-full-phong`, { width: 1280, height: 720 });
  let rects = await widgets(page);
  await page.mouse.move(...centre(rects.view)); // keys reach the lab over the view
  await press(page, '1'); // flat shading: no longer the bundled preset, a #z= link
  const hash = await page.evaluate(() => location.hash);
  assert.match(hash, /^#z=/);
  const own = await page.evaluate(() => location.origin + location.pathname + location.hash);
  assert.equal(own, `${env.base}${hash}`);
  assert.equal(rects['share.qr'], undefined, 'no QR code before Q');

  await press(page, 'q');
  rects = await widgets(page);
  const qr = rects['share.qr'];
  assert.ok(qr && qr.w > 200 && Math.abs(qr.w - qr.h) < 1, `a large square QR code: ${JSON.stringify(qr)}`);
  const png = path.join(os.tmpdir(), 'qr-page.png');
  await page.screenshot({ path: png, clip: { x: qr.x, y: qr.y, width: qr.w, height: qr.h } });
  keepFile(png, 'exercises-qr-page.png');
  assert.equal(decodeQr(png), own, 'the QR code says the page\'s address and the scene\'s link');
  await page.screenshot({ path: path.join(scratch, 'qr-window.png') });
  keepFile(path.join(scratch, 'qr-window.png'), 'exercises-qr-window.png');

  await press(page, 'q');
  assert.equal((await widgets(page))['share.qr'], undefined, 'Q again closes it');

  assert.deepEqual(problems, []);
  await context.close();

  // The panel's button opens it too; in an exercise it says the exercise's link (its start).
  const exercise = await newLabPage(env.browser, `${env.base}#exercise=02-shininess`, { width: 1280, height: 720 });
  const studentPage = exercise.page;
  assert.match(await studentPage.title(), /Find the shininess/);
  const button = (await widgets(studentPage))['share.code'];
  assert.ok(button, 'the panel has the QR code button');
  await studentPage.mouse.click(...centre(button));
  await settle(studentPage);
  const exerciseQr = (await widgets(studentPage))['share.qr'];
  assert.ok(exerciseQr, 'the button opens the QR code');
  const exercisePng = path.join(scratch, 'qr-exercise.png');
  await studentPage.screenshot({ path: exercisePng, clip: { x: exerciseQr.x, y: exerciseQr.y, width: exerciseQr.w, height: exerciseQr.h } });
  assert.equal(decodeQr(exercisePng), `${env.base}#exercise=02-shininess`);
  assert.deepEqual(exercise.problems, []);
  await exercise.context.close();
});

// libqrencode is a module of its own (qr.js, qr.wasm), fetched the first time the QR code window
// asks for a code (core/share/qr_encoder.h), never with the page.
async function fetched(page) {
  return page.evaluate(() => performance.getEntriesByType('resource').map((e) => new URL(e.name).pathname)
    .filter((p) => /^\/qr\.(js|wasm)$/.test(p)).sort());
}

test('the QR encoder is not part of the first load: it is fetched once, when the QR code window asks for a code', async () => {
  const { page, context, problems } = await newLabPage(env.browser, `${env.base}#preset=05-full-phong`, { width: 1280, height: 720 });
  assert.deepEqual(await fetched(page), [], 'the first load fetched no QR encoder');
  await page.mouse.move(...centre((await widgets(page)).view));
  await press(page, 'q');
  const qr = (await widgets(page))['share.qr'];
  assert.ok(qr, 'the window shows the code once the encoder is here');
  const png = path.join(scratch, 'qr-fetched.png');
  await page.screenshot({ path: png, clip: { x: qr.x, y: qr.y, width: qr.w, height: qr.h } });
  assert.equal(decodeQr(png), `${env.base}#preset=05-full-phong`);
  assert.deepEqual(await fetched(page), ['/qr.js', '/qr.wasm'], 'the encoder was fetched');
  await press(page, 'q');
  await press(page, '1'); // another scene, another link: another code
  await press(page, 'q');
  assert.ok((await widgets(page))['share.qr'], 'the second code is shown');
  assert.deepEqual(await fetched(page), ['/qr.js', '/qr.wasm'], 'a second code fetched nothing more');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a QR encoder that cannot be fetched leaves the window saying why, and the next link tries again', async () => {
  const { page, context } = await newLabPage(env.browser, `${env.base}#preset=05-full-phong`, { width: 1280, height: 720 });
  await page.route('**/qr.wasm', (route) => route.fulfill({ status: 404, body: 'not here' }));
  await page.mouse.move(...centre((await widgets(page)).view));
  await press(page, 'q');
  let rects = await widgets(page);
  assert.equal(rects['share.qr'], undefined, 'no code');
  assert.ok(rects['share.problem'], 'the window says why there is none');
  assert.ok(rects['share.close'], 'and can be closed');
  await page.unroute('**/qr.wasm');
  await press(page, 'q');
  await press(page, '1'); // a new link: the encoder is fetched again
  await press(page, 'q');
  rects = await widgets(page);
  assert.ok(rects['share.qr'], 'the code is shown once the encoder can be fetched');
  assert.equal(rects['share.problem'], undefined);
  await context.close();
});

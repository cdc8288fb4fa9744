// view-text.test.mjs — issue 25 in the browser: on a phone, a tablet and a laptop the model of a
// shipped preset is whole in its viewport and no text of the view (header, caption, message, frame
// time, compare labels) lies over it or over other text, nor a light marker over text.
//
//   node --test web/tests/view-text.test.mjs        (after tools/dev web)
//
// The rectangles are the lab's own (lab_widgets): `view` is the model's viewport (`view.a` and
// `view.b` its halves in compare mode), `view.area` the view with its text strips. Whole means the
// lab's F12 picture of the model's viewport has no model pixel on its border.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, newLabPage, settle, frames, widgets, press, viewShot } from './page.mjs';

const env = withBrowser();

const TEXT = ['view.header', 'view.caption', 'view.toast', 'view.frame-time', 'view.label-a', 'view.label-b'];
const overlap = (a, b) => Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x) > 0.5 && Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y) > 0.5;
const inside = (r, o) => r.x >= o.x - 0.5 && r.y >= o.y - 0.5 && r.x + r.w <= o.x + o.w + 0.5 && r.y + r.h <= o.y + o.h + 0.5;

// What is wrong with the view's text and the model, as a list of sentences.
async function viewProblems(page, mode) {
  const rects = await widgets(page);
  const problems = [];
  const area = rects['view.area'];
  if (!area || !rects.view || !rects['view.header']) return [`${mode}: no view, view.area or view.header`];
  const models = rects['view.a'] ? [rects['view.a'], rects['view.b']] : [rects.view];
  const text = TEXT.filter((n) => rects[n]).map((n) => [n, rects[n]]);
  for (let i = 0; i < text.length; ++i) {
    const [name, r] = text[i];
    if (!inside(r, area)) problems.push(`${mode}: ${name} ${JSON.stringify(r)} leaves the view`);
    for (const m of models) if (overlap(r, m)) problems.push(`${mode}: ${name} ${JSON.stringify(r)} over the model ${JSON.stringify(m)}`);
    for (let j = i + 1; j < text.length; ++j) if (overlap(r, text[j][1])) problems.push(`${mode}: ${name} over ${text[j][0]}`);
    for (const [marker, m] of Object.entries(rects)) {
      if (/^view\.light\d/.test(marker) && overlap(r, m)) problems.push(`${mode}: ${marker} over ${name}`);
    }
  }
  if (models.length === 1) {
    const shot = await viewShot(page);
    const bg = shot.data.slice(0, 3);
    let touched = false, model = 0;
    for (let y = 0; y < shot.height; ++y) {
      for (let x = 0; x < shot.width; ++x) {
        const i = 4 * (y * shot.width + x);
        if (Math.abs(shot.data[i] - bg[0]) + Math.abs(shot.data[i + 1] - bg[1]) + Math.abs(shot.data[i + 2] - bg[2]) > 6) {
          model++;
          touched ||= x === 0 || y === 0 || x === shot.width - 1 || y === shot.height - 1;
        }
      }
    }
    if (touched) problems.push(`${mode}: the model is cut at its viewport's border (${shot.width}x${shot.height})`);
    if (model < shot.width * shot.height / 20) problems.push(`${mode}: the model fills ${model} of ${shot.width * shot.height} pixels`);
  }
  return problems;
}

const screens = [
  ['phone', { width: 390, height: 844, scale: 2, touch: true }],
  ['tablet', { width: 768, height: 1024, scale: 2, touch: true }],
  ['laptop', { width: 1280, height: 720 }],
];

for (const [device, options] of screens) {
  test(`on a ${device} (${options.width}x${options.height}) the model is whole and no text covers it, normal, presenter and compare`, async () => {
    const failures = [];
    for (const preset of ['05-full-phong', '13-cook-torrance-beckmann-schlick', '24-gltf-trefoil']) {
      const { page, context, problems } = await newLabPage(env.browser, `${env.base}#preset=${preset}`, options);
      const rects = await widgets(page);
      assert.ok(rects['view.toast'], `${preset}: the opening message is shown`);
      failures.push(...await viewProblems(page, `${preset} normal`));
      await press(page, 'p');
      await frames(page, 2);
      await settle(page);
      assert.ok((await widgets(page))['view.caption'], `${preset}: presenter mode shows the caption`);
      failures.push(...await viewProblems(page, `${preset} presenter`));
      await press(page, 'c');
      failures.push(...await viewProblems(page, `${preset} presenter, compare`));
      assert.deepEqual(problems, []);
      await context.close();
    }
    assert.deepEqual(failures, []);
  });
}

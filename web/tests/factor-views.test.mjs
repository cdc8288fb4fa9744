// factor-views.test.mjs — issue 26 in the browser: the equation's factor buttons show a factor of
// the lighting equation across the model (a colour map on black, a legend strip under the model),
// and the wipe puts the lit model left of a divider that a finger drags.
//
//   cd web && node --test --test-concurrency=1 tests/factor-views.test.mjs      (after tools/dev web)
//
// Widgets are found through the lab's rectangles (lab_widgets), input is real mouse and touch
// events, and pictures are the page's own pixels (screenshots of the model's viewport).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { PNG } from 'pngjs';
import { withBrowser, newLabPage, settle, frames, widgets, finger } from './page.mjs';

const env = withBrowser();
const PRESET = '13-cook-torrance-beckmann-schlick';

const centre = (r) => [r.x + r.w / 2, r.y + r.h / 2];
const inside = (r, o) => r.x >= o.x - 0.5 && r.y >= o.y - 0.5 && r.x + r.w <= o.x + o.w + 0.5 && r.y + r.h <= o.y + o.h + 0.5;
const overlap = (a, b) => Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x) > 0.5 && Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y) > 0.5;
const containers = new Set(['window', 'view', 'view.area', 'view.a', 'view.b', 'panel', 'plots', 'plots.area', 'tabs']);

// The mouse as a pointer: press, move (a frame each), release; a click.
function mouse(page) {
  return {
    down: async (x, y) => { await page.mouse.move(x, y); await page.mouse.down(); },
    move: async (x, y) => { await page.mouse.move(x, y); await frames(page, 1); },
    up: async () => { await page.mouse.up(); await settle(page); },
    async tap(x, y) {
      await page.mouse.click(x, y);
      await settle(page);
    },
  };
}


// From a to b in `steps` moves.
async function drag(pointer, [ax, ay], [bx, by], steps = 8) {
  await pointer.down(ax, ay);
  for (let k = 1; k <= steps; ++k) await pointer.move(ax + (bx - ax) * k / steps, ay + (by - ay) * k / steps);
  await pointer.up();
}

// Scrolls the control panel until widget `name` is whole inside it, by its scrollbar: pressed at
// the top of the track (the panel's right edge; ImGui's scrollbar is at least 14 units wide, 22
// for a finger) and dragged down until the widget shows. (A drag on the panel's background or the
// mouse wheel would do where they work: see panel-scroll.test.mjs.) Returns the widget's rectangle.
async function scrolledTo(page, pointer, name) {
  let rects = await widgets(page);
  const panel = rects.panel, margin = 4;
  assert.ok(panel, 'the control panel is shown');
  const shows = (w) => w && w.y >= panel.y + margin && w.y + w.h <= panel.y + panel.h - margin;
  if (shows(rects[name])) return rects[name];
  assert.ok(rects[name], `the panel has ${name}`);
  const x = panel.x + panel.w - 7;
  let y = panel.y + 30; // below a title bar: on the grab at the top, or the grab jumps to it
  await pointer.down(x, y);
  while (!shows(rects[name]) && y < panel.y + panel.h) {
    y += 6;
    await pointer.move(x, y); // a frame
    rects = await widgets(page);
  }
  await pointer.up();
  rects = await widgets(page);
  assert.ok(shows(rects[name]), `${name} ${JSON.stringify(rects[name])} never came into the panel ${JSON.stringify(panel)}`);
  return rects[name];
}

// The model's viewport as the page shows it (device pixels), and its pixel at (x, y) in page units
// from the viewport's top left.
async function viewPicture(page, view) {
  const png = PNG.sync.read(await page.screenshot({ clip: { x: view.x, y: view.y, width: view.w, height: view.h } }));
  const s = png.width / view.w;
  png.at = (x, y) => {
    const i = 4 * (Math.min(png.height - 1, Math.round(y * s)) * png.width + Math.min(png.width - 1, Math.round(x * s)));
    return [png.data[i], png.data[i + 1], png.data[i + 2]];
  };
  png.scale = s;
  return png;
}

// Pixels of the columns [x0, x1) (page units from the view's left) that differ by more than
// `pixel` levels in a channel, as a share of the columns' pixels.
function changedShare(a, b, x0, x1, pixel = 8) {
  assert.equal(a.width, b.width);
  const c0 = Math.round(x0 * a.scale), c1 = Math.round(x1 * a.scale);
  let changed = 0, count = 0;
  for (let y = 0; y < a.height; ++y) {
    for (let x = c0; x < c1; ++x) {
      const i = 4 * (y * a.width + x);
      count++;
      if (Math.max(Math.abs(a.data[i] - b.data[i]), Math.abs(a.data[i + 1] - b.data[i + 1]), Math.abs(a.data[i + 2] - b.data[i + 2])) > pixel) changed++;
    }
  }
  return changed / count;
}

// Viridis' ends: dark purple (68, 1, 84) at the low end, yellow-green to yellow at the high end.
const black = ([r, g, b]) => r + g + b === 0;
const brightYellowGreen = (r, g, b) => g > 180 && r > 100 && b < 120;
const darkPurple = (r, g, b) => r > 40 && r < 90 && g < 40 && b > 60 && b < 130;

// The share of the columns [x0, x1) (page units) in the lit preset's blue: blue well above red and green.
function litBlue(png, x0, x1) {
  const c0 = Math.round(x0 * png.scale), c1 = Math.round(x1 * png.scale);
  let blue = 0;
  for (let y = 0; y < png.height; ++y) {
    for (let x = c0; x < c1; ++x) {
      const i = 4 * (y * png.width + x);
      const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
      if (b > 60 && b > 1.5 * r && b > 1.4 * g) blue++;
    }
  }
  return blue / ((c1 - c0) * png.height);
}

function census(png) {
  let bright = 0, purple = 0, blackCount = 0;
  for (let i = 0; i < png.data.length; i += 4) {
    const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
    if (r + g + b === 0) blackCount++;
    else if (brightYellowGreen(r, g, b)) bright++;
    else if (darkPurple(r, g, b)) purple++;
  }
  return { bright, purple, black: blackCount, pixels: png.width * png.height };
}

function keep(png, name) {
  if (process.env.LAB_WEB_SHOTS) {
    fs.mkdirSync(process.env.LAB_WEB_SHOTS, { recursive: true });
    fs.writeFileSync(path.join(process.env.LAB_WEB_SHOTS, `factor-views-${name}.png`), PNG.sync.write(png));
  }
}

test('laptop: the D button shows D on black with one bright spot, its legend strip under the model', async () => {
  const { page, context, problems } = await newLabPage(env.browser, `${env.base}#preset=${PRESET}`, { width: 1280, height: 720 });
  let rects = await widgets(page);
  const lit = await viewPicture(page, rects.view);
  keep(lit, 'laptop-lit');
  const litCorner = lit.at(2, 2);
  assert.ok(litCorner[0] + litCorner[1] + litCorner[2] > 20, `the lit preset's background is not black: ${litCorner}`);
  assert.equal(rects['view.legend'], undefined, 'the lit model has no legend');

  const d = await scrolledTo(page, mouse(page), 'equation.d');
  await mouse(page).tap(...centre(d));
  rects = await widgets(page);
  const view = rects.view; // the legend's strip may take some of the model's height
  const shown = await viewPicture(page, view);
  keep(shown, 'laptop-d');
  assert.deepEqual(shown.at(2, 2), [0, 0, 0], 'a factor is drawn on black: the viewport\'s corner');
  assert.deepEqual(shown.at(view.w - 3, view.h - 3), [0, 0, 0], 'and its opposite corner');
  const c = census(shown);
  const model = c.pixels - c.black;
  assert.ok(model > c.pixels / 20, `the model covers the view: ${JSON.stringify(c)}`);
  assert.ok(c.bright > 20, `D's peak is bright yellow-green somewhere: ${JSON.stringify(c)}`);
  assert.ok(c.bright < model / 4, `... in one spot, not across the model: ${JSON.stringify(c)}`);
  assert.ok(c.purple > model / 2, `D is mostly dark purple (viridis' low end): ${JSON.stringify(c)}`);
  const legend = rects['view.legend'], bar = rects['view.legend-bar'];
  assert.ok(legend, 'a value view has its legend strip');
  assert.ok(legend.w > 0 && legend.h > 0, `the legend has a size: ${JSON.stringify(legend)}`);
  assert.ok(legend.y >= view.y + view.h - 0.5, `the legend ${JSON.stringify(legend)} lies below the model ${JSON.stringify(view)}`);
  assert.ok(!overlap(legend, rects.view), 'the legend does not cover the model');
  assert.ok(inside(legend, rects['view.area']), `the legend is in the view's area ${JSON.stringify(rects['view.area'])}`);
  assert.ok(bar && bar.w > legend.w / 3 && inside(bar, legend), `the legend's bar ${JSON.stringify(bar)} is inside it ${JSON.stringify(legend)}`);
  assert.deepEqual(problems, []);
  await context.close();
});

test('phone: the wipe shows the lit model left of its divider, and a finger on the handle moves the divider, not the camera', async () => {
  const { page, context, problems } = await newLabPage(env.browser, `${env.base}#preset=${PRESET}`,
    { width: 390, height: 844, scale: 2, touch: true });
  const touch = await finger(page);
  let rects = await widgets(page);
  const lit = await viewPicture(page, rects.view);
  keep(lit, 'phone-lit');
  const background = lit.at(2, 2);
  assert.ok(background[0] + background[1] + background[2] > 20, `the lit preset's background is not black: ${background}`);
  assert.ok(rects['tab.material'], 'the compact layout, with its tabs');
  await touch.tap(...centre(rects['tab.material']));

  const d = await scrolledTo(page, touch, 'equation.d');
  await touch.tap(...centre(d));
  rects = await widgets(page);
  const view = rects.view; // the legend's strip takes some of the model's height
  assert.ok(rects['view.legend'] && rects['view.legend'].y >= view.y + view.h - 0.5, 'the legend lies under the model');
  const dView = await viewPicture(page, view);
  keep(dView, 'phone-d');
  assert.ok(black(dView.at(2, 2)) && black(dView.at(view.w - 3, 2)), 'D is drawn on black');
  assert.equal(rects['view.wipe'], undefined, 'no divider before the wipe is on');

  const wipe = await scrolledTo(page, touch, 'equation.wipe');
  await touch.tap(wipe.x + wipe.h / 2, wipe.y + wipe.h / 2); // the checkbox's box
  rects = await widgets(page);
  assert.ok(rects['view.wipe'], 'the wipe\'s handle is shown');
  assert.deepEqual(rects.view, view);
  const [hx, hy] = centre(rects['view.wipe']);
  assert.ok(Math.abs(hx - (view.x + view.w / 2)) <= 3, `the divider starts in the middle: ${hx} in ${JSON.stringify(view)}`);
  assert.ok(hy > view.y && hy < view.y + view.h, 'the handle is on the model\'s viewport');
  const wiped = await viewPicture(page, view);
  keep(wiped, 'phone-wiped');
  const half = view.w / 2, gap = rects['view.wipe'].w / 2 + 3;
  assert.deepEqual(wiped.at(2, 2), background, 'left of the divider: the lit model on the preset\'s background');
  assert.ok(black(wiped.at(view.w - 3, 2)), `right of it: D on black (${wiped.at(view.w - 3, 2)})`);
  assert.ok(changedShare(wiped, dView, 0, half - gap) > 0.2, 'the left part is not D');
  assert.ok(litBlue(wiped, 0, half - gap) > 0.05, 'the left part shows the lit model\'s blue');
  assert.ok(litBlue(wiped, 0, half - gap) > 3 * litBlue(dView, 0, half - gap), '(far more than D\'s blue-green ring there)');
  assert.ok(changedShare(wiped, dView, half + gap, view.w) < 0.01, 'the right part is D');

  // One finger that starts on the handle drags the divider to a quarter of the width.
  const to = [view.x + view.w / 4, hy];
  await drag(touch, [hx, hy], to);
  rects = await widgets(page);
  assert.ok(rects['view.wipe'], 'the handle is still shown');
  const [mx] = centre(rects['view.wipe']);
  assert.ok(Math.abs(mx - to[0]) <= 3, `the divider followed the finger to ${to[0]}: ${mx}`);
  const moved = await viewPicture(page, view);
  keep(moved, 'phone-moved');
  const quarter = view.w / 4;
  assert.ok(changedShare(moved, dView, quarter + gap, view.w) < 0.01, 'right of the moved divider, D as it was: the camera did not turn');
  assert.ok(changedShare(moved, wiped, 0, quarter - gap) < 0.01, 'left of it, the lit model as it was');
  assert.deepEqual(problems, []);
  await context.close();
});

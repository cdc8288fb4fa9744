// check-report.test.mjs — the page `lab check` writes for people (issue 23), opened from the file
// system in Debian's Chromium as a course's staff would open it from a CI artifact: every image
// loads, and the slider and the flip show the actual render and the golden.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { PNG } from 'pngjs';
import { repo, withBrowser } from './page.mjs';

const lab = process.env.LAB_EXE || path.join(repo, 'build/lab');
const env = withBrowser({ serve: false, args: ['--allow-file-access-from-files'] }); // the report, from the file system
let dir;

// A check with one failing preset: its golden is another preset's render.
before(async () => {
  assert.ok(fs.existsSync(lab), `no ${lab}: build it first (tools/dev build)`);
  dir = fs.mkdtempSync(path.join(os.tmpdir(), 'lab-report-'));
  const preset = path.join(dir, 'phong & "friends".json');
  const text = JSON.parse(fs.readFileSync(path.join(repo, 'presets/05-full-phong.json'), 'utf8'));
  delete text.sweep;
  fs.writeFileSync(preset, JSON.stringify(text));
  fs.mkdirSync(path.join(dir, 'golden'));
  execFileSync(lab, ['render', path.join(repo, 'presets/01-ambient-only.json'), '--size', '96x96',
    '--out', path.join(dir, 'golden', 'phong & "friends".png')]);
  try {
    execFileSync(lab, ['check', preset, '--golden', path.join(dir, 'golden'), '--report', path.join(dir, 'report'),
      '--size', '96x96'], { stdio: 'pipe' });
    assert.fail('lab check passed on a golden of another picture');
  } catch (e) {
    assert.equal(e.status, 1, String(e.stderr));
  }
});

after(() => fs.rmSync(dir, { recursive: true, force: true }));

function centre(png) {
  const i = ((png.height >> 1) * png.width + (png.width >> 1)) * 4;
  return [png.data[i], png.data[i + 1], png.data[i + 2]];
}

// The centre pixel of what the page shows inside `locator`'s box.
async function shownCentre(page, locator) {
  return centre(PNG.sync.read(await locator.screenshot()));
}

// Within 10 levels: the box's centre may fall a pixel away from the image's (its 1-pixel border).
function near(a, b, what) {
  assert.ok(a.every((v, k) => Math.abs(v - b[k]) <= 10), `${what}: ${a} is not ${b}`);
}

test('the report opens from the file system, its images load, slider and flip show actual and golden', async () => {
  const report = path.join(dir, 'report');
  const context = await env.browser.newContext({ viewport: { width: 1000, height: 700 } });
  const page = await context.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  page.on('pageerror', (e) => problems.push(e.message));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  await page.goto(pathToFileURL(path.join(report, 'index.html')).href);
  await page.waitForLoadState('load');
  assert.deepEqual(problems, []);
  assert.match(await page.title(), /^lab check: 1 failed, 0 passed$/);
  assert.match(await page.locator('section.case h2').innerText(), /FAIL\s+phong & "friends"/);
  const broken = await page.evaluate(() => [...document.images].filter((i) => !i.complete || i.naturalWidth === 0).map((i) => i.src));
  assert.deepEqual(broken, []);
  assert.equal(await page.locator('img').count(), 5); // golden, actual, difference, and the two stacked

  const actual = centre(PNG.sync.read(fs.readFileSync(path.join(report, 'phong & "friends".actual.png'))));
  const golden = centre(PNG.sync.read(fs.readFileSync(path.join(report, 'phong & "friends".golden.png'))));
  assert.ok(actual.some((v, k) => Math.abs(v - golden[k]) > 60), `${actual} and ${golden} are too alike to tell apart`);
  const swipe = page.locator('.swipe img').first(); // the golden, with the actual over it
  const slider = page.locator('.swipe input');
  await slider.fill('100'); // all of the actual
  near(await shownCentre(page, swipe), actual, 'slider at 100');
  await slider.fill('0'); // none of it: the golden
  near(await shownCentre(page, swipe), golden, 'slider at 0');
  await page.locator('.swipe button').click(); // flip: the other whole image
  near(await shownCentre(page, swipe), actual, 'flipped');
  assert.equal(await page.locator('.swipe .which').innerText(), 'actual');
  await page.locator('.swipe img.over').click(); // a click on the picture (the actual, over the golden) flips too
  near(await shownCentre(page, swipe), golden, 'flipped back');
  assert.equal(await page.locator('.swipe .which').innerText(), 'golden');
  await context.close();
});

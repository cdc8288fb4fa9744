// page.mjs — what every browser test file shares: the browser and the page server, a fresh page
// with the lab running, and the ways to wait for it and drive it (see lab.test.mjs).
import { before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';
import { serve } from '../serve.mjs';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const site = process.env.LAB_WEB_SITE || path.join(repo, 'build-web/site');
const chromiumArgs = ['--headless=new', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--force-device-scale-factor=1'];

// The built page served locally and Debian's Chromium; `close()` ends both. `serve: false`: the
// browser alone, for a test that opens no page of the lab (no `server`, no `base`); `args`: more
// of Chromium's switches.
export async function startBrowser({ serve: servePage = true, args = [] } = {}) {
  let server, base;
  if (servePage) {
    assert.ok(fs.existsSync(path.join(site, 'index.html')), `no page in ${site}: build it first (tools/dev web)`);
    server = await serve(site);
    base = `http://127.0.0.1:${server.address().port}/`;
  }
  // A UTF-8 locale, as a student's browser has: in the C locale (a bare Debian root, CI) Chromium
  // cannot hand the page a file whose name is not ASCII ("scène (1).json" arrived as nothing).
  const env = { ...process.env, LANG: 'C.UTF-8', LC_ALL: 'C.UTF-8' };
  const browser = await chromium.launch({ executablePath: process.env.LAB_CHROMIUM || '/usr/bin/chromium',
    args: [...chromiumArgs, ...args], env });
  return { server, browser, base, close: async () => { await browser.close(); server?.close(); } };
}

// startBrowser(options) before a test file's tests and close() after them: `env.browser`, `env.base`.
export function withBrowser(options) {
  const env = {};
  before(async () => { Object.assign(env, await startBrowser(options)); });
  after(async () => { await env.close?.(); });
  return env;
}

// A fresh page (its own profile: no saved state) at `url` with the lab running, and what went
// wrong on it. `touch`: a phone or tablet (touch screen, mobile viewport, coarse pointer);
// `initScript`: run before the page's own scripts; `media`: the system's settings the page sees
// ({ colorScheme: 'light', reducedMotion: 'reduce' }). `loadMs`: from the request to the lab running.
export async function newLabPage(browser, url, { width = 1280, height = 760, scale = 1, touch = false, initScript,
  media = {} } = {}) {
  const context = await browser.newContext({ viewport: { width, height }, deviceScaleFactor: scale, acceptDownloads: true,
    hasTouch: touch, isMobile: touch, colorScheme: 'dark', reducedMotion: 'no-preference', ...media });
  if (initScript) {
    await context.addInitScript(initScript);
  }
  const page = await context.newPage();
  // Playwright turns Chromium's file-chooser interception on when a page gets its first 'filechooser'
  // listener and off when the last one goes, by a message it does not wait for: a click sent right
  // after waitForEvent('filechooser') can open the picker before interception is on, and the event
  // never comes (CI saw it once: 30 s, no 'filechooser'). One listener for the page's life keeps it
  // on from before the page loads; waitForEvent then only adds and removes a second one.
  page.on('filechooser', () => {});
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  page.on('response', (r) => { if (r.status() >= 400) problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  const started = Date.now();
  await page.goto(url);
  await page.waitForFunction(() => window.labReady === true, null, { timeout: 60000 });
  const loadMs = Date.now() - started;
  await settle(page);
  return { page, context, problems, loadMs };
}

// Waits until the lab has handled every event and file it was given and owes no frame (it draws
// only when something changed; lab_settled, web_window.cpp).
export function settle(page) {
  return page.waitForFunction(
    () => window.labFilesPending === 0 && Module.ccall('lab_settled', 'number', [], []) === 1,
    null, { polling: 'raf', timeout: 30000 });
}

// Waits for the browser to draw `n` more animation frames.
export function frames(page, n) {
  return page.evaluate((count) => new Promise((resolve) => {
    const step = (left) => (left === 0 ? resolve() : requestAnimationFrame(() => step(left - 1)));
    step(count);
  }), n);
}

// The rectangles of the widgets the lab drew last (lab_widgets), by name.
export async function widgets(page) {
  const text = await page.evaluate(() => Module.ccall('lab_widgets', 'string', [], []));
  const rects = {};
  for (const line of text.split('\n').filter(Boolean)) {
    const [name, x, y, w, h] = line.split(' ');
    rects[name] = { x: +x, y: +y, w: +w, h: +h };
  }
  return rects;
}

export async function press(page, key) {
  await page.keyboard.down(key);
  await page.keyboard.up(key);
  await settle(page);
}

// Makes the model's viewport `width` x `height` (a golden's size): the page grows by the view's text
// strips (the header above the model, the footer below it). Frames, not settle(): a moving light
// never lets the lab settle.
export async function sizeModelViewport(page, width, height) {
  const r = await widgets(page);
  await page.setViewportSize({ width: width + r['view.area'].w - r.view.w, height: height + r['view.area'].h - r.view.h });
  await frames(page, 5);
  const view = (await widgets(page)).view;
  assert.deepEqual([view.w, view.h], [width, height], 'the model\'s viewport has the golden\'s size');
}

// The lab's screenshot of its 3D view (F12), which the page hands over as a download.
export async function viewShot(page) {
  const [download] = await Promise.all([page.waitForEvent('download'), press(page, 'F12')]);
  return PNG.sync.read(fs.readFileSync(await download.path()));
}

// The screenshot tests' comparison (core/io/image.h): a pixel fails above `pixel` levels in any
// channel; an image fails when more than `share` of its pixels fail or the mean exceeds `mean`.
export function compare(a, b, { pixel = 3, share = 0.001, mean = 0.5 } = {}) {
  if (a.width !== b.width || a.height !== b.height) return { sameSize: false, passes: false };
  let sum = 0, failing = 0, max = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    let worst = 0;
    for (let k = 0; k < 3; ++k) {
      const d = Math.abs(a.data[i + k] - b.data[i + k]);
      sum += d;
      worst = Math.max(worst, d);
    }
    max = Math.max(max, worst);
    if (worst > pixel) failing++;
  }
  const pixels = a.width * a.height;
  const result = { sameSize: true, max, mean: sum / (pixels * 3), failingShare: failing / pixels };
  result.passes = result.failingShare <= share && result.mean <= mean;
  return result;
}

// One finger on a touch screen (Chrome DevTools Protocol touch events): down, move, up, tap.
export async function finger(page) {
  const cdp = await page.context().newCDPSession(page);
  const send = (type, points) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 4, radiusY: 4, force: 1 })) });
  return {
    down: (x, y) => send('touchStart', [[x, y]]),
    move: async (x, y) => { await send('touchMove', [[x, y]]); await frames(page, 1); },
    up: async () => { await send('touchEnd', []); await settle(page); },
    async tap(x, y) {
      await send('touchStart', [[x, y]]);
      await send('touchEnd', []);
      await settle(page);
    },
  };
}

const axePath = createRequire(import.meta.url).resolve('axe-core/axe.min.js');

// axe-core's WCAG 2.1 A and AA rules on the page as it is; the violations, one line each.
export async function axeViolations(page) {
  await page.addScriptTag({ path: axePath });
  const result = await page.evaluate(() => window.axe.run(document, {
    runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] } }));
  return result.violations.map((v) => `${v.id} (${v.impact}): ${v.help} — ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(', ')}`);
}

// figures.test.mjs — Export figures in the browser (issue 16): the button hands every figure of the
// plots to the user as downloads — each plot (lobe, overlay, attenuation, albedo) as SVG, PNG and
// CSV — named after the preset, and the files are what they say they are: the PNGs at the panel's
// scale (2: 1440 pixels wide), the lobe's numbers those the native `lab plot` writes for the same
// preset (build/lab, which tools/dev test builds first).
//
//   node --test --test-name-pattern="figures" web/tests/
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { PNG } from 'pngjs';
import { repo, withBrowser, newLabPage, widgets } from './page.mjs';

const env = withBrowser();

test('figures: Export figures downloads each plot as SVG, PNG and CSV', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base + '#preset=05-full-phong', { width: 1280, height: 760 });
  const w = await widgets(page);
  const button = w['figures.export'];
  assert.ok(button, 'the Export figures button should be shown');
  const downloads = [];
  page.on('download', (d) => downloads.push(d));
  await page.mouse.click(button.x + button.w / 2, button.y + button.h / 2);
  const deadline = Date.now() + 15000;
  while (downloads.length < 12 && Date.now() < deadline) {
    await page.waitForTimeout(200);
  }
  const names = downloads.map((d) => d.suggestedFilename()).sort();
  for (const figure of ['lobe', 'overlay', 'attenuation', 'albedo']) {
    for (const ext of ['svg', 'png', 'csv']) {
      assert.ok(names.some((n) => n.startsWith('05-full-phong') && n.includes(figure) && n.endsWith('.' + ext)),
        `no ${figure} .${ext} among ${names.join(', ')}`);
    }
  }
  for (const d of downloads) {
    const name = d.suggestedFilename();
    const bytes = fs.readFileSync(await d.path());
    if (name.endsWith('.svg')) {
      const text = bytes.toString('utf8');
      assert.match(text, /<svg[^>]*xmlns="http:\/\/www\.w3\.org\/2000\/svg"/, `${name} is not an SVG`);
      assert.match(text, /<\/svg>\s*$/, `${name} is cut short`);
      assert.match(text, /<polyline|<path/, `${name} has no curve`);
    } else if (name.endsWith('.png')) {
      const png = PNG.sync.read(bytes);
      assert.equal(png.width, 1440, `${name} is ${png.width}x${png.height}: scale 2 is 1440 pixels wide`);
    } else {
      const lines = bytes.toString('utf8').trim().split('\n');
      assert.ok(lines.length > 10, `${name} has ${lines.length} lines`);
      assert.match(lines[0], /^[a-z_]+(,[a-z_A-Z0-9]+)+$/, `${name} header ${lines[0]}`);
    }
  }
  // The lobe's curves are the native program's numbers (the same C++ in WebAssembly: equal to the
  // last bits or so, as the two libm's sines may differ there).
  const lab = path.join(repo, 'build/lab');
  assert.ok(fs.existsSync(lab), `no native lab at ${lab}: build it first (tools/dev build)`);
  const nativeCsv = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'lab-figures-')), 'lobe.csv');
  execFileSync(lab, ['plot', path.join(repo, 'presets/05-full-phong.json'), '--out', nativeCsv]);
  const rows = (text) => text.trim().split('\n').map((l) => l.split(','));
  const lobe = downloads.find((d) => d.suggestedFilename().endsWith('lobe.csv'));
  const page_ = rows(fs.readFileSync(await lobe.path(), 'utf8')), native = rows(fs.readFileSync(nativeCsv, 'utf8'));
  assert.deepEqual(page_[0], native[0]);
  assert.equal(page_.length, native.length);
  for (let i = 1; i < native.length; ++i) {
    for (let k = 0; k < native[i].length; ++k) {
      assert.ok(Math.abs(Number(page_[i][k]) - Number(native[i][k])) <= 1e-5 * Math.max(1, Math.abs(Number(native[i][k]))),
        `row ${i} column ${k}: page ${page_[i][k]}, native ${native[i][k]}`);
    }
  }
  assert.deepEqual(problems, []);
  await context.close();
});

// hostile-fields.test.mjs — the page's field edits, fetched modules and saved theme against hostile
// values (issue 49, the fourth round of hardening). Each case failed on the main of 2026-12-07: a
// refused value was quoted whole (a 1 MB line in the message log), a refusal showed an in-range
// number, text typed into a number field was dropped without a word, the field-edit entry point
// took hex floats and cut at a NUL, a broken module's reason was cut at its first ")", a broken QR
// encoder was said nowhere in the page's text, and an unknown saved theme overrode the system's.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, newLabPage, settle, frames, widgets, press } from './page.mjs';

const env = withBrowser();

// The lab's description (access.js keeps the last one) and a field's value in it.
const described = (page) => page.evaluate(() => window.labPageModel);
async function valueOf(page, path) {
  const m = await described(page);
  return m.sections.flatMap((s) => s.controls).find((c) => c.path === path).value;
}
const logText = (page) => page.evaluate(() => [...document.querySelectorAll('#lab-log p')].map((p) => p.textContent));

// The page's own way to send a field (what its controls call), with any text.
async function sendField(page, path, text) {
  await page.evaluate(([p, t]) => Module.labPageField(p, t), [path, text]);
  await frames(page, 2);
  await settle(page);
}

// The log lines since `before` lines were there.
async function newLines(page, before) {
  return (await logText(page)).slice(before.length);
}

test('a refused value is quoted at most 120 bytes long, in the log and on the canvas, and the page keeps drawing', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base);
  const cases = [
    ['material.shininess', '7'.repeat(1 << 20) + 'x', /^material\.shininess: expected a number such as 0\.5, -2 or 1e-3, got "7{120}…" \(1048577 bytes\)$/],
    ['material.shininess', '9'.repeat(10000), /^material\.shininess: number out of range: "9{120}…" \(10000 bytes\)$/],
    ['lights[0].type', 'x'.repeat(1 << 20), /^lights\[0\]\.type: not one of its choices: "x{120}…" \(1048576 bytes\)$/],
    ['m'.repeat(1 << 20), '1', /^"m{120}…" \(1048576 bytes\): not a field the page can set$/],
  ];
  for (const [path, text, expected] of cases) {
    const before = await logText(page);
    await sendField(page, path, text);
    const lines = await newLines(page, before);
    assert.equal(lines.length, 1, `one line for ${path.slice(0, 40)}`);
    const message = lines[0].replace(/^[^:]*:\d\d:\d\d( [AP]M)?: /, '');
    assert.match(message, expected);
    assert.ok(lines[0].length < 400, `a short line: ${lines[0].length} characters`);
  }
  assert.equal(await valueOf(page, 'material.shininess'), 32, 'the lab keeps its value');
  const drawn = await page.evaluate(() => Module.ccall('lab_frames', 'number', [], []));
  await page.mouse.move(640, 300);
  await page.mouse.down();
  await page.mouse.move(700, 320, { steps: 4 });
  await page.mouse.up();
  await settle(page);
  assert.ok(await page.evaluate(() => Module.ccall('lab_frames', 'number', [], [])) > drawn, 'the canvas still draws');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a refusal says the value as it was typed, as the command line does', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base);
  await sendField(page, 'brdf', 'cook-torrance');
  await sendField(page, 'lights[0].type', 'spot');
  const cases = [
    ['material.shininess', '1000001', 'material.shininess: must be in [0.001, 1000000], got 1000001'],
    ['cook_torrance.roughness', '10.00001', 'cook_torrance.roughness: must be in [0.001, 10], got 10.00001'],
    ['lights[0].exponent', '1000000.5', 'lights[0].exponent: must be in [0, 1000000], got 1000000.5'],
    ['material.shininess', '1e39', 'material.shininess: number out of range: 1e39'],
  ];
  for (const [path, text, message] of cases) {
    const before = await logText(page);
    await sendField(page, path, text);
    const lines = await newLines(page, before);
    assert.equal(lines.length, 1, path);
    assert.ok(lines[0].endsWith(': ' + message), `${lines[0]} says ${message}`);
  }
  assert.deepEqual(problems, []);
  await context.close();
});

test('the field-edit entry point takes what a preset file takes, and no more', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base);
  for (const [path, text, said] of [
    ['material.shininess', '0x10', /material\.shininess: expected a number such as 0\.5, -2 or 1e-3, got "0x10"$/],
    ['material.shininess', '5\u0000junk', /material\.shininess: expected a number .* got "5\\0junk"$/],
    ['material.shininess\u0000x', '5', /"material\.shininess\\0x": not a field the page can set$/],
    ['', '5', /"": not a field the page can set$/],
  ]) {
    const before = await logText(page);
    await sendField(page, path, text);
    const lines = await newLines(page, before);
    assert.equal(lines.length, 1, `${JSON.stringify(path)} = ${JSON.stringify(text)} is said`);
    assert.match(lines[0], said);
    assert.equal(await valueOf(page, 'material.shininess'), 32, `${JSON.stringify(text)} did not set the shininess`);
  }
  await sendField(page, 'material.shininess', '.5');
  assert.equal(await valueOf(page, 'material.shininess'), 0.5, '.5 is 0.5, as the panel\'s own fields take it');
  assert.deepEqual(problems, []);
  await context.close();
});

test('text a number field cannot take is refused in words: the log, the field\'s description, aria-invalid; the lab keeps its value', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base);
  const shininess = page.getByRole('spinbutton', { name: /shininess/ });
  for (const [text, leave, said] of [
    ['1e309', 'Enter', /number out of range: 1e309/],
    ['-', 'Tab', /expected a number such as 0\.5, -2 or 1e-3, got "-"/],
    ['e', 'Enter', /got "e"/],
    ['--5', 'Tab', /got "--5"/],
  ]) {
    const before = await logText(page);
    await shininess.focus();
    await page.keyboard.press('Control+A');
    await page.keyboard.type(text);
    await page.keyboard.press(leave);
    await frames(page, 2);
    await settle(page);
    const lines = await newLines(page, before);
    assert.equal(lines.length, 1, `"${text}" then ${leave}: one line in the log`);
    assert.match(lines[0], said);
    assert.equal(await valueOf(page, 'material.shininess'), 32, `"${text}": the lab keeps its value`);
    const field = await shininess.evaluate((e) => ({ invalid: e.getAttribute('aria-invalid'), now: e.getAttribute('aria-valuenow'),
      described: (e.getAttribute('aria-describedby') || '').split(' ').map((id) => document.getElementById(id)?.textContent || '').join(' | ') }));
    assert.equal(field.invalid, 'true', `"${text}": marked invalid`);
    assert.match(field.described, said, `"${text}": the field's description says why`);
    assert.equal(field.now, '32', `"${text}": its accessible value is the lab's`);
  }
  // The accessibility tree: a spin button with the lab's value, invalid, described by the refusal.
  const cdp = await context.newCDPSession(page);
  const { nodes } = await cdp.send('Accessibility.getFullAXTree');
  const node = nodes.find((n) => n.role?.value === 'spinbutton' && /shininess/i.test(n.name?.value || ''));
  assert.ok(node, 'the shininess is a spin button in the tree');
  assert.equal(String(node.value?.value), '32');
  assert.match(JSON.stringify(node.properties), /"invalid"/);
  assert.match(node.description?.value || '', /got "--5"/);
  // A value the lab takes clears the refusal; Up steps from the lab's value.
  await shininess.focus();
  await page.keyboard.press('Control+A');
  await page.keyboard.type('40');
  await page.keyboard.press('Enter');
  await settle(page);
  assert.equal(await valueOf(page, 'material.shininess'), 40);
  assert.equal(await shininess.getAttribute('aria-invalid'), null, 'no longer invalid');
  const step = (await described(page)).sections.flatMap((s) => s.controls).find((c) => c.path === 'material.shininess').step;
  await page.keyboard.press('ArrowUp');
  await settle(page);
  assert.equal(await valueOf(page, 'material.shininess'), 40 + step, `Up adds a step (${step})`);
  await page.keyboard.press('PageDown');
  await settle(page);
  assert.equal(await valueOf(page, 'material.shininess'), Number((40 + step - 10 * step).toPrecision(12)), 'PageDown takes ten');
  assert.deepEqual(problems, []);
  await context.close();
});

test('a shader that quotes a megabyte in its compile log reaches the page cut', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base);
  const click = (label) => page.evaluate((l) => [...document.querySelectorAll('#lab-access button')]
    .find((b) => b.textContent === l).click(), label);
  await click('Shader editor');
  await settle(page);
  await sendField(page, 'shader.lighting', 'vec3 ' + 'x'.repeat(1 << 20) + ' = ;');
  await click('Compile (Ctrl+Enter)');
  await frames(page, 3);
  await settle(page);
  const log = await page.evaluate(() => document.querySelector('#lab-access pre.log')?.textContent || '');
  assert.ok(log.length > 0, 'the compile log is shown');
  assert.ok(log.length < 60000, `the log is bounded: ${log.length} characters`);
  assert.ok(log.split('\n').every((line) => line.length < 1200), 'each line is cut');
  assert.deepEqual(problems.filter((p) => !/WebGL|GL_INVALID|shader/i.test(p)), []);
  await context.close();
});

test('a QR encoder that does not load is said in the page\'s log and tools, with its whole reason', async () => {
  const { page, context } = await newLabPage(env.browser, env.base);
  await page.route('**/qr.wasm', (route) => route.fulfill({ status: 200, contentType: 'application/wasm', body: 'garbage, not wasm' }));
  const rects = await widgets(page);
  await page.mouse.move(rects.view.x + rects.view.w / 2, rects.view.y + rects.view.h / 2);
  await press(page, 'q');
  await page.waitForFunction(() => /QR encoder could not be loaded/.test(document.getElementById('lab-log').textContent),
    null, { timeout: 20000 });
  const log = await page.evaluate(() => document.getElementById('lab-log').textContent);
  assert.match(log, /qr\.wasm could not be loaded: CompileError: WebAssembly\.instantiate(Streaming)?\(\): .*magic/,
    `the reason is whole: ${log}`);
  const tools = await page.evaluate(() => [...document.querySelectorAll('#lab-access p')].map((p) => p.textContent)
    .filter((t) => /QR code/.test(t)));
  assert.equal(tools.length, 1, tools.join(' | '));
  assert.match(tools[0], /^No QR code: The QR encoder could not be loaded: .* The link: http/);
  assert.doesNotMatch(tools[0], /The QR code opens/);
  await context.close();
});

test('a saved theme the lab does not have leaves the system\'s light scheme in place', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base, {
    media: { colorScheme: 'light' }, initScript: () => localStorage.setItem('lighting-lab/theme', 'sepia') });
  assert.equal((await described(page)).theme, 'light');
  assert.equal(await page.evaluate(() => document.documentElement.dataset.theme), 'light');
  assert.deepEqual(problems, []);
  await context.close();
});

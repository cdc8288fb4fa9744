// lecture.test.mjs — the lecture on the page (issue 50): a bundled deck opened by its link, stepped
// with an edit on every slide and no dialog, the speaker's notes; and a dialog the lab draws is an
// alertdialog in the parallel DOM that takes the focus, answers Enter and Esc, and gives it back.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { withBrowser, newLabPage, settle, widgets, press, frames, axeViolations } from './page.mjs';

const env = withBrowser();

const documentName = (page) => page.evaluate(() => document.getElementById('lab-document').textContent);
const dialogShown = (page) => page.evaluate(() => !document.getElementById('lab-dialog').hidden);

test('#deck=lecture opens the bundled deck; Right and Space step it after an edit with no dialog; S shows the notes', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base + '#deck=lecture');
  const names = [await documentName(page)];
  assert.match(names[0], /01-/, 'the deck opens at its first slide');
  for (const key of ['ArrowRight', 'Space', 'PageDown']) {
    await press(page, '2'); // a live edit: Gouraud shading
    await press(page, key);
    const r = await widgets(page);
    assert.equal(r['confirm.discard'], undefined, `${key} after an edit asked about unsaved changes`);
    assert.equal(await dialogShown(page), false, `${key}: a dialog in the page`);
    names.push(await documentName(page));
  }
  assert.equal(new Set(names).size, names.length, `each step opened the next slide: ${names.join(', ')}`);
  await press(page, 'ArrowLeft');
  assert.equal(await documentName(page), names[2], 'Left goes back');
  await press(page, 's');
  const notes = (await widgets(page)).notes;
  assert.ok(notes && notes.w > 0, 'S shows the speaker notes');
  // ... in the page's parallel DOM too, for a screen reader: the slide, its notes, the next one.
  await page.waitForFunction(() => !document.getElementById('lab-notes').hidden, null, { timeout: 10000 });
  const region = await page.getByRole('region', { name: 'Speaker notes' }).textContent();
  assert.match(region, /Slide 3 of 28/, region);
  assert.match(region, /Next: /, region);
  assert.ok(region.length > 80, `the slide's notes are there: ${region}`);
  await press(page, 'S'); // Shift+S: the page has no second window, so the strip goes again
  assert.equal((await widgets(page)).notes, undefined, 'Shift+S on the page toggles the same strip');
  assert.deepEqual(problems, [], 'nothing uncaught, no console error');
  await context.close();
});

test('a dialog the lab draws is an alertdialog in the page: the focus goes to its button, Esc and Enter answer it, the focus comes back', async () => {
  const { page, context, problems } = await newLabPage(env.browser, env.base + '#preset=05-full-phong');
  for (const [answer, link] of [['Escape', '#preset=../../etc/passwd'], ['Enter', '#preset=/etc/passwd']]) {
    const tab = page.getByRole('tab').first();
    await tab.focus();
    await page.evaluate((l) => { location.hash = l; }, link); // (a new hash each time: the same one is no change)
    await frames(page, 2);
    await settle(page);
    await page.waitForFunction(() => !document.getElementById('lab-dialog').hidden, null, { timeout: 10000 });
    const dialog = page.getByRole('alertdialog');
    assert.match(await dialog.getAttribute('aria-labelledby'), /lab-dialog-title/);
    assert.match(await page.locator('#lab-dialog-text').textContent(), /not the name of a bundled preset/);
    const focused = await page.evaluate(() => ({ inDialog: document.getElementById('lab-dialog').contains(document.activeElement),
      text: document.activeElement.textContent }));
    assert.ok(focused.inDialog, 'the focus went into the dialog');
    assert.equal(focused.text, 'OK', 'to its default button');
    assert.ok((await widgets(page)).error, 'the canvas shows the same dialog');
    if (answer === 'Escape') { // once: the dialog as a screen reader meets it, and axe's WCAG 2.1 A/AA rules with it open
      const tree = await page.accessibility.snapshot({ interestingOnly: false });
      const find = (n) => n && (n.role === 'alertdialog' ? n : (n.children || []).map(find).find(Boolean));
      const node = find(tree);
      assert.ok(node, 'an alertdialog in the accessibility tree');
      assert.equal(node.name, 'Error');
      const has = (n, role, name) => n.role === role && n.name === name || (n.children || []).some((c) => has(c, role, name));
      assert.ok(has(node, 'button', 'OK'), `its OK button: ${JSON.stringify(node)}`);
      assert.deepEqual(await axeViolations(page), [], 'axe with the dialog open');
    }
    await page.keyboard.press(answer);
    await settle(page);
    await page.waitForFunction(() => document.getElementById('lab-dialog').hidden, null, { timeout: 10000 });
    assert.equal((await widgets(page)).error, undefined, `${answer} closed the canvas's dialog too`);
    assert.ok(await tab.evaluate((e) => e === document.activeElement), `after ${answer} the focus is back where it was`);
  }
  assert.deepEqual(problems, [], 'nothing uncaught, no console error');
  await context.close();
});

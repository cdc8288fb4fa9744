import { startBrowser, newLabPage, settle, widgets } from './page.mjs';
import fs from 'node:fs';
const env = await startBrowser();
const { page, problems } = await newLabPage(env.browser, env.base);
await page.screenshot({ path: '/tmp/a11y/page.png' });
const cdp = await page.context().newCDPSession(page);
const { nodes } = await cdp.send('Accessibility.getFullAXTree');
const lines = nodes.filter((n) => !n.ignored).map((n) => `${n.role?.value} "${n.name?.value ?? ''}"${n.value ? ' = ' + n.value.value : ''}`);
fs.writeFileSync('/tmp/a11y/axtree.txt', lines.join('\n'));
console.log('nodes', lines.length, 'problems', problems);
// Tab from the canvas
for (let i = 0; i < 6; i++) {
  await page.keyboard.press('Tab');
  console.log(await page.evaluate(() => { const a = document.activeElement; return a.tagName + ' ' + (a.id || '') + ' ' + (a.getAttribute('aria-label') || a.textContent.slice(0, 40)); }));
}
await page.screenshot({ path: '/tmp/a11y/page-tab.png' });
const shin = page.getByRole('spinbutton', { name: /shininess/ });
console.log('shininess controls', await shin.count());
await page.getByRole('tab', { name: 'Material' }).focus(); await page.keyboard.press('Enter');
await shin.first().focus();
await settle(page);
await page.screenshot({ path: '/tmp/a11y/page-shin.png' });
await shin.first().fill('5');
await shin.first().press('Enter');
await settle(page);
await page.screenshot({ path: '/tmp/a11y/page-shin5.png' });
console.log(await page.evaluate(() => window.labPageModel.sections.map((s) => s.id + ':' + s.controls.length).join(' ')));
console.log(problems);
await env.close();

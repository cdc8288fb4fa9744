// temporary: the accessibility tree (abridged) and axe-core's results, for the note
import { startBrowser, newLabPage, settle } from './page.mjs';
import { createRequire } from 'node:module';
import fs from 'node:fs';
const axePath = createRequire(import.meta.url).resolve('axe-core/axe.min.js');
const env = await startBrowser();
const out = [];
for (const [name, fragment, options] of [['default', '', {}], ['exercise', '#exercise=02-shininess', {}], ['phone', '', { width: 390, height: 844, touch: true, scale: 3 }]]) {
  const { page, context } = await newLabPage(env.browser, env.base + fragment, options);
  await page.addScriptTag({ path: axePath });
  const r = await page.evaluate(() => window.axe.run(document, { runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa'] } }));
  out.push(`## ${name}: axe ${r.violations.length} violations, ${r.passes.length} rules passed, ${r.incomplete.length} incomplete`);
  for (const v of r.violations) out.push(`- ${v.id} (${v.impact}): ${v.help} [${v.nodes.length} nodes]`);
  for (const v of r.incomplete) out.push(`- incomplete ${v.id}: ${v.help} [${v.nodes.length}]`);
  if (name === 'default') {
    const cdp = await context.newCDPSession(page);
    const { nodes } = await cdp.send('Accessibility.getFullAXTree');
    const byId = new Map(nodes.map((n) => [n.nodeId, n]));
    const lines = [];
    const walk = (n, depth) => {
      const skip = n.ignored || ['InlineTextBox', 'StaticText', 'generic', 'none', 'LineBreak'].includes(n.role?.value);
      if (!skip) lines.push(`${'  '.repeat(depth)}${n.role?.value} "${n.name?.value ?? ''}"${n.value?.value !== undefined ? ' value=' + JSON.stringify(n.value.value) : ''}`);
      for (const c of n.childIds || []) if (byId.has(c)) walk(byId.get(c), skip ? depth : depth + 1);
    };
    walk(nodes[0], 0);
    fs.writeFileSync(process.env.TREE_OUT || '/tmp/a11y/tree.txt', lines.join('\n') + '\n');
    out.push(`(tree: ${lines.length} lines)`);
  }
  await context.close();
}
console.log(out.join('\n'));
await env.close();

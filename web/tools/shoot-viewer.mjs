// A picture of the live viewer on environment 2 once it is solved, in x-ray: the part, the
// solution and the trees (contact samples in green) in front of the see-through obstacles (the
// README's picture). Usage:
//   node web/tools/shoot-viewer.mjs OUT.png [--size WxH]
import { mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { startTandem, stopTandem, launchBrowser, openViewer } from '../test/harness.mjs';

const [out, flag, size] = process.argv.slice(2);
if (!out || (flag && flag !== '--size')) throw new Error('usage: node web/tools/shoot-viewer.mjs OUT.png [--size WxH]');
const [width, height] = (size ?? '1400x800').split('x').map(Number);
const session = path.join(mkdtempSync(path.join(tmpdir(), 'tandem-shoot-')), 'cluttered-2.jsonl');
const run = await startTandem(['interactive', 'cluttered-2', '--mode', 'interactive-contact', '--port', '0', '--session', session]);
const browser = await launchBrowser();
try {
  const page = await openViewer(browser, run, { viewport: { width, height } });
  await page.waitForFunction(() => window.tandem.status?.status === 'solved', null, { timeout: 300000, polling: 500 });
  await page.waitForFunction(() => window.tandem.counts().nodes === window.tandem.status.nodes, null, { timeout: 60000 });
  await page.keyboard.press('x');
  await page.click('#frame-path');
  await page.evaluate(() => window.tandem.redraw(true));
  await page.waitForTimeout(1500);
  await page.screenshot({ path: out });
  const c = await page.evaluate(() => window.tandem.counts());
  console.log(`wrote ${out}: ${c.nodes} nodes (random ${c.bySource[1]}, operator ${c.bySource[2]}, contact ${c.bySource[3]})`);
} finally {
  await browser.close();
  await stopTandem(run);
}

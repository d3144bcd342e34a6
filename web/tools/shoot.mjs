// A picture of a page `tandem export --html` wrote, at a moment of its animation, taken by headless
// Chromium (the README's picture). Usage:
//   node web/tools/shoot.mjs PAGE.html OUT.png [--at SHARE] [--size WxH]
// SHARE in [0, 1]: how far into the animation (default 0.5).
import { pathToFileURL } from 'node:url';
import { launchBrowser } from '../test/harness.mjs';

function options(argv) {
  const [page, out, ...rest] = argv;
  if (!page || !out) throw new Error('usage: node web/tools/shoot.mjs PAGE.html OUT.png [--at SHARE] [--size WxH]');
  const o = { page, out, at: 0.5, width: 1200, height: 700 };
  for (let i = 0; i < rest.length; i += 2) {
    if (rest[i] === '--at') o.at = Number(rest[i + 1]);
    else if (rest[i] === '--size') [o.width, o.height] = rest[i + 1].split('x').map(Number);
    else throw new Error(`unknown option ${rest[i]}`);
  }
  if (!(o.at >= 0 && o.at <= 1)) throw new Error('--at: a share of the animation in [0, 1]');
  return o;
}

const o = options(process.argv.slice(2));
const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: o.width, height: o.height } });
  await page.goto(pathToFileURL(o.page).href);
  await page.waitForFunction(() => window.tandemPlayer, null, { timeout: 20000 });
  await page.evaluate(async (at) => {
    await window.tandemPlayer.ready;
    window.tandemPlayer.seek(at * window.tandemPlayer.duration);
  }, o.at);
  await page.waitForTimeout(500);
  await page.screenshot({ path: o.out });
  console.log(`wrote ${o.out}`);
} finally {
  await browser.close();
}

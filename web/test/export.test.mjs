// `tandem export` in a real browser (Debian's headless Chromium, playwright-core): the .glb loads
// in three.js's GLTFLoader and its animation ends with the part at the path's last pose; the .html
// page plays offline (opened from a file, no request leaves it), its scrubber moves the part, and
// it draws the scene (its screenshot is kept as an artefact).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { launchBrowser, artefactPath, scratch, tandemBin } from './harness.mjs';

let browser;
before(async () => { browser = await launchBrowser(); });
after(async () => { await browser?.close(); });

const dir = scratch();
const file = (name) => path.join(dir, name);
const tandem = (args) => execFileSync(tandemBin, args, { encoding: 'utf8' });

/** The path file's states: [[x, y, z], [qx, qy, qz, qw]]. */
function readPath(p) {
  return readFileSync(p, 'utf8').split('\n').filter((l) => l.trim() && !l.startsWith('#'))
    .map((l) => l.trim().split(/\s+/).map(Number)).map((v) => [v.slice(0, 3), v.slice(3, 7)]);
}

/** Asserts a pose of the page (three.js arrays) is the state, within float precision; q ~ -q. */
function assertPose(pose, [t, q], what) {
  for (let i = 0; i < 3; i += 1) assert.ok(Math.abs(pose.position[i] - t[i]) < 1e-5, `${what}: position ${pose.position} vs ${t}`);
  const dot = Math.abs(pose.quaternion.reduce((s, v, i) => s + v * q[i], 0));
  assert.ok(dot > 1 - 1e-6, `${what}: rotation ${pose.quaternion} vs ${q} (|<q1,q2>| = ${dot})`);
}

/** The page, opened from its file with every request other than that file refused and counted. */
async function openOffline(html) {
  const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
  const refused = [];
  await page.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith('file:') || url.startsWith('data:') || url.startsWith('blob:')) return route.continue();
    refused.push(url);
    return route.abort();
  });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(pathToFileURL(html).href);
  await page.waitForFunction(() => window.tandemPlayer, null, { timeout: 20000 });
  await page.evaluate(() => window.tandemPlayer.ready);
  return { page, refused, errors };
}

const planned = file('cluttered-1.path');
tandem(['plan', 'cluttered-1', '--seed', '3', '--out', planned]);
tandem(['export', 'cluttered-1', planned, '--glb', file('a.glb'), '--html', file('a.html'),
  '--envelope', '--voxel', '0.08', '--duration', '6']);
const states = readPath(planned);

test('the .glb loads in GLTFLoader and its animation ends at the path\'s last pose', async () => {
  const { page, errors } = await openOffline(file('a.html'));
  const glb = readFileSync(file('a.glb')).toString('base64');
  const loaded = await page.evaluate(async (b64) => {
    const bytes = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    return window.tandemPlayer.load(bytes.buffer);
  }, glb);
  assert.ok(Math.abs(loaded.duration - 6) < 1e-6, `duration ${loaded.duration}`);
  for (const name of ['tandem-z-up', 'object', 'envelope', 'floor', 'oblique-bar'])
    assert.ok(loaded.nodes.includes(name), `node ${name} in ${loaded.nodes}`);
  assertPose(await page.evaluate(() => window.tandemPlayer.seek(0)), states[0], 'start');
  assertPose(await page.evaluate(() => window.tandemPlayer.seek(window.tandemPlayer.duration)),
    states.at(-1), 'end');
  assert.deepEqual(errors, []);
  await page.close();
});

test('the .html page plays offline: it moves the part, its scrubber seeks, it draws', async () => {
  const { page, refused, errors } = await openOffline(file('a.html'));
  const first = await page.evaluate(() => window.tandemPlayer.objectPose());
  await page.waitForTimeout(1500);
  const later = await page.evaluate(() => window.tandemPlayer.objectPose());
  assert.notDeepEqual(later.position, first.position, 'the animation plays');
  await page.locator('#scrub').fill('1000');
  assertPose(await page.evaluate(() => window.tandemPlayer.objectPose()), states.at(-1), 'scrubbed to the end');
  assert.equal(await page.locator('#play').textContent(), 'Play', 'scrubbing pauses');
  await page.locator('#scrub').fill('0');
  assertPose(await page.evaluate(() => window.tandemPlayer.objectPose()), states[0], 'scrubbed to the start');
  const shot = await page.screenshot({ path: artefactPath('export-player.png') });
  assert.ok(shot.length > 20000, `a picture with content (${shot.length} bytes of PNG)`);
  assert.deepEqual(refused, [], 'no request leaves the page');
  assert.deepEqual(errors, []);
  await page.close();
});

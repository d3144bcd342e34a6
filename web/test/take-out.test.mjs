// Taking a part out of a STEP assembly in the viewer (a real tandem, headless Chromium): the page
// shows the assembly's tree, a click on a part in the scene selects it, "take it out" starts the
// session with it on the same address, the page reloads into it, the planner takes the part out,
// the path is drawn coloured by its clearance (the server's certified figures), the motion envelope
// shows on demand, and the animation, its page and the envelope download.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import {
  root, startTandem, stopTandem, launchBrowser, openViewer, artefactPath, scratch, tandemBin,
} from './harness.mjs';

let browser;
before(async () => { browser = await launchBrowser(); });
after(async () => { await browser?.close(); });

const bracket = path.join(root, 'examples', 'bracket.step');
const dir = scratch();

async function waitFor(page, fn, arg, timeout = 30000) {
  await page.waitForFunction(fn, arg, { timeout, polling: 100 });
}

/** Where on the page a point of the scene is, after the camera has settled. */
const screenOf = (page, p) => page.evaluate(([x, y, z]) => window.tandem.screenOf(x, y, z), p);

test('choose the part in the viewer, take it out, see its clearance and envelope, download the animation', { timeout: 180000 }, async () => {
  const run = await startTandem(['interactive', bracket, '--port', '0', '--session', path.join(dir, 'cap.jsonl'), '--alpha', '0.5']);
  try {
    const page = await openViewer(browser, run, { ready: () => window.tandem?.picking });
    const tree = await page.locator('#pick-tree').innerText();
    for (const name of ['bracket', 'walls', 'wall-left', 'wall-right', 'pin', 'block', 'cap', 'base'])
      assert.ok(tree.includes(name), `the tree shows ${name}:\n${tree}`);
    // The cap's middle: x = 0, y = 0, z = 85 mm; nothing is in front of it from above.
    const at = await screenOf(page, [0, 0, 0.0899]);
    await page.mouse.click(at.x, at.y);
    await waitFor(page, () => window.tandem.pickedPart);
    assert.equal(await page.evaluate(() => window.tandem.pickedPart), 'bracket/cap');
    assert.equal(await page.locator('#pick-tree button.active').innerText(), 'cap');
    await page.click('#take-out');
    // The page reloads into the session, which takes the cap out (the part waits for no one).
    await waitFor(page, () => window.tandem?.hello?.mode === 'interactive-contact' && window.tandem.solution.length > 1, null, 90000);
    assert.match(await page.locator('#problem').innerText(), /take bracket\/cap out of bracket/);
    await waitFor(page, () => window.tandem.clearance && window.tandem.solutionLineColours());
    const { clearance, colours, solution } = await page.evaluate(() => ({
      clearance: window.tandem.clearance, colours: window.tandem.solutionLineColours(), solution: window.tandem.solution }));
    assert.equal(clearance.states.length, solution.length);
    assert.equal(colours.length, 2 * solution.length - 1, 'a colour per state and per motion\'s closest point');
    assert.ok(clearance.min_clearance >= 0 && clearance.min_clearance <= Math.min(...clearance.states.map((s) => s.distance)));
    // The closest point of the path is the reddest: its hue is the smallest.
    const hue = ([r, g]) => Math.atan2(g, r);
    const distances = [];
    clearance.states.forEach((s, i) => { distances.push(s.distance); if (clearance.segments[i]) distances.push(clearance.segments[i].lower); });
    const closest = distances.indexOf(Math.min(...distances)), farthest = distances.indexOf(Math.max(...distances));
    assert.ok(hue(colours[closest]) < hue(colours[farthest]), `red near (${colours[closest]}), green far (${colours[farthest]})`);
    // The server's figures are tandem clearance's.
    const pathFile = path.join(dir, 'cap.path');
    writeFileSync(pathFile, await page.evaluate(async () => (await fetch('/api/path')).text()));
    const cli = JSON.parse(execFileSync(tandemBin, ['clearance', bracket, pathFile, '--part', 'bracket/cap', '--json'], { encoding: 'utf8' }));
    assert.ok(Math.abs(cli.min_clearance - clearance.min_clearance) <= 1e-9, `${cli.min_clearance} vs ${clearance.min_clearance}`);
    execFileSync(tandemBin, ['check-path', bracket, pathFile, '--part', 'bracket/cap']);
    // The envelope, on demand.
    await page.check('#show-envelope');
    await waitFor(page, () => window.tandem.envelopeTriangles() > 100, null, 60000);
    // The downloads.
    const downloads = await page.evaluate(async () => Promise.all(['save-glb', 'save-html', 'save-stl'].map(async (id) => {
      const res = await fetch(document.getElementById(id).href);
      const bytes = new Uint8Array(await res.arrayBuffer());
      return { status: res.status, disposition: res.headers.get('content-disposition'), size: bytes.length,
        head: String.fromCharCode(...bytes.slice(0, 15)) };
    })));
    assert.equal(downloads[0].head.slice(0, 4), 'glTF');
    assert.match(downloads[1].head, /<!doctype html>/);
    assert.ok(downloads.every((d) => d.status === 200 && /attachment/.test(d.disposition)), JSON.stringify(downloads));
    await page.screenshot({ path: artefactPath('viewer-take-out.png') });
  } finally {
    await stopTandem(run);
  }
});

test('while choosing, anything but a part of the assembly is refused', { timeout: 60000 }, async () => {
  const run = await startTandem(['interactive', bracket, '--port', '0', '--session', path.join(dir, 'none.jsonl')]);
  try {
    const page = await openViewer(browser, run, { ready: () => window.tandem?.picking });
    await page.evaluate(() => {
      const ws = new WebSocket(`ws://${location.host}/ws`);
      window.replies = [];
      ws.onmessage = (e) => { if (typeof e.data === 'string') window.replies.push(JSON.parse(e.data)); };
      ws.onopen = () => {
        ws.send(JSON.stringify({ type: 'take_out', part: 'bracket/nothing' }));
        ws.send(JSON.stringify({ type: 'take_out', part: 'x'.repeat(2000) }));
        ws.send(JSON.stringify({ type: 'command', command: 'pause' }));
      };
    });
    await waitFor(page, () => window.replies.filter((m) => m.type === 'error').length >= 3);
    const errors = await page.evaluate(() => window.replies.filter((m) => m.type === 'error').map((m) => m.message));
    assert.match(errors.join('\n'), /no part 'bracket\/nothing'/);
    assert.match(errors.join('\n'), /1 to 1024 bytes/);
    assert.match(errors.join('\n'), /choose the part to take out first/);
    assert.equal(await page.evaluate(() => window.tandem.picking), true, 'still choosing');
  } finally {
    await stopTandem(run);
  }
});

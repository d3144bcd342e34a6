// The viewer in a real browser (Debian's headless Chromium, driven by playwright-core), against a
// real tandem process: the page loads, the tree grows, dragging the part adds operator nodes where
// it is dragged, α changes the share of operator nodes, tuning and reset work and the session
// still replays to the identical tree, the tuning panel has the controls of the parameters the
// session announces, a request without the token is refused, hostile messages
// are refused without disturbing the planner, a replay drives the viewer, the path can be saved,
// automatic α moves and can be pinned,
// the layered drawing for software renderers shows the same picture as drawing everything.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import {
  startTandem, stopTandem, launchBrowser, openViewer, artefactPath, scratch, sleep, tandemBin,
  writeSwingTrace, writeClosedScene,
} from './harness.mjs';

let browser;
before(async () => { browser = await launchBrowser(); });
after(async () => { await browser?.close(); });

const dir = scratch();
const session = (name) => path.join(dir, `${name}.jsonl`);
const live = (name, extra) => ['interactive', ...extra, '--port', '0', '--session', session(name)];

function counts(page) { return page.evaluate(() => window.tandem.counts()); }

async function waitFor(page, fn, arg, timeout = 20000) {
  await page.waitForFunction(fn, arg, { timeout, polling: 100 });
}

function request(port, { path: p = '/', headers = {} } = {}) {
  return new Promise((resolve, reject) => {
    const req = http.request({ host: '127.0.0.1', port, path: p, headers }, (res) => {
      let body = '';
      res.on('data', (d) => { body += d; });
      res.on('end', () => resolve({ status: res.statusCode, body }));
    });
    req.on('error', reject);
    req.end();
  });
}

test('the page loads, shows the scene and the tree grows', { timeout: 90000 }, async () => {
  const run = await startTandem(live('grows', ['cluttered-2', '--mode', 'interactive', '--alpha', '0.5']));
  try {
    const page = await openViewer(browser, run);
    const hello = await page.evaluate(() => window.tandem.hello);
    assert.equal(hello.problem, 'cluttered-2');
    assert.equal(await page.locator('#problem').textContent(), 'cluttered-2');
    await waitFor(page, () => window.tandem.counts().nodes > 200);
    const a = await counts(page);
    await sleep(2000);
    const b = await counts(page);
    assert.ok(b.nodes > a.nodes, `the tree grows: ${a.nodes} then ${b.nodes} nodes`);
    assert.ok(b.edges >= b.nodes - 2, 'every node but the roots has its edge');
    const status = await page.evaluate(() => window.tandem.status);
    assert.ok(status.iterations > 0 && status.collision_checks > 0);
    assert.match(await page.locator('#status').textContent(), /iterations\/s/);
    await waitFor(page, () => window.tandem.frames > 10);
    await page.screenshot({ path: artefactPath('viewer.png') });
    assert.deepEqual(page.logs.filter((l) => l.startsWith('page error')), []);
  } finally {
    await stopTandem(run);
  }
});

/** Compares two PNG pictures of the same size in a page, outside the boxes `skip`: how many pixels
 * differ by more than 40 in a channel, how many of the first differ so from the background and
 * how many are near the colour `mark`. */
async function comparePictures(page, a, b, { background, mark, skip }) {
  return page.evaluate(async ([a, b, background, mark, skip]) => {
    const pixels = async (png) => {
      const img = new Image();
      img.src = `data:image/png;base64,${png}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      return { data: g.getImageData(0, 0, c.width, c.height).data, width: c.width };
    };
    const { data: pa, width } = await pixels(a);
    const { data: pb } = await pixels(b);
    const far = (p, i, q, j) => Math.max(Math.abs(p[i] - q[j]), Math.abs(p[i + 1] - q[j + 1]), Math.abs(p[i + 2] - q[j + 2])) > 40;
    let differ = 0, drawn = 0, marked = 0;
    for (let i = 0; i < pa.length; i += 4) {
      const x = (i / 4) % width, y = Math.floor(i / 4 / width);
      if (skip.some((b) => x >= b.left && x <= b.right && y >= b.top && y <= b.bottom)) continue;
      if (far(pa, i, pb, i)) differ++;
      if (far(pa, i, background, 0)) drawn++;
      if (!far(pa, i, mark, 0)) marked++;
    }
    return { pixels: pa.length / 4, differ, drawn, marked };
  }, [a.toString('base64'), b.toString('base64'), background, mark, skip]);
}

test('the demo waits for a browser, then grows trees with operator and contact nodes until solved', { timeout: 200000 }, async () => {
  const run = await startTandem(['demo', '--port', '0', '--session', session('demo')]);
  try {
    assert.match(run.output, /the planner starts when a browser opens the viewer/);
    await sleep(2500);
    assert.doesNotMatch(run.output, /iterations \(/, 'nothing is planned before a browser connects');
    const page = await openViewer(browser, run);
    assert.equal((await page.evaluate(() => window.tandem.hello)).problem, 'shaft-bores');
    // Growing: operator and contact nodes appear, and the tree grows while the page watches.
    await waitFor(page, () => {
      const c = window.tandem.counts();
      return c.bySource[2] > 0 && c.bySource[3] > 0;
    }, null, 90000);
    const a = await counts(page);
    await sleep(1000);
    const b = await counts(page);
    assert.ok(b.nodes > a.nodes || (await page.evaluate(() => window.tandem.status.status)) === 'solved',
      `the trees grow: ${a.nodes} then ${b.nodes} nodes`);
    await waitFor(page, () => window.tandem.status.status === 'solved', null, 150000);
    const solved = await page.evaluate(() => window.tandem.status);
    assert.ok(solved.nodes_by_source[3] > 0, `the solved tree has contact nodes: ${solved.nodes_by_source}`);
    assert.ok(solved.nodes_by_source[2] > 0, `and operator nodes: ${solved.nodes_by_source}`);
    // The page says so, with the session's own counts.
    const text = await page.locator('#status').textContent();
    assert.match(text, /random \/ operator \/ contact/);
    const fmt = (n) => n.toLocaleString('en-US').replace(/,/g, '');
    assert.ok(text.replace(/[\s,\u202f\u00a0]/g, '').includes(
      `${fmt(solved.nodes_by_source[1])}/${fmt(solved.nodes_by_source[2])}/${fmt(solved.nodes_by_source[3])}`), text);
    await page.screenshot({ path: artefactPath('demo.png') });
    assert.deepEqual(page.logs.filter((l) => l.startsWith('page error')), []);
  } finally {
    await stopTandem(run);
  }
});

/** The page's scripts that make an emulated Meta Quest 3 (IWER) the browser's WebXR runtime. */
const emulatedHeadset = [
  { path: path.join(path.dirname(new URL(import.meta.url).pathname), '..', 'node_modules', 'iwer', 'build', 'iwer.min.js') },
  () => {
    window.xrDevice = new IWER.XRDevice(IWER.metaQuest3);
    window.xrDevice.installRuntime({ forceInstall: true }); // over Chromium's own navigator.xr
  },
];

const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const turn = (a, b) => 2 * Math.acos(Math.min(1, Math.abs(a[3] * b[3] + a[4] * b[4] + a[5] * b[5] + a[6] * b[6])));

test('in VR (an emulated headset) the grip holds the part, operator nodes grow where the hand moved it, letting go leaves it; contact is felt', { timeout: 120000 }, async () => {
  // The planner runs only while the test waits for its operator nodes: under a tree that grows
  // all along (contact samples from the idle hand), the page's software-rendered headset view
  // slowed down until, on CI's busier machine, a later step timed out. The operator thread runs
  // throughout, paused or not.
  const run = await startTandem(live('vr', ['shaft-bores', '--operator', 'browser', '--alpha', '0.5', '--paused']));
  try {
    const page = await openViewer(browser, run, { init: emulatedHeadset });
    await waitFor(page, () => !document.getElementById('enter-vr').hidden);
    await page.click('#enter-vr');
    await waitFor(page, () => window.tandem.xr.presenting);
    const hand = (p, q) => page.evaluate(([p, q]) => {
      const c = window.xrDevice.controllers.right;
      c.position.set(...p);
      if (q) c.quaternion.set(...q);
    }, [p, q]);
    const squeeze = (v) => page.evaluate((v) => window.xrDevice.controllers.right.updateButtonValue('squeeze', v), v);
    const pose = () => page.evaluate(() => window.tandem.partPose());
    // (The headset's view covers the page, as a headset's does: the buttons are pressed by script.)
    const command = (c) => page.evaluate((c) => document.getElementById(c).click(), c);

    // Grab the part where it lies (the hand at its reference point) and lift it 0.5 m, 0.4 m along x.
    const start = await pose();
    const at = await page.evaluate((q) => window.tandem.xr.pointOf(q[0], q[1], q[2]), start);
    await hand(at, [0, 0, 0, 1]);
    await sleep(300);
    await squeeze(1);
    await waitFor(page, () => window.tandem.xr.holding);
    const lifted = [start[0] + 0.4, start[1], start[2] + 0.5];
    // The scene's x is the headset space's x, the scene's z its y.
    await hand([at[0] + 0.4, at[1] + 0.5, at[2]]);
    await waitFor(page, ([t, tol]) => Math.hypot(...window.tandem.partPose().slice(0, 3).map((v, k) => v - t[k])) < tol, [lifted, 1e-4]);
    assert.ok(turn(await pose(), start) < 1e-3, 'a hand that does not turn does not turn the part');
    // (The idle hand's contact samples make the tree large by now: the page searches it slowly.)
    await command('resume');
    await waitFor(page, (t) => window.tandem.operatorNodes().some((n) => Math.hypot(n[0] - t[0], n[1] - t[1], n[2] - t[2]) < 0.05), lifted, 60000);
    // The rest (turning, letting go, contact) needs no more nodes: paused again.
    await command('pause');
    await waitFor(page, () => window.tandem.status.paused);
    // Turning the hand 30 degrees about the vertical turns the part 30 degrees.
    const s = Math.sin(Math.PI / 12), c = Math.cos(Math.PI / 12);
    await hand([at[0] + 0.4, at[1] + 0.5, at[2]], [0, s, 0, c]);
    await waitFor(page, (q0) => {
      const q = window.tandem.partPose();
      const dot = Math.abs(q[3] * q0[3] + q[4] * q0[4] + q[5] * q0[5] + q[6] * q0[6]);
      return Math.abs(2 * Math.acos(Math.min(1, dot)) - Math.PI / 6) < 1e-3;
    }, start);

    // Letting go leaves the part where it is: the hand moves on without it.
    await squeeze(0);
    await waitFor(page, () => !window.tandem.xr.holding);
    // Released as the hand left it, turned, and the server's operator there too. (Just after
    // letting go the page may show, for a moment, a pose the server echoed from before the turn:
    // a flicker, noted and not fixed; the pose then settles where the part was let go.)
    await waitFor(page, ([q0, t0]) => {
      const q = window.tandem.partPose(), o = window.tandem.operator.q;
      const dot = Math.abs(q[3] * q0[3] + q[4] * q0[4] + q[5] * q0[5] + q[6] * q0[6]);
      return Math.abs(2 * Math.acos(Math.min(1, dot)) - Math.PI / 6) < 1e-3 &&
        Math.hypot(q[0] - t0[0], q[1] - t0[1], q[2] - t0[2]) < 1e-4 &&
        q.every((v, k) => Math.abs(v - o[k]) < 1e-6);
    }, [start, lifted]);
    const released = await pose();
    const h = [at[0] - 0.3, at[1] + 0.2, at[2] + 0.2];
    await hand(h, [0, 0, 0, 1]);
    await sleep(1000);
    // (To the rounding of the pose's way through the server and back: the hand moved 0.4 m.)
    const now = await pose();
    assert.ok(distance(now, released) < 1e-6 && turn(now, released) < 1e-6,
      `the part stays where it was let go: ${now} against ${released}`);
    assert.ok(distance(await page.evaluate(() => window.tandem.operator.q), released) < 1e-6, 'the operator is where it was let go');

    // Grab again where the hand is now (the clutch) and bring the part 2 cm above the left housing:
    // contact mode, felt as pulses of the holding controller.
    await squeeze(1);
    await waitFor(page, () => window.tandem.xr.holding);
    const p = await pose();
    const above = [-0.25, 0.0, 0.65];
    await hand([h[0] + above[0] - p[0], h[1] + above[2] - p[2], h[2] - (above[1] - p[1])]);
    await waitFor(page, () => window.tandem.operator?.contact === true);
    await waitFor(page, () => window.tandem.xr.pulses > 0);
    await page.screenshot({ path: artefactPath('vr.png') });

    // Out of VR, a gamepad rumbles for the same cue (the part still held near the housing by the
    // browser, the input in control).
    await squeeze(0);
    // (The emulated headset's view covers the page, as a headset's does: the button is pressed by
    // script.)
    await page.evaluate(() => document.getElementById('enter-vr').click());
    await waitFor(page, () => !window.tandem.xr.presenting);
    await page.evaluate(() => {
      window.__effects = [];
      const vibrationActuator = { playEffect: async (type, p) => { window.__effects.push({ type, ...p }); return 'complete'; } };
      navigator.getGamepads = () => [{ axes: [0, 0, 0, 0], buttons: [], vibrationActuator }];
    });
    await waitFor(page, () => window.__effects.length > 0);
    const effect = await page.evaluate(() => window.__effects[0]);
    assert.equal(effect.type, 'dual-rumble');
    assert.ok(effect.strongMagnitude > 0 && effect.strongMagnitude <= 1, JSON.stringify(effect));
    assert.deepEqual(page.logs.filter((l) => l.startsWith('page error')), []);
  } finally {
    await stopTandem(run);
  }
});

test('the layered drawing (software renderer) shows what drawing everything shows; the trees are thinned only while the camera turns', { timeout: 90000 }, async () => {
  const run = await startTandem(live('layers', ['cluttered-2', '--mode', 'interactive', '--alpha', '1', '--operator', 'browser']));
  try {
    // This page draws the growing trees into its kept image, a batch at a time.
    const layered = await openViewer(browser, run, { query: '&layers=on' });
    assert.equal((await layered.evaluate(() => window.tandem.rendering)).mode, 'layered');
    await waitFor(layered, () => window.tandem.counts().edges > 10000, undefined, 40000);
    await layered.click('#pause');
    await waitFor(layered, () => window.tandem.status.paused);
    // Every node the session has, in the page and drawn.
    await waitFor(layered, () => window.tandem.counts().edges === window.tandem.status.edges
      && window.tandem.rendering.drawnEdges === window.tandem.status.edges);
    const edges = await layered.evaluate(() => window.tandem.status.edges);
    // This one draws everything every frame.
    const direct = await openViewer(browser, run, { query: '&layers=off' });
    assert.equal((await direct.evaluate(() => window.tandem.rendering)).mode, 'direct');
    await waitFor(direct, (n) => window.tandem.counts().edges === n && window.tandem.rendering.drawnEdges === n, edges);
    await sleep(500);
    const a = await layered.locator('#view').screenshot({ path: artefactPath('viewer-layered.png') });
    const b = await direct.locator('#view').screenshot({ path: artefactPath('viewer-direct.png') });
    // Outside the part, the start and goal ghosts and transparent obstacles, which the layered
    // drawing draws over the trees' lines (layers.js); marked: the colour of the random edges.
    const view = await direct.locator('#view').boundingBox();
    const skip = (await direct.evaluate(() => window.tandem.overlaidBoxes())).map((b) => ({
      left: b.left - view.x - 3, right: b.right - view.x + 3, top: b.top - view.y - 3, bottom: b.bottom - view.y + 3 }));
    const cmp = await comparePictures(layered, b, a, { background: [0x1d, 0x20, 0x26], mark: [0x60, 0xa5, 0xfa], skip });
    assert.ok(cmp.drawn > 0.1 * cmp.pixels, `the picture shows the scene: ${JSON.stringify(cmp)}`);
    assert.ok(cmp.marked > 1000, `the picture shows the tree: ${JSON.stringify(cmp)}`);
    // Measured: 2–4% of the marked pixels differ (where lines and nodes overlap, drawn in another
    // order); without the new edges drawn into the kept image, 65–100%.
    assert.ok(cmp.differ < 0.15 * cmp.marked, `layered and direct differ: ${JSON.stringify(cmp)}`);
    await direct.close();

    // Thinned beyond 1000 edges while the camera turns, in full once it stops.
    const thinned = await openViewer(browser, run, { query: '&lod=1000' });
    await waitFor(thinned, (n) => window.tandem.counts().edges === n, edges);
    await thinned.evaluate(() => window.tandem.spin(true));
    await sleep(600);
    const turning = await thinned.evaluate(() => window.tandem.rendering.drawnEdges);
    assert.ok(turning > 0 && turning <= 1000, `${turning} of ${edges} edges drawn while turning`);
    await thinned.evaluate(() => window.tandem.spin(false));
    await waitFor(thinned, (n) => window.tandem.rendering.drawnEdges === n, edges);
  } finally {
    await stopTandem(run);
  }
});

test('a request without the token, from another host name or origin is refused', { timeout: 60000 }, async () => {
  const run = await startTandem(live('token', ['cluttered-1', '--paused']));
  try {
    const host = `127.0.0.1:${run.port}`;
    assert.equal((await request(run.port, { headers: { Host: host } })).status, 403);
    assert.equal((await request(run.port, { path: '/api/scene?token=wrong', headers: { Host: host } })).status, 403);
    const ok = await request(run.port, { path: `/api/scene?token=${run.token}`, headers: { Host: host } });
    assert.equal(ok.status, 200);
    const rebinding = await request(run.port, { path: `/?token=${run.token}`, headers: { Host: `evil.example:${run.port}` } });
    assert.equal(rebinding.status, 403, 'DNS rebinding: a foreign Host is refused');
    const upgrade = { Host: host, Connection: 'Upgrade', Upgrade: 'websocket', 'Sec-WebSocket-Version': '13',
      'Sec-WebSocket-Key': 'dGhlIHNhbXBsZSBub25jZQ==' };
    const foreign = await request(run.port, { path: `/ws?token=${run.token}`, headers: { ...upgrade, Origin: 'http://evil.example' } });
    assert.equal(foreign.status, 403, 'a WebSocket from another origin is refused');
    const noToken = await request(run.port, { path: '/ws', headers: upgrade });
    assert.equal(noToken.status, 403, 'a WebSocket without the token is refused');
    // And in a browser that never had the token: the page is refused, its socket never opens.
    const context = await browser.newContext();
    try {
      const page = await context.newPage();
      const response = await page.goto(`http://127.0.0.1:${run.port}/`);
      assert.equal(response.status(), 403);
      const opened = await page.evaluate((port) => new Promise((resolve) => {
        const ws = new WebSocket(`ws://127.0.0.1:${port}/ws`);
        ws.onopen = () => resolve(true);
        ws.onerror = () => resolve(false);
      }), run.port);
      assert.equal(opened, false);
    } finally {
      await context.close();
    }
    assert.match(run.errors, /refused .* missing or wrong token/);
  } finally {
    await stopTandem(run);
  }
});

test('dragging the part adds operator nodes where it is dragged', { timeout: 90000 }, async () => {
  // α = 0: every iteration grows toward the part; the operator is the browser only.
  const run = await startTandem(live('drag', ['cluttered-1', '--mode', 'interactive', '--alpha', '0', '--operator', 'browser']));
  try {
    const page = await openViewer(browser, run);
    await waitFor(page, () => window.tandem.operator);
    const before = await page.evaluate(() => window.tandem.operator.q);
    const from = await page.evaluate(() => window.tandem.partScreen());
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let k = 1; k <= 10; ++k) await page.mouse.move(from.x + 4 * k, from.y - 9 * k);
    await page.mouse.up();
    await sleep(300); // the last pointer events reach the gizmo
    const dragged = await page.evaluate(() => window.tandem.partPose());
    const moved = Math.hypot(dragged[0] - before[0], dragged[1] - before[1], dragged[2] - before[2]);
    assert.ok(moved > 0.2, `the drag moved the part (${moved.toFixed(3)} m)`);
    // The operator thread takes the pose; the planner grows a node there.
    await waitFor(page, (q) => {
      const op = window.tandem.operator;
      return op && Math.hypot(op.q[0] - q[0], op.q[1] - q[1], op.q[2] - q[2]) < 1e-3;
    }, dragged);
    await waitFor(page, (q) => window.tandem.operatorNodes().some(
      (p) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) < 0.05), dragged);
    const status = await page.evaluate(() => window.tandem.status);
    assert.equal(status.input, 'browser');
    const near = await page.evaluate((q) => window.tandem.operatorNodes().filter(
      (p) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) < 0.05).length, dragged);
    assert.ok(near >= 1, 'an operator node where the part was dragged');
    await page.screenshot({ path: artefactPath('viewer-drag.png') });
  } finally {
    await stopTandem(run);
  }
});

test('the keyboard, a gamepad and a WebHID SpaceMouse move the part', { timeout: 90000 }, async () => {
  const run = await startTandem(live('devices', ['cluttered-1', '--mode', 'interactive', '--alpha', '0', '--operator', 'browser']));
  try {
    const page = await openViewer(browser, run);
    // Stand-ins for the devices (the browser has none here): the Gamepad API and WebHID as a
    // device would drive them.
    await page.evaluate(() => {
      window.__pad = { axes: [0, 0, 0, 0], buttons: [] };
      navigator.getGamepads = () => [window.__pad];
      const listeners = [];
      window.__hid = {
        productName: 'SpaceMouse Compact (stand-in)', opened: true,
        addEventListener: (type, f) => listeners.push(f), open: async () => {},
        send(reportId, values) {
          const data = new DataView(new ArrayBuffer(2 * values.length));
          values.forEach((v, k) => data.setInt16(2 * k, v, true));
          for (const f of listeners) f({ reportId, data });
        },
      };
      Object.defineProperty(navigator, 'hid', { value: { requestDevice: async () => [window.__hid] } });
    });
    const z = () => page.evaluate(() => window.tandem.operator.q[2]);
    const x = () => page.evaluate(() => window.tandem.operator.q[0]);
    await waitFor(page, () => window.tandem.operator);
    const z0 = await z();
    await page.locator('#view canvas').focus().catch(() => {});
    // Each input is held until the planner's operator has moved: the page moves the part by
    // velocity × frame time, and a busy machine's software-rendered frames are slow and few.
    await page.keyboard.down('KeyE');
    await waitFor(page, (z1) => window.tandem.operator.q[2] > z1 + 0.1, z0);
    await page.keyboard.up('KeyE');
    const x0 = await x();
    await page.evaluate(() => { window.__pad.axes = [0.8, 0, 0, 0]; });
    await waitFor(page, (x1) => window.tandem.operator.q[0] > x1 + 0.1, x0);
    await page.evaluate(() => { window.__pad.axes = [0, 0, 0, 0]; });
    const x2 = await x();
    await page.click('#webhid');
    await waitFor(page, () => /SpaceMouse Compact/.test(document.getElementById('message').textContent));
    await page.evaluate(() => window.__hid.send(1, [-300, 0, 0, 0, 0, 0]));
    await waitFor(page, (x3) => window.tandem.operator.q[0] < x3 - 0.1, x2);
    await page.evaluate(() => window.__hid.send(1, [0, 0, 0, 0, 0, 0]));
    // And a node grows where the part went.
    await waitFor(page, () => {
      const q = window.tandem.operator.q;
      return window.tandem.operatorNodes().some((p) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) < 0.05);
    });
  } finally {
    await stopTandem(run);
  }
});

// Over `ms` of the run: the iterations, the operator's iterations, and the nodes added in all and
// by the operator.
async function operatorCounts(page, ms) {
  const status = () => page.evaluate(() => window.tandem.status);
  const [a, sa] = [await counts(page), await status()];
  await sleep(ms);
  const [b, sb] = [await counts(page), await status()];
  return {
    added: b.nodes - a.nodes, byOperator: b.bySource[2] - a.bySource[2],
    iterations: sb.iterations - sa.iterations, turns: sb.operator_iterations - sa.operator_iterations,
  };
}

// The operator's share of the iterations (what α sets: 1 − α of them) and of the nodes added (fewer
// than that, as an operator target near the tree adds little), summed over windows.
function operatorShare(windows) {
  const sum = (key) => windows.reduce((total, w) => total + w[key], 0);
  const [added, iterations] = [sum('added'), sum('iterations')];
  return {
    added, iterations,
    share: sum('byOperator') / Math.max(added, 1), turns: sum('turns') / Math.max(iterations, 1),
  };
}

async function setAlpha(page, value) {
  await page.locator('#alpha').fill(String(value));
  await page.locator('#alpha').dispatchEvent('change');
  await waitFor(page, (v) => Math.abs(window.tandem.status.settings.alpha - v) < 1e-9, value);
}

test('changing α in the viewer changes the operator\'s share of the iterations and of the nodes', { timeout: 90000 }, async () => {
  const run = await startTandem(live('alpha', [writeClosedScene(dir), '--mode', 'interactive', '--alpha', '0.5',
    '--operator', `trace:${writeSwingTrace(dir)}`]));
  try {
    const page = await openViewer(browser, run);
    // The operator's region is fresh at first, and every node its iterations add fills it: how
    // many nodes an operator iteration adds there drifts as the run goes on, at a pace set by the
    // machine's load. So the tree first covers the region, and the windows go α 0.95, 0.05, 0.05,
    // 0.95, so that a steady drift weighs on both settings alike.
    await sleep(3000);
    await setAlpha(page, 0.95);
    const first = await operatorCounts(page, 2000);
    await setAlpha(page, 0.05);
    const operator = operatorShare([await operatorCounts(page, 4000)]);
    await setAlpha(page, 0.95);
    const computer = operatorShare([first, await operatorCounts(page, 2000)]);
    assert.ok(computer.added > 50 && operator.added > 50, `nodes were added (${computer.added}, ${operator.added})`);
    assert.ok(computer.iterations > 1000 && operator.iterations > 1000,
      `iterations ran (${computer.iterations}, ${operator.iterations})`);
    // Thousands of draws: the operator's share of the iterations is 1 − α to within a few points.
    const pct = (x) => `${(100 * x).toFixed(1)}%`;
    assert.ok(Math.abs(computer.turns - 0.05) < 0.03, `operator iterations at α 0.95: ${pct(computer.turns)}`);
    assert.ok(Math.abs(operator.turns - 0.95) < 0.03, `operator iterations at α 0.05: ${pct(operator.turns)}`);
    // The nodes follow, less sharply: an operator target near the tree adds little.
    assert.ok(operator.share > computer.share + 0.1,
      `operator nodes: ${pct(computer.share)} at α 0.95, ${pct(operator.share)} at α 0.05`);
  } finally {
    await stopTandem(run);
  }
});

test('automatic α: the viewer shows α moving; unticking it, or setting α by hand, pins α', { timeout: 90000 }, async () => {
  // The closed scene: a solution would stop the planner, and α with it, mid-test.
  const run = await startTandem(live('auto-alpha', [writeClosedScene(dir), '--mode', 'interactive-contact',
    '--auto-alpha', 'true']));
  try {
    const page = await openViewer(browser, run);
    await waitFor(page, () => typeof window.tandem.status?.alpha === 'number');
    const seen = new Set();
    for (let k = 0; k < 30; ++k) {
      seen.add(await page.evaluate(() => window.tandem.status.alpha));
      await sleep(100);
    }
    const values = [...seen];
    assert.ok(values.length > 3, `α moved: ${values.join(', ')}`);
    // The floor is on each side's share of the work: α, a share of the iterations, stays inside (0, 1).
    assert.ok(values.every((a) => a > 0 && a < 1), `α a probability: ${values.join(', ')}`);
    assert.match(await page.locator('#status').innerText(), /authority α\s+0\.\d\d \(automatic\)/);
    // Unticking pins α where it was.
    const before = await page.evaluate(() => window.tandem.status.alpha);
    await page.locator('#auto_alpha').uncheck();
    await waitFor(page, () => window.tandem.status.settings.auto_alpha === false);
    const pinned = await page.evaluate(() => window.tandem.status.settings.alpha);
    assert.ok(Math.abs(pinned - before) < 0.2, `pinned at ${pinned}, shown ${before} just before`);
    await sleep(500);
    assert.equal(await page.evaluate(() => window.tandem.status.alpha), pinned, 'α stays pinned');
    assert.match(await page.locator('#status').innerText(), /\(pinned\)/);
    // Ticked again it moves; setting α by hand pins it at that value.
    await page.locator('#auto_alpha').check();
    await waitFor(page, () => window.tandem.status.settings.auto_alpha === true);
    await setAlpha(page, 0.3);
    await waitFor(page, () => window.tandem.status.settings.auto_alpha === false && window.tandem.status.alpha === 0.3);
  } finally {
    await stopTandem(run);
  }
});

test('pause, step, reset and tuning from the viewer; the session replays to the identical tree', { timeout: 120000 }, async () => {
  const file = session('tuning');
  const run = await startTandem(live('tuning', ['cluttered-2', '--mode', 'interactive-contact', '--alpha', '0.5']));
  try {
    const page = await openViewer(browser, run);
    await waitFor(page, () => window.tandem.counts().nodes > 100);
    await page.click('#pause');
    await waitFor(page, () => window.tandem.status.paused);
    const paused = await page.evaluate(() => window.tandem.status.steps);
    await sleep(500);
    assert.equal(await page.evaluate(() => window.tandem.status.steps), paused, 'paused: no steps');
    for (let k = 0; k < 3; ++k) await page.click('#step');
    await waitFor(page, (s) => window.tandem.status.steps === s + 3, paused);
    await page.locator('#contact_samples').fill('25');
    await page.locator('#contact_samples').dispatchEvent('change');
    await waitFor(page, () => window.tandem.status.settings.contact_samples === 25);
    await page.click('#reset');
    await waitFor(page, () => window.tandem.status.resets === 1 && window.tandem.counts().nodes <= 2);
    await page.click('#resume');
    await waitFor(page, () => !window.tandem.status.paused && window.tandem.counts().nodes > 50);
    await setAlpha(page, 0.3);
  } finally {
    await stopTandem(run);
  }
  assert.equal(run.exited.code, 1, 'interrupted, not solved');
  const journal = readFileSync(file, 'utf8');
  assert.match(journal, /"reset":/);
  assert.match(journal, /"params":/);
  const replay = spawnSync(tandemBin, ['replay', file], { encoding: 'utf8' });
  const kept = artefactPath('tuning-session.jsonl');
  if (replay.status !== 0) copyFileSync(file, kept);
  assert.equal(replay.status, 0, `tandem replay ${file} (kept as ${kept}): ${replay.stdout}${replay.stderr}`);
  assert.match(replay.stdout, /identical to the session's tree/);
});

/** The session's announced parameters (hello.parameters) and the tuning panel's controls. */
async function tuningPanelOf(name, mode) {
  const run = await startTandem(live(name, ['cluttered-1', '--mode', mode, '--paused']));
  try {
    const page = await openViewer(browser, run);
    return await page.evaluate(() => ({
      parameters: window.tandem.hello.parameters,
      controls: [...document.querySelectorAll('#tuning-controls input, #tuning-controls select')].map((el) => ({
        id: el.id, type: el.type, min: el.getAttribute('min'), max: el.getAttribute('max') })),
    }));
  } finally {
    await stopTandem(run);
  }
}

test('the tuning panel has a control per parameter the session announces, with its bounds', { timeout: 90000 }, async () => {
  const bound = (x) => (x === null || x === undefined ? null : Number(x));
  for (const mode of ['interactive-contact', 'irrt']) {
    const { parameters, controls } = await tuningPanelOf(`panel-${mode}`, mode);
    assert.ok(Array.isArray(parameters) && parameters.length > 0, `${mode} announces parameters`);
    assert.deepEqual(controls.map((c) => c.id), parameters.map((p) => p.name), `${mode}: one control per parameter, in order`);
    parameters.forEach((p, k) => {
      const c = controls[k];
      if (p.kind === 'boolean') assert.equal(c.type, 'checkbox', p.name);
      else if (p.kind === 'choice') assert.equal(c.type, 'select-one', p.name);
      else {
        assert.equal(bound(c.min), bound(p.min), `${mode} ${p.name}: min`);
        assert.equal(bound(c.max), bound(p.max), `${mode} ${p.name}: max`);
      }
    });
    if (mode === 'interactive-contact') {
      for (const name of ['alpha', 'contact_samples']) assert.ok(controls.some((c) => c.id === name), name);
    }
  }
});

test('hostile messages are refused with an error; a viewer that goes away does not disturb the planner', { timeout: 90000 }, async () => {
  const run = await startTandem(live('hostile', ['cluttered-2', '--mode', 'interactive', '--alpha', '0.5']));
  try {
    const page = await openViewer(browser, run);
    const replies = await page.evaluate(async ({ port, token }) => {
      const ws = new WebSocket(`ws://127.0.0.1:${port}/ws?token=${token}`);
      const errors = [];
      ws.onmessage = (e) => { if (typeof e.data === 'string' && JSON.parse(e.data).type === 'error') errors.push(JSON.parse(e.data).message); };
      await new Promise((r) => { ws.onopen = r; });
      for (const m of ['not json', '[1,2]', '{"type":"pose","q":[1,2]}', '{"type":"pose","q":[0,0,0,0,0,0,0]}',
        '{"type":"params","alpha":7}', '{"type":"params","contact_samples":"many"}', '{"type":"nope"}',
        '{"type":"command","command":"rm -rf"}', '{"type":"pose","q":[1e308,0,0,0,0,0,1]}'])
        ws.send(m);
      await new Promise((r) => setTimeout(r, 1000));
      const closed = new Promise((r) => { ws.onclose = r; });
      ws.send('x'.repeat(100000)); // over the limit: the server closes this socket
      await closed;
      return errors;
    }, { port: run.port, token: run.token });
    assert.equal(replies.length, 9, `one error per bad message: ${JSON.stringify(replies)}`);
    assert.match(run.errors, /refused a message from 127\.0\.0\.1: not JSON/);
    await page.close(); // the viewer goes away
    const before = JSON.parse((await request(run.port, { path: `/api/scene?token=${run.token}`, headers: { Host: `127.0.0.1:${run.port}` } })).status === 200 ? '1' : '0');
    assert.equal(before, 1);
    const progress = (s) => Number([...s.matchAll(/(\d+) iterations \(/g)].at(-1)?.[1] ?? 0);
    const a = progress(run.output);
    await sleep(2500);
    assert.ok(progress(run.output) > a, 'the planner goes on');
    const again = await openViewer(browser, run);
    await waitFor(again, () => window.tandem.counts().nodes > 100);
    await again.close();
    assert.equal(run.exited, null, 'tandem is still running');
  } finally {
    await stopTandem(run);
  }
});

test('a solved session: the path and the session can be saved from the viewer', { timeout: 90000 }, async () => {
  const run = await startTandem(live('solve', ['cluttered-1', '--mode', 'interactive-contact', '--alpha', '0.5']));
  try {
    const page = await openViewer(browser, run);
    await waitFor(page, () => window.tandem.solution.length > 1, null, 60000);
    await waitFor(page, () => window.tandem.status.status === 'solved');
    assert.equal(await page.locator('#path-box').isHidden(), false);
    await page.click('#play');
    await sleep(300);
    const text = await page.evaluate(async () => (await fetch(document.getElementById('save-path').href)).text());
    const lines = text.trim().split('\n');
    assert.ok(lines.length >= 2 && lines.every((l) => l.trim().split(/\s+/).length === 7), 'OMPL path format');
    const file = path.join(path.dirname(session('solve')), 'solve.path');
    writeFileSync(file, text);
    execFileSync(tandemBin, ['check-path', 'cluttered-1', file]);
    const journal = await page.evaluate(async () => (await fetch(document.getElementById('save-session').href)).text());
    assert.match(journal.split('\n')[0], /"journal":"tandem session"/);
    await page.screenshot({ path: artefactPath('viewer-solved.png') });
  } finally {
    await stopTandem(run);
  }
});

test('a replay drives the viewer to the recorded tree', { timeout: 90000 }, async () => {
  const file = session('replayed');
  // Solved (exit 0) or not in the 3 s (exit 1), the journal is complete and replays.
  const recorded = spawnSync(tandemBin, ['interactive', 'cluttered-1', '--headless', '--time-limit', '3',
    '--alpha', '0.5', '--session', file], { encoding: 'utf8' });
  assert.ok(recorded.status === 0 || recorded.status === 1, recorded.stderr);
  const end = readFileSync(file, 'utf8').trim().split('\n').map((l) => JSON.parse(l)).filter((r) => r.end).at(-1);
  const run = await startTandem(['replay', file, '--serve', '--port', '0', '--speed', '0']);
  try {
    const page = await openViewer(browser, run);
    await waitFor(page, () => window.tandem.status.status !== 'replaying');
    await waitFor(page, (n) => window.tandem.counts().nodes === n, end.nodes);
    assert.match(run.output, /identical to the session's tree/);
    // A replay cannot be tuned: it announces no parameter and the panel has no control.
    assert.deepEqual(await page.evaluate(() => window.tandem.hello.parameters), []);
    assert.equal(await page.locator('#tuning-controls input, #tuning-controls select').count(), 0);
  } finally {
    await stopTandem(run);
  }
});

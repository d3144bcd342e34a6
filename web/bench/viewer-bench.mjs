// The viewer's benchmark (not a test): on this machine, with Debian's headless Chromium,
//   1. planner iterations in a fixed planning time with the viewer attached vs headless (the
//      same seeded BiRRT, α = 1, on environment 2: the same tree, so the count is the throughput);
//   2. the time from a browser input event (a drag of the part) to its node in the tree: as the
//      session measures it (event received → operator node grown) and as the page sees it (event
//      sent → the status announcing that node received);
//   3. the viewer's frame rate with more than 100 000 edges, while the planner runs and paused.
// Usage: node bench/viewer-bench.mjs [--runs N] [--seconds S] [--parts throughput,latency,fps]
//        [--out FILE.json]
import { spawnSync } from 'node:child_process';
import { writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import {
  startTandem, stopTandem, launchBrowser, openViewer, scratch, sleep, tandemBin, root, writeSwingTrace,
} from '../test/harness.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const runs = Number(arg('--runs', 3));
const seconds = Number(arg('--seconds', 20));
const out = arg('--out', path.join(root, 'bench-results', 'viewer', 'viewer.json'));
const parts = new Set(arg('--parts', 'throughput,latency,fps').split(','));
const dir = scratch();
const median = (xs) => { const s = [...xs].sort((a, b) => a - b); const m = s.length >> 1; return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2; };
const quantile = (xs, q) => { const s = [...xs].sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.floor(q * s.length))]; };
const iterationsOf = (text) => Number(text.match(/(?:timeout|solved|interrupted) after (\d+) iterations/)?.[1]);

const browser = await launchBrowser();
const result = { machine: `${process.platform} ${(await import('node:os')).cpus().length} cores`, seconds, runs };

// 1. Throughput.
const common = ['cluttered-2', '--mode', 'interactive', '--alpha', '1', '--operator', 'browser', '--seed', '1',
  '--time-limit', String(seconds)];
const headless = [], viewer = [];
for (let r = 0; parts.has('throughput') && r < runs; ++r) {
  // Exit 1: not solved within the time limit (as expected here).
  const h = spawnSync(tandemBin, ['interactive', ...common, '--headless', '--session', path.join(dir, `h${r}.jsonl`)],
    { encoding: 'utf8' });
  headless.push(iterationsOf(h.stdout));
  const run = await startTandem(['interactive', ...common, '--port', '0', '--exit-when-done', '--session', path.join(dir, `v${r}.jsonl`)]);
  const page = await openViewer(browser, run);
  await run.exit;
  const shown = await page.evaluate(() => window.tandem.counts().edges);
  await page.close();
  viewer.push(iterationsOf(run.output));
  console.error(`throughput run ${r + 1}: headless ${headless.at(-1)}, with the viewer ${viewer.at(-1)} iterations (viewer showed ${shown} edges)`);
}
if (parts.has('throughput')) result.throughput = { headless, viewer, ratio: median(viewer) / median(headless) };

// 2. Input to node.
if (parts.has('latency')) {
  const run = await startTandem(['interactive', 'cluttered-1', '--mode', 'interactive', '--alpha', '0', '--operator', 'browser',
    '--port', '0', '--session', path.join(dir, 'latency.jsonl')]);
  const page = await openViewer(browser, run);
  await page.waitForFunction(() => window.tandem.operator);
  for (let k = 0; k < 24; ++k) {
    const from = await page.evaluate(() => window.tandem.partScreen());
    const dy = k % 2 ? 30 : -30;
    await page.mouse.move(from.x, from.y);
    await page.mouse.down();
    for (let s = 1; s <= 3; ++s) await page.mouse.move(from.x, from.y + (dy * s) / 3);
    await page.mouse.up();
    await sleep(400);
  }
  const lat = await page.evaluate(() => window.tandem.latencies);
  await stopTandem(run);
  const server = lat.map((l) => l.server_ms), trip = lat.map((l) => l.round_trip_ms);
  result.latency = { samples: lat.length, server_median_ms: median(server), server_p90_ms: quantile(server, 0.9),
    round_trip_median_ms: median(trip), round_trip_p90_ms: quantile(trip, 0.9) };
  console.error(`latency: ${JSON.stringify(result.latency)}`);
}

// 3. Frame rate with > 100k edges: how the page draws with a software renderer (layers.js):
//    the camera still (the kept image, new edges only), the camera turning (the trees thinned
//    while it moves), the camera turning in full detail (?lod=0) and drawing everything every
//    frame as with a GPU (?layers=off); while the planner runs, then paused.
if (parts.has('fps')) {
  const trace = writeSwingTrace(dir, 600);
  // α = 0: the trees grow only toward the swinging part, so they reach 100k edges without solving.
  const run = await startTandem(['interactive', 'cluttered-2', '--mode', 'interactive', '--alpha', '0', '--operator',
    `trace:${trace}`, '--port', '0', '--session', path.join(dir, 'fps.jsonl')]);
  // Uncapped (the viewer draws at most 30 frames a second by default), a frame drawn every time
  // (the camera turning, or redraw(true) with it still): what the renderer can do.
  const ways = [
    { name: 'still', query: '', hook: 'redraw' },
    { name: 'turning', query: '', hook: 'spin' },
    { name: 'turning_full_detail', query: '&lod=0', hook: 'spin' },
    { name: 'turning_direct', query: '&layers=off', hook: 'spin' },
  ];
  const measure = async (way) => {
    const page = await openViewer(browser, run, { query: `&maxfps=0${way.query}` });
    await page.waitForFunction(() => window.tandem.counts().edges > 100000, null, { timeout: 120000, polling: 500 });
    await page.evaluate((hook) => window.tandem[hook](true), way.hook);
    await sleep(1000);
    const f0 = await page.evaluate(() => window.tandem.frames);
    const t0 = Date.now();
    await sleep(5000);
    const fps = (1000 * ((await page.evaluate(() => window.tandem.frames)) - f0)) / (Date.now() - t0);
    const { edges } = await page.evaluate(() => window.tandem.counts());
    const { drawnEdges } = await page.evaluate(() => window.tandem.rendering);
    await page.close();
    return { fps, edges, drawn_edges_last_frame: drawnEdges };
  };
  result.frame_rate = { planning: {}, paused: {} };
  for (const way of ways) result.frame_rate.planning[way.name] = await measure(way);
  const control = await openViewer(browser, run);
  await control.click('#pause');
  await control.waitForFunction(() => window.tandem.status.paused);
  await control.close();
  for (const way of ways) result.frame_rate.paused[way.name] = await measure(way);
  await stopTandem(run);
  console.error(`frame rate: ${JSON.stringify(result.frame_rate)}`);
}
await browser.close();

mkdirSync(path.dirname(out), { recursive: true });
writeFileSync(out, `${JSON.stringify(result, null, 2)}\n`);
const f = (x, d = 0) => x.toLocaleString('en', { maximumFractionDigits: d, minimumFractionDigits: d });
const rows = ['| measure | value |', '| --- | ---: |'];
if (result.throughput) {
  rows.push(`| planner iterations in ${seconds} s, headless (median of ${runs}) | ${f(median(headless))} |`,
    `| the same with the viewer attached | ${f(median(viewer))} |`,
    `| with the viewer / headless | ${f(100 * result.throughput.ratio, 1)}% |`);
}
if (result.latency) {
  const l = result.latency;
  rows.push(`| input event → its node, in the session (median, p90 of ${l.samples}) | ${f(l.server_median_ms, 1)} ms, ${f(l.server_p90_ms, 1)} ms |`,
    `| input event sent → the page has its node (median, p90) | ${f(l.round_trip_median_ms, 1)} ms, ${f(l.round_trip_p90_ms, 1)} ms |`);
}
if (result.frame_rate) {
  const what = {
    still: 'camera still (kept image, new edges drawn)',
    turning: 'camera turning (trees thinned while it moves)',
    turning_full_detail: 'camera turning, full detail (`?lod=0`)',
    turning_direct: 'camera turning, everything every frame (`?layers=off`, as with a GPU)',
  };
  for (const state of ['planning', 'paused']) {
    for (const [name, r] of Object.entries(result.frame_rate[state])) {
      rows.push(`| frame rate, ${f(r.edges)} edges, planner ${state === 'planning' ? 'running' : 'paused'}, ${what[name]}, uncapped; edges drawn | ${f(r.fps, 1)} fps; ${f(r.drawn_edges_last_frame)} |`);
    }
  }
}
console.log(rows.join('\n'));

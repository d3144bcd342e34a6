// Starts tandem with its viewer and a headless Debian Chromium (playwright-core) for the tests and
// the benchmark. The tandem binary: $TANDEM_BIN, else ../build/apps/tandem/tandem.
import { execFileSync, spawn } from 'node:child_process';
import { mkdtempSync, existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
export const root = path.resolve(here, '..', '..');
export const tandemBin = process.env.TANDEM_BIN ?? path.join(root, 'build', 'apps', 'tandem', 'tandem');
export const artefacts = process.env.TANDEM_ARTEFACTS ?? path.join(root, 'build', 'test-artefacts');
export const chromiumPath = process.env.CHROMIUM ?? '/usr/bin/chromium';

export function scratch() {
  return mkdtempSync(path.join(tmpdir(), 'tandem-viewer-'));
}

// Every tandem this process started, ended (Ctrl-C) when it exits, also after an uncaught error: a
// failed test or benchmark must not leave a planner running on the machine.
const running = new Set();
process.on('exit', () => { for (const proc of running) proc.kill('SIGINT'); });

/** Runs `tandem ARGS` until it prints its viewer's URL; resolves to {proc, url, port, token, output}. */
export function startTandem(args, { urlPattern = /viewer: (http:\/\/\S+)/ } = {}) {
  if (!existsSync(tandemBin)) throw new Error(`no tandem binary at ${tandemBin} (build it first)`);
  const proc = spawn(tandemBin, args, { stdio: ['ignore', 'pipe', 'pipe'] });
  running.add(proc);
  proc.on('exit', () => running.delete(proc));
  const run = { proc, output: '', errors: '', exited: null };
  proc.stdout.on('data', (d) => { run.output += d; });
  proc.stderr.on('data', (d) => { run.errors += d; });
  run.exit = new Promise((resolve) => proc.on('exit', (code, signal) => {
    run.exited = { code, signal };
    resolve(run.exited);
  }));
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`tandem printed no URL:\n${run.output}\n${run.errors}`)), 20000);
    const check = () => {
      const m = run.output.match(urlPattern);
      if (m) {
        clearTimeout(timer);
        const url = new URL(m[1]);
        Object.assign(run, { url: m[1], port: Number(url.port), token: url.searchParams.get('token') });
        resolve(run);
      }
    };
    proc.stdout.on('data', check);
    proc.on('exit', () => { clearTimeout(timer); reject(new Error(`tandem exited:\n${run.output}\n${run.errors}`)); });
  });
}

const openPages = new Set();

/** Closes the test's pages (a page left open keeps rendering), then ends tandem with Ctrl-C. */
export async function stopTandem(run) {
  for (const page of openPages) await page.close().catch(() => {});
  openPages.clear();
  if (!run || run.exited) return run?.exited;
  run.proc.kill('SIGINT');
  return run.exit;
}

/** Headless Chromium with the flags this machine needs (no network, no sandbox as root). */
export async function launchBrowser() {
  return chromium.launch({
    executablePath: chromiumPath,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--disable-quic',
      '--no-first-run', '--disable-background-networking', '--disable-component-update',
      '--disable-sync'],
  });
}

/** Opens the viewer of `run` in a new page; `init`: scripts (addInitScript's arguments) that run
 * in the page before its own; `ready`: what the page shows once it is ready (in the page; default:
 * connected, with a status). */
export async function openViewer(browser, run, {
  viewport = { width: 1280, height: 800 }, query = '', init = [],
  ready = () => window.tandem?.connected && window.tandem.status,
} = {}) {
  const page = await browser.newPage({ viewport });
  openPages.add(page);
  for (const script of init) await page.addInitScript(script);
  const logs = [];
  page.on('console', (m) => logs.push(m.text()));
  page.on('pageerror', (e) => logs.push(`page error: ${e.message}`));
  await page.goto(run.url + query);
  await page.waitForFunction(ready, null, { timeout: 20000 });
  page.logs = logs;
  return page;
}

export function artefactPath(name) {
  mkdirSync(artefacts, { recursive: true });
  return path.join(artefacts, name);
}

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/**
 * A recorded operator (seconds) that swings the part to and fro near environment 2's start, in free
 * space: each new pose is a target the tree can reach (for measuring the share of operator nodes).
 */
/** Environment 2 with the tube's mouth closed: no path, so the trees grow for as long as a test
 * watches them (the open scene is solved within seconds at some settings). */
export function writeClosedScene(dir) {
  const scene = execFileSync(tandemBin, ['scenes', 'cluttered-2'], { encoding: 'utf8' });
  const plug = '\n[[obstacle]]\nname = "plug"\nbox = [0.05, 0.8, 0.4]\nposition = [-0.025, 0.0, 1.0]\n';
  const file = path.join(dir, 'cluttered-2-closed.toml');
  writeFileSync(file, scene + plug);
  return file;
}

export function writeSwingTrace(dir, seconds = 120) {
  const s = Math.sin(Math.PI / 18), c = Math.cos(Math.PI / 18);
  const lines = ['# tandem operator trace 1', '# clock: seconds', '# t x y z qx qy qz qw buttons'];
  for (let k = 0; k <= 50 * seconds; ++k) {
    const t = k / 50;
    lines.push(`${t} ${-0.9 + 0.1 * Math.sin(t)} 0.25 ${1.2 + 0.03 * Math.cos(3 * t) - 0.03} 0 0 ${s} ${c} 0`);
  }
  const file = path.join(dir, 'swing.trace');
  writeFileSync(file, `${lines.join('\n')}\n`);
  return file;
}

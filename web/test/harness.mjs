// Starts tandem with its viewer and a headless Debian Chromium (playwright-core) for the tests and
// the benchmark. The tandem binary: $TANDEM_BIN, else ../build/apps/tandem/tandem.
import { spawn } from 'node:child_process';
import { mkdtempSync, existsSync, mkdirSync } from 'node:fs';
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

/** Runs `tandem ARGS` until it prints its viewer's URL; resolves to {proc, url, port, token, output}. */
export function startTandem(args, { urlPattern = /viewer: (http:\/\/\S+)/ } = {}) {
  if (!existsSync(tandemBin)) throw new Error(`no tandem binary at ${tandemBin} (build it first)`);
  const proc = spawn(tandemBin, args, { stdio: ['ignore', 'pipe', 'pipe'] });
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

export async function openViewer(browser, run, { viewport = { width: 1280, height: 800 }, query = '' } = {}) {
  const page = await browser.newPage({ viewport });
  openPages.add(page);
  const logs = [];
  page.on('console', (m) => logs.push(m.text()));
  page.on('pageerror', (e) => logs.push(`page error: ${e.message}`));
  await page.goto(run.url + query);
  await page.waitForFunction(() => window.tandem?.connected && window.tandem.status, null, { timeout: 20000 });
  page.logs = logs;
  return page;
}

export function artefactPath(name) {
  mkdirSync(artefacts, { recursive: true });
  return path.join(artefacts, name);
}

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

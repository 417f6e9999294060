// browser.mjs — serve a built site (scripts/build-web.sh) and open it in headless
// Chromium: shared by the end-to-end test (tests/web/e2e.test.mjs) and the benchmark
// (tools/bench/web_bench.mjs).
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import httpServer from 'http-server';
import { chromium } from 'playwright-core';

export const CHROMIUM = '/usr/bin/chromium';
// TOOLCHAIN.md's flags for this machine's Chromium.
const ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--no-first-run'];

// Serve `root` on 127.0.0.1 at a free port: {url, close()}.
export async function serveSite(root) {
  const server = httpServer.createServer({ root, cache: -1, showDir: 'false' });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.server.address();
  return { url: `http://127.0.0.1:${port}/`, close: () => new Promise((resolve) => server.server.close(resolve)) };
}

// A fresh browser profile each time: {browser, context, close()}.
export async function openBrowser({ viewport = { width: 1320, height: 900 } } = {}) {
  const profile = mkdtempSync(join(tmpdir(), 'pogon-chromium-'));
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM, args: ARGS, headless: true, viewport, acceptDownloads: true,
  });
  return {
    context,
    close: async () => {
      await context.close();
      rmSync(profile, { recursive: true, force: true });
    },
  };
}

// Open the page and wait until the app has stepped a few frames.
export async function openPage(context, url, errors) {
  const page = context.pages()[0] || await context.newPage();
  page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  await page.goto(url);
  await page.waitForFunction(() => window.pogon && window.pogon.frame() > 5, null, { timeout: 20000 });
  return page;
}

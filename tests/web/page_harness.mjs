// What the browser tests of the web page share (web_ui_test.mjs, web_canvas_test.mjs): Debian's
// Chromium driven by playwright-core, against the real lpv-server on a free port.
//   LPV_SERVER_BINARY  the lpv-server to start (required)
//   LPV_WEB_ARTIFACTS  where screenshots go (default: ./web_ui_artifacts)
//   LPV_CHROMIUM       the browser (default: /usr/bin/chromium)
// A test file calls `setUp(name)` once: exit status 77 (CTest's SKIP_RETURN_CODE) only when the
// browser cannot start, with the reason printed; a missing playwright-core is a failure
// (scripts/install-deps.sh installs it).
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { createInterface } from 'node:readline';
import { after, before } from 'node:test';

const SKIP = 77;
const chromiumPath = process.env.LPV_CHROMIUM ?? '/usr/bin/chromium';
const artifacts = resolve(process.env.LPV_WEB_ARTIFACTS ?? 'web_ui_artifacts');

export const server = { origin: '', child: null, browser: null };

// Starts lpv-server on a free port: its first line names the port; ready once /readyz is 200.
async function startServer() {
  const binary = process.env.LPV_SERVER_BINARY;
  assert.ok(binary, 'LPV_SERVER_BINARY must name the lpv-server binary');
  const child = spawn(binary, ['--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  const firstLine = await new Promise((resolveLine, reject) => {
    createInterface({ input: child.stdout }).once('line', resolveLine);
    child.once('exit', (code) => reject(new Error(`lpv-server exited with ${code} before listening`)));
  });
  child.stdout.resume();  // the request log: read and dropped, so the pipe never fills
  const url = firstLine.match(/listening on (http:\/\/\S+)/)?.[1];
  assert.ok(url, `unexpected first line from lpv-server: ${firstLine}`);
  for (const deadline = Date.now() + 120_000; Date.now() < deadline; await new Promise((r) => setTimeout(r, 200))) {
    const ready = await fetch(`${url}/readyz`).then((r) => r.ok, () => false);
    if (ready) return { child, url };
  }
  throw new Error('lpv-server was not ready within 120 s');
}

export async function setUp(name) {
  let chromium;
  try {
    ({ chromium } = await import('playwright-core'));
  } catch (error) {
    console.error(`${name}: playwright-core is not installed (${error.message}); scripts/install-deps.sh runs npm ci in tests/web`);
    process.exit(1);
  }
  before(async () => {
    mkdirSync(artifacts, { recursive: true });
    if (!existsSync(chromiumPath)) {
      console.log(`SKIP ${name}: no browser at ${chromiumPath} (Debian's chromium package; scripts/install-deps.sh installs it)`);
      process.exit(SKIP);
    }
    try {
      server.browser = await chromium.launch({
        executablePath: chromiumPath,
        // As root in a container: no sandbox. No background traffic: only this server is reachable.
        args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--disable-background-networking',
          '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic'],
      });
    } catch (error) {
      console.log(`SKIP ${name}: Chromium (${chromiumPath}) cannot start: ${error.message.split('\n')[0]}`);
      process.exit(SKIP);
    }
    ({ child: server.child, url: server.origin } = await startServer());
  });
  after(async () => {
    await server.browser?.close();
    server.child?.kill('SIGTERM');
  });
}

// A fresh page on `hash`, with every console error and uncaught exception collected, once
// its first frame is on screen (unless `frame` is false: a link the server refuses).
export async function openPage(t, hash = '', { frame = true, viewport = { width: 1500, height: 1100 } } = {}) {
  const context = await server.browser.newContext({ viewport });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (message) => {
    if (message.type() === 'error') errors.push(`console: ${message.text()}`);
  });
  page.on('pageerror', (error) => errors.push(`exception: ${error.message}`));
  const requests = [];
  page.on('request', (request) => {
    if (request.method() === 'POST' && request.url().endsWith('/v1/render')) requests.push(JSON.parse(request.postData()));
  });
  await page.goto(`${server.origin}/${hash}`);
  if (frame) await frameShown(page);
  t.after(() => context.close());
  return { page, errors, requests };
}

// Waits until the page is idle with a frame on the canvas whose request `matches`, and returns
// that request. Polled from here: the page's Content-Security-Policy allows no eval there.
export async function frameShown(page, matches = () => true, timeoutMs = 60_000) {
  for (const deadline = Date.now() + timeoutMs; ; await new Promise((r) => setTimeout(r, 20))) {
    const shown = await page.evaluate(() => {
      const frame = document.getElementById('frame');
      const canvas = document.getElementById('view-canvas');
      const idle = frame.getAttribute('aria-busy') === 'false' && !canvas.hidden;
      return idle ? frame.dataset.request ?? null : null;
    });
    if (shown && matches(JSON.parse(shown))) return JSON.parse(shown);
    if (Date.now() > deadline) throw new Error(`no matching frame within ${timeoutMs} ms; on screen: ${shown}`);
  }
}

export async function screenshot(page, name) {
  await page.screenshot({ path: join(artifacts, `${name}.png`), fullPage: true });
}

export function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

// Chromium logs each failed HTTP request as a console error of its own: those the test
// provokes are expected, nothing else is.
export function unexpected(errors) {
  return errors.filter((e) => !/Failed to load resource: the server responded with a status of (400|422)/.test(e));
}

// The RGBA of a PNG's pixels at `points` ([[x, y], ...]), decoded by the browser itself.
export async function pngPixels(page, png, points) {
  return page.evaluate(async ({ bytes, points }) => {
    const bitmap = await createImageBitmap(new Blob([new Uint8Array(bytes)], { type: 'image/png' }));
    const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
    const ctx = canvas.getContext('2d');
    ctx.drawImage(bitmap, 0, 0);
    return points.map(([x, y]) => [...ctx.getImageData(x, y, 1, 1).data]);
  }, { bytes: [...png], points });
}

// The RGBA on the page's canvas at canvas (CSS pixel) points, device pixel ratio 1.
export async function canvasPixels(page, points) {
  return page.evaluate((points) => {
    const ctx = document.getElementById('view-canvas').getContext('2d');
    return points.map(([x, y]) => [...ctx.getImageData(Math.floor(x), Math.floor(y), 1, 1).data]);
  }, points);
}

// How long each key takes to change the canvas: the key's handler, the draw and its raster,
// forced by reading a pixel back (a 2D canvas rasterises lazily), all in one task. Compositing
// to the screen is the browser's and comes after.
export async function keyToCanvasTimes(page, keys, rounds) {
  return page.evaluate(({ keys, rounds }) => {
    const ctx = document.getElementById('view-canvas').getContext('2d');
    const times = [];
    for (let round = 0; round < rounds; round++) {
      for (const key of keys) {
        const start = performance.now();
        document.body.dispatchEvent(new KeyboardEvent('keydown', { key, bubbles: true }));
        ctx.getImageData(0, 0, 1, 1);
        times.push(performance.now() - start);
      }
    }
    return times;
  }, { keys, rounds });
}

// The web parameter explorer (docs/web.md) in a real browser: Debian's Chromium driven by
// playwright-core, against the real lpv-server on a free port. Run by CTest as `web_ui`:
//   LPV_SERVER_BINARY  the lpv-server to start (required)
//   LPV_WEB_ARTIFACTS  where screenshots go (default: ./web_ui_artifacts)
//   LPV_CHROMIUM       the browser (default: /usr/bin/chromium)
// Exit status 77 (CTest's SKIP_RETURN_CODE) only when the browser cannot start, with the
// reason printed; a missing playwright-core is a failure (scripts/install-deps.sh installs it).
import assert from 'node:assert/strict';
import { execFile, spawn } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync } from 'node:fs';
import { mkdtemp } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { createInterface } from 'node:readline';
import { after, before, test } from 'node:test';
import { promisify } from 'node:util';

const SKIP = 77;
const chromiumPath = process.env.LPV_CHROMIUM ?? '/usr/bin/chromium';
const artifacts = resolve(process.env.LPV_WEB_ARTIFACTS ?? 'web_ui_artifacts');
const uploadFile = '/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb';

let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch (error) {
  console.error(`web_ui: playwright-core is not installed (${error.message}); scripts/install-deps.sh runs npm ci in tests/web`);
  process.exit(1);
}

let server;
let origin;
let browser;

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

before(async () => {
  mkdirSync(artifacts, { recursive: true });
  if (!existsSync(chromiumPath)) {
    console.log(`SKIP web_ui: no browser at ${chromiumPath} (Debian's chromium package; scripts/install-deps.sh installs it)`);
    process.exit(SKIP);
  }
  try {
    browser = await chromium.launch({
      executablePath: chromiumPath,
      // As root in a container: no sandbox. No background traffic: only this server is reachable.
      args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage', '--disable-background-networking',
        '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic'],
    });
  } catch (error) {
    console.log(`SKIP web_ui: Chromium (${chromiumPath}) cannot start: ${error.message.split('\n')[0]}`);
    process.exit(SKIP);
  }
  ({ child: server, url: origin } = await startServer());
});

after(async () => {
  await browser?.close();
  server?.kill('SIGTERM');
});

// A fresh page on `hash`, with every console error and uncaught exception collected, once
// its first frame is on screen (unless `frame` is false: a link the server refuses).
async function openPage(t, hash = '', { frame = true } = {}) {
  const context = await browser.newContext({ viewport: { width: 1500, height: 1100 } });
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
  await page.goto(`${origin}/${hash}`);
  if (frame) await frameShown(page);
  t.after(() => context.close());
  return { page, errors, requests };
}

// Waits until the page is idle with a frame on screen whose request `matches`, and returns
// that request. Polled from here: the page's Content-Security-Policy allows no eval there.
async function frameShown(page, matches = () => true, timeoutMs = 60_000) {
  for (const deadline = Date.now() + timeoutMs; ; await new Promise((r) => setTimeout(r, 20))) {
    const shown = await page.evaluate(() => {
      const frame = document.getElementById('frame');
      const image = document.getElementById('frame-image');
      const idle = frame.getAttribute('aria-busy') === 'false' && image.complete && image.naturalWidth > 0;
      return idle ? frame.dataset.request ?? null : null;
    });
    if (shown && matches(JSON.parse(shown))) return JSON.parse(shown);
    if (Date.now() > deadline) throw new Error(`no matching frame within ${timeoutMs} ms; on screen: ${shown}`);
  }
}

async function screenshot(page, name) {
  await page.screenshot({ path: join(artifacts, `${name}.png`), fullPage: true });
}

function median(values) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

test('the page loads with no console errors and shows the first frame', async (t) => {
  const { page, errors, requests } = await openPage(t);
  assert.equal(await page.title(), 'LPV parameter explorer');
  assert.deepEqual(requests[0], {}, 'the first frame is the default request');
  assert.equal(await page.locator('#frame-image').evaluate((img) => img.naturalWidth), 512);
  await page.waitForFunction(() => document.querySelectorAll('#scene option').length >= 3);
  await page.waitForFunction(() => document.getElementById('device').textContent.includes('·'));
  const unlabelled = await page.evaluate(() => [...document.querySelectorAll('input, select, button')]
    .filter((e) => !e.labels?.length && !e.getAttribute('aria-label') && !e.getAttribute('aria-labelledby') && !e.textContent.trim())
    .map((e) => e.outerHTML));
  assert.deepEqual(unlabelled, [], 'every control has a name');
  // What the page costs to load: every file it fetched that is not an API call, as files
  // and as transferred (the server compresses text for browsers that accept it).
  const files = await page.evaluate(() => [...performance.getEntriesByType('navigation'), ...performance.getEntriesByType('resource')]
    .filter((entry) => !new URL(entry.name).pathname.startsWith('/v1/'))
    .map((entry) => [entry.decodedBodySize, entry.encodedBodySize]));
  const kib = (i) => (files.reduce((sum, sizes) => sum + sizes[i], 0) / 1024).toFixed(1);
  console.log(`web_ui: the page's assets: ${files.length} files, ${kib(0)} KiB (${kib(1)} KiB compressed as served)`);
  await screenshot(page, '01-loaded');
  assert.deepEqual(errors, []);
});

test('moving a slider renders a new frame whose request carried the new value', async (t) => {
  const { page, errors } = await openPage(t);
  const slider = page.locator('#lpv-iterations-range');
  const firstSrc = await page.locator('#frame-image').getAttribute('src');
  const sent = page.waitForRequest((r) => r.url().endsWith('/v1/render') && JSON.parse(r.postData()).lpv?.iterations === 12);
  await slider.fill('12');
  assert.equal(await page.locator('#busy').isVisible(), true, 'busy while the new frame is on its way');
  assert.equal(await page.locator('#frame').getAttribute('aria-busy'), 'true');
  assert.equal((await sent).headers().accept, 'image/png');
  await frameShown(page, (request) => request.lpv?.iterations === 12);
  assert.notEqual(await page.locator('#frame-image').getAttribute('src'), firstSrc, 'a new image is on screen');
  assert.equal(await page.locator('#lpv-iterations').inputValue(), '12', 'the number box follows the slider');
  assert.match(page.url(), /request=.*iterations/, 'the URL holds the new value');

  // A change while a request is in flight aborts it: its frame never reaches the screen. Frames
  // of a 64³ grid take long enough that the next change surely comes while one is in flight.
  await page.locator('#lpv-grid').fill('64');
  await frameShown(page, (request) => request.lpv?.grid === 64);
  await page.evaluate(() => {
    const frame = document.getElementById('frame');
    window.framesShown = [];
    new MutationObserver(() => window.framesShown.push(JSON.parse(frame.dataset.request).lpv?.iterations))
      .observe(frame, { attributes: true, attributeFilter: ['data-request'] });
  });
  const isRender = (r, iterations) => r.url().endsWith('/v1/render') && JSON.parse(r.postData()).lpv?.iterations === iterations;
  const aborted = page.waitForEvent('requestfailed', (r) => isRender(r, 20));
  const inFlight = page.waitForRequest((r) => isRender(r, 20));
  await slider.fill('20');
  await inFlight;
  await slider.fill('21');
  await aborted;
  await frameShown(page, (request) => request.lpv?.iterations === 21);
  assert.deepEqual(await page.evaluate(() => window.framesShown), [21], 'only the newest request was shown');
  await page.locator('#lpv-grid').fill('16');  // the default again, for the timings below
  await frameShown(page, (request) => request.lpv?.grid === undefined && request.lpv?.iterations === 21);

  // Time from a slider change to its frame on screen (cornell-box, 512x512), from the
  // page's own performance marks, and what it is made of: the debounce, the server and
  // HTTP (of which the frame's wall time on the device), and decoding and painting.
  const parts = { change: [], server: [], wall: [], browser: [] };
  for (const value of [4, 6, 10, 14, 16, 5, 9]) {
    const answer = page.waitForResponse((r) => r.url().endsWith('/v1/render'));
    await slider.fill(String(value));
    parts.wall.push(JSON.parse((await answer).headers()['x-render-stats']).wall_ms.median);
    await frameShown(page, (request) => request.lpv?.iterations === value);
    const [change, server, browser] = await page.evaluate(() => ['lpv:change-to-frame', 'lpv:request-to-answer', 'lpv:answer-to-frame']
      .map((name) => performance.getEntriesByName(name).at(-1).duration));
    parts.change.push(change);
    parts.server.push(server);
    parts.browser.push(browser);
  }
  const ms = (values) => `${median(values).toFixed(0)} ms`;
  console.log(`web_ui: slider change to new frame on screen, cornell-box 512x512 on ${await page.locator('#device').textContent()}: ` +
    `median ${ms(parts.change)} (min ${Math.min(...parts.change).toFixed(0)}, max ${Math.max(...parts.change).toFixed(0)}, ` +
    `${parts.change.length} changes) = 120 ms debounce + ${ms(parts.server)} server and HTTP (the frame's wall time: ` +
    `${ms(parts.wall)}) + ${ms(parts.browser)} decoding and painting in the browser`);
  await screenshot(page, '02-slider');
  assert.deepEqual(errors, []);
});

test('the timing chart and the plan appear, with the reasons of skipped passes', async (t) => {
  const { page, errors } = await openPage(t);
  const ran = await page.locator('#plan-passes .ran').count();
  assert.ok(ran >= 5, `passes that ran: ${ran}`);
  assert.equal(await page.locator('#pass-chart svg rect').count(), ran, 'one bar per pass that ran');
  assert.match(await page.locator('#pass-chart svg').textContent(), /gather.*ms/s);
  assert.ok(await page.locator('#plan-decisions li').count() >= 1);
  assert.match(await page.locator('#plan-passes li', { hasText: 'propagate' }).textContent(), /propagate skipped: .*gather/,
    'the default gathers, and propagation says so');

  await page.locator('#output-view').selectOption('direct');
  await frameShown(page, (request) => request.output?.view === 'direct');
  const skipped = await page.locator('#plan-passes li', { hasText: 'gather' }).textContent();
  assert.match(skipped, /gather skipped: .+/, 'a skipped pass says why');
  assert.ok(await page.locator('#pass-chart svg rect').count() < ran, 'the chart follows the plan');
  await screenshot(page, '03-plan');
  assert.deepEqual(errors, []);
});

test('A/B compare shows A and B, the difference, metrics and both timings', async (t) => {
  const { page, errors } = await openPage(t);
  await page.locator('#ab-pin').click();
  await page.locator('#lpv-grid').fill('8');
  await frameShown(page, (request) => request.lpv?.grid === 8);
  assert.match(await page.locator('#ab-changes').textContent(), /lpv\.grid: default → 8/);
  const sent = page.waitForRequest((r) => r.url().endsWith('/v1/compare'));
  await page.locator('#ab-run').click();
  const body = JSON.parse((await sent).postData());
  assert.deepEqual(body.base, {}, 'A is the default request');
  assert.deepEqual(body.against, { lpv: { grid: 8 } }, 'B is A with the grid changed');
  await page.locator('#ab-result').waitFor({ state: 'visible', timeout: 60_000 });
  for (const id of ['ab-image-a', 'ab-image-b', 'ab-overlay-a', 'ab-overlay-b', 'ab-difference'])
    assert.ok(await page.locator(`#${id}`).evaluate((img) => img.naturalWidth) > 0, `${id} is an image`);
  const rmse = await page.locator('#ab-metrics tr', { hasText: 'RMSE' }).first().locator('td').first().textContent();
  assert.ok(Number(rmse) > 0, `RMSE of A against B: ${rmse}`);
  assert.ok(await page.locator('#ab-chart svg rect.series-0').count() >= 5, 'A has bars');
  assert.ok(await page.locator('#ab-chart svg rect.series-1').count() >= 5, 'B has bars');
  await page.locator('#ab-slider').fill('20');
  assert.equal(await page.locator('#ab-overlay').evaluate((e) => e.style.getPropertyValue('--split')), '20%');
  await screenshot(page, '04-ab-compare');
  assert.deepEqual(errors, []);
});

// Chromium logs each failed HTTP request as a console error of its own: those the test
// provokes are expected, nothing else is.
function unexpected(errors) {
  return errors.filter((e) => !/Failed to load resource: the server responded with a status of (400|422)/.test(e));
}

test('a bad value shows the server\'s message next to its control', async (t) => {
  const { page, errors } = await openPage(t);
  await page.locator('#output-width').fill('-5');
  const widthError = page.locator('.control:has(#output-width) .field-error');
  await widthError.waitFor({ timeout: 30_000 });
  assert.equal(await widthError.textContent(), 'output.width: must be an integer in [1, 8192], got -5');
  assert.equal(await page.locator('#output-width').getAttribute('aria-invalid'), 'true');
  assert.ok(await page.locator('#frame').evaluate((f) => f.classList.contains('outdated')), 'the old frame is marked as such');
  await screenshot(page, '05-bad-value');

  await page.locator('#output-width').fill('256');
  await frameShown(page, (request) => request.output?.width === 256);
  assert.equal(await widthError.count(), 0, 'the message goes once the value is valid');

  await page.locator('#lpv-iterations').fill('500');  // over this server's limit (422), not the API's
  const iterationsError = page.locator('.control:has(#lpv-iterations) .field-error');
  await iterationsError.waitFor({ timeout: 30_000 });
  assert.equal(await iterationsError.textContent(), 'lpv.iterations: is 500; this server allows at most 64');
  await page.locator('#lpv-iterations').fill('32');  // the default
  await frameShown(page, (request) => request.output?.width === 256 && request.lpv === undefined);

  // A light's field: the editor's input for lights[0].intensity gets the message.
  const intensity = page.locator('[data-field="lights[0].intensity"]');
  await intensity.fill('-1');
  const lightError = page.locator('.control:has([data-field="lights[0].intensity"]) .field-error');
  await lightError.waitFor({ timeout: 30_000 });
  assert.match(await lightError.textContent(), /^lights\[0\]\.intensity: .+/);
  await screenshot(page, '05-bad-light');
  assert.deepEqual(unexpected(errors), []);
});

test('a shared link with a bad value shows that field\'s error, and no frame', async (t) => {
  const link = '#request=' + encodeURIComponent(JSON.stringify({ output: { width: 0, height: 96 } }));
  const { page, errors } = await openPage(t, link, { frame: false });
  const widthError = page.locator('.control:has(#output-width) .field-error');
  await widthError.waitFor({ timeout: 30_000 });
  assert.equal(await widthError.textContent(), 'output.width: must be an integer in [1, 8192], got 0');
  assert.equal(await page.locator('#output-width').getAttribute('aria-invalid'), 'true');
  assert.equal(await page.locator('#output-height').getAttribute('aria-invalid'), null, 'its neighbour is not outlined');
  assert.equal(await page.locator('[aria-invalid="true"]').count(), 1, 'only the invalid field is outlined');
  assert.equal(await page.locator('#frame-image').isVisible(), false, 'no image, so no broken one');
  assert.equal(await page.locator('#frame').evaluate((f) => f.classList.contains('outdated')), false);
  const caption = await page.locator('#frame-caption').textContent();
  assert.doesNotMatch(caption, /earlier settings/, 'there was no earlier frame');
  assert.match(caption, /refused/);
  await screenshot(page, '06-shared-bad-link');

  await page.locator('#output-width').fill('128');
  await frameShown(page, (request) => request.output?.width === 128 && request.output?.height === 96);
  assert.equal(await page.locator('#frame-image').isVisible(), true);
  assert.equal(await page.locator('[aria-invalid="true"]').count(), 0);
  assert.deepEqual(unexpected(errors), []);
});

test('a dry run shows its plan, its passes planned, and no image', async (t) => {
  const { page, errors } = await openPage(t, '#request=' + encodeURIComponent('{"dry_run":true}'), { frame: false });
  await page.waitForFunction(() => document.getElementById('plan-passes').textContent.includes('planned (dry run)'), null, { timeout: 30_000 });
  assert.doesNotMatch(await page.locator('#plan-passes').textContent(), / ran, /, 'nothing ran');
  assert.equal(await page.locator('#frame-image').isVisible(), false, 'no image, so no broken one');
  assert.match(await page.locator('#frame-caption').textContent(), /dry run/);
  await screenshot(page, '06-dry-run');
  assert.deepEqual(errors, []);
});

test('the light editor shows values as a person would write them', async (t) => {
  // Doubles carrying a float's rounding (a light exported in 32 bits, a computed position)
  // show as a float's 7 significant digits: 3 and 1.9. The request keeps what it holds.
  const light = { type: 'spot', position: [0, 1.899999976158142, 0], direction: [0, -1, 0], intensity: 3.0000001,
    inner_cone_deg: 35, outer_cone_deg: 40 };
  const { page, errors, requests } = await openPage(t, '#request=' + encodeURIComponent(JSON.stringify({ lights: [light] })));
  assert.equal(await page.locator('#lights [data-field="lights[0].intensity"]').inputValue(), '3');
  const position = await page.locator('#lights [data-field="lights[0].position"]').evaluateAll((inputs) => inputs.map((i) => i.value));
  assert.deepEqual(position, ['0', '1.9', '0']);
  for (const value of await page.locator('#lights input[type="number"]').evaluateAll((inputs) => inputs.map((i) => i.value)))
    assert.match(value, /^(-?\d+(\.\d{1,6})?)?$/, 'no float noise on show');
  assert.equal(requests[0].lights[0].intensity, 3.0000001, 'the request is sent as it is');
  assert.deepEqual(errors, []);
});

test('a shared URL restores the same settings, A included', async (t) => {
  const first = await openPage(t);
  await first.page.locator('#ab-pin').click();
  await first.page.locator('#lpv-iterations').fill('5');
  await first.page.locator('#output-view').selectOption('indirect');
  await first.page.locator('#output-exposure').fill('1.5');
  const shown = await frameShown(first.page, (r) => r.lpv?.iterations === 5 && r.output?.view === 'indirect' && r.output?.exposure === 1.5);
  const link = first.page.url();

  const second = await openPage(t, new URL(link).hash);
  assert.deepEqual(second.requests[0], shown, 'the same request renders the same frame');
  assert.equal(await second.page.locator('#lpv-iterations').inputValue(), '5');
  assert.equal(await second.page.locator('#output-view').inputValue(), 'indirect');
  assert.equal(await second.page.locator('#output-exposure').inputValue(), '1.5');
  assert.equal(await second.page.locator('#ab-run').isEnabled(), true, 'A is pinned again');
  assert.match(await second.page.locator('#ab-changes').textContent(), /lpv\.iterations: default → 5/);
  await screenshot(second.page, '06-shared-url');
  assert.deepEqual([...first.errors, ...second.errors], []);
});

test('"copy as curl" gives the command that renders the same frame', async (t) => {
  const { page, errors } = await openPage(t);
  // The bytes of the frame the page shows, taken on their way in (the browser keeps no
  // copy of a body the page has read as a blob).
  let shownPng;
  await page.route('**/v1/render', async (route) => {
    const response = await route.fetch();
    shownPng = await response.body();
    await route.fulfill({ response });
  });
  await page.locator('#lpv-grid').fill('24');
  await frameShown(page, (request) => request.lpv?.grid === 24);
  await page.locator('#copy-curl').click();
  const command = await page.locator('#curl-command').textContent();
  assert.match(command, /^curl -o frame\.png -H 'Content-Type: application\/json' -d '\{"lpv":\{"grid":24\}\}' 'http:/);
  const directory = await mkdtemp(join(tmpdir(), 'web-ui-curl-'));
  await promisify(execFile)('sh', ['-c', command], { cwd: directory });
  assert.ok(readFileSync(join(directory, 'frame.png')).equals(shownPng), 'curl gets the very PNG the page shows');
  assert.deepEqual(errors, []);
});

test('the error against the reference, and a sweep whose points load their settings', async (t) => {
  // Propagation, whose iterations the sweep below varies (the gather has none).
  const request = '{"output":{"width":128,"height":128},"lpv":{"transfer":"sharpened"}}';
  const { page, errors } = await openPage(t, '#request=' + encodeURIComponent(request));
  await page.locator('#reference-samples').fill('16');
  await page.locator('#reference-run').click();
  await page.locator('#reference-result').waitFor({ state: 'visible', timeout: 60_000 });
  assert.ok(await page.locator('#reference-difference').evaluate((img) => img.naturalWidth) === 128);
  assert.ok(Number(await page.locator('#reference-metrics td').first().textContent()) > 0, 'an RMSE');

  await page.locator('#sweep-grid').fill('4, 8');
  await page.locator('#sweep-iterations').fill('4');
  await page.locator('#sweep-size').fill('64');
  await page.locator('#sweep-samples').fill('16');
  await page.locator('#sweep-run').click();
  await page.waitForFunction(() => document.getElementById('sweep-progress-label').textContent.startsWith('Done'), null, { timeout: 120_000 });
  assert.equal(await page.locator('#sweep-progress').evaluate((p) => p.value), 1);
  assert.equal(await page.locator('#sweep-run').isDisabled(), false, 'Run is back');
  assert.equal(await page.locator('#sweep-stop').isDisabled(), true, 'nothing to stop');
  assert.equal(await page.locator('#sweep-plot circle').count(), 3, 'LPV off, 4³ and 8³');
  assert.ok(await page.locator('#sweep-plot circle.pareto').count() >= 1, 'the Pareto front is marked');
  // Each row timed over 3 frames (the default repeat): the median and its range.
  const times = await page.locator('#sweep-table tr td:nth-child(2)').allTextContents();
  assert.equal(times.length, 3);
  for (const text of times) assert.match(text, /^[\d.]+ \([\d.]+–[\d.]+\)$/, `GPU ms with its range: ${text}`);
  await screenshot(page, '07-sweep');

  // The server's words for a row's settings (api::describe), the same as its SVG plot's.
  assert.match(await page.locator('#sweep-plot circle[aria-label^="LPV 8x8x8"]').getAttribute('aria-label'),
    /^LPV 8x8x8, 4 iterations, 1 cascade, RSM \d+, VPL downsample \d+, 1 bounce, occlusion (on|off), transfer [a-z]+, blocking [a-z_]+: /,
    'counted in good English, the transfer and the blocking named');
  await page.locator('#sweep-plot circle[aria-label^="LPV 8x8x8"]').click();
  const loaded = await frameShown(page, (request) => request.lpv?.grid === 8 && request.lpv?.iterations === 4);
  assert.equal(loaded.output.width, 128, 'only the LPV settings change');
  assert.equal(await page.locator('#lpv-grid').inputValue(), '8');

  // A long sweep stopped after its first rows: the label says so and stays, Run comes back.
  await page.locator('#sweep-grid').fill('8, 16, 24, 32');
  await page.locator('#sweep-iterations').fill('1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16');
  await page.locator('#sweep-run').click();
  await page.waitForFunction(() => document.getElementById('sweep-progress-label').textContent.startsWith('Rendered'), null, { timeout: 60_000 });
  await page.locator('#sweep-stop').click();
  await page.waitForTimeout(500);
  assert.equal(await page.locator('#sweep-progress-label').textContent(), 'Stopped');
  assert.equal(await page.locator('#sweep-run').isDisabled(), false, 'Run is back after Stop');
  assert.equal(await page.locator('#sweep-stop').isDisabled(), true, 'Stop is off after Stop');
  assert.deepEqual(errors, []);
});

test('every point of the sweep plot can be clicked and reached by keyboard, wherever it lies', async (t) => {
  // A fixed table (sweep_plot_fixture) served as the sweep's answer: rows 1 and 3 lie on the
  // front's staircase, every row has a whisker. A click that another element would take fails.
  const fixture = JSON.parse((await promisify(execFile)(process.env.LPV_SWEEP_PLOT_FIXTURE)).stdout);
  const request = '{"output":{"width":64,"height":64},"lpv":{"transfer":"sharpened"}}';
  const { page, errors } = await openPage(t, '#request=' + encodeURIComponent(request));
  await page.route((url) => url.pathname === '/v1/sweep', (route) => route.fulfill({
    status: 200, contentType: 'application/x-ndjson',
    body: JSON.stringify({ event: 'done', complete: true, ...fixture }) + '\n',
  }));
  await page.locator('#sweep-run').click();
  await page.waitForFunction(() => document.getElementById('sweep-progress-label').textContent.startsWith('Done'));
  const rows = fixture.table.rows;
  assert.deepEqual(rows.map((row) => row.pareto), [true, false, true, false], 'the fixture\'s layout');
  assert.equal(await page.locator('#sweep-plot circle[tabindex="0"]').count(), rows.length, 'each point is in the tab order');
  const grids = rows.map((row) => row.settings.grid[0]);
  for (const [index, grid] of grids.entries()) {
    // Each row's grid differs from the one before it, so that each load is a change that shows.
    await page.locator('#sweep-plot circle[data-row="' + index + '"]').click({ timeout: 5_000 });
    await frameShown(page, (shown) => shown.lpv?.grid === grid);
  }
  for (const [index, grid] of grids.entries()) {
    if (index === 0) continue;  // row 0 first, then row `index`: each a change
    await page.locator('#sweep-plot circle[data-row="0"]').focus();
    await page.keyboard.press('Enter');
    await frameShown(page, (shown) => shown.lpv?.grid === grids[0]);
    await page.locator('#sweep-plot circle[data-row="' + index + '"]').focus();
    await page.keyboard.press(index % 2 ? 'Enter' : ' ');
    await frameShown(page, (shown) => shown.lpv?.grid === grid);
  }
  await screenshot(page, '07b-sweep-fixed-layout');
  assert.deepEqual(errors, []);
});

test('dragging the frame orbits the camera', async (t) => {
  const { page, errors } = await openPage(t);
  await page.waitForFunction(() => document.querySelector('[data-field="camera.position"]').value !== '');
  const box = await page.locator('#frame-area').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 20, { steps: 5 });
  await page.mouse.up();
  const shown = await frameShown(page, (request) => Array.isArray(request.camera?.position));
  assert.notDeepEqual(shown.camera.position, [0, 1, 3.4], 'the camera moved');
  assert.deepEqual(shown.camera.target, [0, 1, 0], 'orbiting keeps the target');
  await screenshot(page, '08-orbit');
  assert.deepEqual(errors, []);
});

test('uploading a .glb adds the scene and renders it', { skip: !existsSync(uploadFile) && `no ${uploadFile}` }, async (t) => {
  const { page, errors } = await openPage(t);
  await page.locator('#scene-file').setInputFiles({ name: 'broken.glb', mimeType: 'model/gltf-binary', buffer: Buffer.from('not glTF') });
  const uploadError = page.locator('.control:has(#scene-file) .field-error');
  await uploadError.waitFor({ timeout: 30_000 });
  assert.match(await uploadError.textContent(), /^upload: .+/, 'a file that does not load says why, next to the file input');

  await page.locator('#scene-file').setInputFiles(uploadFile);
  const shown = await frameShown(page, (request) => /^[0-9a-f]{64}$/.test(request.scene ?? ''));
  assert.equal(await page.locator('#scene').inputValue(), shown.scene);
  assert.match(await page.locator('#scene option:checked').textContent(), /BoxTextured/);
  await screenshot(page, '09-upload');
  assert.deepEqual(unexpected(errors), []);
});

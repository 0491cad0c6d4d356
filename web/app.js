// The web parameter explorer (docs/web.md): wires the request state to the controls, the
// URL, the render loop, the canvas and its metrics. Each piece lives in its own module; this
// one only connects them.
//
// B is the frame of the current settings, A the frame pinned, the reference the path tracer's
// image of B's view: all three are linear images on one canvas (canvas_view.js).

import { device, render, setToken, token } from './api_client.js';
import { attachCameraControls } from './camera_drag.js';
import { CanvasView } from './canvas_view.js';
import { ComparisonMetrics } from './comparison_metrics.js';
import { legendGradient } from './difference_maps.js';
import { FieldErrors } from './field_errors.js';
import { bindInputs } from './form_binding.js';
import { LightsEditor } from './lights_editor.js';
import { requestThatRan } from './lpv_settings.js';
import { RenderLoop } from './render_loop.js';
import { RequestState, clone, describeChanges } from './request_state.js';
import { ScenePicker } from './scene_picker.js';
import { attachShareButtons } from './share.js';
import { passTimeChart, showStats } from './stats_view.js';
import { SweepPanel } from './sweep_panel.js';
import { readUrlState, urlStateHash, writeUrlState } from './url_state.js';
import { PAIRS, ViewControls, fillHelp } from './view_controls.js';

const $ = (id) => document.getElementById(id);
const settings = $('settings');
const header = document.querySelector('header');
const state = new RequestState();
const view = new CanvasView($('view-canvas'));
document.documentElement.style.setProperty('--header', `${header.offsetHeight}px`);

// The server's 401 names no field: it belongs to the token box, which appears then.
function withTokenField(error) {
  if (error.code !== 'unauthorized') return error;
  $('token-control').hidden = false;
  return Object.assign(error, { field: 'token' });
}

function errorsFor(panel, fallback, prefixes) {
  const errors = new FieldErrors({ roots: [...new Set([panel, settings, header])], fallback, prefixes });
  return { show: (error) => errors.show(withTokenField(error)), clear: () => errors.clear() };
}

const renderErrors = errorsFor(settings, $('render-error'), []);
const pinned = { request: null, stats: null };  // A
let current = { stats: null, queueMs: 0 };      // B's
let pointerPixel = null;

// --- B: the render loop ---------------------------------------------------------------------
const loop = new RenderLoop({
  render,
  show: async (answer, request) => {
    const { stats } = answer;
    current = { stats, queueMs: answer.queueMs };
    if (answer.image) view.setImage('b', answer.image);
    $('view-canvas').hidden = !answer.image;  // a dry run has none
    showFrameStats();
    $('frame-caption').textContent = `${stats.scene}, ${stats.width}×${stats.height}, view ${stats.view}: ` + (answer.image
      ? `${stats.gpu_ms.median.toFixed(1)} ms on the device (${stats.device})`
      : 'a dry run, the plan alone: no image, nothing timed (see the passes under "Cost and plan")') + budgetText(stats.budget);
    // What the frame ran with: under a budget, its choice (what A, the metrics and a pin measure).
    $('frame').dataset.request = JSON.stringify(requestThatRan(request, stats));
    sweepPanel.showBudgetChoice(stats.budget?.chosen.description ?? null);
    $('frame').classList.remove('outdated');
    renderErrors.clear();
    if (answer.image) updateMetricsSoon();
  },
  onBusy: (busy) => {
    $('frame').setAttribute('aria-busy', String(busy));
    $('busy').hidden = !busy;
  },
  onError: (error) => {
    renderErrors.show(error);
    // With no frame on show (a shared link with a bad value, or after a dry run) there is
    // none to mark as earlier: the canvas stays hidden, not broken, and the caption says why.
    const frameOnShow = !$('view-canvas').hidden && Boolean(view.image('b'));
    $('view-canvas').hidden = !frameOnShow;
    $('frame').classList.toggle('outdated', frameOnShow);
    $('frame-caption').textContent = frameOnShow
      ? 'This frame is for earlier settings: the current ones were refused (see the message).'
      : 'No frame: these settings were refused (see the message).';
    // 503: the device is still starting or the queue is full; the server says to retry in a second.
    if (error.status === 503) setTimeout(() => retryRender(), 1000);
  },
});

// "; budget 60 ms: LPV 12x12x12, ... (predicted 41.0 ms)": what a time budget chose.
function budgetText(budget) {
  if (!budget) return '';
  const { chosen } = budget;
  return `; budget ${budget.budget_ms} ms chose ${chosen.description} (predicted ${chosen.predicted_ms.toFixed(1)} ms` +
    `${chosen.fits ? '' : ', over the budget: nothing fits'})`;
}

function showFrameStats() {
  const { stats, queueMs } = current;
  if (!stats) return;
  showStats(stats, queueMs, {
    chart: $('pass-chart'), totals: $('frame-totals'), passes: $('plan-passes'),
    decisions: $('plan-decisions'), warnings: $('warnings'), warningsBlock: $('warnings-block'),
  });
  if (pinned.stats && stats.passes.some((pass) => pass.ran)) {
    $('pass-chart').replaceChildren(passTimeChart([pinned.stats, stats], {
      title: 'GPU time per pass of A and B (median, ms)',
      legend: [{ series: 'series-0', label: 'A' }, { series: 'series-1', label: 'B' }],
    }));
  }
}

// --- A: the pinned frame --------------------------------------------------------------------
async function pin(request, { image = null, stats = null } = {}) {
  pinned.request = request ? clone(request) : null;
  pinned.stats = stats;
  $('ab-unpin').disabled = !request;
  view.setImage('a', image);
  showChanges();
  writeState();
  showFrameStats();
  if (request && !image) {  // a shared link's A: render it once
    try {
      const answer = await render(request);
      if (JSON.stringify(pinned.request) !== JSON.stringify(request)) return;
      pinned.stats = answer.stats;
      view.setImage('a', answer.image);
      showFrameStats();
    } catch (error) {
      renderErrors.show(error);
    }
  }
  updateMetrics();
}

function pinCurrent() {
  const shown = $('frame').dataset.request;
  if (!shown || !view.image('b')) return;
  pin(JSON.parse(shown), { image: view.image('b'), stats: current.stats });
}

function showChanges() {
  const lines = pinned.request ? describeChanges(pinned.request, state.request) : [];
  const items = pinned.request ? (lines.length ? lines.map((line) => `B: ${line}`) : ['B is the same as A so far: change a setting.']) : [];
  $('ab-changes').replaceChildren(...items.map((line) => Object.assign(document.createElement('li'), { textContent: line })));
}

$('ab-pin').addEventListener('click', pinCurrent);
$('ab-unpin').addEventListener('click', () => pin(null));

// --- the metrics and the reference ----------------------------------------------------------
const metrics = new ComparisonMetrics({
  table: $('metrics'), status: $('metrics-status'), caption: $('metrics-caption'),
  errors: errorsFor($('reference-form'), $('metrics-error'), ['base.', 'against.']),
});

function updateMetrics() {
  const b = JSON.parse($('frame').dataset.request ?? 'null');
  if (!b) return;
  metrics.update({ a: pinned.request, b, region: view.view.region }, ({ reference, flips }) => {
    if (reference) view.setImage('reference', reference);
    for (const [pair, values] of Object.entries(flips)) view.setFlip(...pair.split('|'), values);
    showLabel();
  });
}

// After a frame, the metrics wait until the frames rest: a compare occupies the server for
// several frames' time (it renders both sides again and runs FLIP), so asking for one per
// frame of a dragged slider would queue the next frame behind it.
const METRICS_REST_MS = 250;
let metricsTimer = 0;
function updateMetricsSoon() {
  clearTimeout(metricsTimer);
  const b = JSON.parse($('frame').dataset.request ?? 'null');
  if (b) metrics.markStale(view.view.region, b);
  metricsTimer = setTimeout(updateMetrics, METRICS_REST_MS);
}

function traceReference() {
  metrics.reference = { samples: Number($('reference-samples').value), mask: $('reference-mask').value };
  writeState();
  updateMetrics();
}
$('reference-form').addEventListener('submit', (event) => {
  event.preventDefault();
  traceReference();
});

// --- the canvas ----------------------------------------------------------------------------
function show(source) {
  if (source === 'reference' && !metrics.reference) traceReference();
  view.set({ source });
}

const controls = new ViewControls({
  view,
  area: $('frame-area'),
  dragModeInputs: [...document.querySelectorAll('input[name="drag"]')],
  actions: {
    show,
    pin: pinCurrent,
    toggleDrawer,
    toggleHelp,
    closeHelp: () => {
      const open = !$('help').hidden;
      $('help').hidden = true;
      return open;
    },
    onPointer: (pixel) => {
      pointerPixel = pixel;
      showReadout();
    },
    onRegion: () => updateMetrics(),
    onShown: showLabel,
  },
});
attachCameraControls($('frame-area'), state, { enabled: () => controls.dragMode === 'camera' });

for (const button of document.querySelectorAll('button.source')) button.addEventListener('click', () => show(button.dataset.source));
$('pair').addEventListener('change', () => view.set({ pair: $('pair').value.split('|') }));
$('difference-kind').addEventListener('change', () => view.set({ kind: $('difference-kind').value }));
$('lock-scale').addEventListener('change', () => controls.lockScale());
$('wipe').addEventListener('input', () => view.set({ wipe: Number($('wipe').value) }));
$('zoom-fit').addEventListener('click', () => view.fit());
$('zoom-one').addEventListener('click', () => view.oneToOne());
$('display-exposure').addEventListener('input', () => view.set({ exposure: Number($('display-exposure').value) }));
$('display-tonemap').addEventListener('change', () => view.set({ tonemap: $('display-tonemap').value }));

// The toolbar, the label, the legend and the URL follow the view.
view.addEventListener('viewchange', () => {
  const v = view.view;
  for (const button of document.querySelectorAll('button.source')) button.setAttribute('aria-pressed', String(button.dataset.source === v.source));
  $('pair').value = v.pair.join('|');
  $('difference-kind').value = v.kind;
  $('lock-scale').checked = v.lockedScale !== null;
  $('wipe').value = String(v.wipe);
  $('display-exposure').value = String(v.exposure);
  $('display-exposure-value').textContent = `${v.exposure > 0 ? '+' : ''}${v.exposure}`;
  $('display-tonemap').value = v.tonemap;
  $('zoom-level').textContent = v.zoom > 0 ? `${Math.round(v.zoom * 100)}%` : 'fit';
  writeState();
});
view.addEventListener('drawn', () => {
  showLabel();
  showReadout();
});

function showLabel() {
  $('source-label').textContent = view.describe();
  const d = view.shown === 'difference' ? view.difference() : null;
  $('legend').hidden = !d || Boolean(d.missing);
  if (!d || d.missing) return;
  const scale = d.scale.toPrecision(3);
  $('legend-low').textContent = d.kind === 'signed' ? `−${scale}` : '0';
  $('legend-high').textContent = `${d.kind === 'signed' ? '+' : ''}${scale}${view.view.lockedScale !== null ? ' (locked)' : ''}`;
  $('legend-bar').style.background = legendGradient(d.kind);
}

// Pixel coordinates and the linear RGB of every source under the pointer, and the pair's
// error there; values to six significant digits, as the PFMs hold them.
function showReadout() {
  const readout = $('readout');
  if (!pointerPixel) return;
  const { x, y } = pointerPixel;
  const size = view.imageSize;
  const value = (image) => {
    if (!image || image.width !== size.width || image.height !== size.height) return null;
    const i = 3 * (y * image.width + x);
    return [image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]];
  };
  const text = (rgb) => rgb.map((c) => c.toPrecision(6)).join(' ');
  const spans = [Object.assign(document.createElement('span'), { textContent: `(${x}, ${y})` })];
  const values = {};
  for (const [source, name] of [['b', 'B'], ['a', 'A'], ['reference', 'ref']]) {
    values[source] = value(view.image(source));
    if (!values[source]) continue;
    const span = Object.assign(document.createElement('span'), { textContent: `${name} ${text(values[source])}` });
    span.dataset.source = source;
    spans.push(span);
  }
  const [p, q] = view.view.pair;
  if (values[p] && values[q]) {
    const span = Object.assign(document.createElement('span'), {
      textContent: `${p === 'b' ? 'B' : 'A'} − ${q === 'reference' ? 'ref' : 'B'} ${text(values[p].map((v, c) => v - values[q][c]))}`,
    });
    span.dataset.source = 'error';
    spans.push(span);
  }
  readout.replaceChildren(...spans.flatMap((span, i) => (i ? ['   ', span] : [span])));
}

// --- drawer, tabs and help ------------------------------------------------------------------
function toggleDrawer() {
  const closed = document.querySelector('.layout').classList.toggle('drawer-closed');
  $('drawer-toggle').setAttribute('aria-expanded', String(!closed));
}
$('drawer-toggle').addEventListener('click', toggleDrawer);
for (const tab of document.querySelectorAll('[role="tab"]')) {
  tab.addEventListener('click', () => {
    for (const other of document.querySelectorAll('[role="tab"]')) {
      other.setAttribute('aria-selected', String(other === tab));
      $(other.getAttribute('aria-controls')).hidden = other !== tab;
    }
  });
}
fillHelp($('help-keys'));
function toggleHelp() {
  $('help').hidden = !$('help').hidden;
  if (!$('help').hidden) $('help-close').focus();
}
$('help-open').addEventListener('click', toggleHelp);
$('help-close').addEventListener('click', toggleHelp);

// --- the rest of the page -------------------------------------------------------------------
const sweepPanel = new SweepPanel({
  state,
  // A path-traced row is not a setting of B: it loads as the reference at its samples.
  onPathTraced: (samples) => {
    $('reference-samples').value = String(samples);
    traceReference();
    show('reference');
  },
  errors: errorsFor($('sweep-panel'), $('sweep-error'), ['base.']),
  elements: {
    form: $('sweep-form'), run: $('sweep-run'), stop: $('sweep-stop'), size: $('sweep-size'), samples: $('sweep-samples'),
    metric: $('sweep-metric'), image: $('sweep-image'), lpvOff: $('sweep-lpv-off'), pathTraced: $('sweep-path-traced'),
    occlusionOn: $('sweep-occlusion-on'), occlusionOff: $('sweep-occlusion-off'), iterationsControl: $('sweep-iterations-control'),
    lists: {
      grid: $('sweep-grid'), iterations: $('sweep-iterations'), cascades: $('sweep-cascades'), rsm: $('sweep-rsm'),
      vpl_downsample: $('sweep-vpl-downsample'), bounces: $('sweep-bounces'),
    },
    progress: $('sweep-progress'), progressLabel: $('sweep-progress-label'), status: $('sweep-status'),
    plot: $('sweep-plot'), table: $('sweep-table'), hover: $('sweep-hover'),
  },
});

const scenes = new ScenePicker({ select: $('scene'), fileInput: $('scene-file'), state, onError: renderErrors.show });
new LightsEditor({ container: $('lights'), addButton: $('light-add'), resetButton: $('lights-reset'), state });
bindInputs(settings, state);
attachShareButtons({
  linkButton: $('copy-link'), curlButton: $('copy-curl'), commandBox: $('curl-command'), status: $('share-status'), state,
});
$('camera-reset').addEventListener('click', () => state.remove('camera'));
settings.addEventListener('submit', (event) => event.preventDefault());  // Enter in a box submits nothing

// --- the URL --------------------------------------------------------------------------------
// What of the canvas a link keeps: everything but the images.
function viewState() {
  const { source, pair, kind, zoom, center, region, wipe, exposure, tonemap, lockedScale } = view.view;
  return { source, pair, kind, zoom, center, region, wipe, exposure, tonemap, lockedScale, reference: metrics.reference };
}

// Wheel zooms and drags change the view many times a second: the URL follows once they rest.
let urlTimer = 0;
function writeState() {
  clearTimeout(urlTimer);
  urlTimer = setTimeout(() => writeUrlState({ request: state.request, a: pinned.request, view: viewState() }), 150);
}

// Every change of the request goes to the URL, and to the renderer when it changes the frame.
let scheduled = '';
function renderIfChanged() {
  const request = state.request;
  const json = JSON.stringify(request);
  if (json !== scheduled) {
    scheduled = json;
    clearTimeout(metricsTimer);  // the metrics wait for the frame this change brings
    loop.schedule(request);
  }
  showChanges();
  writeState();
}
state.addEventListener('change', renderIfChanged);
function retryRender() {
  scheduled = '';
  renderIfChanged();
}

$('token').value = token();
$('token-control').addEventListener('submit', (event) => event.preventDefault());
$('token').addEventListener('change', () => {
  setToken($('token').value);
  retryRender();
  scenes.load().catch(renderErrors.show);
});

// A link pasted into this tab's address bar changes only the fragment.
function loadFromUrl() {
  try {
    const { request, a, view: saved } = readUrlState();
    if (saved) {
      const { reference, ...rest } = saved;
      const known = Object.fromEntries(Object.entries(rest).filter(([key]) => key in view.view));
      if (known.pair && !PAIRS.some((p) => p.join() === known.pair.join())) delete known.pair;
      view.set(known);
      if (reference) {
        $('reference-samples').value = reference.samples;
        $('reference-mask').value = reference.mask;
        metrics.reference = reference;
      }
    }
    state.replace(request ?? {});
    pin(a ?? null);
  } catch (error) {
    $('share-status').textContent = error.message;
    state.replace({});
  }
}
window.addEventListener('hashchange', () => {
  if (location.hash !== urlStateHash({ request: state.request, a: pinned.request, view: viewState() })) loadFromUrl();
});

loadFromUrl();
scenes.load().catch(renderErrors.show);
device()
  .then((d) => {
    $('device').textContent = `${d.name} · ${d.driver}`;
  })
  .catch((error) => {
    $('device').textContent = `device: ${error.message}`;
  });

// The web parameter explorer (docs/web.md): wires the request state to the controls, the
// URL, the render loop and the panels. Each piece lives in its own module; this one only
// connects them.

import { AbCompare } from './ab_compare.js';
import { device, render, setToken, token } from './api_client.js';
import { attachCameraControls } from './camera_drag.js';
import { FieldErrors } from './field_errors.js';
import { bindInputs } from './form_binding.js';
import { showImage } from './images.js';
import { LightsEditor } from './lights_editor.js';
import { ReferencePanel } from './reference_panel.js';
import { RenderLoop } from './render_loop.js';
import { RequestState } from './request_state.js';
import { ScenePicker } from './scene_picker.js';
import { attachShareButtons } from './share.js';
import { showStats } from './stats_view.js';
import { SweepPanel } from './sweep_panel.js';
import { readUrlState, urlStateHash, writeUrlState } from './url_state.js';

// Long enough that a dragged slider or the camera sends one request when it stops, short
// enough not to be noticed.
const DEBOUNCE_MS = 120;

const $ = (id) => document.getElementById(id);
const settings = $('settings');
const header = document.querySelector('header');
const state = new RequestState();

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

const loop = new RenderLoop({
  debounceMs: DEBOUNCE_MS,
  render,
  show: async (answer, request) => {
    if (answer.png) await showImage($('frame-image'), answer.png);
    $('frame-image').hidden = !answer.png;  // a dry run has none
    const { stats } = answer;
    showStats(stats, answer.queueMs, {
      chart: $('pass-chart'), totals: $('frame-totals'), passes: $('plan-passes'),
      decisions: $('plan-decisions'), warnings: $('warnings'), warningsBlock: $('warnings-block'),
    });
    $('frame-caption').textContent = `${stats.scene}, ${stats.width}×${stats.height}, view ${stats.view}: ` + (answer.png
      ? `${stats.gpu_ms.median.toFixed(1)} ms on the device (${stats.device})`
      : 'a dry run, the plan alone: no image, nothing timed (see the passes below)');
    $('frame').dataset.request = JSON.stringify(request);
    $('frame').classList.remove('outdated');
    renderErrors.clear();
  },
  onBusy: (busy) => {
    $('frame').setAttribute('aria-busy', String(busy));
    $('busy').hidden = !busy;
  },
  onError: (error) => {
    renderErrors.show(error);
    // With no frame on show (a shared link with a bad value, or after a dry run) there is
    // none to mark as earlier: the image stays hidden, not broken, and the caption says why.
    const frameOnShow = !$('frame-image').hidden;
    $('frame').classList.toggle('outdated', frameOnShow);
    $('frame-caption').textContent = frameOnShow
      ? 'This frame is for earlier settings: the current ones were refused (see the message).'
      : 'No frame: these settings were refused (see the message).';
    // 503: the device is still starting or the queue is full; the server says to retry in a second.
    if (error.status === 503) setTimeout(() => retryRender(), 1000);
  },
});

const ab = new AbCompare({
  state,
  errors: errorsFor($('ab-panel'), $('ab-error'), ['against.', 'base.']),
  elements: {
    pin: $('ab-pin'), unpin: $('ab-unpin'), run: $('ab-run'), changes: $('ab-changes'), status: $('ab-status'),
    result: $('ab-result'), imageA: $('ab-image-a'), imageB: $('ab-image-b'), overlay: $('ab-overlay'),
    overlayA: $('ab-overlay-a'), overlayB: $('ab-overlay-b'), slider: $('ab-slider'), difference: $('ab-difference'),
    differenceCaption: $('ab-difference-caption'), metrics: $('ab-metrics'), chart: $('ab-chart'),
  },
});

new ReferencePanel({
  state,
  errors: errorsFor($('reference-panel'), $('reference-error'), ['base.']),
  elements: {
    form: $('reference-form'), samples: $('reference-samples'), mask: $('reference-mask'), button: $('reference-run'),
    status: $('reference-status'), result: $('reference-result'), referenceImage: $('reference-image'),
    differenceImage: $('reference-difference'), differenceCaption: $('reference-difference-caption'),
    metrics: $('reference-metrics'), noise: $('reference-noise'),
  },
});

new SweepPanel({
  state,
  errors: errorsFor($('sweep-panel'), $('sweep-error'), ['base.']),
  elements: {
    form: $('sweep-form'), run: $('sweep-run'), stop: $('sweep-stop'), size: $('sweep-size'), samples: $('sweep-samples'),
    metric: $('sweep-metric'), image: $('sweep-image'), lpvOff: $('sweep-lpv-off'),
    occlusionOn: $('sweep-occlusion-on'), occlusionOff: $('sweep-occlusion-off'),
    lists: {
      grid: $('sweep-grid'), iterations: $('sweep-iterations'), cascades: $('sweep-cascades'), rsm: $('sweep-rsm'),
      vpl_downsample: $('sweep-vpl-downsample'), bounces: $('sweep-bounces'),
    },
    progress: $('sweep-progress'), progressLabel: $('sweep-progress-label'), status: $('sweep-status'),
    plot: $('sweep-plot'), table: $('sweep-table'),
  },
});

const scenes = new ScenePicker({ select: $('scene'), fileInput: $('scene-file'), state, onError: renderErrors.show });
new LightsEditor({ container: $('lights'), addButton: $('light-add'), resetButton: $('lights-reset'), state });
bindInputs(settings, state);
attachCameraControls($('frame-area'), state);
attachShareButtons({
  linkButton: $('copy-link'), curlButton: $('copy-curl'), commandBox: $('curl-command'), status: $('share-status'), state,
});
$('camera-reset').addEventListener('click', () => state.remove('camera'));
settings.addEventListener('submit', (event) => event.preventDefault());  // Enter in a box submits nothing

// Every change of the request goes to the URL, and to the renderer when it changes the frame.
let scheduled = '';
function renderIfChanged() {
  const request = state.request;
  const json = JSON.stringify(request);
  if (json !== scheduled) {
    scheduled = json;
    loop.schedule(request);
  }
  writeUrlState({ request, a: ab.pinned });
}
state.addEventListener('change', renderIfChanged);
function retryRender() {
  scheduled = '';
  renderIfChanged();
}
ab.addEventListener('pinned', () => writeUrlState({ request: state.request, a: ab.pinned }));

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
    const { request, a } = readUrlState();
    state.replace(request ?? {});
    ab.pin(a ?? null);
  } catch (error) {
    $('share-status').textContent = error.message;
    state.replace({});
  }
}
window.addEventListener('hashchange', () => {
  if (location.hash !== urlStateHash({ request: state.request, a: ab.pinned })) loadFromUrl();
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

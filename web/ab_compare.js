// A/B compare: the pinned settings (A) against the current ones (B) with POST /v1/compare,
// base = A and "against" = the merge patch from A to B: both images side by side and under
// a slider, the difference, the metrics of A against B and each pass's time for both.

import { compare } from './api_client.js';
import { LatestRun } from './latest_run.js';
import { showPng } from './images.js';
import { clone, describeChanges, mergePatch } from './request_state.js';
import { showMetrics } from './metrics_table.js';
import { passTimeChart } from './stats_view.js';

export class AbCompare extends EventTarget {
  #run = new LatestRun();
  #pinned = null;

  constructor({ elements, state, errors }) {
    super();
    Object.assign(this, { elements, state, errors });
    elements.pin.addEventListener('click', () => this.pin(state.request));
    elements.unpin.addEventListener('click', () => this.pin(null));
    elements.run.addEventListener('click', () => this.run());
    elements.slider.addEventListener('input', () => this.#placeSlider());
    state.addEventListener('change', () => this.#showChanges());
    this.#placeSlider();
  }

  get pinned() {
    return clone(this.#pinned);
  }

  // Pins `request` as A (null unpins); the URL keeps it, so a link shares both sides.
  pin(request) {
    this.#pinned = request ? clone(request) : null;
    this.elements.run.disabled = !request;
    this.elements.unpin.disabled = !request;
    this.#showChanges();
    this.dispatchEvent(new Event('pinned'));
  }

  #showChanges() {
    const lines = this.#pinned ? describeChanges(this.#pinned, this.state.request) : [];
    const items = lines.length ? lines : [this.#pinned ? 'B is the same as A so far: change a setting.' : 'Nothing pinned.'];
    this.elements.changes.replaceChildren(...items.map((line) => Object.assign(document.createElement('li'), { textContent: line })));
  }

  // The top image (A) shows left of the slider, B right of it.
  #placeSlider() {
    this.elements.overlay.style.setProperty('--split', `${this.elements.slider.value}%`);
  }

  async run() {
    if (!this.#pinned) return;
    const { elements } = this;
    const body = { base: this.#pinned, against: mergePatch(this.#pinned, this.state.request) };
    const options = { button: elements.run, status: elements.status, errors: this.errors,
                      busyText: 'Rendering A and B…', enabled: () => Boolean(this.#pinned) };
    await this.#run.start(options, async (signal) => {
      const answer = await compare(body, signal);
      await Promise.all([
        showPng([elements.imageA, elements.overlayA], answer.base.image),
        showPng([elements.imageB, elements.overlayB], answer.other.image),
        showPng(elements.difference, answer.difference.image),
      ]);
      elements.differenceCaption.textContent = `|A − B| of luminance, 0 to ${answer.difference.scale.toPrecision(3)} (black to pale yellow)`;
      showMetrics(elements.metrics, answer.metrics, `A against B (${answer.mask})`);
      elements.chart.replaceChildren(passTimeChart([answer.base.stats, answer.other.stats], {
        title: 'GPU time per pass of A and B (median, ms)',
        legend: [{ series: 'series-0', label: 'A' }, { series: 'series-1', label: 'B' }],
      }));
      elements.result.hidden = false;
      elements.status.textContent = `Done: A, and B = A with ${Object.keys(body.against).length ? JSON.stringify(body.against) : 'nothing changed'}.`;
    });
  }
}

// "Compute the error": the current settings against the ground truth (POST /v1/compare
// with "reference"), a CPU path tracer's image of the same view: the reference, the heat
// map of the difference and the metrics, with the reference's own noise to read them by.

import { compare } from './api_client.js';
import { LatestRun } from './latest_run.js';
import { showPng } from './images.js';
import { deepEqual } from './request_state.js';
import { showMetrics } from './metrics_table.js';
import { formatMs } from './svg.js';

export class ReferencePanel {
  #run = new LatestRun();
  #computedFor = null;  // the request the result on show answers

  constructor({ elements, state, errors }) {
    Object.assign(this, { elements, state, errors });
    elements.form.addEventListener('submit', (event) => {
      event.preventDefault();
      this.run();
    });
    state.addEventListener('change', () => this.#markOutdated());
  }

  async run() {
    const { elements } = this;
    const request = this.state.request;
    const body = { base: request, reference: { samples: Number(elements.samples.value) }, mask: elements.mask.value };
    const options = { button: elements.button, status: elements.status, errors: this.errors,
                      busyText: 'Tracing the reference and rendering…' };
    await this.#run.start(options, async (signal) => {
      const answer = await compare(body, signal);
      await Promise.all([
        showPng(elements.referenceImage, answer.other.image),
        showPng(elements.differenceImage, answer.difference.image),
      ]);
      elements.differenceCaption.textContent = `|difference| of luminance, 0 to ${answer.difference.scale.toPrecision(3)} (black to pale yellow)`;
      showMetrics(elements.metrics, answer.metrics, `These settings against a ${body.reference.samples}-sample reference (${answer.mask})`);
      const reference = answer.other.reference;
      elements.noise.textContent = `The reference's own noise adds ${reference.noise_rmse.toPrecision(3)} RMSE ` +
        `(${(reference.relative_noise * 100).toFixed(0)}% of its mean indirect light): differences below that need more samples. ` +
        (reference.cached ? 'It came from the cache.' : `Tracing it took ${formatMs(reference.trace_ms)} ms.`);
      elements.result.hidden = false;
      this.#computedFor = request;
      elements.status.textContent = 'Done: for the current settings.';
    });
  }

  #markOutdated() {
    if (this.#computedFor && !deepEqual(this.#computedFor, this.state.request))
      this.elements.status.textContent = 'The settings have changed since: the result on show is for earlier ones.';
  }
}

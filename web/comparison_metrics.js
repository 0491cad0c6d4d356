// The numbers beside the canvas: A against the reference, B against the reference and A
// against B, each from the server (POST /v1/compare, "images": "pfm"), over the whole image
// and, once one is dragged, over a rectangle. The metrics are the server's, computed on its
// own linear images, so the page's exposure and tone map never move them. The same answers
// bring the reference's linear pixels and the FLIP maps the canvas shows.
//
// A comparison is asked for again only when its body changes: moving the light of B re-asks
// B's two rows, not A's row against the reference; the reference itself is traced once per
// view and cached by the server.

import { compare } from './api_client.js';
import { decodePfmBase64 } from './pfm.js';
import { clone, mergePatch } from './request_state.js';

// [pair, x, y]: x tested against y.
const ROWS = [
  ['a|reference', 'A', 'reference'],
  ['b|reference', 'B', 'reference'],
  ['a|b', 'A', 'B'],
];
const COLUMNS = [
  ['rmse', 'RMSE'],
  ['relative_mse', 'rel. MSE (ε 0.01)'],
  ['psnr_db', 'PSNR dB'],
  ['ssim', 'SSIM'],
  ['flip', 'mean FLIP'],
  ['indirect_ratio', 'indirect ÷'],
];

function format(value) {
  if (value === null || value === undefined) return '∞';
  if (typeof value === 'string') return value;
  return Math.abs(value) >= 100 ? value.toFixed(1) : value.toPrecision(4);
}

// The view the metrics measure: the final image, or the indirect light when that is on show.
function measuredImage(request) {
  return request.output?.view === 'indirect' ? 'indirect' : 'image';
}

export class ComparisonMetrics extends EventTarget {
  #answers = new Map();  // body JSON -> answer (the latest few)
  #last = {};            // pair -> the answer on show
  #stale = new Set();    // pairs whose answer on show is for earlier settings
  #controller = null;

  constructor({ table, status, caption, errors }) {
    super();
    Object.assign(this, { table, status, caption, errors });
    this.reference = null;  // { samples, mask } once the user asks for the reference
  }

  #body(base, other) {
    const body = { base: clone(base), mask: this.reference?.mask ?? 'interior', images: 'pfm' };
    delete body.base.repeat;  // the metrics need no timing
    if (other === 'reference') body.reference = { samples: this.reference.samples };
    else body.against = mergePatch(base, other);
    return body;
  }

  async #ask(body, signal) {
    const key = JSON.stringify(body);
    if (!this.#answers.has(key)) {
      const answer = await compare(body, signal);
      this.#answers.set(key, answer);
      if (this.#answers.size > 12) this.#answers.delete(this.#answers.keys().next().value);
    }
    return this.#answers.get(key);
  }

  // The rows on show answer earlier settings: dimmed until update brings theirs. Called as
  // soon as the settings change, before the update itself, which waits for the frames to rest.
  markStale(region, b) {
    this.#stale = new Set(Object.keys(this.#last));
    this.#show(region, b);
  }

  // Recomputes every row for B = `b`, A = `a` (null: none pinned) and `region` (null: none),
  // aborting the previous update. onImages({ reference, flips }) gets the pixels for the canvas.
  async update({ a, b, region }, onImages) {
    this.#controller?.abort();
    const controller = new AbortController();
    this.#controller = controller;
    const { signal } = controller;
    const jobs = [];
    if (this.reference) {
      jobs.push(['b|reference', this.#body(b, 'reference')]);
      if (a) jobs.push(['a|reference', this.#body(a, 'reference')]);
    }
    if (a) jobs.push(['a|b', this.#body(a, b)]);
    if (region) {
      const [x, y, width, height] = region;
      for (const [pair, body] of [...jobs]) jobs.push([`${pair} region`, { ...body, region: { x, y, width, height } }]);
    }
    if (!jobs.length) {
      this.#last = {};
      this.#show(region, b);
      this.status.textContent = 'Pin A (key A) or add the reference (key 3) to measure the error.';
      return;
    }
    this.errors.clear();
    // The numbers on show stay, dimmed, until the new ones come: no flash of dashes per frame.
    const wanted = new Set(jobs.map(([pair]) => pair));
    for (const pair of Object.keys(this.#last)) if (!wanted.has(pair)) delete this.#last[pair];
    this.markStale(region, b);
    this.status.textContent = this.reference ? `Measuring against a ${this.reference.samples}-sample reference…` : 'Measuring A against B…';
    try {
      // One at a time: the server renders them in turn anyway, and the first rows show sooner.
      for (const [pair, body] of jobs) {
        const answer = await this.#ask(body, signal);
        if (signal.aborted) return;
        this.#last[pair] = answer;
        this.#stale.delete(pair);
        this.#show(region, b);
        if (!pair.endsWith('region')) onImages(this.#images(pair, answer, b));
      }
      const reference = this.#last['b|reference']?.other.reference;
      this.status.textContent = reference
        ? `Reference: ${reference.samples} samples, ${reference.bounces} bounce${reference.bounces === 1 ? '' : 's'}; its own noise is ${reference.noise_rmse.toPrecision(3)} RMSE ` +
          `(${(reference.relative_noise * 100).toFixed(0)}% of its mean indirect light): smaller differences need more samples.`
        : 'A against B: no reference (key 3 adds it).';
    } catch (error) {
      if (error.name === 'AbortError' || signal.aborted) return;
      this.status.textContent = 'The metrics failed.';
      this.errors.show(error);
    }
  }

  // The canvas's pixels of an answer, decoded once: a cached answer (A's row against the
  // reference, while B changes) comes back with every update and costs no second decoding.
  #images(pair, answer, b) {
    const which = measuredImage(b);
    answer.decoded ??= {};
    const decode = (key, base64) => (answer.decoded[key] ??= base64 ? decodePfmBase64(base64) : null);
    const images = { flips: { [pair]: decode('flip', answer.flip?.values) } };
    if (pair === 'b|reference') images.reference = decode(which, which === 'indirect' ? answer.other.indirect : answer.other.image);
    return images;
  }

  #show(region, b) {
    const answers = this.#last;
    const image = measuredImage(b) === 'indirect' ? 'indirect' : 'final';
    const head = document.createElement('tr');
    head.append(cell('th', 'compared', 'col'), ...COLUMNS.map(([, label]) => cell('th', label, 'col')));
    const rows = [];
    for (const suffix of region ? ['', ' region'] : ['']) {
      for (const [pair, x, y] of ROWS) {
        const answer = answers[pair + suffix];
        const row = document.createElement('tr');
        row.dataset.pair = pair + suffix;
        row.classList.toggle('stale', this.#stale.has(pair + suffix));
        const name = `${x} vs ${y}` + (suffix ? ` in ${region[2]}×${region[3]} at (${region[0]}, ${region[1]})` : '');
        row.append(cell('th', name, 'row'));
        for (const [key] of COLUMNS) {
          const value = !answer ? '–' : key === 'indirect_ratio' ? answer.indirect_ratio : answer.metrics[image][key];
          const td = cell('td', format(value));
          td.dataset.metric = key;
          row.append(td);
        }
        rows.push(row);
      }
    }
    const thead = document.createElement('thead');
    thead.append(head);
    const tbody = document.createElement('tbody');
    tbody.append(...rows);
    const viewing = Object.values(answers)[0]?.flip?.viewing;
    this.caption.textContent = `Metrics of the ${image === 'final' ? 'final image' : 'indirect light'} on the server's linear images, over ` +
      `${this.reference?.mask ?? 'interior'} pixels; indirect ÷ is the mean indirect light's ratio.` +
      (viewing ? ` FLIP as seen at ${viewing.pixels_per_degree.toFixed(0)} pixels per degree (${viewing.distance_m} m from a ` +
                 `${viewing.monitor_width_m} m wide, ${viewing.monitor_width_px} px display).` : '');
    this.table.replaceChildren(thead, tbody);
    this.dispatchEvent(new Event('shown'));
  }
}

function cell(tag, text, scope) {
  const element = document.createElement(tag);
  element.textContent = text;
  if (scope) element.scope = scope;
  return element;
}

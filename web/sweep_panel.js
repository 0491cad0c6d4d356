// Sweeps from the page: POST /v1/sweep?format=ndjson with the current settings as the base
// (at a smaller image size: a sweep renders every row and traces a reference), read as a
// stream so progress shows while the reference is traced and the rows arrive in the table;
// the plot, the server's own, comes with the timed table when the sweep is done. A point (or
// a row's button) loads its configuration into the settings.

import { sweep } from './api_client.js';
import { sweepPlot } from './sweep_plot.js';
import { formatMs } from './svg.js';
import { LatestRun } from './latest_run.js';
import { lpvFieldsOf } from './lpv_settings.js';

const LIST_PARAMETERS = ['grid', 'iterations', 'cascades', 'rsm', 'vpl_downsample', 'bounces'];

// "8, 16, 32" -> [8, 16, 32]; what is not a number goes to the server as text, which names it.
function parseList(text) {
  return text.split(',').map((item) => item.trim()).filter(Boolean).map((item) => (Number.isNaN(Number(item)) ? item : Number(item)));
}

export class SweepPanel {
  #run = new LatestRun();
  #rows = [];
  #plot = null;  // the server's SVG plot, once the sweep is done
  #budgetChoice = null;  // the label of the row a time budget chose for the frame on show
  #axis = null;          // the plot's, once drawn

  constructor({ elements, state, errors, onPathTraced }) {
    Object.assign(this, { elements, state, errors, onPathTraced });
    elements.form.addEventListener('submit', (event) => {
      event.preventDefault();
      this.run();
    });
    // Iterations move light only in a propagation: under the gather (and auto, which gathers
    // at the grids a sweep offers by default) a list of them would time one frame twice.
    const offerIterations = () => {
      const propagates = ['sharpened', 'cosine'].includes(state.get('lpv.transfer'));
      elements.iterationsControl.hidden = !propagates;
      if (!propagates) elements.lists.iterations.value = '';
    };
    state.addEventListener('change', offerIterations);
    offerIterations();
    elements.stop.addEventListener('click', () => {
      this.#run.stop();
      this.#progress('Stopped', elements.progress.value);
    });
  }

  #body() {
    const { elements } = this;
    const parameters = {};
    for (const name of LIST_PARAMETERS) {
      const values = parseList(elements.lists[name].value);
      if (values.length) parameters[name] = values;
    }
    const occlusion = [];
    if (elements.occlusionOn.checked) occlusion.push(true);
    if (elements.occlusionOff.checked) occlusion.push(false);
    if (occlusion.length) parameters.occlusion = occlusion;
    const pathTraced = parseList(elements.pathTraced.value);
    const base = this.state.request;
    delete base.budget_ms;  // a sweep measures the settings it names: the request's own
    const side = Number(elements.size.value);
    base.output = { ...base.output, width: side, height: side };
    return {
      base,
      parameters,
      lpv_off_row: elements.lpvOff.checked,
      ...(pathTraced.length ? { path_traced: { samples: pathTraced } } : {}),
      reference: { samples: Number(elements.samples.value) },
      axis: { image: elements.image.value, metric: elements.metric.value },
    };
  }

  async run() {
    const { elements } = this;
    const body = this.#body();
    this.#rows = [];
    this.#plot = null;
    this.#draw(body.axis);
    elements.progress.value = 0;
    await this.#run.start(
      { button: elements.run, stopButton: elements.stop, status: elements.progressLabel, errors: this.errors, busyText: 'Tracing the reference' },
      (signal) => sweep(body, signal, (event) => this.#onEvent(event, body.axis)),
    );
  }

  #onEvent(event, axis) {
    const { elements } = this;
    switch (event.event) {
      case 'reference_progress':
        this.#progress('Tracing the reference', event.fraction);
        break;
      case 'reference':
        elements.status.textContent = `Reference: ${event.reference.samples} samples per pixel, traced in ${formatMs(event.reference.trace_ms)} ms` +
          `${event.reference.cached ? ' (cached)' : ''}, noise RMSE ${event.reference.noise_rmse.toPrecision(3)}.`;
        break;
      case 'row':  // its errors; its times come in the timed rounds
        this.#rows[event.index] = event.row;
        this.#progress(`Rendered ${event.index + 1} of ${event.total} configurations`, 0.5 * (event.index + 1) / event.total);
        this.#draw(axis);
        break;
      case 'timing_progress':
        this.#progress(`Timing: frame ${event.done} of ${event.total}, the rows taking turns`, 0.5 + 0.5 * event.done / event.total);
        break;
      case 'done':
        this.#rows = event.table.rows;
        this.#plot = event.plot;
        this.#progress(event.complete ? `Done: ${this.#rows.length} configurations` : 'Ended early at the deadline', 1);
        this.#draw(axis);
        break;
      case 'error':
        this.#progress('Failed', this.elements.progress.value);
        this.errors.show(event.error);
        break;
    }
  }

  #progress(text, fraction) {
    this.elements.progressLabel.textContent = text;
    this.elements.progress.value = fraction;
  }

  #draw(axis) {
    const rows = this.#rows.filter(Boolean);
    this.#axis = axis;
    this.elements.plot.replaceChildren(this.#plot
      ? sweepPlot(this.#plot, this.#rows, (row) => this.load(row), (row) => this.#hover(row, axis), this.#budgetChoice)
      : Object.assign(document.createElement('p'), { className: 'hint', textContent: 'The plot of error against time per frame comes when the rows are timed.' }));
    this.#table(rows, axis);
  }

  // Rings the row whose settings a time budget chose for the frame on show (its label, as the
  // stats' budget.chosen.description says it); null: none.
  showBudgetChoice(label) {
    if (label === this.#budgetChoice) return;
    this.#budgetChoice = label;
    if (this.#axis) this.#draw(this.#axis);
  }

  #table(rows, axis) {
    const table = this.elements.table;
    const caption = Object.assign(document.createElement('caption'), { textContent: 'The rows: load one into the settings' });
    const head = document.createElement('tr');
    for (const title of ['configuration', 'ms', `${axis.metric} (${axis.image})`, 'Pareto', 'device', ''])
      head.append(Object.assign(document.createElement('th'), { textContent: title, scope: 'col' }));
    const body = rows.map((row) => {
      const tr = document.createElement('tr');
      const load = Object.assign(document.createElement('button'), { type: 'button', textContent: 'Load' });
      load.addEventListener('click', () => this.load(row));
      const error = row[`${axis.image}_error`][axis.metric];
      for (const text of [row.label, timeText(row), error === null ? '∞' : error.toPrecision(3), paretoText(row), row.device])
        tr.append(Object.assign(document.createElement('td'), { textContent: text }));
      const cell = document.createElement('td');
      cell.append(load);
      tr.append(cell);
      return tr;
    });
    table.replaceChildren(caption, head, ...body);
  }

  // The row under the pointer (or focused), in words: its settings, error and time.
  #hover(row, axis) {
    const error = row[`${axis.image}_error`][axis.metric];
    this.elements.hover.textContent = `${row.label}: ${axis.metric} of the ${axis.image} image ${error === null ? '∞' : error.toPrecision(3)}, ` +
      `${timeText(row)} ms on ${row.device}. Click or Enter loads it ` +
      (row.settings.path_traced_samples > 0 ? 'as the reference.' : 'as B.');
  }

  // A row's settings into the request's LPV fields (the rest of the settings stay): that is B.
  // A path-traced row is traced as the reference instead.
  load(row) {
    const { settings } = row;
    if (settings.path_traced_samples > 0) return this.onPathTraced(settings.path_traced_samples);
    const values = Object.fromEntries(Object.entries(lpvFieldsOf(settings)).map(([name, value]) => [`lpv.${name}`, value]));
    this.state.setAll(values);
  }
}

// The median and, from several frames, their range; a dash until the row is timed.
function timeText(row) {
  if (row.gpu_ms === null) return '—';
  return row.frames > 1 ? `${formatMs(row.gpu_ms)} (${formatMs(row.gpu_ms_range[0])}–${formatMs(row.gpu_ms_range[1])})` : formatMs(row.gpu_ms);
}

// ★ on the front; a question mark where the frames' ranges could put the row either side.
function paretoText(row) {
  if (row.pareto_uncertain) return row.pareto ? '★?' : '?';
  return row.pareto ? '★' : '';
}

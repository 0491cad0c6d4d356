// Turns changes of the request into frames: a change aborts the request in flight at once
// (its answer, should it still arrive, is dropped) and sends the new one after a short
// debounce, so a dragged slider sends one request, not fifty. The frame on screen is thus
// never replaced by one older than the newest change.
//
// Performance marks (read by the browser test): "lpv:change" at each change, "lpv:request"
// when its request is sent, "lpv:answer" when the answer is in, "lpv:frame" once its image
// is painted; the measures "lpv:change-to-frame", "lpv:request-to-answer" (the server and
// HTTP) and "lpv:answer-to-frame" (decoding and painting).

import { ApiError } from './api_client.js';
import { nextPaint } from './images.js';

export class RenderLoop {
  #timer = 0;
  #inFlight = null;  // the AbortController of the newest request

  // render(request, signal) -> answer; show(answer, request) -> promise, resolves when shown
  constructor({ debounceMs, render, show, onBusy, onError }) {
    Object.assign(this, { debounceMs, render, show, onBusy, onError });
  }

  schedule(request) {
    performance.mark('lpv:change');
    this.#inFlight?.abort();
    this.#inFlight = null;
    clearTimeout(this.#timer);
    this.onBusy(true);
    this.#timer = setTimeout(() => this.#run(request), this.debounceMs);
  }

  async #run(request) {
    const controller = new AbortController();
    this.#inFlight = controller;
    const current = () => this.#inFlight === controller;
    performance.mark('lpv:request');
    try {
      const answer = await this.render(request, controller.signal);
      if (!current()) return;
      performance.mark('lpv:answer');
      await this.show(answer, request);
      if (!current()) return;
      await nextPaint();
      performance.mark('lpv:frame');
      performance.measure('lpv:change-to-frame', 'lpv:change', 'lpv:frame');
      performance.measure('lpv:request-to-answer', 'lpv:request', 'lpv:answer');
      performance.measure('lpv:answer-to-frame', 'lpv:answer', 'lpv:frame');
    } catch (error) {
      if (!current() || error.name === 'AbortError') return;
      this.onError(error instanceof ApiError ? error : new ApiError(0, { code: 'network', message: String(error.message ?? error) }));
    } finally {
      if (current()) {
        this.#inFlight = null;
        this.onBusy(false);
      }
    }
  }
}

// Turns changes of the request into frames, as fast as the renderer allows and never out of
// order: a change when nothing is in flight is sent at once (no debounce: the frame shows within
// the render's own time and a few milliseconds of decoding); a change while a frame is being
// rendered waits, replacing any change that waited before it, and is sent when that frame is
// in. So a dragged slider gets a frame per render time, each for newer settings than the last,
// and the frame on screen is never replaced by one older than itself.
//
// Performance marks (read by the browser test): "lpv:change" at each change, "lpv:request"
// when its request is sent, "lpv:answer" when the answer is in, "lpv:frame" once its image
// is painted; the measures "lpv:change-to-frame", "lpv:request-to-answer" (the server and
// HTTP) and "lpv:answer-to-frame" (decoding and painting).

import { ApiError } from './api_client.js';

export class RenderLoop {
  #inFlight = null;  // the request being rendered
  #waiting = null;   // the newest change that came while one was in flight

  // render(request, signal) -> answer; show(answer, request) -> promise, resolves when shown
  constructor({ render, show, onBusy, onError }) {
    Object.assign(this, { render, show, onBusy, onError });
  }

  schedule(request) {
    performance.mark('lpv:change');
    this.onBusy(true);
    if (this.#inFlight) this.#waiting = request;
    else this.#run(request);
  }

  async #run(request) {
    this.#inFlight = request;
    performance.mark('lpv:request');
    try {
      const answer = await this.render(request);
      performance.mark('lpv:answer');
      await this.show(answer, request);
      await nextPaint();
      performance.mark('lpv:frame');
      performance.measure('lpv:change-to-frame', 'lpv:change', 'lpv:frame');
      performance.measure('lpv:request-to-answer', 'lpv:request', 'lpv:answer');
      performance.measure('lpv:answer-to-frame', 'lpv:answer', 'lpv:frame');
    } catch (error) {
      // An error for settings already changed again is no longer news: the next frame answers.
      if (!this.#waiting)
        this.onError(error instanceof ApiError ? error : new ApiError(0, { code: 'network', message: String(error.message ?? error) }));
    } finally {
      this.#inFlight = null;
      const next = this.#waiting;
      this.#waiting = null;
      if (next) this.#run(next);
      else this.onBusy(false);
    }
  }
}

// Resolves after the browser has painted what the DOM holds now.
function nextPaint() {
  return new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
}

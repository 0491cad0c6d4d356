// One run at a time for a panel (A/B, error against the reference, a sweep): starting
// another aborts the one in flight, whose answer then never shows; a failure shows the
// server's message next to the field it names; the panel's buttons come back when the newest
// run ends.

export class LatestRun {
  #controller = null;

  // Aborts the run in flight, if any (a Stop button).
  stop() {
    this.#controller?.abort();
  }

  // `work(signal)` does the request and shows its answer; `enabled()` says whether the
  // button should be usable once this run is over; `stopButton`, if any, is usable while
  // the run is in flight.
  async start({ button, stopButton, status, errors, busyText, enabled = () => true }, work) {
    this.stop();
    const controller = new AbortController();
    this.#controller = controller;
    errors.clear();
    status.textContent = busyText;
    button.disabled = true;
    if (stopButton) stopButton.disabled = false;
    try {
      await work(controller.signal);
    } catch (error) {
      if (error.name === 'AbortError') return;
      status.textContent = 'Failed.';
      errors.show(error);
    } finally {
      if (this.#controller === controller) {
        button.disabled = !enabled();
        if (stopButton) stopButton.disabled = true;
      }
    }
  }
}

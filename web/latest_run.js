// One compare at a time for a panel (A/B, error against the reference): starting another
// aborts the one in flight, whose answer then never shows; a failure shows the server's
// message next to the field it names; the panel's button comes back when the newest run ends.

export class LatestRun {
  #controller = null;

  // `work(signal)` does the request and shows its answer; `enabled()` says whether the
  // button should be usable once this run is over.
  async start({ button, status, errors, busyText, enabled = () => true }, work) {
    this.#controller?.abort();
    const controller = new AbortController();
    this.#controller = controller;
    errors.clear();
    status.textContent = busyText;
    button.disabled = true;
    try {
      await work(controller.signal);
    } catch (error) {
      if (error.name === 'AbortError') return;
      status.textContent = 'Failed.';
      errors.show(error);
    } finally {
      if (this.#controller === controller) button.disabled = !enabled();
    }
  }
}

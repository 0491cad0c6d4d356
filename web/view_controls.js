// The canvas's keys, pointer and toolbar (docs/web.md "Keys"). One table of shortcuts drives
// both the handler and the help that `?` opens, so the two cannot disagree.
//
// Dragging on the canvas does one of three things, the drag mode: move the camera (C, as the
// page always did: orbit, right- or Shift-drag to pan), move the view (V) or draw a rectangle
// whose metrics are measured (R). The wheel zooms the view about the pointer in every mode.

import { DIFFERENCE_KINDS } from './difference_maps.js';
import { TONEMAPS } from './display_transfer.js';

export const PAIRS = [['b', 'reference'], ['a', 'reference'], ['a', 'b']];

const next = (list, value) => list[(list.indexOf(value) + 1) % list.length];

// [keys as shown, what they do, handler(controls, event)]; the handler runs on keydown.
const SHORTCUTS = [
  ['1', 'show B, the current frame', (c) => c.actions.show('b')],
  ['2', 'show A, the pinned frame', (c) => c.actions.show('a')],
  ['3', 'show the reference (traced the first time)', (c) => c.actions.show('reference')],
  ['W', 'wipe between the pair: the first left, the second right', (c) => c.actions.show('wipe')],
  ['D', 'the difference of the pair', (c) => c.actions.show('difference')],
  ['Space (hold)', 'flip to the reference, or to A when there is none', (c, e) => c.hold(e)],
  ['P', 'next pair: B vs reference, A vs reference, A vs B', (c) => c.view.set({ pair: next(PAIRS, PAIRS.find((p) => p.join() === c.view.view.pair.join())) })],
  ['K', 'next difference: absolute, signed, relative, FLIP', (c) => c.view.set({ kind: next(DIFFERENCE_KINDS, c.view.view.kind) })],
  ['L', 'lock the difference scale (or unlock it), so that two maps share one', (c) => c.lockScale()],
  ['[ and ]', 'move the wipe left and right', (c, e) => c.view.set({ wipe: Math.min(1, Math.max(0, c.view.view.wipe + (e.key === '[' ? -0.05 : 0.05))) })],
  ['F', 'fit the image to the canvas', (c) => c.view.fit()],
  ['0', 'one image pixel to one screen pixel', (c) => c.view.oneToOne()],
  ['+ and −', 'zoom in and out (the wheel does, about the pointer)', (c, e) => c.view.zoomBy(e.key === '-' ? 0.5 : 2)],
  ['arrows', 'pan the view (in camera mode, with the canvas focused: orbit the camera)', (c, e) => c.arrow(e)],
  ['C, V, R', 'dragging moves the camera, moves the view, or draws a rectangle to measure', (c, e) => c.setDragMode({ c: 'camera', v: 'view', r: 'region' }[e.key.toLowerCase()])],
  ['Esc', 'clear the rectangle; close this list', (c) => c.escape()],
  ['E and Shift+E', 'exposure up and down by half a stop (the display only)', (c, e) => c.view.set({ exposure: c.view.view.exposure + (e.shiftKey ? -0.5 : 0.5) })],
  ['T', 'next tone map: none, reinhard, aces (the display only)', (c) => c.view.set({ tonemap: next(TONEMAPS, c.view.view.tonemap) })],
  ['A', 'pin the current settings and frame as A', (c) => c.actions.pin()],
  ['S', 'show or hide the settings', (c) => c.actions.toggleDrawer()],
  ['?', 'this list', (c) => c.actions.toggleHelp()],
];

// event.key -> the shortcut's handler
const HANDLERS = new Map();
for (const [keys, , handler] of SHORTCUTS) {
  const names = keys === 'Space (hold)' ? [' '] : keys === 'arrows' ? ['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown']
    : keys === '+ and −' ? ['+', '=', '-'] : keys === '[ and ]' ? ['[', ']'] : keys === 'Esc' ? ['Escape']
    : keys === 'E and Shift+E' ? ['e', 'E'] : keys.split(', ').flatMap((k) => [k.toLowerCase(), k.toUpperCase()]);
  for (const name of names) HANDLERS.set(name, handler);
}

export function fillHelp(table) {
  const rows = SHORTCUTS.map(([keys, what]) => {
    const row = document.createElement('tr');
    const th = Object.assign(document.createElement('th'), { scope: 'row' });
    th.append(Object.assign(document.createElement('kbd'), { textContent: keys }));
    row.append(th, Object.assign(document.createElement('td'), { textContent: what }));
    return row;
  });
  table.replaceChildren(...rows);
}

// view: the CanvasView; area: the element the pointer acts on; actions: { show(source),
// pin(), toggleDrawer(), toggleHelp(), closeHelp() -> whether it was open, onPointer(pixel |
// null), onRegion(), onShown() (the source on show changed without a view change) }.
export class ViewControls {
  constructor({ view, area, actions, dragModeInputs }) {
    Object.assign(this, { view, area, actions, dragModeInputs });
    this.dragMode = 'camera';
    document.addEventListener('keydown', (event) => this.#key(event));
    document.addEventListener('keyup', (event) => {
      if (event.key === ' ' && this.held) {
        this.held = false;
        view.hold(null);
        actions.onShown();
      }
    });
    for (const input of dragModeInputs) input.addEventListener('change', () => this.setDragMode(input.value));
    this.#pointer();
  }

  #key(event) {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    // Typing goes to form fields, and Space and Enter to the button in focus (a sweep's point).
    const target = event.target;
    const inField = target instanceof HTMLElement && target.closest('input, select, textarea');
    const onButton = target instanceof Element && target.closest('button, [role="button"]');
    if ((inField && event.key !== 'Escape') || (onButton && (event.key === ' ' || event.key === 'Enter'))) return;
    const handler = HANDLERS.get(event.key);
    if (!handler) return;
    // The camera's own keys (camera_drag.js) act on the focused canvas in camera mode.
    if (event.key.startsWith('Arrow') && this.dragMode === 'camera' && this.area.contains(target)) return;
    event.preventDefault();
    if (event.repeat && event.key === ' ') return;
    handler(this, event);
  }

  hold(event) {
    if (event.repeat) return;
    this.held = true;
    this.view.hold(this.view.image('reference') ? 'reference' : 'a');
    this.actions.onShown();
  }

  lockScale() {
    const d = this.view.difference();
    this.view.set({ lockedScale: this.view.view.lockedScale === null && !d.missing ? d.scale : null });
  }

  arrow(event) {
    const step = 40;
    const moves = { ArrowLeft: [step, 0], ArrowRight: [-step, 0], ArrowUp: [0, step], ArrowDown: [0, -step] };
    this.view.panBy(...moves[event.key]);
  }

  setDragMode(mode) {
    this.dragMode = mode;
    for (const input of this.dragModeInputs) input.checked = input.value === mode;
    this.area.dataset.drag = mode;
  }

  escape() {
    if (this.actions.closeHelp()) return;
    if (this.view.view.region) {
      this.view.set({ region: null });
      this.actions.onRegion();
    }
  }

  #pointer() {
    const { view, area } = this;
    const local = (event) => {
      const box = view.canvas.getBoundingClientRect();
      return [event.clientX - box.left, event.clientY - box.top];
    };
    let drag = null;
    area.addEventListener('pointerdown', (event) => {
      if (this.dragMode === 'camera' || event.button !== 0) return;
      const [x, y] = local(event);
      drag = { x, y, start: view.toImage(x, y) };
      area.setPointerCapture(event.pointerId);
    });
    area.addEventListener('pointermove', (event) => {
      const [x, y] = local(event);
      this.actions.onPointer(view.pixelAt(x, y));
      if (!drag) return;
      if (this.dragMode === 'view') {
        view.panBy(x - drag.x, y - drag.y);
        Object.assign(drag, { x, y });
      } else if (drag.start) {
        view.set({ region: this.#region(drag.start, view.toImage(x, y)) });
      }
    });
    const end = () => {
      if (drag && this.dragMode === 'region' && view.view.region) this.actions.onRegion();
      drag = null;
    };
    area.addEventListener('pointerup', end);
    area.addEventListener('pointercancel', end);
    area.addEventListener('pointerleave', () => this.actions.onPointer(null));
    area.addEventListener('wheel', (event) => {
      if (event.altKey) return;  // Alt+wheel moves the camera (camera_drag.js)
      event.preventDefault();
      const [x, y] = local(event);
      view.zoomBy(Math.exp(-event.deltaY * 0.002), x, y);
    }, { passive: false });
  }

  // The pixels whose centres lie between two image points, clamped to the image; null if none.
  #region(a, b) {
    const size = this.view.imageSize;
    const clamp = (v, max) => Math.min(max, Math.max(0, v));
    const x0 = clamp(Math.round(Math.min(a[0], b[0])), size.width);
    const y0 = clamp(Math.round(Math.min(a[1], b[1])), size.height);
    const x1 = clamp(Math.round(Math.max(a[0], b[0])), size.width);
    const y1 = clamp(Math.round(Math.max(a[1], b[1])), size.height);
    return x1 > x0 && y1 > y0 ? [x0, y0, x1 - x0, y1 - y0] : null;
  }
}

// The one canvas every image is seen on (docs/web.md "The canvas"): the current frame (B),
// the pinned frame (A), the reference, a wipe between the pair being compared, and their
// difference. The view (zoom and pan) belongs to the canvas, not to a source, so it stays put
// when the source or the frame changes. Drawing is synchronous and cheap: each source is kept
// as an offscreen canvas already tone mapped, so a switch or a wipe step is one or two
// drawImage calls (the browser test times a key to its pixels drawn).

import { displayImage } from './display_transfer.js';
import { automaticScale, differenceImage, differenceValues } from './difference_maps.js';

const NAMES = { b: 'B (current)', a: 'A (pinned)', reference: 'reference' };
const MIN_ZOOM = 1 / 32;
const MAX_ZOOM = 64;  // a pixel 64 screen pixels wide: single pixels and their readout

function offscreen(imageData) {
  const canvas = document.createElement('canvas');
  canvas.width = imageData.width;
  canvas.height = imageData.height;
  canvas.getContext('2d').putImageData(imageData, 0, 0);
  return canvas;
}

export class CanvasView extends EventTarget {
  #images = {};      // name -> { width, height, rgb }: linear, from PFM
  #pictures = {};    // name -> offscreen canvas of the image as displayed
  #flip = {};        // "x|y" -> { rgb } the server's FLIP map of x against y
  #difference = null;  // { key, canvas, scale, values } of the map on show
  #held = null;      // the source shown while Space is held
  #warming = 0;      // the timer that makes the pair's map ahead of need

  constructor(canvas) {
    super();
    this.canvas = canvas;
    this.view = { source: 'b', pair: ['b', 'reference'], kind: 'absolute', zoom: 0, center: null, region: null,
                  wipe: 0.5, exposure: 0, tonemap: 'none', lockedScale: null };
    new ResizeObserver(() => this.draw()).observe(canvas);
  }

  // --- sources ---------------------------------------------------------------------------
  setImage(name, image) {
    if (image) this.#images[name] = image;
    else delete this.#images[name];
    this.#repaint(name);
    this.#mapsChanged();
  }

  image(name) {
    return this.#images[name] ?? null;
  }

  // The server's FLIP map of `x` tested against `y` (null: none yet).
  setFlip(x, y, values) {
    if (values) this.#flip[`${x}|${y}`] = values;
    else delete this.#flip[`${x}|${y}`];
    this.#mapsChanged();
  }

  // New pixels: the map on hand is stale. The pair's map is made again once the browser is
  // idle, not when D is pressed, so that showing it costs a draw, not a pass over the image.
  #mapsChanged() {
    this.#difference = null;
    this.draw();
    clearTimeout(this.#warming);
    this.#warming = setTimeout(() => this.difference(), 0);
  }

  #repaint(name) {
    const image = this.#images[name];
    if (image) this.#pictures[name] = offscreen(displayImage(image, this.view));
    else delete this.#pictures[name];
  }

  // --- the view --------------------------------------------------------------------------
  set(changes) {
    const displayChanged = ('exposure' in changes && changes.exposure !== this.view.exposure) ||
                           ('tonemap' in changes && changes.tonemap !== this.view.tonemap);
    const differenceChanged = ['pair', 'kind', 'lockedScale'].some((key) => key in changes);
    Object.assign(this.view, changes);
    if (displayChanged) for (const name of Object.keys(this.#images)) this.#repaint(name);
    if (differenceChanged) this.#difference = null;
    this.draw();
    this.dispatchEvent(new Event('viewchange'));
  }

  hold(source) {
    this.#held = source;
    this.draw();
  }

  get shown() {
    return this.#held ?? this.view.source;
  }

  // The size of what is compared: B's, or whichever image there is.
  get imageSize() {
    const image = this.#images.b ?? this.#images.a ?? this.#images.reference;
    return image ? { width: image.width, height: image.height } : null;
  }

  fit() {
    this.set({ zoom: 0, center: null });
  }

  oneToOne() {
    this.zoomTo(1);
  }

  // Zooms by `factor` keeping the image point under the canvas point (cx, cy) in place.
  zoomBy(factor, cx = this.canvas.clientWidth / 2, cy = this.canvas.clientHeight / 2) {
    const { zoom } = this.#transform();
    const anchor = this.toImage(cx, cy);
    const next = Math.min(MAX_ZOOM, Math.max(MIN_ZOOM, zoom * factor));
    if (!anchor) return this.set({ zoom: next });
    // the anchor stays at (cx, cy): centre = anchor + (canvas centre - (cx, cy)) / next
    const center = [anchor[0] + (this.canvas.clientWidth / 2 - cx) / next, anchor[1] + (this.canvas.clientHeight / 2 - cy) / next];
    this.set({ zoom: next, center });
  }

  zoomTo(zoom) {
    const current = this.#transform();
    this.set({ zoom, center: current.center });
  }

  panBy(dx, dy) {
    const { zoom, center } = this.#transform();
    if (!center) return;
    this.set({ zoom, center: [center[0] - dx / zoom, center[1] - dy / zoom] });
  }

  // zoom 0 is "fit": the whole image in the canvas, as large as it goes.
  #transform() {
    const size = this.imageSize;
    const width = this.canvas.clientWidth;
    const height = this.canvas.clientHeight;
    if (!size || !width || !height) return { zoom: 1, center: null };
    const fitZoom = Math.min(width / size.width, height / size.height);
    const zoom = this.view.zoom > 0 ? this.view.zoom : fitZoom;
    const center = this.view.zoom > 0 && this.view.center ? this.view.center : [size.width / 2, size.height / 2];
    return { zoom, center, offsetX: width / 2 - center[0] * zoom, offsetY: height / 2 - center[1] * zoom };
  }

  // Canvas (CSS pixel) point to image coordinates (fractional), or null without an image.
  toImage(cx, cy) {
    const t = this.#transform();
    if (!t.center) return null;
    return [(cx - t.offsetX) / t.zoom, (cy - t.offsetY) / t.zoom];
  }

  // The integer pixel under a canvas point, or null outside the image.
  pixelAt(cx, cy) {
    const point = this.toImage(cx, cy);
    const size = this.imageSize;
    if (!point || !size) return null;
    const [x, y] = point.map(Math.floor);
    return x >= 0 && y >= 0 && x < size.width && y < size.height ? { x, y } : null;
  }

  // --- the difference --------------------------------------------------------------------
  // { kind, x, y, values, scale, canvas } of the pair's map, or { missing: why }.
  difference() {
    const { kind, pair: [x, y], lockedScale } = this.view;
    const key = `${kind}|${x}|${y}|${lockedScale}`;
    if (this.#difference?.key === key) return this.#difference;
    const a = this.#images[x];
    const b = this.#images[y];
    const flip = this.#flip[`${x}|${y}`];
    let missing = '';
    if (!a || !b) missing = `no ${!a ? NAMES[x] : NAMES[y]} image yet`;
    else if (a.width !== b.width || a.height !== b.height) missing = `${NAMES[x]} and ${NAMES[y]} differ in size`;
    else if (kind === 'flip' && !flip) missing = `no FLIP map of ${NAMES[x]} against ${NAMES[y]} yet (it comes with the metrics)`;
    if (missing) return { key, missing };
    const values = differenceValues(kind, a, b, flip);
    const scale = lockedScale ?? automaticScale(kind, values);
    this.#difference = { key, kind, x, y, values, scale, width: a.width,
                         canvas: offscreen(differenceImage(kind, values, a.width, a.height, scale)) };
    return this.#difference;
  }

  // What is on screen, in words: the label over the canvas.
  describe() {
    const { pair: [x, y] } = this.view;
    const source = this.shown;
    if (source === 'wipe') return `wipe: ${NAMES[x]} left | ${NAMES[y]} right`;
    if (source === 'difference') {
      const d = this.difference();
      return d.missing ? `difference: ${d.missing}` : `difference (${d.kind}) of ${NAMES[x]} against ${NAMES[y]}`;
    }
    return this.#pictures[source] ? NAMES[source] : `${NAMES[source]}: none yet`;
  }

  // --- drawing ---------------------------------------------------------------------------
  draw() {
    const { canvas } = this;
    const ratio = window.devicePixelRatio || 1;
    const width = Math.round(canvas.clientWidth * ratio);
    const height = Math.round(canvas.clientHeight * ratio);
    if (canvas.width !== width || canvas.height !== height) Object.assign(canvas, { width, height });
    const ctx = canvas.getContext('2d');
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#111';
    ctx.fillRect(0, 0, width, height);
    const t = this.#transform();
    if (t.center) {
      ctx.setTransform(t.zoom * ratio, 0, 0, t.zoom * ratio, t.offsetX * ratio, t.offsetY * ratio);
      ctx.imageSmoothingEnabled = t.zoom < 1;  // magnified pixels stay square
      const source = this.shown;
      const [x, y] = this.view.pair;
      if (source === 'wipe') {
        const size = this.imageSize;
        const split = this.view.wipe * size.width;
        if (this.#pictures[y]) ctx.drawImage(this.#pictures[y], 0, 0);
        if (this.#pictures[x]) {
          ctx.save();
          ctx.beginPath();
          ctx.rect(0, 0, split, size.height);
          ctx.clip();
          ctx.drawImage(this.#pictures[x], 0, 0);
          ctx.restore();
        }
        ctx.fillStyle = '#fff';
        ctx.fillRect(split - 0.5 / t.zoom, 0, 1 / t.zoom, size.height);
      } else if (source === 'difference') {
        const d = this.difference();
        if (d.canvas) ctx.drawImage(d.canvas, 0, 0);
      } else if (this.#pictures[source]) {
        ctx.drawImage(this.#pictures[source], 0, 0);
      }
      const region = this.view.region;
      if (region) {
        ctx.strokeStyle = '#4fc3f7';
        ctx.lineWidth = 2 / t.zoom;
        ctx.strokeRect(region[0], region[1], region[2], region[3]);
      }
    }
    this.dispatchEvent(new Event('drawn'));
  }
}

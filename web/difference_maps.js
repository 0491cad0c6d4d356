// Difference maps of two linear images, drawn to a scale a user can lock so that two maps
// (A's and B's against the reference) are read against the same maximum:
//   absolute  |L(x) - L(y)|                  of luminance L, 0 .. scale, sequential colours
//   signed    L(x) - L(y)                    -scale .. +scale, blue (darker) to red (brighter)
//   relative  |L(x) - L(y)| / (L(y) + 0.01)  the relative MSE's epsilon (docs/accuracy.md)
//   flip      the server's per-pixel FLIP (POST /v1/compare "flip"), always 0 .. 1
// x is the image tested and y the one it is tested against (the reference, or B for A).

import { luminance } from './pfm.js';

export const DIFFERENCE_KINDS = ['absolute', 'signed', 'relative', 'flip'];
const RELATIVE_EPSILON = 0.01;

// A dark-to-bright sequential ramp (black, purple, orange, pale yellow: readable in grey
// too) and a diverging one (blue, white, red), as stops of [t, r, g, b].
const SEQUENTIAL = [[0, 0, 0, 4], [0.25, 80, 18, 123], [0.5, 183, 55, 121], [0.75, 252, 137, 97], [1, 252, 253, 191]];
const DIVERGING = [[0, 33, 102, 172], [0.5, 247, 247, 247], [1, 178, 24, 43]];

function ramp(stops, t) {
  const u = Math.min(Math.max(t, 0), 1);
  let i = 1;
  while (i < stops.length - 1 && stops[i][0] < u) i++;
  const [t0, ...c0] = stops[i - 1];
  const [t1, ...c1] = stops[i];
  const f = (u - t0) / (t1 - t0);
  return c0.map((c, k) => Math.round(c + (c1[k] - c) * f));
}

// A CSS gradient of the kind's colours, for its legend.
export function legendGradient(kind) {
  const stops = kind === 'signed' ? DIVERGING : SEQUENTIAL;
  return `linear-gradient(to right, ${stops.map(([t, r, g, b]) => `rgb(${r} ${g} ${b}) ${t * 100}%`).join(', ')})`;
}

// The map's values, one per pixel. `flipValues` ({ rgb } of the server's FLIP map) for "flip".
export function differenceValues(kind, x, y, flipValues) {
  const n = x.width * x.height;
  const values = new Float32Array(n);
  if (kind === 'flip') {
    for (let i = 0; i < n; i++) values[i] = flipValues.rgb[3 * i];
    return values;
  }
  for (let i = 0; i < n; i++) {
    const d = luminance(x.rgb, i) - luminance(y.rgb, i);
    if (kind === 'signed') values[i] = d;
    else if (kind === 'relative') values[i] = Math.abs(d) / (Math.max(luminance(y.rgb, i), 0) + RELATIVE_EPSILON);
    else values[i] = Math.abs(d);
  }
  return values;
}

// The scale a map is drawn to unless locked: FLIP's own range, else the 99th percentile of
// the magnitudes, so one stray pixel does not wash out the rest (it saturates instead). Found
// from a histogram of 4096 bins, not a sort: a source switch must draw within a frame. It is
// the top of the bin the percentile falls in, so a hair above the exact percentile.
export function automaticScale(kind, values) {
  if (kind === 'flip') return 1;
  let max = 0;
  for (const v of values) max = Math.max(max, Math.abs(v));
  if (!(max > 0)) return 1;
  const bins = new Uint32Array(4096);
  for (const v of values) bins[Math.min(4095, Math.floor((Math.abs(v) / max) * 4096))]++;
  const wanted = Math.ceil(0.99 * values.length);
  let seen = 0;
  for (let i = 0; i < bins.length; i++) {
    seen += bins[i];
    if (seen >= wanted) return ((i + 1) / 4096) * max;
  }
  return max;
}

// The colour of a value at `scale`: what the canvas shows and what the browser test expects.
export function differenceColour(kind, value, scale) {
  return kind === 'signed' ? ramp(DIVERGING, 0.5 + value / (2 * scale)) : ramp(SEQUENTIAL, value / scale);
}

export function differenceImage(kind, values, width, height, scale) {
  const out = new ImageData(width, height);
  for (let i = 0; i < values.length; i++) {
    const [r, g, b] = differenceColour(kind, values[i], scale);
    out.data[4 * i] = r;
    out.data[4 * i + 1] = g;
    out.data[4 * i + 2] = b;
    out.data[4 * i + 3] = 255;
  }
  return out;
}

// Linear light to the canvas's 8-bit sRGB, for display only: the page's exposure and tone map
// change what is drawn, never a metric (those are the server's, on its own images). The tone
// curves and the sRGB curve are those of shaders/shared/display_transfer.h, the one definition
// the shading and the server's pictures use; with exposure 0 the canvas shows the same 8-bit
// values as the server's PNG of the frame (the browser test checks it, within one level).

export const TONEMAPS = ['none', 'reinhard', 'aces'];

const CURVES = {
  none: (x) => x,
  reinhard: (x) => x / (1 + x),
  aces: (x) => (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14),  // Narkowicz fit
};

function toneCurve(x, tonemap) {
  return (CURVES[tonemap] ?? CURVES.none)(x);
}

function srgbEncode(c) {
  return c > 0.0031308 ? 1.055 * Math.pow(c, 1 / 2.4) - 0.055 : 12.92 * c;
}

// One channel's 8-bit display level. Negative and NaN values are black, as on the server.
function displayLevel(value, gain, tonemap) {
  const x = value * gain > 0 ? value * gain : 0;
  const mapped = Math.min(Math.max(toneCurve(x, tonemap), 0), 1);
  return Math.min(Math.max(srgbEncode(mapped), 0), 1) * 255 + 0.5 | 0;
}

// The level of a tone-mapped value m in [0, 1], exactly displayLevel's, without a power: m
// falls in one of 2^16 bins, which holds the level at its start and at most one threshold
// where the level steps up (levels are at least 1 / (12.92 * 255) apart, 50 bins). Each
// threshold, the least m of its level, is found by bisection on displayLevel itself.
const BINS = 1 << 16;
const BIN_LEVEL = new Uint8Array(BINS);
const BIN_STEP = new Float64Array(BINS).fill(Infinity);
for (let bin = 0; bin < BINS; bin++) {
  BIN_LEVEL[bin] = displayLevel(bin / BINS, 1, 'none');
  if (displayLevel((bin + 1) / BINS, 1, 'none') === BIN_LEVEL[bin]) continue;
  let [low, high] = [bin / BINS, (bin + 1) / BINS];
  for (let step = 0; step < 60; step++) {
    const middle = (low + high) / 2;
    if (displayLevel(middle, 1, 'none') > BIN_LEVEL[bin]) high = middle;
    else low = middle;
  }
  BIN_STEP[bin] = high;
}

function levelOfMapped(m) {
  if (m >= 1) return 255;
  const bin = (m * BINS) | 0;
  return BIN_LEVEL[bin] + (m >= BIN_STEP[bin] ? 1 : 0);
}

// image: { width, height, rgb } (pfm.js). Fills and returns an ImageData.
export function displayImage(image, { exposure = 0, tonemap = 'none' } = {}) {
  const gain = Math.pow(2, exposure);
  const out = new ImageData(image.width, image.height);
  const { rgb } = image;
  const pixels = out.data;
  const curve = CURVES[tonemap] ?? CURVES.none;
  for (let i = 0, n = image.width * image.height; i < n; i++) {
    for (let c = 0; c < 3; c++) {
      const x = rgb[3 * i + c] * gain;
      pixels[4 * i + c] = x > 0 ? levelOfMapped(curve(x)) : 0;
    }
    pixels[4 * i + 3] = 255;
  }
  return out;
}

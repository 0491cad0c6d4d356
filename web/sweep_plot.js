// The sweep's error against GPU time, log scales as the server's own plot (?format=svg), but
// with points that are buttons: clicking one (or Enter on it) loads its configuration. The
// Pareto front (the server marks it: no other row both faster and at least as accurate)
// is drawn as a line through its points.

import { formatMs, svgElement } from './svg.js';

const WIDTH = 560;
const HEIGHT = 340;
const MARGIN = { left: 64, right: 16, top: 16, bottom: 44 };

function logScale(values, from, to) {
  const low = Math.log10(Math.min(...values));
  const high = Math.log10(Math.max(...values));
  const span = high - low || 1;
  return (v) => from + ((Math.log10(v) - low) / span) * (to - from);
}

function linearScale(values, from, to) {
  const low = Math.min(...values);
  const span = Math.max(...values) - low || 1;
  return (v) => from + ((v - low) / span) * (to - from);
}

// rows: the sweep's rows so far; axis: {image, metric}; onPick(row) loads a row.
export function sweepPlot(rows, axis, onPick) {
  const errorOf = (row) => row[`${axis.image}_error`][axis.metric];
  const points = rows.filter((row) => row.gpu_ms > 0 && Number.isFinite(errorOf(row)));
  const svg = svgElement('svg', { viewBox: `0 0 ${WIDTH} ${HEIGHT}`, class: 'sweep', role: 'group', 'aria-label': `${axis.metric} of the ${axis.image} image against GPU time` });
  const xLabel = svgElement('text', { x: (MARGIN.left + WIDTH - MARGIN.right) / 2, y: HEIGHT - 8, 'text-anchor': 'middle', class: 'axis-label' }, 'GPU time per frame (ms, log scale)');
  const yLabel = svgElement('text', { x: 14, y: HEIGHT / 2, 'text-anchor': 'middle', class: 'axis-label', transform: `rotate(-90 14 ${HEIGHT / 2})` }, `${axis.metric} (${axis.image})`);
  svg.append(xLabel, yLabel);
  if (!points.length) return svg;

  const x = logScale(points.map((row) => row.gpu_ms), MARGIN.left, WIDTH - MARGIN.right);
  const errors = points.map(errorOf);
  const y = (errors.every((e) => e > 0) ? logScale : linearScale)(errors, HEIGHT - MARGIN.bottom, MARGIN.top);

  svg.append(svgElement('rect', { x: MARGIN.left, y: MARGIN.top, width: WIDTH - MARGIN.left - MARGIN.right, height: HEIGHT - MARGIN.top - MARGIN.bottom, class: 'plot-area' }));
  for (const [value, anchor] of [[Math.min(...points.map((r) => r.gpu_ms)), 'start'], [Math.max(...points.map((r) => r.gpu_ms)), 'end']])
    svg.append(svgElement('text', { x: x(value), y: HEIGHT - MARGIN.bottom + 16, 'text-anchor': anchor, class: 'tick' }, formatMs(value)));
  for (const value of [Math.min(...errors), Math.max(...errors)])
    svg.append(svgElement('text', { x: MARGIN.left - 4, y: y(value) + 4, 'text-anchor': 'end', class: 'tick' }, value.toPrecision(3)));

  const front = points.filter((row) => row.pareto).sort((a, b) => a.gpu_ms - b.gpu_ms);
  if (front.length > 1)
    svg.append(svgElement('polyline', { points: front.map((row) => `${x(row.gpu_ms)},${y(errorOf(row))}`).join(' '), class: 'front' }));

  for (const row of points) {
    const label = `${row.label}: ${formatMs(row.gpu_ms)} ms, ${axis.metric} ${errorOf(row).toPrecision(3)}` +
      (row.pareto ? ', on the Pareto front' : '') + '. Load these settings.';
    const point = svgElement('circle', {
      cx: x(row.gpu_ms), cy: y(errorOf(row)), r: 6, tabindex: 0, role: 'button', 'aria-label': label,
      class: row.pareto ? 'point pareto' : 'point',
    });
    point.append(svgElement('title', {}, label));
    point.addEventListener('click', () => onPick(row));
    point.addEventListener('keydown', (event) => {
      if (event.key !== 'Enter' && event.key !== ' ') return;
      event.preventDefault();
      onPick(row);
    });
    svg.append(point);
  }
  return svg;
}

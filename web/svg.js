// Small SVG builders for the charts: drawn here rather than with a library, so the page
// needs nothing but itself. Colours come from style.css through class names.

const NS = 'http://www.w3.org/2000/svg';

function svgElement(name, attributes = {}, text) {
  const element = document.createElementNS(NS, name);
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, String(value));
  if (text !== undefined) element.textContent = text;
  return element;
}

export function formatMs(ms) {
  return ms >= 100 ? ms.toFixed(0) : ms >= 10 ? ms.toFixed(1) : ms.toFixed(2);
}

// Horizontal bars, one group per row: rows = [{label, values: [{value, series}]}], where
// `series` names the CSS class of the bar (one per compared setting). Each bar has a
// <title> and its value written next to it, so the chart reads without hovering.
export function barChart(rows, { title, unit = 'ms', legend = [] }) {
  const labelWidth = 130;
  const valueWidth = 70;
  const width = 520;
  const barHeight = 16;
  const gap = 6;
  const seriesCount = Math.max(1, ...rows.map((row) => row.values.length));
  const groupHeight = seriesCount * barHeight + gap;
  const legendHeight = legend.length ? 22 : 0;
  const height = rows.length * groupHeight + legendHeight + gap;
  const max = Math.max(1e-9, ...rows.flatMap((row) => row.values.map((v) => v.value)));
  const scale = (width - labelWidth - valueWidth) / max;

  const svg = svgElement('svg', { viewBox: `0 0 ${width} ${height}`, role: 'img', 'aria-label': title, class: 'bars' });
  svg.append(svgElement('title', {}, title));
  legend.forEach(({ series, label }, i) => {
    svg.append(svgElement('rect', { x: labelWidth + i * 90, y: 4, width: 12, height: 12, class: series }));
    svg.append(svgElement('text', { x: labelWidth + i * 90 + 16, y: 14, class: 'legend' }, label));
  });
  rows.forEach((row, r) => {
    const top = legendHeight + r * groupHeight;
    svg.append(svgElement('text', { x: labelWidth - 6, y: top + (seriesCount * barHeight) / 2 + 4, class: 'label', 'text-anchor': 'end' }, row.label));
    row.values.forEach(({ value, series }, s) => {
      const y = top + s * barHeight;
      const bar = svgElement('rect', { x: labelWidth, y: y + 1, width: Math.max(1, value * scale), height: barHeight - 2, class: series });
      bar.append(svgElement('title', {}, `${row.label}: ${formatMs(value)} ${unit}`));
      svg.append(bar);
      svg.append(svgElement('text', { x: labelWidth + value * scale + 4, y: y + barHeight - 4, class: 'value' }, `${formatMs(value)} ${unit}`));
    });
  });
  return svg;
}

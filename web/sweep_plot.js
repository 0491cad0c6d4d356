// The sweep's plot is the server's own (api::to_svg_plot, the `plot` of the stream's done
// event, the same document as ?format=svg): the page draws none of its own, it only makes
// the plot's points buttons. Each marker (a circle, or a diamond for a path-traced row) names
// its row (data-row); clicking one (or Enter or Space on it) loads that row's configuration.

// svgText: the server's SVG; rows: the table's rows; onPick(row) loads a row; onHover(row)
// says what the row under the pointer or the focus is; chosenLabel: the label of the row a
// time budget chose (ringed, class "budget-choice"), or null.
export function sweepPlot(svgText, rows, onPick, onHover, chosenLabel = null) {
  const parsed = new DOMParser().parseFromString(svgText, 'image/svg+xml').documentElement;
  if (parsed.nodeName !== 'svg') throw new Error('the sweep plot is not an SVG document');
  const svg = document.importNode(parsed, true);
  // Its width and height are the server's; the page's CSS sizes it by its viewBox.
  svg.removeAttribute('width');
  svg.removeAttribute('height');
  svg.setAttribute('class', 'sweep');
  svg.setAttribute('role', 'group');
  for (const point of svg.querySelectorAll('[data-row]')) {
    const row = rows[Number(point.dataset.row)];
    if (!row) continue;
    // The tooltip's lines after the first (which is the row's label) say its time and error.
    const details = point.querySelector('title')?.textContent.split('\n').slice(1).join(', ') ?? '';
    point.setAttribute('tabindex', '0');
    point.setAttribute('role', 'button');
    const chosen = row.label === chosenLabel;
    point.classList.toggle('budget-choice', chosen);
    point.setAttribute('aria-label', `${row.label}: ${details}.${chosen ? ' The time budget chose it.' : ''} Load these settings.`);
    point.addEventListener('click', () => onPick(row));
    point.addEventListener('pointerenter', () => onHover(row));
    point.addEventListener('focus', () => onHover(row));
    point.addEventListener('keydown', (event) => {
      if (event.key !== 'Enter' && event.key !== ' ') return;
      event.preventDefault();
      onPick(row);
    });
  }
  return svg;
}

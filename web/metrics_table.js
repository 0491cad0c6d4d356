// The error metrics of a comparison (docs/accuracy.md "The metrics") as a table: one row
// per metric, one column for the final image and one for the indirect light alone.

const METRICS = [
  ['rmse', 'RMSE'],
  ['relative_mse', 'relative MSE'],
  ['psnr_db', 'PSNR (dB)'],
  ['ssim', 'SSIM'],
  ['mean_abs_error', 'mean |error|'],
  ['max_abs_error', 'max |error|'],
  ['mean_signed_error', 'mean signed error (bias)'],
  ['flip', 'FLIP (mean, as displayed)'],
  ['pixels', 'pixels compared'],
];

function format(value) {
  if (value === null || value === undefined) return '∞';  // PSNR of identical images
  if (Number.isInteger(value)) return String(value);
  return Math.abs(value) >= 100 ? value.toFixed(1) : value.toPrecision(4);
}

function cell(tag, text, scope) {
  const element = document.createElement(tag);
  element.textContent = text;
  if (scope) element.scope = scope;
  return element;
}

export function showMetrics(table, metrics, caption) {
  const head = document.createElement('thead');
  head.append(rowOf([cell('th', 'metric', 'col'), cell('th', 'final image', 'col'), cell('th', 'indirect light', 'col')]));
  const body = document.createElement('tbody');
  for (const [key, label] of METRICS)
    body.append(rowOf([cell('th', label, 'row'), cell('td', format(metrics.final[key])), cell('td', format(metrics.indirect[key]))]));
  table.replaceChildren(cell('caption', caption), head, body);
}

function rowOf(cells) {
  const row = document.createElement('tr');
  row.append(...cells);
  return row;
}

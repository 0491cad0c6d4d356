// A frame's cost and plan from its stats (docs/rendering.md "Stats", docs/planner.md):
// the device time of each pass as bars, the totals, which passes ran or were skipped and
// why, and what the planner changed from the request.

import { barChart, formatMs } from './svg.js';

// One row per pass that ran in any of `statsList` (A and B may run different passes), with
// a value per stats: its median device time, 0 where it did not run.
export function passTimeChart(statsList, { title, legend = [] }) {
  const names = [];
  for (const stats of statsList)
    for (const pass of stats.passes ?? []) if (pass.ran && !names.includes(pass.name)) names.push(pass.name);
  const rows = names.map((name) => ({
    label: name,
    values: statsList.map((stats, i) => {
      const pass = (stats.passes ?? []).find((p) => p.name === name && p.ran);
      return { value: pass ? pass.gpu_ms.median : 0, series: `series-${i}` };
    }),
  }));
  return barChart(rows, { title, legend });
}

function listItems(list, items) {
  list.replaceChildren(...items.map((item) => {
    const li = document.createElement('li');
    if (typeof item === 'string') li.textContent = item;
    else li.append(...item);
    return li;
  }));
}

function passItem(pass) {
  const name = document.createElement('strong');
  name.textContent = pass.name;
  const state = document.createElement('span');
  // A dry run's passes are planned but none ran: no time to show.
  const [className, text] = pass.ran ? ['ran', ` ran, ${formatMs(pass.gpu_ms.median)} ms`]
    : pass.planned ? ['planned', ' planned (dry run)'] : ['skipped', ' skipped'];
  state.className = className;
  state.textContent = text;
  const parts = [name, state];
  if (pass.reason) parts.push(`: ${pass.reason}`);
  return parts;
}

export function showStats(stats, queueMs, elements) {
  elements.chart.replaceChildren(passTimeChart([stats], { title: 'GPU time per pass (median, ms)' }));
  const totals = [
    ['GPU, all passes', `${formatMs(stats.gpu_ms.median)} ms`],
    ['one frame, wall', `${formatMs(stats.wall_ms.median)} ms`],
    ['waited in the queue', `${formatMs(queueMs)} ms`],
    ['frames timed', String(stats.frames)],
  ];
  elements.totals.replaceChildren(...totals.flatMap(([term, value]) => {
    const dt = document.createElement('dt');
    dt.textContent = term;
    const dd = document.createElement('dd');
    dd.textContent = value;
    return [dt, dd];
  }));
  listItems(elements.passes, stats.passes.map(passItem));
  const decisions = stats.plan?.decisions ?? [];
  listItems(elements.decisions, decisions.length ? decisions : [`none: plan "${stats.plan?.mode ?? 'auto'}" ran the request as given`]);
  listItems(elements.warnings, stats.warnings ?? []);
  elements.warningsBlock.hidden = !(stats.warnings ?? []).length;
}

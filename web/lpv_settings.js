// A sweep row's or a budget's LPV settings (api::SweepSettings as JSON: lpv, grid,
// iterations, cascades, rsm, vpl_downsample, bounces, occlusion, transfer, blocking,
// line_blocking) as the request's `lpv` fields: what loading a sweep row sets, and what a
// budget's frame ran with. A table written before line_blocking has none: the field is left
// as it is.
export function lpvFieldsOf(settings) {
  if (!settings.lpv) return { enabled: false };
  const cubic = settings.grid.every((cells) => cells === settings.grid[0]);
  const fields = { enabled: true, grid: cubic ? settings.grid[0] : settings.grid };
  for (const name of ['iterations', 'cascades', 'rsm', 'vpl_downsample', 'bounces', 'occlusion', 'transfer', 'blocking', 'line_blocking'])
    if (settings[name] !== undefined) fields[name] = settings[name];
  return fields;
}

// The request a frame rendered: with budget_ms, the budget's chosen settings in place of the
// budget (the stats' budget.chosen); else the request itself.
export function requestThatRan(request, stats) {
  const chosen = stats?.budget?.chosen;
  if (!chosen || request.budget_ms === undefined) return request;
  const ran = JSON.parse(JSON.stringify(request));
  delete ran.budget_ms;
  ran.lpv = { ...(ran.lpv ?? {}), ...lpvFieldsOf(chosen.settings) };
  return ran;
}

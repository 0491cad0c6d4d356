// The whole state of the page lives in the URL's fragment, so a link reproduces the view:
// #request=<the render request as JSON (B)>&a=<the pinned A, when there is one>&view=<the
// canvas: source, pair, difference, zoom, pan, rectangle, display, reference>. The fragment
// never reaches the server, and replaceState keeps the history free of every slider step.

export function readUrlState(hash = location.hash) {
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  return { request: parseJson(params.get('request'), 'request'), a: parseJson(params.get('a'), 'a'),
           view: parseJson(params.get('view'), 'view') };
}

function parseJson(text, name) {
  if (text === null || text === '') return undefined;
  try {
    const value = JSON.parse(text);
    if (value !== null && typeof value === 'object' && !Array.isArray(value)) return value;
  } catch {
    // reported below
  }
  throw new Error(`the link's "${name}" is not a JSON object; starting from the defaults`);
}

export function urlStateHash({ request, a, view }) {
  const params = new URLSearchParams();
  params.set('request', JSON.stringify(request));
  if (a) params.set('a', JSON.stringify(a));
  if (view) params.set('view', JSON.stringify(view));
  return '#' + params.toString();
}

export function writeUrlState(state) {
  const hash = urlStateHash(state);
  if (hash !== location.hash) history.replaceState(null, '', hash);
}

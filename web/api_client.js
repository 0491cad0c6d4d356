// Calls to lpv-server's API (api/openapi.yaml) from the page. Every failure becomes an
// ApiError carrying the server's {"error": {"code", "message", "field"}}, so the page can
// show the message next to the control that `field` names.

import { decodePfm } from './pfm.js';

const TOKEN_KEY = 'lpv-server-token';

export class ApiError extends Error {
  constructor(status, { code = 'http_error', message = `HTTP ${status}`, field = '' } = {}) {
    super(message);
    this.status = status;
    this.code = code;
    this.field = field;
  }
}

// The server's token (--token), when it has one: kept for this tab only, never in the URL.
export function token() {
  return sessionStorage.getItem(TOKEN_KEY) ?? '';
}

export function setToken(value) {
  if (value) sessionStorage.setItem(TOKEN_KEY, value);
  else sessionStorage.removeItem(TOKEN_KEY);
}

async function call(path, { method = 'GET', body, contentType = 'application/json', accept = 'application/json', signal } = {}) {
  const headers = { Accept: accept };
  if (body !== undefined) headers['Content-Type'] = contentType;
  if (token()) headers.Authorization = `Bearer ${token()}`;
  const response = await fetch(path, {
    method,
    headers,
    body: body === undefined || body instanceof Blob ? body : JSON.stringify(body),
    signal,
  });
  if (!response.ok) throw await errorOf(response);
  return response;
}

async function errorOf(response) {
  try {
    const body = await response.json();
    if (body?.error) return new ApiError(response.status, body.error);
  } catch {
    // not JSON: a proxy or a broken connection; the status says enough
  }
  return new ApiError(response.status);
}

export async function listScenes() {
  return (await (await call('/v1/scenes')).json()).scenes;
}

export async function device() {
  return (await call('/v1/device')).json();
}

export async function uploadScene(file) {
  const name = file.name.replace(/\.(glb|gltf)$/i, '');
  const response = await call(`/v1/scenes?name=${encodeURIComponent(name)}`, {
    method: 'POST', body: file, contentType: 'application/octet-stream',
  });
  return response.json();
}

// The frame as a linear PFM (pfm.js) with its stats from the X-Render-Stats header: the page
// shows it through its own exposure and tone map, and reads exact values from it. The header
// leaves out the LPV flux statistics when they are long; the page shows none of them.
export async function render(request, signal) {
  const body = { ...request, output: { ...request.output, format: 'pfm' } };
  const response = await call('/v1/render', { method: 'POST', body, accept: 'application/x-pfm', signal });
  if (response.headers.get('Content-Type')?.startsWith('application/json')) {  // a dry run: the plan, no image
    const { stats, queue_ms: queueMs } = await response.json();
    return { stats, queueMs, image: null };
  }
  const queue = /(?:^|,)\s*queue;dur=([\d.]+)/.exec(response.headers.get('Server-Timing') ?? '');
  return {
    stats: JSON.parse(response.headers.get('X-Render-Stats')),
    queueMs: queue ? Number(queue[1]) : 0,
    image: decodePfm(await response.arrayBuffer()),
  };
}

export async function compare(body, signal) {
  return (await call('/v1/compare', { method: 'POST', body, signal })).json();
}

// Streams the sweep's NDJSON events (reference_progress, reference, row, done or error) to
// `onEvent` as they arrive; resolves after the last one.
export async function sweep(body, signal, onEvent) {
  const response = await call('/v1/sweep?format=ndjson', { method: 'POST', body, accept: 'application/x-ndjson', signal });
  const reader = response.body.pipeThrough(new TextDecoderStream()).getReader();
  let pending = '';
  for (;;) {
    const { value, done } = await reader.read();
    if (done) break;
    pending += value;
    const lines = pending.split('\n');
    pending = lines.pop();
    for (const line of lines) if (line.trim()) onEvent(JSON.parse(line));
  }
  if (pending.trim()) onEvent(JSON.parse(pending));
}

// Dredd's hooks for lpv-server's contract (tests/web/dredd_contract.mjs). Dredd 14 makes one
// transaction for each documented response of an operation, all from the operation's first
// request example, and a server answers one request one way: so each transaction's request is
// turned here into one that a token-less server answers with the documented status, and what
// one such server on one machine cannot show is skipped, each with its reason below.
const hooks = require('hooks');
const { readFileSync } = require('node:fs');

const server = process.env.LPV_CONTRACT_URL;
// The contract's own upload example (a triangle as .gltf), which dredd_contract.mjs reads out.
const scene = process.env.LPV_CONTRACT_SCENE;
// The JSON responses' schemas, by "METHOD /path/{template} STATUS media/type".
const schemas = JSON.parse(readFileSync(process.env.LPV_CONTRACT_SCHEMAS, 'utf8'));

// Statuses no request to one token-less server provokes on its own, and where they are tested.
const unprovokable = {
  401: 'needs a server with --token (server_http: Access.*)',
  503: 'needs a full render queue or a device still starting (server_load)',
  504: 'needs a deadline that the work misses, which depends on the device (server_load)',
  507: 'needs a full scene store (server_http: HttpScenes.*)',
};

const text = JSON.stringify;
// Bodies each route refuses, by status, after reading them.
const bodies = {
  400: {
    '/v1/render': text({ output: { width: -5 } }),
    '/v1/compare': text({ base: {}, against: {}, reference: { samples: 1 } }),
    '/v1/sweep': text({ base: {}, parameters: { grid: [8, 0] } }),
    '/v1/bench': text({ suite: 'tiny', version: 1, cases: [{ name: 'x', request: { output: { width: 0 } } }] }),
  },
  404: {
    '/v1/render': text({ scene: 'atlantis' }),
    '/v1/compare': text({ base: { scene: 'atlantis' }, reference: { samples: 1 } }),
    '/v1/sweep': text({ base: { scene: 'atlantis' }, parameters: { grid: [4] }, reference: { samples: 1 } }),
    '/v1/bench': text({ suite: 'tiny', version: 1, cases: [{ name: 'x', request: { scene: 'atlantis' } }] }),
  },
  422: {
    '/v1/render': text({ lpv: { iterations: 500 } }),
    '/v1/compare': text({ base: { output: { width: 4096, height: 4096 } }, reference: { samples: 4096 } }),
    '/v1/sweep': text({ base: { output: { width: 4096, height: 4096 } }, parameters: { grid: [4] }, reference: { samples: 4096 } }),
    '/v1/bench': text({ suite: 'tiny', version: 1, repetitions: 1000, cases: [{ name: 'x', request: {} }] }),
  },
};
const unknownId = '0'.repeat(64);

// Where the request goes: Dredd sends to fullPath, and reports uri.
function setPath(transaction, uri) {
  transaction.request.uri = uri;
  transaction.fullPath = uri;
}

function setHeader(request, name, value) {
  for (const key of Object.keys(request.headers)) if (key.toLowerCase() === name.toLowerCase()) delete request.headers[key];
  if (value !== undefined) request.headers[name] = value;
}

// A scene no earlier transaction uploaded: the example's glTF with a field of its own.
let uploads = 0;
function freshScene(body) {
  const gltf = JSON.parse(body);
  gltf.asset = { ...gltf.asset, extras: { contract_upload: ++uploads, at: Date.now() } };
  return JSON.stringify(gltf);
}

async function upload(body) {
  const r = await fetch(`${server}/v1/scenes`, { method: 'POST', headers: { 'Content-Type': 'model/gltf+json' }, body });
  return (await r.json()).id;
}

async function prepare(transaction) {
  const status = Number(transaction.expected.statusCode);
  const request = transaction.request;
  const path = request.uri.split('?')[0];
  const method = request.method;
  const type = transaction.expected.headers?.['Content-Type'];
  // A JSON body is held to its schema, not to its example's keys (dredd_contract.mjs).
  const schema = schemas[`${method} ${transaction.origin.resourceName} ${status} ${type}`];
  if (schema) {
    transaction.expected.bodySchema = schema;
    delete transaction.expected.body;
  }
  // Present only when X-Render-Stats was shortened.
  delete transaction.expected.headers?.['X-Render-Stats-Omitted'];

  if (path === '/v1/render' && status === 200) {
    // Each documented media type, asked for by its format (Accept for JSON), on a small frame.
    const format = { 'image/png': 'png', 'image/x-exr': 'exr', 'application/x-pfm': 'pfm' }[type];
    request.body = text({ output: { width: 32, height: 32, ...(format ? { format } : {}) } });
    setHeader(request, 'Accept', type);
    // The JSON answer carries the stats in its body, not in a header.
    if (!format) delete transaction.expected.headers['X-Render-Stats'];
  } else if (path === '/v1/sweep' && status === 200) {
    const format = { 'application/json': 'json', 'text/csv': 'csv', 'image/svg+xml': 'svg', 'application/x-ndjson': 'ndjson' }[type];
    setPath(transaction, `/v1/sweep?format=${format}`);
  } else if (transaction.origin.resourceName === '/{asset}' && status === 200) {
    setPath(transaction, { 'text/css; charset=utf-8': '/style.css', 'image/svg+xml': '/favicon.svg' }[type] ?? '/app.js');
  } else if (path === '/v1/scenes' && method === 'POST') {
    // Both request media types' transactions send the example's glTF.
    setHeader(request, 'Content-Type', 'model/gltf+json');
    request.body = status === 201 ? freshScene(scene) : scene;
    if (status === 200) await upload(scene);  // the same bytes again: 200
    if (status === 400) setPath(transaction, '/v1/scenes?name=' + 'n'.repeat(300));
    if (status === 422) request.body = '{"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4, "uri": "triangle.bin"}]}';
  } else if (path.startsWith('/v1/scenes/') && method === 'DELETE') {
    if (status === 204) setPath(transaction, `/v1/scenes/${await upload(freshScene(scene))}`);
    if (status === 404) setPath(transaction, `/v1/scenes/${unknownId}`);
  } else if (path.startsWith('/v1/scenes/') && method === 'GET' && status === 404) {
    setPath(transaction, '/v1/scenes/atlantis');
  } else if (bodies[status]?.[path]) {
    request.body = bodies[status][path];
  } else if (status === 304) {
    const etag = (await fetch(`${server}${request.uri}`)).headers.get('ETag');
    setHeader(request, 'If-None-Match', etag);
  } else if (status === 404) {
    setPath(transaction, method === 'GET' ? '/no-such-file.js' : '/v1/no-such-route');
  }
  switch (status) {
    case 403: setHeader(request, 'Origin', 'http://evil.example'); break;
    case 405: request.method = 'PUT'; break;  // no route takes PUT
    case 413: request.body = ' '.repeat(300 * 1024); break;  // over --max-body-bytes and --max-scene-bytes
    case 415: setHeader(request, 'Content-Type', 'text/plain'); break;
    case 421: setHeader(request, 'Host', 'evil.example:8080'); break;
  }
}

hooks.beforeEach((transaction, done) => {
  const status = Number(transaction.expected.statusCode);
  if (unprovokable[status]) {
    transaction.skip = true;
    hooks.log(`skipped ${transaction.name}: ${unprovokable[status]}`);
    return done();
  }
  prepare(transaction).then(() => done(), (error) => {
    transaction.fail = `the hook could not prepare the request: ${error.message}`;
    done();
  });
});

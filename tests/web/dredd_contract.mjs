// api/openapi.yaml against the live lpv-server with an independent contract tester, Dredd 14
// (from package-lock.json here), run by CTest as `contract_dredd`. Every documented response
// of every operation is one transaction: dredd_hooks.cjs turns each request into one that
// this server answers with the documented status, or skips it with the reason (what one
// token-less server cannot show). The server's own contract test (server_http:
// HttpContract.*) sends the examples; this one checks status, headers and bodies as a
// client's tooling reads the file.
//   LPV_SERVER_BINARY  the lpv-server to start (required)
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { createInterface } from 'node:readline';
import { fileURLToPath } from 'node:url';
import SwaggerParser from '@apidevtools/swagger-parser';
import YAML from 'yaml';

const here = dirname(fileURLToPath(import.meta.url));
const [openapiFile = join(here, '../../api/openapi.yaml')] = process.argv.slice(2);
const binary = process.env.LPV_SERVER_BINARY;
if (!binary) {
  console.error('contract_dredd: LPV_SERVER_BINARY must name the lpv-server binary');
  process.exit(1);
}

// Dredd 14 reads a parameter's `example`, not its named `examples`, and stops at a path
// parameter without one: each parameter gets its first named example as `example`.
const contract = YAML.parse(readFileSync(openapiFile, 'utf8'));
for (const operations of Object.values(contract.paths))
  for (const operation of Object.values(operations))
    for (const parameter of operation.parameters ?? [])
      if (parameter.examples && parameter.example === undefined) {
        parameter.example = Object.values(parameter.examples)[0].value;
        delete parameter.examples;
      }
const scene = contract.paths['/v1/scenes'].post.requestBody.content['model/gltf+json'].examples.triangle.value;
const work = mkdtempSync(join(tmpdir(), 'lpv-contract-'));
const readable = join(work, 'openapi.yaml');
writeFileSync(readable, YAML.stringify(contract));

// Dredd 14 holds a JSON body to the response's example, key by key and array element by
// element, and not to its schema: every documented JSON response's schema, its references
// resolved and OpenAPI's `nullable` written as JSON Schema's null type, for the hooks to
// check the body against instead ("METHOD /path/{template} STATUS media/type" -> schema).
function jsonSchema(node) {
  if (Array.isArray(node)) return node.map(jsonSchema);
  if (node === null || typeof node !== 'object') return node;
  const out = {};
  for (const [key, value] of Object.entries(node)) if (key !== 'nullable' && key !== 'example') out[key] = jsonSchema(value);
  if (node.nullable) {
    if (out.type) out.type = [out.type, 'null'];
    else return { anyOf: [out, { type: 'null' }] };
  }
  return out;
}
const resolved = await SwaggerParser.dereference(JSON.parse(JSON.stringify(contract)));
const schemas = {};
for (const [path, operations] of Object.entries(resolved.paths))
  for (const [method, operation] of Object.entries(operations))
    for (const [status, response] of Object.entries(operation.responses ?? {}))
      for (const [type, media] of Object.entries(response.content ?? {}))
        if (type.startsWith('application/json') && media.schema)
          schemas[`${method.toUpperCase()} ${path} ${status} ${type}`] = jsonSchema(media.schema);
const schemaFile = join(work, 'schemas.json');
writeFileSync(schemaFile, JSON.stringify(schemas));

// The server, on a free port; --max-scene-bytes low so that an upload's 413 is cheap to send.
const server = spawn(binary, ['--port', '0', '--max-scene-bytes', '65536'], { stdio: ['ignore', 'pipe', 'inherit'] });
const firstLine = await new Promise((resolve, reject) => {
  createInterface({ input: server.stdout }).once('line', resolve);
  server.once('exit', (code) => reject(new Error(`lpv-server exited with ${code} before listening`)));
});
server.stdout.resume();
const url = firstLine.match(/listening on (http:\/\/\S+)/)?.[1];
let ready = false;
for (const deadline = Date.now() + 120_000; !ready && Date.now() < deadline; await new Promise((r) => setTimeout(r, 200)))
  ready = await fetch(`${url}/readyz`).then((r) => r.ok, () => false);
if (!ready) {
  console.error('contract_dredd: lpv-server was not ready within 120 s');
  server.kill('SIGKILL');
  process.exit(1);
}

const dredd = spawn(process.execPath, [join(here, 'node_modules/dredd/bin/dredd'), readable, url,
  `--hookfiles=${join(here, 'dredd_hooks.cjs')}`, '--loglevel=warning', '--color=false'], {
  stdio: 'inherit',
  env: { ...process.env, LPV_CONTRACT_URL: url, LPV_CONTRACT_SCENE: JSON.stringify(scene), LPV_CONTRACT_SCHEMAS: schemaFile },
});
const code = await new Promise((resolve) => dredd.once('exit', (c) => resolve(c ?? 1)));
server.kill('SIGTERM');
process.exit(code);

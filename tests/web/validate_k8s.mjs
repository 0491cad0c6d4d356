// The Kubernetes manifests of docker/k8s/ against the Kubernetes API's own JSON schemas
// (kubernetes-models, from tests/web/package-lock.json): every document of every file must
// be an object the API would accept, of a kind the deployment needs, and the pieces must fit
// together (the probes reach the health port, the grace period exceeds the drain, the claim
// is ReadWriteMany, the token comes from the secret). Exits 1 naming each problem.
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { parseAllDocuments } from 'yaml';
import { Deployment } from 'kubernetes-models/apps/v1/Deployment';
import { HorizontalPodAutoscaler } from 'kubernetes-models/autoscaling/v2/HorizontalPodAutoscaler';
import { PersistentVolumeClaim } from 'kubernetes-models/v1/PersistentVolumeClaim';
import { Secret } from 'kubernetes-models/v1/Secret';
import { Service } from 'kubernetes-models/v1/Service';

const kinds = { Deployment, HorizontalPodAutoscaler, PersistentVolumeClaim, Secret, Service };
const dir = process.argv[2];
const problems = [];
const objects = [];
for (const file of readdirSync(dir).filter((f) => f.endsWith('.yaml')).sort()) {
  for (const doc of parseAllDocuments(readFileSync(join(dir, file), 'utf8'))) {
    if (doc.errors.length) { problems.push(`${file}: ${doc.errors[0].message}`); continue; }
    const object = doc.toJS();
    const Model = kinds[object?.kind];
    if (!Model) { problems.push(`${file}: kind ${object?.kind} is not one the deployment uses`); continue; }
    try {
      new Model(object).validate();
      objects.push({ file, object });
    } catch (e) {
      problems.push(`${file}: ${e.message}`);
    }
  }
}

const of = (kind) => objects.filter((o) => o.object.kind === kind);
// A flag's value in a container's args, or `fallback` (the server's default) when absent.
const flag = (args, name, fallback) => (args.includes(name) ? Number(args[args.indexOf(name) + 1]) : fallback);
for (const { file, object } of of('Deployment')) {
  const pod = object.spec.template.spec;
  const c = pod.containers[0];
  const healthPort = flag(c.args, '--health-port', -1);
  const probesPort = c.ports.find((p) => p.name === 'probes')?.containerPort;
  if (!(healthPort > 0) || healthPort !== probesPort) problems.push(`${file}: the probes port is not --health-port`);
  for (const probe of ['readinessProbe', 'livenessProbe'])
    if (c[probe]?.httpGet?.port !== 'probes') problems.push(`${file}: ${probe} does not use the probes port`);
  if (!(pod.terminationGracePeriodSeconds * 1000 > flag(c.args, '--drain-ms', 10000) + 2000))
    problems.push(`${file}: terminationGracePeriodSeconds does not exceed --drain-ms by 2 s`);
  if (!c.env.some((e) => e.name === 'LPV_SERVER_TOKEN' && e.valueFrom?.secretKeyRef?.name === 'lpv-server-token'))
    problems.push(`${file}: LPV_SERVER_TOKEN does not come from the secret`);
  if (!pod.securityContext?.runAsNonRoot) problems.push(`${file}: runs as root`);
  if (!c.resources?.limits?.memory || !c.resources?.requests?.cpu) problems.push(`${file}: no resources`);
}
if (!of('Deployment').some((d) => d.object.spec.template.spec.containers[0].resources.limits['nvidia.com/gpu']))
  problems.push('no GPU variant requests nvidia.com/gpu');
for (const { file, object } of of('PersistentVolumeClaim'))
  if (!object.spec.accessModes.includes('ReadWriteMany')) problems.push(`${file}: the scene store is not ReadWriteMany`);
for (const kind of ['Service', 'HorizontalPodAutoscaler', 'PersistentVolumeClaim', 'Secret'])
  if (!of(kind).length) problems.push(`no ${kind}`);

if (problems.length) {
  for (const p of problems) console.error(`k8s_manifests: ${p}`);
  process.exit(1);
}
console.log(`k8s_manifests: ${objects.length} objects valid (${objects.map((o) => o.object.kind).join(', ')})`);

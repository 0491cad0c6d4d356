// The render request the page explores: exactly the JSON body of POST /v1/render. It holds
// only what differs from the API's defaults, so links and curl commands stay short. Controls
// read values through `get`, which falls back to the defaults below and to the scene's own
// camera and lights (GET /v1/scenes). DEFAULTS copies the request parser's defaults
// (api/request_json.cpp, documented in api/openapi.yaml); a value equal to its copy is left
// out of the request, so the two must agree (tests/api/test_web_defaults.cpp reads this
// object and checks it against the parser).

const DEFAULTS = {
  scene: 'cornell-box',
  output: { width: 512, height: 512, view: 'final', exposure: 0, tonemap: 'none' },
  shadows: { enabled: true },
  lpv: {
    enabled: true, grid: 16, cascades: 1, iterations: 32, rsm: 256, vpl_downsample: 1,
    occlusion: true, occlusion_sources: ['scene'], blocking: 'projected', bounces: 1, injection: 'trilinear', injection_offset: 0.5,
    transfer: 'auto', far_lines: 'per_block', line_blocking: 'located', intensity: 1, convergence: 0.001,
  },
  plan: 'auto',
  plan_keep: [],
  repeat: 1,
};

// Fields whose default comes from the scene; once changed, the request carries all of it.
const SCENE_FIELDS = ['camera', 'lights'];

// "lights[0].position" -> ["lights", 0, "position"]
function parsePath(path) {
  return path.split(/\.|(?=\[)/).map((part) => (part.startsWith('[') ? Number(part.slice(1, -1)) : part));
}

function lookup(object, keys) {
  let value = object;
  for (const key of keys) {
    if (value === undefined || value === null) return undefined;
    value = value[key];
  }
  return value;
}

export function clone(value) {
  return value === undefined ? undefined : JSON.parse(JSON.stringify(value));
}

export function deepEqual(a, b) {
  return JSON.stringify(a) === JSON.stringify(b);
}

function isObject(value) {
  return value !== null && typeof value === 'object' && !Array.isArray(value);
}

// Removes objects left empty by deleting their last field.
function prune(object, keys) {
  for (let depth = keys.length - 1; depth > 0; depth--) {
    const parent = lookup(object, keys.slice(0, depth - 1));
    const key = keys[depth - 1];
    if (isObject(parent?.[key]) && Object.keys(parent[key]).length === 0) delete parent[key];
  }
}

// The RFC 7386 merge patch that turns `from` into `to`: what POST /v1/compare's "against"
// takes (null removes a field; arrays are replaced whole).
export function mergePatch(from, to) {
  const patch = {};
  for (const key of Object.keys(from)) if (!(key in to)) patch[key] = null;
  for (const [key, value] of Object.entries(to)) {
    if (deepEqual(from[key], value)) continue;
    patch[key] = isObject(from[key]) && isObject(value) ? mergePatch(from[key], value) : clone(value);
  }
  return patch;
}

// Each changed leaf of a merge patch as "path: old → new", for people.
export function describeChanges(from, to, prefix = '') {
  const lines = [];
  for (const [key, value] of Object.entries(mergePatch(from, to))) {
    const path = prefix + key;
    const text = (v) => (v === undefined || v === null ? 'default' : JSON.stringify(v));
    if (isObject(value) && isObject(to[key])) lines.push(...describeChanges(from[key] ?? {}, to[key], path + '.'));
    else lines.push(`${path}: ${text(from[key])} → ${text(to[key])}`);
  }
  return lines;
}

export class RequestState extends EventTarget {
  #request = {};
  #scene = null;  // the scene's report from GET /v1/scenes, once known

  get request() {
    return clone(this.#request);
  }

  // The scene's report supplies the defaults of its camera and lights.
  setSceneReport(report) {
    this.#scene = report;
    this.#changed('scene-report');
  }

  sceneReport() {
    return this.#scene;
  }

  defaultOf(path) {
    const keys = parsePath(path);
    if (SCENE_FIELDS.includes(keys[0])) return clone(lookup(this.#scene, keys));
    return clone(lookup(DEFAULTS, keys));
  }

  get(path) {
    const value = lookup(this.#request, parsePath(path));
    return value === undefined ? this.defaultOf(path) : clone(value);
  }

  set(path, value) {
    if (path === 'scene') return this.setScene(value);
    this.#assign(path, value);
    this.#changed(path);
  }

  // Several fields at once, as one change (one frame, not one per field).
  setAll(values) {
    for (const [path, value] of Object.entries(values)) this.#assign(path, value);
    this.#changed('*');
  }

  #assign(path, value) {
    const keys = parsePath(path);
    if (SCENE_FIELDS.includes(keys[0]) && this.#request[keys[0]] === undefined) {
      const sceneValue = this.defaultOf(keys[0]);
      if (sceneValue === undefined) return;  // the scene is not known yet: nothing to edit
      this.#request[keys[0]] = sceneValue;
    }
    let parent = this.#request;
    for (let i = 0; i < keys.length - 1; i++) {
      if (parent[keys[i]] === undefined) parent[keys[i]] = typeof keys[i + 1] === 'number' ? [] : {};
      parent = parent[keys[i]];
    }
    const last = keys[keys.length - 1];
    const isStaticDefault = !SCENE_FIELDS.includes(keys[0]) && deepEqual(value, lookup(DEFAULTS, keys));
    if (value === undefined || isStaticDefault) {
      delete parent[last];
      prune(this.#request, keys);
    } else {
      parent[last] = clone(value);
    }
  }

  remove(path) {
    this.set(path, undefined);
  }

  // A new scene keeps the settings but not the old scene's camera and lights.
  setScene(id) {
    const settings = this.request;
    delete settings.camera;
    delete settings.lights;
    delete settings.light_edits;
    settings.scene = id;
    this.replace(settings);
  }

  replace(request) {
    this.#request = isObject(request) ? clone(request) : {};
    if (this.#request.scene === DEFAULTS.scene) delete this.#request.scene;
    this.#changed('*');
  }

  #changed(path) {
    this.dispatchEvent(new CustomEvent('change', { detail: { path } }));
  }
}

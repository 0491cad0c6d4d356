// Two-way binding between inputs and the request: every element with data-field="path"
// edits that field of the request, read according to data-kind:
//   int, number  a number; what the user typed goes to the server as typed (out of range
//                too: the server's message then says why), an empty box changes nothing
//   count        a <select>'s value: a number, or a word the field also takes ("bounces": "all")
//   bool         a checkbox
//   enum         a <select>'s value as text
//   vec3         one component (data-index) of a 3-vector; a scalar field ("grid": 32)
//                becomes [32, 32, 32] when one component changes
//   set          a checkbox adding or removing data-value in an array of names
//   color        an <input type="color"> as linear [r, g, b] in 0..1
// data-optional: emptying the input removes the field (the server then fits it).

function toHex(rgb) {
  return '#' + rgb.map((c) => Math.round(Math.min(Math.max(c, 0), 1) * 255).toString(16).padStart(2, '0')).join('');
}

function fromHex(hex) {
  return [1, 3, 5].map((i) => Number((parseInt(hex.slice(i, i + 2), 16) / 255).toFixed(3)));
}

// A number as a person would write it: values from the server (a scene's lights and camera)
// are 32-bit floats widened to doubles, 3.0000001 or 1.899999976158142; to a float's 7
// significant digits they read 3 and 1.9 again.
function shown(value) {
  return typeof value === 'number' ? String(Number(value.toPrecision(7))) : String(value);
}

function asVec3(value) {
  return Array.isArray(value) ? value : [value, value, value];
}

// What the input says the field should become; undefined: leave the request as it is.
function readInput(input, state) {
  const field = input.dataset.field;
  const optional = 'optional' in input.dataset;
  switch (input.dataset.kind) {
    case 'bool':
      return input.checked;
    case 'enum':
      return input.value;
    case 'count':
      return Number.isNaN(Number(input.value)) ? input.value : Number(input.value);
    case 'color':
      return fromHex(input.value);
    case 'set': {
      const names = (state.get(field) ?? []).filter((name) => name !== input.dataset.value);
      return input.checked ? [...names, input.dataset.value] : names;
    }
    case 'vec3': {
      const group = [...input.closest('.control').querySelectorAll(`[data-field="${CSS.escape(field)}"][data-kind="vec3"]`)];
      if (optional && group.every((box) => box.value === '')) return null;
      if (group.some((box) => box.value === '')) return undefined;
      const vector = asVec3(state.get(field) ?? [0, 0, 0]).slice();
      vector[Number(input.dataset.index)] = Number(input.value);
      return vector;
    }
    default:  // int, number
      if (input.value === '') return optional ? null : undefined;
      return Number(input.value);
  }
}

function showValue(input, value) {
  switch (input.dataset.kind) {
    case 'bool':
      input.checked = Boolean(value);
      return;
    case 'set':
      input.checked = (value ?? []).includes(input.dataset.value);
      return;
    case 'color':
      input.value = toHex(value ?? [1, 1, 1]);
      return;
    case 'vec3':
      input.value = value === undefined || value === null ? '' : shown(asVec3(value)[Number(input.dataset.index)]);
      return;
    default:
      input.value = value === undefined || value === null ? '' : shown(Array.isArray(value) ? value[0] : value);
  }
}

// Shows the request's values in every bound input of `root`, except the one being typed in
// (rewriting it would move the caret or undo a half-typed number).
export function refreshInputs(root, state) {
  for (const input of root.querySelectorAll('[data-field][data-kind]')) {
    if (input === document.activeElement && input.type !== 'range' && input.type !== 'checkbox') continue;
    showValue(input, state.get(input.dataset.field));
  }
}

export function bindInputs(root, state) {
  root.addEventListener('input', (event) => {
    const input = event.target.closest('[data-field][data-kind]');
    if (!input || !root.contains(input)) return;
    const value = readInput(input, state);
    if (value === null) state.remove(input.dataset.field);
    else if (value !== undefined) state.set(input.dataset.field, value);
  });
  state.addEventListener('change', () => refreshInputs(root, state));
  refreshInputs(root, state);
}

// The lights: the scene's own until one is edited, then the request's "lights" (which
// replaces the scene's). Each light gets inputs bound to "lights[i].<field>", so the server's
// errors for a light land next to its field. The list is rebuilt only when lights are
// added, removed or change type; values are refreshed in place (form_binding.js).

import { refreshInputs } from './form_binding.js';

const UNITS = { directional: 'W/m²', point: 'W/sr', spot: 'W/sr' };

let inputCount = 0;  // ids for the labels' `for`

function control(labelText, ...inputs) {
  const block = document.createElement('div');
  block.className = inputs.length === 3 ? 'control vec3' : 'control';
  const label = document.createElement(inputs.length === 1 ? 'label' : 'span');
  label.className = 'label';
  label.textContent = labelText;
  if (inputs.length === 1) {
    inputs[0].id ||= `light-input-${++inputCount}`;
    label.htmlFor = inputs[0].id;
  }
  block.append(label, ...inputs);
  return block;
}

function input(field, kind, attributes = {}) {
  const element = document.createElement(kind === 'enum' ? 'select' : 'input');
  element.dataset.field = field;
  element.dataset.kind = kind;
  if (kind === 'color') element.type = 'color';
  else if (kind !== 'enum') element.type = 'number';
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, value);
  return element;
}

function vector(field, what, step = '0.1') {
  return [0, 1, 2].map((i) => input(field, 'vec3', { 'data-index': i, step, 'aria-label': `${what} ${'xyz'[i]}` }));
}

function lightBlock(light, i, onRemove) {
  const base = `lights[${i}]`;
  const fieldset = document.createElement('fieldset');
  fieldset.className = 'light';
  const legend = document.createElement('legend');
  legend.textContent = `Light ${i + 1}`;
  const type = input(`${base}.type`, 'enum');
  type.append(...['spot', 'point', 'directional'].map((t) => new Option(t, t)));
  fieldset.append(legend, control('Type', type));
  if (light.type !== 'directional') fieldset.append(control('Position', ...vector(`${base}.position`, `Light ${i + 1} position`)));
  if (light.type !== 'point') fieldset.append(control('Direction (travel)', ...vector(`${base}.direction`, `Light ${i + 1} direction`)));
  fieldset.append(
    control('Colour', input(`${base}.color`, 'color')),
    control(`Intensity (${UNITS[light.type] ?? ''})`, input(`${base}.intensity`, 'number', { min: 0, step: 0.5 })),
  );
  if (light.type !== 'directional') fieldset.append(control('Range (m, 0: unlimited)', input(`${base}.range`, 'number', { min: 0, step: 0.1 })));
  if (light.type === 'spot') {
    fieldset.append(
      control('Inner cone (°)', input(`${base}.inner_cone_deg`, 'number', { min: 0, max: 90, step: 1 })),
      control('Outer cone (°)', input(`${base}.outer_cone_deg`, 'number', { min: 0, max: 90, step: 1 })),
    );
  }
  const remove = document.createElement('button');
  remove.type = 'button';
  remove.textContent = `Remove light ${i + 1}`;
  remove.addEventListener('click', () => onRemove(i));
  fieldset.append(remove);
  return fieldset;
}

export class LightsEditor {
  #shape = '';

  constructor({ container, addButton, resetButton, state }) {
    Object.assign(this, { container, state });
    addButton.addEventListener('click', () => this.#add());
    resetButton.addEventListener('click', () => state.remove('lights'));
    state.addEventListener('change', () => this.#render());
  }

  #render() {
    const lights = this.state.get('lights') ?? [];
    const shape = lights.map((light) => light.type).join(',');
    if (shape === this.#shape && this.container.children.length) return;
    this.#shape = shape;
    this.container.replaceChildren(...lights.map((light, i) => lightBlock(light, i, (index) => this.#remove(index))));
    refreshInputs(this.container, this.state);
  }

  #add() {
    const bounds = this.state.sceneReport()?.bounds;
    const light = { type: 'point', position: bounds?.center ?? [0, 1, 0], color: [1, 1, 1], intensity: 5 };
    this.state.set('lights', [...(this.state.get('lights') ?? []), light]);
  }

  #remove(index) {
    this.state.set('lights', (this.state.get('lights') ?? []).filter((_, i) => i !== index));
  }
}

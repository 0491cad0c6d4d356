// Shows a server error next to the control that caused it. The server names the field by
// its JSON path ("lpv.grid", "lights[0].intensity", "base.output.width"); controls carry
// that path in data-field (request fields) or data-error-field (anything else). A path
// with no control of its own falls back to its parent ("lpv.grid[1]" -> "lpv.grid"), then
// to a general message element.
//
// Each part of the page (the frame, the reference, A/B, the sweep) has its own FieldErrors,
// so clearing one part's errors leaves the others' in place.

let slotCount = 0;

function controlFor(roots, path) {
  for (let p = path; ; ) {
    const escaped = CSS.escape(p);
    for (const root of roots) {
      const control = root.querySelector(`[data-error-field="${escaped}"], [data-field="${escaped}"]`);
      if (control) return control;
    }
    const parent = p.replace(/(\.[^.[\]]+|\[\d+\])$/, '');
    if (parent === p) return null;
    p = parent;
  }
}

// The inputs an error is about: those bound to the field (a slider and its box share one),
// and of a vector only the component the path names ("camera.position[1]": the y box); a
// block that stands for the field as a whole (data-error-field) has all of its inputs.
function invalidInputs(block, control, path) {
  const inputs = [...block.querySelectorAll('input, select')];
  const field = control.dataset.field;
  if (!field) return inputs;
  const index = path.startsWith(field) ? path.slice(field.length).match(/^\[(\d+)\]/)?.[1] : undefined;
  return inputs.filter((input) => input.dataset.field === field &&
    (index === undefined || input.dataset.index === undefined || input.dataset.index === index));
}

export class FieldErrors {
  #slots = [];

  // roots: where to look for controls, in order (a panel before the settings form);
  // fallback: where a message without a control goes; prefixes: leading parts of a path
  // that name the request inside a larger body ("base." for compare and sweep, "against."
  // for B): a control for the whole path wins, then one for the path without its prefix.
  constructor({ roots, fallback, prefixes = [] }) {
    Object.assign(this, { roots, fallback, prefixes });
  }

  show(error) {
    this.clear();
    const path = error.field ?? '';
    let control = path ? controlFor(this.roots, path) : null;
    let controlPath = path;  // the path as the control names it, without a prefix
    for (const prefix of this.prefixes) {
      if (control || !path.startsWith(prefix)) continue;
      controlPath = path.slice(prefix.length);
      control = controlFor(this.roots, controlPath);
    }
    const text = path ? `${path}: ${error.message}` : error.message;
    if (!control) {
      this.fallback.textContent = text;
      this.fallback.hidden = false;
      return;
    }
    const block = control.closest('.control') ?? control;
    const slot = document.createElement('p');
    slot.className = 'field-error';
    slot.id = `field-error-${++slotCount}`;
    slot.setAttribute('role', 'alert');
    slot.textContent = text;
    block.append(slot);
    const inputs = invalidInputs(block, control, controlPath);
    for (const input of inputs) {
      input.setAttribute('aria-invalid', 'true');
      input.setAttribute('aria-describedby', slot.id);
    }
    this.#slots.push({ slot, inputs });
  }

  clear() {
    for (const { slot, inputs } of this.#slots) {
      slot.remove();
      for (const input of inputs) {
        if (input.getAttribute('aria-describedby') !== slot.id) continue;
        input.removeAttribute('aria-invalid');
        input.removeAttribute('aria-describedby');
      }
    }
    this.#slots = [];
    this.fallback.hidden = true;
    this.fallback.textContent = '';
  }
}

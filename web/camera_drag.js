// Moving the camera with the pointer or the keyboard, over the frame, while the canvas's
// drag mode is "camera" (view_controls.js; the plain wheel zooms the view, not the camera):
//   drag                 orbit around the target (about the camera's up axis, then sideways)
//   right or Shift-drag  pan: camera and target move together in the view plane
//   Alt+wheel            dolly: the distance to the target scales
//   arrows, Page Up and Page Down  the same from the keyboard, the canvas focused
// The result is the request's camera (position, target, up, fov), which starts as the
// scene's camera; every move goes through the render loop's debounce like any control.

const sub = (a, b) => a.map((v, i) => v - b[i]);
const add = (a, b) => a.map((v, i) => v + b[i]);
const scale = (a, s) => a.map((v) => v * s);
const dot = (a, b) => a.reduce((sum, v, i) => sum + v * b[i], 0);
const length = (a) => Math.sqrt(dot(a, a));
const normalize = (a) => scale(a, 1 / (length(a) || 1));
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const round = (a) => a.map((v) => Number(v.toFixed(4)));

// Rodrigues' rotation of `v` about the unit `axis`.
function rotate(v, axis, angle) {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  return add(add(scale(v, c), scale(cross(axis, v), s)), scale(axis, dot(axis, v) * (1 - c)));
}

const ORBIT_RADIANS_PER_PIXEL = 0.008;
const MAX_ELEVATION = (89 * Math.PI) / 180;  // stay off the up axis: the view must not flip

function orbit(camera, dx, dy) {
  const up = normalize(camera.up);
  let offset = sub(camera.position, camera.target);
  offset = rotate(offset, up, -dx * ORBIT_RADIANS_PER_PIXEL);
  const right = normalize(cross(up, offset));
  const elevation = Math.asin(Math.max(-1, Math.min(1, dot(normalize(offset), up))));
  const wanted = Math.max(-MAX_ELEVATION, Math.min(MAX_ELEVATION, elevation + dy * ORBIT_RADIANS_PER_PIXEL));
  offset = rotate(offset, right, -(wanted - elevation));
  return { ...camera, position: round(add(camera.target, offset)) };
}

// Moves by `dx`, `dy` pixels of a frame `height` pixels tall, at the target's depth.
function pan(camera, dx, dy, height) {
  const forward = normalize(sub(camera.target, camera.position));
  const right = normalize(cross(forward, camera.up));
  const up = cross(right, forward);
  const metresPerPixel = (2 * length(sub(camera.target, camera.position)) * Math.tan((camera.fov_y_deg * Math.PI) / 360)) / height;
  const move = add(scale(right, -dx * metresPerPixel), scale(up, dy * metresPerPixel));
  return { ...camera, position: round(add(camera.position, move)), target: round(add(camera.target, move)) };
}

function zoom(camera, factor) {
  const offset = scale(sub(camera.position, camera.target), factor);
  if (length(offset) < 1e-3) return camera;
  return { ...camera, position: round(add(camera.target, offset)) };
}

export function attachCameraControls(area, state, { enabled }) {
  const camera = () => (enabled() ? state.get('camera') : undefined);
  const apply = (next) => {
    if (next) state.set('camera', next);
  };
  let drag = null;

  area.addEventListener('contextmenu', (event) => event.preventDefault());
  area.addEventListener('pointerdown', (event) => {
    if (!camera()) return;
    drag = { x: event.clientX, y: event.clientY, panning: event.button === 2 || event.shiftKey };
    area.setPointerCapture(event.pointerId);
  });
  area.addEventListener('pointermove', (event) => {
    if (!drag) return;
    const dx = event.clientX - drag.x;
    const dy = event.clientY - drag.y;
    if (dx === 0 && dy === 0) return;
    drag.x = event.clientX;
    drag.y = event.clientY;
    apply(drag.panning ? pan(camera(), dx, dy, area.clientHeight || 512) : orbit(camera(), dx, dy));
  });
  const end = () => {
    drag = null;
  };
  area.addEventListener('pointerup', end);
  area.addEventListener('pointercancel', end);
  area.addEventListener('wheel', (event) => {
    if (!event.altKey || !camera()) return;
    event.preventDefault();
    apply(zoom(camera(), Math.exp(event.deltaY * 0.001)));
  }, { passive: false });
  area.addEventListener('keydown', (event) => {
    if (!camera()) return;
    const step = 20;  // pixels of a drag
    const moves = {
      ArrowLeft: () => orbit(camera(), -step, 0),
      ArrowRight: () => orbit(camera(), step, 0),
      ArrowUp: () => orbit(camera(), 0, -step),
      ArrowDown: () => orbit(camera(), 0, step),
      PageUp: () => zoom(camera(), 0.9),
      PageDown: () => zoom(camera(), 1 / 0.9),
    };
    if (!moves[event.key]) return;
    event.preventDefault();
    apply(moves[event.key]());
  });
}

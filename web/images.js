// Images from the API, as PNG bytes or as base64 in JSON, are shown through blob: URLs (the
// page's Content-Security-Policy allows no data: images); each <img> frees its previous one.

const urls = new WeakMap();

function pngBlob(base64) {
  const binary = atob(base64);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return new Blob([bytes], { type: 'image/png' });
}

// One image (base64 PNG) into one <img> or several: decoded from base64 once.
export function showPng(imgs, base64) {
  const blob = pngBlob(base64);
  return Promise.all([imgs].flat().map((img) => showImage(img, blob)));
}

// Resolves once the image is decoded, so the caller knows it is ready to be painted.
export async function showImage(img, blob) {
  const url = URL.createObjectURL(blob);
  const previous = urls.get(img);
  urls.set(img, url);
  img.src = url;
  try {
    await img.decode();
  } finally {
    if (previous) URL.revokeObjectURL(previous);
  }
}

// Resolves after the browser has painted what the DOM holds now.
export function nextPaint() {
  return new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve)));
}

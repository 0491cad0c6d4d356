// Portable Float Maps, the API's linear images (`"format": "pfm"`, image/pfm.hpp): a header
// "PF\n<width> <height>\n<scale>\n" (a negative scale: little-endian) and width * height RGB
// float32 triples, rows stored bottom-to-top. The page reads exact linear values from them:
// the readout and the difference maps come from these, never from an 8-bit picture.

// bytes: an ArrayBuffer or Uint8Array. Returns { width, height, rgb: Float32Array } with row 0
// at the top and three floats per pixel.
export function decodePfm(bytes) {
  const data = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  let at = 0;
  const token = () => {
    while (at < data.length && /\s/.test(String.fromCharCode(data[at]))) at++;
    const start = at;
    while (at < data.length && !/\s/.test(String.fromCharCode(data[at]))) at++;
    return new TextDecoder().decode(data.subarray(start, at));
  };
  const magic = token();
  if (magic !== 'PF') throw new Error(`not a colour PFM (it starts with "${magic.slice(0, 8)}")`);
  const width = Number(token());
  const height = Number(token());
  const scale = Number(token());
  at++;  // the single whitespace byte that ends the header
  if (!(width > 0 && height > 0 && Number.isInteger(width) && Number.isInteger(height) && scale))
    throw new Error('the PFM header is malformed');
  const count = width * height * 3;
  if (data.length - at < count * 4) throw new Error(`the PFM holds ${data.length - at} bytes of pixels, ${count * 4} expected`);
  const rgb = new Float32Array(count);
  const row = width * 3;
  // A little-endian map on a little-endian host (every one the page runs on) is copied a row at
  // a time through an aligned view; anything else goes float by float.
  const hostLittleEndian = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;
  if ((scale < 0) === hostLittleEndian) {
    const floats = new Float32Array(new Uint8Array(data.subarray(at, at + count * 4)).buffer);  // a copy: aligned
    for (let y = 0; y < height; y++) rgb.set(floats.subarray((height - 1 - y) * row, (height - y) * row), y * row);
  } else {
    const view = new DataView(data.buffer, data.byteOffset + at, count * 4);
    for (let y = 0; y < height; y++)  // stored bottom-to-top
      for (let i = 0; i < row; i++) rgb[y * row + i] = view.getFloat32(((height - 1 - y) * row + i) * 4, scale < 0);
  }
  return { width, height, rgb };
}

export function decodePfmBase64(base64) {
  const binary = atob(base64);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return decodePfm(bytes);
}

// Rec. 709 luminance, as the server's metrics weigh the channels (image/metrics.hpp).
export function luminance(rgb, i) {
  return 0.2126 * rgb[3 * i] + 0.7152 * rgb[3 * i + 1] + 0.0722 * rgb[3 * i + 2];
}

// A layer as an image, one pixel a cell, row j=0 in the bottom image row (y up), for the 2D
// layer view (opaque) and the cutting plane of the 3D view (empty cells transparent).

import { CELL_RGB } from './palette.js';

/** Paints `layer` into a new canvas of nx x ny pixels. */
export function layerCanvas(layer, { transparentEmpty = false } = {}) {
  const { nx, ny } = layer;
  const canvas = document.createElement('canvas');
  canvas.width = nx;
  canvas.height = ny;
  const ctx = canvas.getContext('2d');
  const image = ctx.createImageData(nx, ny);
  const pixels = new Uint32Array(image.data.buffer);
  const lut = new Uint32Array(4);
  for (let code = 0; code < 4; ++code) {
    const [r, g, b] = CELL_RGB[code];
    const a = transparentEmpty && code === 0 ? 0 : 255;
    lut[code] = ((a << 24) | (b << 16) | (g << 8) | r) >>> 0; // little-endian RGBA
  }
  const p = layer.packed;
  for (let j = 0; j < ny; ++j) {
    const row = (ny - 1 - j) * nx;
    const first = j * nx;
    for (let i = 0; i < nx; ++i) {
      const n = first + i;
      pixels[row + i] = lut[(p[n >> 2] >> (6 - 2 * (n & 3))) & 3];
    }
  }
  ctx.putImageData(image, 0, 0);
  return canvas;
}

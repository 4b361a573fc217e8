// The page's data: reads the JSON embedded in the page (web/DATA.md), checks it, and decodes
// the binary arrays. Layers are inflated lazily, when a view asks for them, and kept in a
// least-recently-used cache bounded in bytes.

export const CODE_EMPTY = 0;
export const CODE_INTERIOR = 1;
export const CODE_BOUNDARY = 3;

export const CLASS_WORDS = ['empty', 'interior', 'reserved', 'boundary'];

/** An error whose message is meant for the person reading the page. */
export class DataError extends Error {}

/** The embedded JSON text, parsed and checked. Throws DataError with a readable message. */
/**
 * The page's data: embedded, or, when the embedded JSON is {"format": "strata-view-remote",
 * "url": ...} (the viewer that strata serve hands out), fetched from that same-origin URL.
 */
export async function loadPageData(doc = document) {
  const element = doc.getElementById('strata-data');
  const text = element?.textContent.trim() ?? '';
  if (text.startsWith('{"format":"strata-view-remote"')) {
    let remote;
    try {
      remote = JSON.parse(text);
    } catch (e) {
      throw new DataError(`The page's data link is not valid JSON (${e.message}).`);
    }
    if (typeof remote.url !== 'string' || !remote.url.startsWith('/')) throw new DataError('The page\'s data link names no URL on this server.');
    let response;
    try {
      response = await fetch(remote.url, { cache: 'no-store' });
    } catch (e) {
      throw new DataError(`The server did not answer (${e.message}).`);
    }
    if (!response.ok) {
      const reason = await response.json().then((j) => j.error, () => response.statusText);
      throw new DataError(`The server has no data for this page: ${reason}.`);
    }
    let data;
    try {
      data = await response.json();
    } catch (e) {
      throw new DataError(`The server's data is not valid JSON (${e.message}).`);
    }
    checkData(data);
    return data;
  }
  return readEmbeddedData(doc);
}

export function readEmbeddedData(doc = document) {
  const element = doc.getElementById('strata-data');
  if (!element) throw new DataError('This page holds no model data (no element #strata-data).');
  const text = element.textContent.trim();
  if (/^__STRATA_[A-Z_]+__$/.test(text)) {
    throw new DataError(
      'This is the bare page template: the model data was never put in place. ' +
        'Make a page with "strata view MODEL -o FILE.html".');
  }
  if (text === '') throw new DataError('The model data of this page is empty.');
  let data;
  try {
    data = JSON.parse(text);
  } catch (e) {
    throw new DataError(`The model data of this page is not valid JSON (${e.message}).`);
  }
  checkData(data);
  return data;
}

function require(condition, what) {
  if (!condition) throw new DataError(`The model data is invalid: ${what}.`);
}

function isCount(v) {
  return Number.isInteger(v) && v >= 0;
}

/** Checks the parts of the data the page relies on (DATA.md, version 1). */
export function checkData(data) {
  require(data && typeof data === 'object', 'not a JSON object');
  require(data.format === 'strata-view', `format is ${JSON.stringify(data.format)}, not "strata-view"`);
  require(data.version === 1, `version ${JSON.stringify(data.version)} is not supported (expected 1)`);
  const g = data.grid;
  require(g && typeof g === 'object', 'no grid');
  for (const key of ['nx', 'ny', 'nz']) require(isCount(g[key]) && g[key] > 0, `grid.${key} is not a positive integer`);
  for (const key of ['x0', 'y0', 'z0']) require(Number.isFinite(g[key]), `grid.${key} is not a number`);
  for (const key of ['dx', 'dy', 'dz']) require(Number.isFinite(g[key]) && g[key] > 0, `grid.${key} is not positive`);
  const l = data.layers;
  require(l && typeof l === 'object', 'no layers');
  require(l.encoding === '2bit-msb-zlib', `layer encoding ${JSON.stringify(l.encoding)} is not supported`);
  // No stored layer: a model checked but not sliced yet (the page shows the model only).
  require(Array.isArray(l.stored), 'layers.stored is missing');
  require(Array.isArray(l.cells) && l.cells.length === l.stored.length, 'layers.cells does not match layers.stored');
  for (let n = 0; n < l.stored.length; ++n) {
    const k = l.stored[n];
    require(isCount(k) && k < g.nz, `stored layer ${k} is outside the grid`);
    require(n === 0 || k > l.stored[n - 1], 'layers.stored is not increasing');
  }
  if (l.contours != null) require(Array.isArray(l.contours) && l.contours.length === l.stored.length, 'layers.contours does not match layers.stored');
  if (l.hatches != null) require(Array.isArray(l.hatches) && l.hatches.length === l.stored.length, 'layers.hatches does not match layers.stored');
  if (data.volume != null) {
    const v = data.volume;
    for (const key of ['nx', 'ny', 'nz', 'bx', 'by', 'bz']) require(isCount(v[key]) && v[key] > 0, `volume.${key} is not a positive integer`);
    require(typeof v.data === 'string', 'volume.data is missing');
  }
  if (data.mesh != null) {
    require(typeof data.mesh.positions === 'string' && typeof data.mesh.indices === 'string', 'mesh arrays are missing');
  }
  if (data.notes != null) require(Array.isArray(data.notes), 'notes is not a list');
}

// ---------------------------------------------------------------------------------------------
// Binary arrays.

/** base64 text to bytes. */
export function base64Bytes(text) {
  if (typeof Uint8Array.fromBase64 === 'function') return Uint8Array.fromBase64(text);
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let n = 0; n < binary.length; ++n) bytes[n] = binary.charCodeAt(n);
  return bytes;
}

export function base64Float32(text) {
  const bytes = base64Bytes(text ?? '');
  return new Float32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength >> 2);
}

export function base64Uint32(text) {
  const bytes = base64Bytes(text ?? '');
  return new Uint32Array(bytes.buffer, bytes.byteOffset, bytes.byteLength >> 2);
}

/** Inflates RFC 1950 (zlib) data. */
export async function inflate(bytes) {
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

// ---------------------------------------------------------------------------------------------
// Layers.

/** One decoded layer: nx*ny cells packed 2 bits a cell, row j=0 first, first cell in the high bits. */
export class Layer {
  constructor(k, packed, nx, ny) {
    this.k = k;
    this.packed = packed;
    this.nx = nx;
    this.ny = ny;
  }

  code(i, j) {
    const n = j * this.nx + i;
    return (this.packed[n >> 2] >> (6 - 2 * (n & 3))) & 3;
  }

  /** Calls fn(code, n) for every cell n = j*nx + i in order; fast path for painting. */
  forEach(fn) {
    const total = this.nx * this.ny;
    const p = this.packed;
    for (let n = 0; n < total; ++n) fn((p[n >> 2] >> (6 - 2 * (n & 3))) & 3, n);
  }
}

export class StrataData {
  constructor(raw, { cacheBytes = 256 * 1024 * 1024 } = {}) {
    this.raw = raw;
    this.grid = raw.grid;
    this.title = raw.title || 'model';
    this.notes = raw.notes || [];
    this.report = raw.report || null;
    this.check = raw.check || null;
    this.validation = raw.validation || null;
    this.stored = raw.layers.stored;
    this.stride = raw.layers.stride || 1;
    this.cacheBytes = cacheBytes;
    this.cache = new Map(); // stored index -> Promise<Layer>, in least-recently-used order
    this.done = new Map(); // stored index -> Layer, for the cached layers already decoded
    this.cachedBytes = 0;
    this.layerBytes = Math.ceil((this.grid.nx * this.grid.ny) / 4);
    this.reportLayers = new Map();
    for (const l of this.report?.layers ?? []) this.reportLayers.set(l.k, l);
    this.differing = new Map(); // k -> [[i, j, fast, exact], ...]
    for (const c of this.validation?.cells ?? []) {
      if (!this.differing.has(c[2])) this.differing.set(c[2], []);
      this.differing.get(c[2]).push([c[0], c[1], c[3], c[4]]);
    }
    this.differingLayers = new Set(this.validation?.layers_differing ?? []);
  }

  get layerCount() {
    return this.stored.length;
  }

  /** The stored index of the layer nearest to grid layer k (at or below it when between). */
  indexOfLayer(k) {
    let lo = 0;
    let hi = this.stored.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (this.stored[mid] <= k) lo = mid;
      else hi = mid - 1;
    }
    return lo;
  }

  /** z of the slicing plane of grid layer k (the cell centres). */
  layerZ(k) {
    return this.grid.z0 + (k + 0.5) * this.grid.dz;
  }

  /** The decoded layer at stored index n (a Promise; cached). */
  layer(n) {
    let entry = this.cache.get(n);
    if (entry) {
      this.cache.delete(n);
      this.cache.set(n, entry);
      return entry;
    }
    entry = this.#decodeLayer(n);
    this.cache.set(n, entry);
    this.cachedBytes += this.layerBytes;
    while (this.cachedBytes > this.cacheBytes && this.cache.size > 1) {
      const oldest = this.cache.keys().next().value;
      this.cache.delete(oldest);
      this.done.delete(oldest);
      this.cachedBytes -= this.layerBytes;
    }
    return entry;
  }

  /** The decoded layer if it is already cached and finished, else null. */
  layerIfReady(n) {
    return this.done.get(n) ?? null;
  }

  async #decodeLayer(n) {
    const { nx, ny } = this.grid;
    let packed;
    try {
      packed = await inflate(base64Bytes(this.raw.layers.cells[n]));
    } catch (e) {
      this.cache.delete(n);
      this.cachedBytes -= this.layerBytes;
      throw new DataError(`layer ${this.stored[n]} could not be decoded (${e.message})`);
    }
    if (packed.length < this.layerBytes) {
      this.cache.delete(n);
      this.cachedBytes -= this.layerBytes;
      throw new DataError(`layer ${this.stored[n]} holds ${packed.length} bytes, expected ${this.layerBytes}`);
    }
    const layer = new Layer(this.stored[n], packed, nx, ny);
    if (this.cache.has(n)) this.done.set(n, layer);
    return layer;
  }

  /** Contours of stored layer n: [{kind, points: Float32Array [x,y,...]}]. Decoded once. */
  contours(n) {
    this.contourCache ??= new Map();
    let c = this.contourCache.get(n);
    if (!c) {
      const raw = this.raw.layers.contours?.[n] ?? [];
      c = raw.map((loop) => ({ kind: loop.kind, points: base64Float32(loop.points) }));
      this.contourCache.set(n, c);
    }
    return c;
  }

  get hasHatches() {
    return Array.isArray(this.raw.layers.hatches);
  }

  /** Scanline segments of stored layer n: Float32Array [x1,y1,x2,y2,...] (empty when absent). */
  hatches(n) {
    this.hatchCache ??= new Map();
    let h = this.hatchCache.get(n);
    if (!h) {
      h = base64Float32(this.raw.layers.hatches?.[n] ?? '');
      this.hatchCache.set(n, h);
    }
    return h;
  }

  /** The display mesh: {positions: Float32Array, indices: Uint32Array, ...} or null. */
  mesh() {
    const m = this.raw.mesh;
    if (!m) return null;
    return {
      positions: base64Float32(m.positions),
      indices: base64Uint32(m.indices),
      facetsInModel: m.facets_in_model,
      facetsShown: m.facets_shown,
      simplified: !!m.simplified,
    };
  }

  /** Defects from strata check, arrays decoded. */
  defects() {
    return (this.check?.defects ?? []).map((d) => ({ ...d, values: base64Float32(d.data ?? '') }));
  }

  /** The reduced block volume, inflated (a Promise), or null. */
  async volume() {
    const v = this.raw.volume;
    if (!v) return null;
    const blocks = await inflate(base64Bytes(v.data));
    if (blocks.length < v.nx * v.ny * v.nz) {
      throw new DataError(`the block volume holds ${blocks.length} bytes, expected ${v.nx * v.ny * v.nz}`);
    }
    return { ...v, blocks };
  }
}

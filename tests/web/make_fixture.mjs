// Writes the data of a view page (web/DATA.md) for an analytic model: a box 20 x 10 x 6 mm with
// a conical hole, its cells classified from the exact distance to the surface, with a few
// made-up defects and validation findings so every part of the page has something to show.
//
//   node tests/web/make_fixture.mjs OUT.json [--lite]
//
// --lite: no mesh, no check, no validation, no hatches, every 2nd layer stored, blocks of
// 2 x 2 x 2 cells in the volume (the reduced forms a large model gets).

import { writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import { deflateSync } from 'node:zlib';
import { pathToFileURL } from 'node:url';

export const BOX = { x0: -10, x1: 10, y0: -5, y1: 5, z0: 0, z1: 6 };
export const HOLE = { cx: 4, cy: 1, r0: 1.5, r1: 3.5 }; // radius at z0 and at z1
export const GRID = { nx: 40, ny: 20, nz: 24, x0: -10, y0: -5, z0: 0, dx: 0.5, dy: 0.5, dz: 0.25 };
export const SHELL = 0.5;
export const CODES = { empty: 0, interior: 1, boundary: 3 };
export const WORDS = { 0: 'empty', 1: 'interior', 3: 'boundary' };

const slope = (HOLE.r1 - HOLE.r0) / (BOX.z1 - BOX.z0);

export function holeRadius(z) {
  return HOLE.r0 + slope * (z - BOX.z0);
}

/** The class code of a point: 0 outside the solid, 3 within SHELL of its surface, else 1. */
export function classifyPoint(x, y, z) {
  const inBox = x > BOX.x0 && x < BOX.x1 && y > BOX.y0 && y < BOX.y1 && z > BOX.z0 && z < BOX.z1;
  const r = Math.hypot(x - HOLE.cx, y - HOLE.cy);
  const rc = holeRadius(z);
  if (!inBox || r <= rc) return 0;
  const d = Math.min(x - BOX.x0, BOX.x1 - x, y - BOX.y0, BOX.y1 - y, z - BOX.z0, BOX.z1 - z, (r - rc) / Math.sqrt(1 + slope * slope));
  return d <= SHELL ? 3 : 1;
}

/** The class code of cell (i, j, k). */
export function classify(i, j, k) {
  const g = GRID;
  return classifyPoint(g.x0 + (i + 0.5) * g.dx, g.y0 + (j + 0.5) * g.dy, g.z0 + (k + 0.5) * g.dz);
}

const b64 = (typedArray) => Buffer.from(typedArray.buffer, typedArray.byteOffset, typedArray.byteLength).toString('base64');
const f32 = (values) => b64(new Float32Array(values));

function packLayer(k) {
  const { nx, ny } = GRID;
  const bytes = new Uint8Array(Math.ceil((nx * ny) / 4));
  for (let j = 0; j < ny; ++j) {
    for (let i = 0; i < nx; ++i) {
      const n = j * nx + i;
      bytes[n >> 2] |= classify(i, j, k) << (6 - 2 * (n & 3));
    }
  }
  return bytes;
}

function meshOfModel() {
  const positions = [];
  const indices = [];
  const vertex = (p) => {
    positions.push(...p);
    return positions.length / 3 - 1;
  };
  const triangle = (a, b, c, outward) => {
    const [pa, pb, pc] = [a, b, c].map((v) => positions.slice(3 * v, 3 * v + 3));
    const u = pb.map((x, n) => x - pa[n]);
    const w = pc.map((x, n) => x - pa[n]);
    const normal = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    const dot = normal[0] * outward[0] + normal[1] * outward[1] + normal[2] * outward[2];
    indices.push(...(dot >= 0 ? [a, b, c] : [a, c, b]));
  };
  const quad = (a, b, c, d, outward) => {
    triangle(a, b, c, outward);
    triangle(a, c, d, outward);
  };
  const { x0, x1, y0, y1, z0, z1 } = BOX;
  // the four sides
  const corner = (x, y, z) => vertex([x, y, z]);
  quad(corner(x0, y0, z0), corner(x1, y0, z0), corner(x1, y0, z1), corner(x0, y0, z1), [0, -1, 0]);
  quad(corner(x1, y1, z0), corner(x0, y1, z0), corner(x0, y1, z1), corner(x1, y1, z1), [0, 1, 0]);
  quad(corner(x0, y1, z0), corner(x0, y0, z0), corner(x0, y0, z1), corner(x0, y1, z1), [-1, 0, 0]);
  quad(corner(x1, y0, z0), corner(x1, y1, z0), corner(x1, y1, z1), corner(x1, y0, z1), [1, 0, 0]);
  // top and bottom: rings around the hole, the rectangle's corners included
  const { cx, cy } = HOLE;
  const angles = [];
  for (let n = 0; n < 48; ++n) angles.push((2 * Math.PI * n) / 48);
  for (const [x, y] of [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]) angles.push((Math.atan2(y - cy, x - cx) + 2 * Math.PI) % (2 * Math.PI));
  angles.sort((a, b) => a - b);
  const onRectangle = (t) => {
    const c = Math.cos(t);
    const s = Math.sin(t);
    const tx = c > 0 ? (x1 - cx) / c : c < 0 ? (x0 - cx) / c : Infinity;
    const ty = s > 0 ? (y1 - cy) / s : s < 0 ? (y0 - cy) / s : Infinity;
    const d = Math.min(tx, ty);
    return [cx + d * c, cy + d * s];
  };
  const ring = (z, radius) => ({
    outer: angles.map((t) => vertex([...onRectangle(t), z])),
    inner: angles.map((t) => vertex([cx + radius * Math.cos(t), cy + radius * Math.sin(t), z])),
  });
  const top = ring(z1, HOLE.r1);
  const bottom = ring(z0, HOLE.r0);
  const m = angles.length;
  for (let n = 0; n < m; ++n) {
    const n1 = (n + 1) % m;
    quad(top.outer[n], top.outer[n1], top.inner[n1], top.inner[n], [0, 0, 1]);
    quad(bottom.outer[n], bottom.outer[n1], bottom.inner[n1], bottom.inner[n], [0, 0, -1]);
    const t = (angles[n] + angles[n1] + (n1 === 0 ? 2 * Math.PI : 0)) / 2;
    quad(bottom.inner[n], bottom.inner[n1], top.inner[n1], top.inner[n], [-Math.cos(t), -Math.sin(t), 0]);
  }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices) };
}

function circle(cx, cy, r, points, clockwise) {
  const out = [];
  for (let n = 0; n < points; ++n) {
    const t = ((clockwise ? -1 : 1) * 2 * Math.PI * n) / points;
    out.push(cx + r * Math.cos(t), cy + r * Math.sin(t));
  }
  return out;
}

function hatchesOfLayer(z) {
  const g = GRID;
  const rc = holeRadius(z);
  const segments = [];
  for (let j = 0; j < g.ny; ++j) {
    const y = g.y0 + (j + 0.5) * g.dy;
    const dy = y - HOLE.cy;
    if (Math.abs(dy) < rc) {
      const half = Math.sqrt(rc * rc - dy * dy);
      segments.push(BOX.x0, y, HOLE.cx - half, y, HOLE.cx + half, y, BOX.x1, y);
    } else {
      segments.push(BOX.x0, y, BOX.x1, y);
    }
  }
  return segments;
}

/** The fixture's data object (DATA.md version 1). */
export function makeFixture({ lite = false } = {}) {
  const g = GRID;
  const stride = lite ? 2 : 1;
  const stored = [];
  for (let k = 0; k < g.nz; k += stride) stored.push(k);
  const zOf = (k) => g.z0 + (k + 0.5) * g.dz;
  const rectangleArea = (BOX.x1 - BOX.x0) * (BOX.y1 - BOX.y0);

  // layers, contours, hatches
  const cells = [];
  const contours = [];
  const hatches = [];
  for (const k of stored) {
    cells.push(deflateSync(packLayer(k)).toString('base64'));
    const z = zOf(k);
    const loops = [
      { kind: 'outer', points: f32([BOX.x0, BOX.y0, BOX.x1, BOX.y0, BOX.x1, BOX.y1, BOX.x0, BOX.y1]) },
      { kind: 'hole', points: f32(circle(HOLE.cx, HOLE.cy, holeRadius(z), 72, true)) },
    ];
    if (k === 5) {
      const arc = [];
      for (let n = 0; n <= 12; ++n) arc.push(-6 + 0.4 * n, 2 + Math.sin(n / 2));
      loops.push({ kind: 'open', points: f32(arc) });
    }
    contours.push(loops);
    hatches.push(f32(hatchesOfLayer(z)));
  }

  // the report
  const counts = { empty: 0, interior: 0, boundary: 0 };
  const layers = [];
  for (let k = 0; k < g.nz; ++k) {
    const layer = { interior: 0, boundary: 0 };
    for (let j = 0; j < g.ny; ++j) {
      for (let i = 0; i < g.nx; ++i) {
        const c = classify(i, j, k);
        if (c === 1) ++layer.interior;
        else if (c === 3) ++layer.boundary;
        else ++counts.empty;
      }
    }
    counts.interior += layer.interior;
    counts.boundary += layer.boundary;
    const r = holeRadius(zOf(k));
    layers.push({
      k,
      z_mm: zOf(k),
      segments: 4 + 72,
      outer_loops: 1,
      holes: 1,
      open_chains: k === 5 ? 1 : 0,
      loops_cross: false,
      outline: false,
      contour_area_mm2: rectangleArea - Math.PI * r * r,
      interior: layer.interior,
      boundary: layer.boundary,
    });
  }
  const cellVolume = (counts.interior + counts.boundary) * g.dx * g.dy * g.dz;
  const height = BOX.z1 - BOX.z0;
  const holeVolume = (Math.PI * height * (HOLE.r0 ** 2 + HOLE.r0 * HOLE.r1 + HOLE.r1 ** 2)) / 3;
  const meshVolume = rectangleArea * height - holeVolume;
  const contourVolume = layers.reduce((s, l) => s + l.contour_area_mm2 * g.dz, 0);

  const mesh = meshOfModel();
  const report = {
    strata_version: '0.1.0',
    model: {
      path: 'fixture/box-with-conical-hole.stl',
      format: 'stl-binary',
      facets: mesh.indices.length / 3,
      vertices: mesh.positions.length / 3,
      bbox_min_mm: [BOX.x0, BOX.y0, BOX.z0],
      bbox_max_mm: [BOX.x1, BOX.y1, BOX.z1],
      read_diagnostics: [],
      defects: { open_edges: 0, non_manifold_edges: 0, degenerate_facets: 0, duplicate_facets: 0, inconsistent_edge_pairs: 0, shells: 1, verdict: 'printable' },
    },
    parameters: { layer_mm: g.dz, dx_mm: g.dx, dy_mm: g.dy, shell_mm: SHELL, shell_mode: 'distance', fill_rule: 'nonzero', scan_offset_mm: 0, kernel: 'fast', threads: 2 },
    grid: { nx: g.nx, ny: g.ny, nz: g.nz, origin_mm: [g.x0, g.y0, g.z0], spacing_mm: [g.dx, g.dy, g.dz] },
    cells: { ...counts, solid_volume_mm3: cellVolume },
    metrics: {
      mesh_volume_mm3: meshVolume,
      cell_volume_mm3: cellVolume,
      contour_volume_mm3: contourVolume,
      cell_volume_relative_error: (cellVolume - meshVolume) / meshVolume,
      surface_area_mm2: 2 * (20 * 10 + 20 * 6 + 10 * 6),
      segments: layers.reduce((s, l) => s + l.segments, 0),
      exact_fallbacks: 3,
      crossing_loop_layers: 0,
      misnested_loop_layers: 0,
      outline_layers: 0,
    },
    open_chains: { count: 1, first: [{ layer: 5, z_mm: zOf(5), start_mm: [-6, 2], end_mm: [-1.2, 2 + Math.sin(6)], gap_mm: 4.9, segments: 12 }] },
    layers,
    empty_layers_inside_model: 0,
    diagnostics: [{ severity: 'warning', code: 'open-chain', message: 'layer 5: an open chain of 12 segments was closed by its outline' }],
    timings_s: { read: 0.002, weld: 0.001, slice: 0.034, total: 0.041 },
  };

  // the block volume
  const b = lite ? 2 : 1;
  const vnx = Math.ceil(g.nx / b);
  const vny = Math.ceil(g.ny / b);
  const vnz = Math.ceil(g.nz / b);
  const blocks = new Uint8Array(vnx * vny * vnz);
  for (let k = 0; k < g.nz; ++k) {
    for (let j = 0; j < g.ny; ++j) {
      for (let i = 0; i < g.nx; ++i) {
        const n = (Math.floor(k / b) * vny + Math.floor(j / b)) * vnx + Math.floor(i / b);
        blocks[n] = Math.max(blocks[n], classify(i, j, k));
      }
    }
  }

  // two interior cells of layer 7 left of the hole, said to differ between the paths
  const differing = [];
  for (let i = 0; i < g.nx && differing.length < 2; ++i) if (classify(i, 10, 7) === 1 && classify(i + 1, 10, 7) === 3 && i > 10) differing.push([i, 10, 7, 1, 3]);
  if (differing.length === 1) differing.push([differing[0][0] - 1, 10, 7, 1, 3]);

  const defect = (kind, label, count, shape, values) => ({ kind, label, count, shape, data: f32(values), shown: values.length / { segments: 6, triangles: 9, points: 3 }[shape] });
  const rTop = HOLE.r1;
  const arcSegments = [];
  for (let n = 0; n < 3; ++n) {
    const t0 = (n * Math.PI) / 8;
    const t1 = ((n + 1) * Math.PI) / 8;
    arcSegments.push(HOLE.cx + rTop * Math.cos(t0), HOLE.cy + rTop * Math.sin(t0), BOX.z1, HOLE.cx + rTop * Math.cos(t1), HOLE.cy + rTop * Math.sin(t1), BOX.z1);
  }

  return {
    format: 'strata-view',
    version: 1,
    title: lite ? 'box-with-conical-hole (reduced)' : 'box-with-conical-hole',
    generator: 'strata 0.1.0',
    source: { kind: 'model', path: 'fixture/box-with-conical-hole.stl' },
    notes: lite
      ? ['stack subsampled: every 2nd layer', 'volume reduced to blocks of 2 × 2 × 2 cells', 'no display mesh in this page']
      : ['analytic test model: a box 20 × 10 × 6 mm with a conical hole (radius 1.5 to 3.5 mm)'],
    grid: { ...g },
    shell_mm: SHELL,
    report,
    mesh: lite
      ? null
      : { facets_in_model: mesh.indices.length / 3, facets_shown: mesh.indices.length / 3, simplified: false, positions: b64(mesh.positions), indices: b64(mesh.indices) },
    check: lite
      ? null
      : {
          verdict: 'needs-repair',
          reason: '5 open edges',
          defects: [
            defect('open_edges', 'open edges', 5, 'segments', arcSegments),
            defect('degenerate_facets', 'degenerate facets', 2, 'triangles', [-8, -5, 1, -6, -5, 1, -7, -5, 2.5, -3, -5, 3, -1, -5, 3, -2, -5, 4.5]),
            defect('non_manifold_vertices', 'non-manifold vertices', 2, 'points', [BOX.x0, BOX.y0, BOX.z1, BOX.x1, BOX.y1, BOX.z1]),
          ],
        },
    layers: { encoding: '2bit-msb-zlib', stored, stride, cells, contours, hatches: lite ? null : hatches },
    volume: { nx: vnx, ny: vny, nz: vnz, bx: b, by: b, bz: b, data: deflateSync(blocks).toString('base64') },
    validation: lite ? null : { cells_compared: g.nx * g.ny * g.nz, cells_differing: differing.length, layers_differing: [7], cells: differing },
  };
}

/** Escapes "</" as the writer of the page does. */
export function fixtureJson(options) {
  return JSON.stringify(makeFixture(options)).replace(/<\//g, '<\\/');
}

if (process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href) {
  const args = process.argv.slice(2);
  const out = args.find((a) => !a.startsWith('-'));
  if (!out) {
    console.error('usage: node tests/web/make_fixture.mjs OUT.json [--lite]');
    process.exit(2);
  }
  mkdirSync(path.dirname(path.resolve(out)), { recursive: true });
  writeFileSync(out, fixtureJson({ lite: args.includes('--lite') }));
  console.log(`wrote ${out}`);
}


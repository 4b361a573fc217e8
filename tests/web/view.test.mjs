// Browser tests of the view page, in one headless Chromium for the whole run.
//
// Pages: always the analytic fixture (tests/web/make_fixture.mjs) and its reduced form, and the
// bare template; when STRATA_CLI names the strata binary, also pages that `strata view` writes
// for a box it slices (boundary at the top and bottom of its section) and for the models in
// STRATA_VIEW_MODELS (paths, default data/ring.stl), checked against the cells file that
// `strata slice --format cells` writes, read back with `strata info --cell`.
//
// Environment: STRATA_CLI, STRATA_VIEW_MODELS (comma list), STRATA_VIEW_ARGS
// (slice options, default "--cell 0.5 --layer 0.5"), STRATA_CHROMIUM (default /usr/bin/chromium),
// STRATA_TEST_ARTIFACTS (screenshots and pages, default build/web-artifacts/).

import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { acquireBrowser, newContext, releaseBrowser, VIEWPORT } from './browser.mjs';
import { buildTemplate, insertData } from '../../web/build.mjs';
import { CANVAS_BACKGROUND, CELL_RGB } from '../../web/src/palette.js';
import { classify, fixtureJson, WORDS } from './make_fixture.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const artifacts = path.resolve(process.env.STRATA_TEST_ARTIFACTS || path.join(repo, 'build', 'web-artifacts'));
const cli = process.env.STRATA_CLI ? path.resolve(process.env.STRATA_CLI) : null;
const models = (process.env.STRATA_VIEW_MODELS || path.join(repo, 'data', 'ring.stl'))
  .split(',')
  .map((s) => s.trim())
  .filter(Boolean)
  .map((s) => path.resolve(repo, s));
const sliceArgs = (process.env.STRATA_VIEW_ARGS || '--cell 0.5 --layer 0.5').split(/\s+/).filter(Boolean);

const BACKGROUND = hexRgb(CANVAS_BACKGROUND);
const CLASS_COLOURS = { empty: CELL_RGB[0], interior: CELL_RGB[1], boundary: CELL_RGB[3], background: BACKGROUND };

function hexRgb(hex) {
  const v = parseInt(hex.slice(1), 16);
  return [(v >> 16) & 255, (v >> 8) & 255, v & 255];
}

/** The palette name nearest to an RGB colour, or 'other' when none is close. */
function colourClass(rgb) {
  let best = 'other';
  let bestDistance = 40;
  for (const [name, c] of Object.entries(CLASS_COLOURS)) {
    const d = Math.hypot(rgb[0] - c[0], rgb[1] - c[1], rgb[2] - c[2]);
    if (d < bestDistance) {
      best = name;
      bestDistance = d;
    }
  }
  return best;
}

function run(file, args) {
  return execFileSync(file, args, { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'], timeout: 120_000 });
}

// ---------------------------------------------------------------------------------------------
// The pages under test.

let browser;
let template;
const pages = [];

function fixturePage(name, options) {
  const file = path.join(artifacts, `${name}.html`);
  writeFileSync(file, insertData(template, fixtureJson(options)));
  return { name, file, truth: async (i, j, k) => WORDS[classify(i, j, k)], analyticBox: true, boxColumn: true };
}

/** An ASCII STL of the box [0, 10] x [0, 8] x [0, 4] mm, facets counter-clockwise from outside. */
function writeBox(file) {
  const v = (x, y, z) => [x * 10, y * 8, z * 4];
  const quads = [
    [v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)], [v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)],
    [v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)], [v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)],
    [v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)], [v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)],
  ];
  const facet = (a, b, c) => `facet normal 0 0 0\n outer loop\n${[a, b, c].map((p) => `  vertex ${p.join(' ')}\n`).join('')} endloop\nendfacet\n`;
  writeFileSync(file, `solid box\n${quads.map((q) => facet(q[0], q[1], q[2]) + facet(q[0], q[2], q[3])).join('')}endsolid box\n`);
}

function realPage(source, options = {}) {
  const stem = path.basename(source).replace(/\.(stl|obj|off|ply)(\.gz)?$/i, '');
  const file = path.join(artifacts, `${stem}.html`);
  const sliceDir = path.join(artifacts, `${stem}-slice`);
  run(cli, ['view', source, '-o', file, ...sliceArgs]);
  run(cli, ['slice', source, '-o', sliceDir, ...sliceArgs, '--format', 'cells']);
  const cells = path.join(sliceDir, `${stem}.cells`);
  const cache = new Map();
  return {
    name: stem,
    file,
    analyticBox: false,
    boxColumn: !!options.boxColumn,
    truth: async (i, j, k) => {
      const key = `${i},${j},${k}`;
      if (!cache.has(key)) {
        const out = run(cli, ['info', cells, '--cell', key]);
        const m = /cell\s+(\d+),(\d+),(\d+)\s+(empty|interior|boundary)/.exec(out);
        assert.ok(m, `strata info --cell ${key} printed no class: ${out.trim()}`);
        cache.set(key, m[4]);
      }
      return cache.get(key);
    },
  };
}

before(async () => {
  mkdirSync(artifacts, { recursive: true });
  template = await buildTemplate();
  writeFileSync(path.join(artifacts, 'template.html'), template);
  pages.push(fixturePage('fixture', {}), fixturePage('fixture-reduced', { lite: true }));
  if (cli) {
    const box = path.join(artifacts, 'box.stl');
    writeBox(box);
    pages.push(realPage(box, { boxColumn: true }));
    for (const model of models) pages.push(realPage(model));
  }
  browser = await acquireBrowser();
});

after(async () => {
  await releaseBrowser();
});

/** Opens a page with the network blocked (file:// only) and its errors recorded. */
async function open(file) {
  const context = await newContext(browser, { viewport: VIEWPORT, deviceScaleFactor: 1 });
  const record = { errors: [], blocked: [] };
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith('file:')) return route.continue();
    record.blocked.push(url);
    return route.abort();
  });
  const page = await context.newPage();
  page.on('console', (message) => {
    if (message.type() === 'error') record.errors.push(`console: ${message.text()}`);
  });
  page.on('pageerror', (error) => record.errors.push(`page error: ${error.message}`));
  await page.goto(pathToFileURL(file).href);
  return { context, page, record };
}

function assertClean(record) {
  assert.deepEqual(record.errors, [], 'console or page errors');
  assert.deepEqual(record.blocked, [], 'network requests were attempted');
}

async function shoot(page, name) {
  // the status bar sticks to the window's bottom; in a picture of the whole page it goes last
  await page.screenshot({ path: path.join(artifacts, `${name}.png`), fullPage: true, style: '.status { position: static; }' });
}

// ---------------------------------------------------------------------------------------------
// Reading the page like a person: pixels of canvases, the texts shown.

/** Distinct colours and the grey-level deviation of the 3D canvas. */
async function canvas3dStats(page) {
  return page.evaluate(async () => {
    const canvas = document.querySelector('.view3d-canvas');
    const image = new Image();
    image.src = canvas.toDataURL('image/png');
    await image.decode();
    const c = document.createElement('canvas');
    c.width = image.width;
    c.height = image.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(image, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    const colours = new Set();
    let sum = 0;
    let sum2 = 0;
    let hash = 0;
    for (let n = 0; n < d.length; n += 4) {
      colours.add((d[n] << 16) | (d[n + 1] << 8) | d[n + 2]);
      const grey = (d[n] + d[n + 1] + d[n + 2]) / 3;
      sum += grey;
      sum2 += grey * grey;
      hash = (hash * 31 + d[n] + 7 * d[n + 1] + 13 * d[n + 2]) >>> 0;
    }
    const count = d.length / 4;
    return { distinct: colours.size, deviation: Math.sqrt(sum2 / count - (sum / count) ** 2), hash };
  });
}

async function canvasHash(page, selector) {
  return page.evaluate((sel) => {
    const c = document.querySelector(sel);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let hash = 0;
    for (let n = 0; n < d.length; n += 4) hash = (hash * 31 + d[n] + 7 * d[n + 1] + 13 * d[n + 2]) >>> 0;
    return hash;
  }, selector);
}

async function waitLayerDrawn(page) {
  await page.waitForFunction(() => window.strataView.drawnLayer() === window.strataView.layer());
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

async function rendered(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

/** The rectangle (client pixels) the cells of the layer or section view cover, as last drawn. */
async function gridRect(page, selector) {
  const rect = await page.evaluate((which) => window.strataView.gridRect(which), selector === '#section-canvas' ? 'section' : 'layer');
  assert.ok(rect && rect.width > 0 && rect.height > 0, `no cells drawn in ${selector}`);
  return rect;
}

/** The pixel colour class at client point (x, y) of a canvas. */
async function pixelClass(page, selector, x, y) {
  const rgb = await page.evaluate(
    ([sel, cx, cy]) => {
      const c = document.querySelector(sel);
      const r = c.getBoundingClientRect();
      const px = Math.floor(((cx - r.left) / r.width) * c.width);
      const py = Math.floor(((cy - r.top) / r.height) * c.height);
      return [...c.getContext('2d').getImageData(px, py, 1, 1).data.slice(0, 3)];
    },
    [selector, x, y],
  );
  return colourClass(rgb);
}

const CELL_INFO = /^i=(\d+) j=(\d+) k=(\d+) x=(-?[\d.]+) y=(-?[\d.]+) z=(-?[\d.]+) mm {2}(empty|interior|boundary)/;

async function cellInfo(page) {
  const text = await page.textContent('#cell-info');
  const m = CELL_INFO.exec(text);
  assert.ok(m, `#cell-info does not name a cell: "${text}"`);
  return { i: +m[1], j: +m[2], k: +m[3], x: +m[4], y: +m[5], z: +m[6], word: m[7], text };
}

function assertCentre(grid, c) {
  assert.ok(Math.abs(c.x - (grid.x0 + (c.i + 0.5) * grid.dx)) < 1e-3, `x of ${c.text}`);
  assert.ok(Math.abs(c.y - (grid.y0 + (c.j + 0.5) * grid.dy)) < 1e-3, `y of ${c.text}`);
  assert.ok(Math.abs(c.z - (grid.z0 + (c.k + 0.5) * grid.dz)) < 1e-3, `z of ${c.text}`);
}

/** A cell of layer k whose class differs from that of its mirror image in y (catches flips). */
function asymmetricCell(grid, k) {
  for (let j = 0; j < grid.ny; ++j) {
    for (let i = 0; i < grid.nx; ++i) if (classify(i, j, k) !== classify(i, grid.ny - 1 - j, k)) return [i, j];
  }
  throw new Error(`the fixture's layer ${k} is symmetric in y`);
}

function layerOfLabel(text) {
  const m = /^layer (\d+) of (\d+), z = (-?[\d.]+) mm/.exec(text);
  assert.ok(m, `#layer-label reads "${text}"`);
  return { k: +m[1], nz: +m[2], z: +m[3] };
}

// ---------------------------------------------------------------------------------------------
// The tests.

test('the bare template says that the data is missing, without an uncaught error', async () => {
  const { context, page, record } = await open(path.join(artifacts, 'template.html'));
  try {
    const ready = await page.evaluate(() => window.strataView.ready);
    assert.equal(ready.ok, false);
    assert.ok(await page.isVisible('#error'));
    const text = await page.textContent('#error');
    assert.match(text, /template/i);
    assert.equal(await page.isVisible('#app'), false);
    await shoot(page, 'template');
    assertClean(record);
  } finally {
    await context.close();
  }
});

const pageNames = () => pages.map((p) => p.name);

describe('view pages', () => {
  test('each page', async (t) => {
    assert.ok(pageNames().length >= 2);
    for (const spec of pages) {
      await t.test(spec.name, async (t) => {
        const { context, page, record } = await open(spec.file);
        try {
          await checkPage(t, spec, page, record);
        } finally {
          await context.close();
        }
      });
    }
  });
});

async function checkPage(t, spec, page, record) {
  const ready = await page.evaluate(() => window.strataView.ready);
  assert.deepEqual(ready, { ok: true, error: null }, `the page did not start: ${ready.error}`);
  const grid = await page.evaluate(() => window.strataView.grid());
  await shoot(page, `${spec.name}-initial`);

  await t.test('the 3D view is not blank', async () => {
    const s = await canvas3dStats(page);
    assert.ok(s.distinct >= 8, `only ${s.distinct} colours in the 3D view`);
    assert.ok(s.deviation > 3, `the 3D view is nearly uniform (deviation ${s.deviation.toFixed(2)})`);
  });

  await t.test('each view button moves the camera, wheel zooms, fit restores', async () => {
    let previous = await page.evaluate(() => window.strataView.camera());
    for (const view of ['top', 'bottom', 'front', 'back', 'left', 'right', 'iso']) {
      await page.click(`[data-view="${view}"]`);
      await rendered(page);
      const now = await page.evaluate(() => window.strataView.camera());
      const moved = Math.hypot(now.x - previous.x, now.y - previous.y, now.z - previous.z);
      assert.ok(moved > 1e-3, `the ${view} button did not move the camera`);
      if (view === 'top') assert.ok(now.z > Math.abs(now.x) && now.z > Math.abs(now.y) - 1e-6, 'top looks from +z');
      if (view === 'front') assert.ok(now.y < 0, 'front looks from -y');
      previous = now;
    }
    const iso = previous;
    const box = await page.locator('.view3d-canvas').boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.wheel(0, -400);
    await rendered(page);
    const zoomed = await page.evaluate(() => window.strataView.camera());
    assert.ok(Math.hypot(zoomed.x - iso.x, zoomed.y - iso.y, zoomed.z - iso.z) > 1e-3, 'the wheel did not zoom');
    await page.click('[data-view="fit"]');
    await rendered(page);
    const fitted = await page.evaluate(() => window.strataView.camera());
    assert.ok(Math.hypot(fitted.x - iso.x, fitted.y - iso.y, fitted.z - iso.z) < 1e-3 * Math.hypot(iso.x, iso.y, iso.z) + 1e-6, 'fit did not restore the view');
  });

  await t.test('the slider moves through the layers by keyboard and by pointer', async () => {
    await waitLayerDrawn(page);
    const layers = await page.evaluate(() => window.strataView.layers());
    const startLabel = layerOfLabel(await page.textContent('#layer-label'));
    assert.equal(startLabel.k, await page.evaluate(() => window.strataView.layer()));
    assert.equal(startLabel.nz, grid.nz);
    assert.ok(Math.abs(startLabel.z - (grid.z0 + (startLabel.k + 0.5) * grid.dz)) < 1e-3);
    const startImage = await canvasHash(page, '#layer-canvas');

    await page.focus('#layer-slider');
    await page.keyboard.press('End');
    await waitLayerDrawn(page);
    assert.equal(layerOfLabel(await page.textContent('#layer-label')).k, layers.at(-1));
    assert.notEqual(await canvasHash(page, '#layer-canvas'), startImage, 'End did not change the layer image');

    await page.keyboard.press('Home');
    await waitLayerDrawn(page);
    assert.equal(layerOfLabel(await page.textContent('#layer-label')).k, layers[0]);
    const bottomImage = await canvasHash(page, '#layer-canvas');
    for (let n = 0; n < 3; ++n) await page.keyboard.press('ArrowRight');
    await waitLayerDrawn(page);
    assert.equal(layerOfLabel(await page.textContent('#layer-label')).k, layers[Math.min(3, layers.length - 1)]);
    await page.keyboard.press('ArrowLeft');
    await waitLayerDrawn(page);
    assert.equal(layerOfLabel(await page.textContent('#layer-label')).k, layers[Math.min(2, layers.length - 1)]);
    assert.notEqual(await canvasHash(page, '#layer-canvas'), bottomImage, 'the arrow keys did not change the layer image');

    // keys work with the focus elsewhere too (not in a form field)
    await page.locator('#layer-canvas').click();
    await page.keyboard.press('PageUp');
    await waitLayerDrawn(page);
    assert.ok(layerOfLabel(await page.textContent('#layer-label')).k > layers[Math.min(2, layers.length - 1)] || layers.length <= 3);

    // a click on the track
    const before = await canvasHash(page, '#layer-canvas');
    const beforeK = await page.evaluate(() => window.strataView.layer());
    const slider = await page.locator('#layer-slider').boundingBox();
    await page.mouse.click(slider.x + slider.width * 0.8, slider.y + slider.height / 2);
    await waitLayerDrawn(page);
    const afterK = await page.evaluate(() => window.strataView.layer());
    assert.notEqual(afterK, beforeK, 'a click on the slider did not change the layer');
    assert.equal(layerOfLabel(await page.textContent('#layer-label')).k, afterK);
    // Two layers of a real part can hold the same cells; the image must change when they differ.
    const counts = await page.evaluate(([a, b]) => {
      const layers = JSON.parse(document.getElementById('strata-data').textContent).report?.layers ?? [];
      const of = (k) => layers.find((l) => l.k === k);
      return [a, b].map((k) => (of(k) ? `${of(k).interior},${of(k).boundary}` : null));
    }, [beforeK, afterK]);
    if (counts[0] === null || counts[0] !== counts[1]) {
      assert.notEqual(await canvasHash(page, '#layer-canvas'), before, `the layer image did not change from layer ${beforeK} to ${afterK}`);
    }
  });

  await t.test('the pointer over the layer names the cell and its class', async () => {
    // a middle layer, the whole layer in view, no scanlines
    await page.focus('#layer-slider');
    await page.keyboard.press('Home');
    const layers = await page.evaluate(() => window.strataView.layers());
    const middle = Math.floor((layers.length - 1) / 2);
    for (let n = 0; n < middle; ++n) await page.keyboard.press('ArrowRight');
    await page.click('#layer-fit');
    await waitLayerDrawn(page);
    const k = await page.evaluate(() => window.strataView.layer());
    assert.equal(k, layers[middle]);
    const rect = await gridRect(page, '#layer-canvas');
    const cw = rect.width / grid.nx;
    const ch = rect.height / grid.ny;
    assert.ok(Math.abs(cw - ch * (grid.dx / grid.dy)) < 1.5, 'cells keep their aspect');
    const j = Math.floor(grid.ny / 2);
    const targets = spec.analyticBox
      ? [[0, j], [5, j], [28, j], [Math.floor(grid.nx / 2), 0], [grid.nx - 1, grid.ny - 1], asymmetricCell(grid, k)]
      : [0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 0.9].map((f) => [Math.floor(f * grid.nx), j]);
    const seen = new Set();
    for (const [i, jj] of targets) {
      const x = rect.left + (i + 0.5) * cw;
      const y = rect.top + (grid.ny - 1 - jj + 0.5) * ch; // row j=0 at the bottom
      await page.mouse.move(x, y);
      const c = await cellInfo(page);
      assert.equal(c.i, i, `i under the pointer: ${c.text}`);
      assert.equal(c.j, jj, `j under the pointer: ${c.text}`);
      assert.equal(c.k, k);
      assertCentre(grid, c);
      assert.equal(c.word, await spec.truth(i, jj, k), `class of cell ${i},${jj},${k}`);
      assert.equal(await pixelClass(page, '#layer-canvas', x, y), c.word, `colour of cell ${i},${jj},${k}`);
      seen.add(c.word);
    }
    if (spec.analyticBox) assert.deepEqual([...seen].sort(), ['boundary', 'empty', 'interior']);
    await shoot(page, `${spec.name}-layer`);
  });

  await t.test('wheel zoom and drag pan reach single cells', async () => {
    const canvas = await page.locator('#layer-canvas').boundingBox();
    const cx = canvas.x + canvas.width / 2;
    const cy = canvas.y + canvas.height / 2;
    await page.mouse.move(cx, cy);
    const centre = await cellInfo(page);
    for (let n = 0; n < 6; ++n) await page.mouse.wheel(0, -300);
    await rendered(page);
    await page.mouse.move(cx + 1, cy);
    const zoomed = await cellInfo(page);
    assert.ok(Math.abs(zoomed.i - centre.i) <= 1 && Math.abs(zoomed.j - centre.j) <= 1, 'the zoom kept the cell under the pointer');
    await page.mouse.down();
    await page.mouse.move(cx + 120, cy + 60, { steps: 4 });
    await page.mouse.up();
    await rendered(page);
    await page.mouse.move(cx, cy);
    const panned = await cellInfo(page);
    assert.ok(panned.i < zoomed.i && panned.j < zoomed.j + 1, `the drag did not pan (${zoomed.text} -> ${panned.text})`);
    await shoot(page, `${spec.name}-layer-zoomed`);
    await page.click('#layer-fit');
    await page.mouse.move(1, 1);
  });

  await t.test('the section shows the cells from bottom to top, boundary at top and bottom', async () => {
    await page.evaluate(() => document.querySelector('#section-canvas').scrollIntoView({ block: 'center' }));
    await page.waitForFunction(() => window.strataView.section()?.complete === true);
    await rendered(page);
    const rect = await gridRect(page, '#section-canvas');
    const section = await page.evaluate(() => window.strataView.section());
    assert.equal(section.axis, 'xz');
    const cw = rect.width / grid.nx;
    const ch = rect.height / grid.nz;
    assert.ok(Math.abs(cw / ch - grid.dx / grid.dz) < 0.1 * (grid.dx / grid.dz) + 0.2, 'cells at their true aspect');
    if (spec.boxColumn) {
      // the middle column: background, boundary, interior, boundary, background, bottom to top
      const column = await page.evaluate(
        ([x, top, height]) => {
          const c = document.querySelector('#section-canvas');
          const r = c.getBoundingClientRect();
          const px = Math.floor(((x - r.left) / r.width) * c.width);
          const d = c.getContext('2d').getImageData(px, 0, 1, c.height).data;
          const out = [];
          for (let y = 0; y < c.height; ++y) out.push([d[4 * y], d[4 * y + 1], d[4 * y + 2]]);
          return out;
        },
        [rect.left + (Math.floor(grid.nx / 2) + 0.5) * cw, rect.top, rect.height],
      );
      const runs = [];
      for (const rgb of column) {
        const c = colourClass(rgb);
        if (c === 'other') continue;
        if (runs.at(-1) !== c) runs.push(c);
      }
      assert.deepEqual(runs, ['background', 'boundary', 'interior', 'boundary', 'background'], `the middle column reads ${runs.join(', ')}`);
    }
    // hover: the cell and its class, against the truth and the pixel colour
    const across = [0.2, 0.5, 0.8].map((f) => Math.floor(f * grid.nx));
    const heights = [0, 1, 2, Math.floor(grid.nz / 2), grid.nz - 2, grid.nz - 1];
    if (spec.analyticBox) {
      // a cell whose class differs from that of its mirror image in z (catches flips)
      const i = across.find((a) => heights.some((k) => classify(a, section.position, k) !== classify(a, section.position, grid.nz - 1 - k)));
      assert.ok(i != null, 'the fixture is symmetric in z');
    }
    const layers = await page.evaluate(() => window.strataView.layers());
    for (const i of across) {
      for (const kk of heights) {
        if (!layers.includes(kk)) continue;
        const x = rect.left + (i + 0.5) * cw;
        const y = rect.top + (grid.nz - 1 - kk + 0.5) * ch; // z up
        await page.mouse.move(x, y);
        const c = await cellInfo(page);
        assert.equal(c.i, i, c.text);
        assert.equal(c.j, section.position, c.text);
        assert.equal(c.k, kk, c.text);
        assertCentre(grid, c);
        assert.equal(c.word, await spec.truth(i, section.position, kk), `class of cell ${i},${section.position},${kk}`);
        const colour = await pixelClass(page, '#section-canvas', x, y);
        if (colour !== 'other') assert.equal(colour, c.word, `colour of section cell ${c.text}`);
      }
    }
    await page.selectOption('#section-axis', 'yz');
    await page.waitForFunction(() => window.strataView.section()?.complete === true && window.strataView.section().axis === 'yz');
    await rendered(page);
    await page.locator('#section-canvas').screenshot({ path: path.join(artifacts, `${spec.name}-section-yz.png`) });
    await page.selectOption('#section-axis', 'xz');
    await page.waitForFunction(() => window.strataView.section()?.complete === true && window.strataView.section().axis === 'xz');
  });

  await t.test('a click on a plot selects a layer', async () => {
    const over = page.locator('.plot .u-over').first();
    if ((await over.count()) === 0) return;
    await over.scrollIntoViewIfNeeded();
    const box = await over.boundingBox();
    await page.mouse.click(box.x + box.width * 0.9, box.y + box.height / 2);
    await waitLayerDrawn(page);
    const k = await page.evaluate(() => window.strataView.layer());
    assert.ok(k >= Math.floor(grid.nz * 0.7), `the click selected layer ${k}`);
  });

  await t.test('clip and cells change the 3D view', async () => {
    await page.locator('.panel-3d').scrollIntoViewIfNeeded();
    const before = (await canvas3dStats(page)).hash;
    await page.check('#clip');
    await rendered(page);
    const clipped = (await canvas3dStats(page)).hash;
    assert.notEqual(clipped, before, 'clip did not change the 3D view');
    await page.check('#show-cells');
    await page.waitForFunction(() => window.strataView.cellsShown());
    await rendered(page);
    await page.check('#cells-beside');
    await rendered(page);
    const s = await canvas3dStats(page);
    assert.notEqual(s.hash, clipped, 'the cells did not show');
    assert.ok(s.distinct >= 8);
    await page.locator('.panel-3d').screenshot({ path: path.join(artifacts, `${spec.name}-3d-cells.png`) });
  });

  await t.test('no errors and no network requests', () => assertClean(record));
}

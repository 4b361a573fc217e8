// Browser tests of strata serve: the app page in headless Chromium (the browser of browser.mjs),
// against `strata serve --port 0` on 127.0.0.1. Needs STRATA_CLI (the strata executable);
// skipped without it.
//
// Environment: STRATA_CLI, STRATA_DATA_DIR (default data/), STRATA_SHARED_DIR (default
// ../shared), STRATA_TEST_ARTIFACTS (screenshots and downloads, default build/web-artifacts/).

import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawn } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { acquireBrowser, newContext, releaseBrowser, VIEWPORT } from './browser.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const artifacts = path.resolve(process.env.STRATA_TEST_ARTIFACTS || path.join(repo, 'build', 'web-artifacts'));
const cli = process.env.STRATA_CLI ? path.resolve(process.env.STRATA_CLI) : null;
const dataDir = path.resolve(process.env.STRATA_DATA_DIR || path.join(repo, 'data'));
const sharedDir = path.resolve(process.env.STRATA_SHARED_DIR || path.join(repo, '..', 'shared'));
const ring = path.join(dataDir, 'ring.stl');
const unparseable = path.join(sharedDir, 'corpus', 'openscad', 'tests', 'data', 'stl', 'unparseable.stl');
// 16 non-manifold edges and 356 self-intersecting facets (the corpus manifest).
const defective = path.join(sharedDir, 'corpus', 'assimp-testmodels', 'models', 'STL', '3DSMaxExport.STL');
const MAX_UPLOAD_MB = 4;

let browser;
let server; // { process, base, jobsDir, exited }

/** Starts `strata serve --port 0` and reads the address it prints. */
function startServer(args = []) {
  return new Promise((resolve, reject) => {
    const child = spawn(cli, ['serve', '--port', '0', '--max-upload', String(MAX_UPLOAD_MB), ...args], { stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '';
    let err = '';
    const exited = new Promise((done) => child.on('exit', (code, signal) => done({ code, signal, err })));
    const timer = setTimeout(() => reject(new Error(`strata serve printed no address: ${out} ${err}`)), 15_000);
    child.stderr.on('data', (d) => (err += d));
    child.stdout.on('data', (d) => {
      out += d;
      const m = /open (http:\/\/127\.0\.0\.1:(\d+)\/) in a browser \(jobs in (.+?)(, removed at exit)?; Ctrl-C stops\)/.exec(out);
      if (m) {
        clearTimeout(timer);
        resolve({ process: child, base: m[1], jobsDir: m[3], exited });
      }
    });
    child.on('error', reject);
  });
}

/** A raw request, the target sent exactly as given (no URL normalisation). */
function rawRequest(method, target, { body = null, headers = {} } = {}) {
  const url = new URL(server.base);
  return new Promise((resolve, reject) => {
    const req = http.request({ host: url.hostname, port: url.port, method, path: target, headers }, (res) => {
      let text = '';
      res.setEncoding('utf8');
      res.on('data', (d) => (text += d));
      res.on('end', () => resolve({ status: res.statusCode, text }));
    });
    req.on('error', reject);
    if (body) req.write(body);
    req.end();
  });
}

async function openApp() {
  const context = await newContext(browser, { viewport: VIEWPORT, deviceScaleFactor: 1, acceptDownloads: true });
  const errors = [];
  const page = await context.newPage();
  page.on('pageerror', (error) => errors.push(`page error: ${error.message}`));
  await page.goto(server.base);
  await page.evaluate(() => window.strataServe.ready);
  return { context, page, errors };
}

async function upload(page, file) {
  await page.setInputFiles('[data-testid="model-file"]', file);
}

/**
 * Uploads a model and waits until the app has selected its new job and checked it; the job's id.
 * The app opens on the last job of the tests before, whose verdict is already on the page: a
 * verdict alone does not tell that the upload's job is the one shown.
 */
async function uploadChecked(page, file) {
  const before = await page.evaluate(() => window.strataServe.selected());
  await upload(page, file);
  await page.waitForFunction((previous) => {
    const job = window.strataServe.job();
    return job !== null && job.id !== previous && job.check.state === 'done';
  }, before);
  await page.waitForSelector('[data-testid="verdict"]');
  return page.evaluate(() => window.strataServe.selected());
}

async function setOptions(page, options) {
  for (const [key, value] of Object.entries(options)) {
    await page.fill(`[data-testid="option-${key}"]`, String(value));
  }
}

/** The viewer of job id: of its slice (sliced), or of the model alone before it is sliced. */
async function viewerFrame(page, id, sliced = true) {
  // A check or slice under the sanitizers may take long: the context allows PAGE_TIMEOUT_MS.
  const element = await page.waitForSelector(`[data-testid="viewer-${id}"][data-sliced="${sliced}"]`);
  const frame = await element.contentFrame();
  assert.ok(frame, `no viewer frame for job ${id}`);
  await frame.waitForFunction(() => window.strataView?.ready);
  const ready = await frame.evaluate(() => window.strataView.ready);
  assert.equal(ready.error, null, `the viewer of job ${id} failed: ${ready.error}`);
  return frame;
}

function jobFolders() {
  return readdirSync(server.jobsDir).filter((n) => /^[0-9a-f]+$/.test(n)).sort();
}

describe('strata serve', { skip: cli ? false : 'STRATA_CLI is not set' }, () => {
  before(async () => {
    mkdirSync(artifacts, { recursive: true });
    server = await startServer();
    browser = await acquireBrowser();
  });

  after(async () => {
    if (server && server.process.exitCode == null) server.process.kill('SIGKILL');
    await releaseBrowser();
  });

  test('a model from data/ is uploaded, checked, sliced with a shell thickness; its cells file is the CLI\'s, byte for byte', async () => {
    const { context, page, errors } = await openApp();
    await uploadChecked(page, ring);
    assert.match(await page.textContent('[data-testid="model-info"]'), /ring\.stl/);
    const options = { layer: 0.5, cell: 0.5, shell: 1.25 };
    await setOptions(page, options);
    await page.click('[data-testid="slice"]');
    await page.waitForSelector('[data-testid="slice-done"]');
    const id = await page.evaluate(() => window.strataServe.selected());

    // The viewer of strata view on the result: move the layer slider.
    const frame = await viewerFrame(page, id);
    const layers = await frame.evaluate(() => window.strataView.layers());
    assert.ok(layers.length > 2, 'the viewer holds the layers');
    const slider = frame.locator('#layer-slider');
    await slider.focus();
    await slider.press('Home');
    assert.equal(await frame.evaluate(() => window.strataView.layer()), layers[0]);
    await slider.press('ArrowRight');
    await slider.press('ArrowRight');
    assert.equal(await frame.evaluate(() => window.strataView.layer()), layers[2]);
    await frame.waitForFunction((k) => window.strataView.drawnLayer() === k, layers[2]);

    // Download the cells file and compare it with strata slice on the same options.
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-testid="download-cells"]')]);
    assert.equal(download.suggestedFilename(), 'ring.cells');
    const got = path.join(artifacts, 'serve-ring.cells');
    await download.saveAs(got);
    const reference = path.join(artifacts, 'serve-reference');
    rmSync(reference, { recursive: true, force: true });
    execFileSync(cli, ['slice', ring, '--layer', '0.5', '--cell', '0.5', '--shell', '1.25', '--format', 'cells', '-o', reference, '-q']);
    assert.ok(readFileSync(got).equals(readFileSync(path.join(reference, 'ring.cells'))), 'the downloaded cells file differs from strata slice');

    // Every other output is offered.
    for (const kind of ['png', 'svg', 'cli', 'json', 'html']) {
      const response = await rawRequest('GET', `/api/jobs/${id}/files/${kind}`);
      assert.equal(response.status, 200, `download ${kind}`);
    }

    // A second parameter set on the same model, compared side by side.
    await setOptions(page, { shell: 0.5 });
    await page.click('[data-testid="slice"]');
    // The first job's "done" is still on the page until the new job is selected: wait for that.
    await page.waitForFunction((first) => window.strataServe.selected() !== first, id);
    const second = await page.evaluate(() => window.strataServe.selected());
    await page.waitForFunction(() => window.strataServe.job()?.slice?.state === 'done');
    await page.waitForSelector('[data-testid="slice-done"]');
    assert.notEqual(second, id, 'a new parameter set is a new job');
    await page.check(`[data-testid="job-${id}"] input[type="checkbox"]`);
    await viewerFrame(page, second);
    await viewerFrame(page, id);
    await page.waitForTimeout(500);
    await page.screenshot({ path: path.join(artifacts, 'serve.png') });

    // Jobs survive a reload.
    await page.reload();
    await page.evaluate(() => window.strataServe.ready);
    assert.equal(await page.evaluate(() => window.strataServe.selected()), second);
    assert.equal(await page.locator('[data-testid^="job-"]').count() >= 2, true);
    assert.deepEqual(errors, []);
    await context.close();
  });

  test('once checked, before any slice, the model and its defects are drawn in 3D', { skip: existsSync(defective) ? false : `${defective} is missing` }, async () => {
    const { context, page } = await openApp();
    const id = await uploadChecked(page, defective);
    const frame = await viewerFrame(page, id, false);
    assert.match(await frame.textContent('#model-meta'), /not sliced yet/);
    const legend = await frame.textContent('#legend-3d');
    assert.match(legend, /non-manifold edges: 16/);
    assert.match(legend, /self-intersecting facets: 356/);
    assert.equal(await frame.isVisible('#layer-canvas'), false, 'no layer view before the slice');
    const colours = await frame.evaluate(() => {
      const d = document.querySelector('#view3d canvas').toDataURL('image/png');
      return d.length;
    });
    assert.ok(colours > 5000, 'the 3D view is drawn');
    await page.screenshot({ path: path.join(artifacts, 'serve-checked.png') });
    await context.close();
  });

  test('a malformed model is reported in the page with the reader\'s message, and the server stays up', { skip: existsSync(unparseable) ? false : `${unparseable} is missing` }, async () => {
    const { context, page } = await openApp();
    await upload(page, unparseable);
    const error = page.locator('[data-testid="model-error"]');
    await error.waitFor();
    const text = await error.textContent();
    assert.match(text, /cannot be read/);
    assert.match(text, /unparseable\.stl/);
    assert.ok(!text.includes(server.jobsDir), 'the message names the file, not its place on the server');
    assert.equal(await page.isDisabled('[data-testid="slice"]'), true);
    await page.screenshot({ path: path.join(artifacts, 'serve-malformed.png') });
    const info = await rawRequest('GET', '/api/info');
    assert.equal(info.status, 200);
    await context.close();
  });

  test('an upload over the size limit is refused with a clear message and nothing is kept', async () => {
    const big = path.join(artifacts, 'too-big.stl');
    writeFileSync(big, Buffer.alloc((MAX_UPLOAD_MB + 1) * 1_000_000, 32));
    const before = jobFolders();
    // In the page, before sending.
    const { context, page } = await openApp();
    await upload(page, big);
    await page.waitForSelector('[data-testid="message"]:not([hidden])');
    assert.match(await page.textContent('[data-testid="message"]'), /larger than the upload limit of 4\.00 MB/);
    await context.close();
    // At the server, whatever the page does.
    const bytes = readFileSync(big);
    const refused = await rawRequest('POST', '/api/jobs?name=too-big.stl', { body: bytes, headers: { 'Content-Type': 'application/octet-stream', 'Content-Length': bytes.length } });
    const chunked = await rawRequest('POST', '/api/jobs?name=too-big.stl', { body: bytes, headers: { 'Transfer-Encoding': 'chunked' } });
    assert.equal(chunked.status, 411);
    assert.equal(refused.status, 413);
    assert.match(JSON.parse(refused.text).error, /larger than the upload limit of 4 MB.*nothing was kept/);
    assert.deepEqual(jobFolders(), before, 'no job folder was kept');
    rmSync(big);
  });

  test('a long job is cancelled mid-way and leaves no output', async () => {
    const { context, page } = await openApp();
    await uploadChecked(page, ring);
    // Many cheap layers (10000 of 200 x 200 cells, a shell that reaches 10 layers): under the
    // sanitizers the first ones come within a second or two, the whole job takes a minute or more.
    // (800 x 800 cells a layer and a shell reaching 25 layers once took over 2 minutes to the
    // first layer under the sanitizers beside the other tests.)
    await setOptions(page, { layer: 0.001, cell: 0.2, shell: 0.01 });
    await page.click('[data-testid="slice"]');
    const id = await page.evaluate(() => window.strataServe.selected());
    await page.waitForFunction(() => (window.strataServe.job()?.slice.done ?? 0) > 0);
    await page.click('[data-testid="cancel"]');
    await page.waitForSelector('[data-testid="slice-cancelled"]');
    const status = JSON.parse((await rawRequest('GET', `/api/jobs/${id}`)).text);
    assert.equal(status.slice.state, 'cancelled');
    assert.ok(status.slice.done < status.slice.total, 'cancelled before the last layer');
    assert.deepEqual(status.files.filter((f) => !['model', 'check'].includes(f)), []);
    assert.equal(existsSync(path.join(server.jobsDir, id, 'out')), false, 'no partial output');
    assert.equal((await rawRequest('GET', `/api/jobs/${id}/files/cells`)).status, 404);
    await context.close();
  });

  test('only the page\'s API is served; path traversal and foreign hosts are refused', async () => {
    for (const target of ['/api/jobs/../../etc/passwd', '/api/jobs/000001/files/../../job.json', '/api/jobs/%2e%2e/x', '/..%2fetc', '/api/jobs/000001\\..\\x']) {
      const r = await rawRequest('GET', target);
      assert.equal(r.status, 400, target);
    }
    for (const target of ['/etc/passwd', '/api/jobs/000001/job.json', '/api/jobs/000001/files/options', '/api/jobs/ZZ', '/index.html', '/api/jobs/000001/model/ring.stl']) {
      const r = await rawRequest('GET', target);
      assert.equal(r.status, 404, target);
    }
    assert.equal((await rawRequest('PUT', '/api/jobs/000001')).status, 405);
    assert.equal((await rawRequest('POST', '/api/jobs?name=..%2F..%2Fevil.sh')).status, 400);
    assert.equal((await rawRequest('GET', '/api/jobs', { headers: { Host: 'attacker.example' } })).status, 403);
  });

  test('Ctrl-C stops the server cleanly and removes the temporary jobs folder', async () => {
    assert.ok(existsSync(server.jobsDir));
    server.process.kill('SIGINT');
    const { code, signal } = await server.exited;
    assert.equal(signal, null);
    assert.equal(code, 0);
    assert.equal(existsSync(server.jobsDir), false);
  });
});

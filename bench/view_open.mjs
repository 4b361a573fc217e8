// Times what a person waits for in the view page, in headless Chromium (Debian's chromium):
//   node bench/view_open.mjs [--runs N] PAGE.html [PAGE.html ...]
// For each page, N fresh loads (median and range printed): load until the first layer and the 3D
// view are drawn, the next 20 layers one key press at a time, the section built from every
// layer, the sliced entity shown in 3D; and the page's JavaScript heap afterwards.
// Make the pages with `strata view` (the README's "Seeing a slice" gives the commands).
import { statSync } from 'node:fs';
import path from 'node:path';
import { chromium } from 'playwright-core';

const args = process.argv.slice(2);
let runs = 3;
const pages = [];
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--runs') runs = Number(args[++i]);
  else pages.push(args[i]);
}
if (!pages.length || !(runs >= 1)) {
  console.error('usage: node bench/view_open.mjs [--runs N] PAGE.html [PAGE.html ...]');
  process.exit(2);
}

const browser = await chromium.launch({
  executablePath: process.env.STRATA_CHROMIUM ?? '/usr/bin/chromium',
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox',
    '--disable-background-networking', '--disable-component-update', '--no-first-run'],
});

async function waitFor(page, predicate, arg, timeout = 600_000) {
  await page.waitForFunction(predicate, arg, { timeout, polling: 'raf' });
}

async function once(file) {
  const context = await browser.newContext({ viewport: { width: 1600, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  const t0 = performance.now();
  await page.goto(`file://${path.resolve(file)}`, { timeout: 600_000 });
  await page.evaluate(() => window.strataView.ready);
  const load = performance.now() - t0;

  await page.locator('#layer-slider').focus();
  const t1 = performance.now();
  for (let step = 0; step < 20; ++step) {
    const before = await page.evaluate(() => window.strataView.drawnLayer());
    await page.keyboard.press('ArrowRight');
    await waitFor(page, (b) => window.strataView.drawnLayer() !== b, before);
  }
  const layerStep = (performance.now() - t1) / 20;

  const t2 = performance.now();
  await page.locator('#section-canvas').scrollIntoViewIfNeeded();
  await waitFor(page, () => window.strataView.section()?.complete === true);
  const section = performance.now() - t2;

  await page.locator('#view3d').scrollIntoViewIfNeeded();
  const t3 = performance.now();
  await page.locator('#show-cells').check();
  await waitFor(page, () => window.strataView.cellsShown());
  const cells3d = performance.now() - t3;

  const session = await context.newCDPSession(page);
  await session.send('Performance.enable');
  const { metrics } = await session.send('Performance.getMetrics');
  const heap = metrics.find((m) => m.name === 'JSHeapUsedSize')?.value ?? NaN;
  await context.close();
  if (errors.length) throw new Error(`${file}: ${errors.join('; ')}`);
  return { load, layerStep, section, cells3d, heap: heap / 2 ** 20 };
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const cell = (xs, digits = 0) => {
  const s = [...xs].sort((a, b) => a - b);
  return `${median(s).toFixed(digits)} (${s[0].toFixed(digits)}–${s.at(-1).toFixed(digits)})`;
};

console.log(`| page | size | load to first layer, ms | next layer, ms | section, ms | cells in 3D, ms | JS heap, MiB |`);
console.log(`|---|---|---|---|---|---|---|`);
for (const file of pages) {
  const results = [];
  for (let r = 0; r < runs; ++r) results.push(await once(file));
  const size = statSync(file).size / 1e6;
  const col = (key, digits) => cell(results.map((x) => x[key]), digits);
  console.log(`| ${path.basename(file)} | ${size.toFixed(1)} MB | ${col('load')} | ${col('layerStep', 1)} | ${col('section')} | ${col('cells3d')} | ${col('heap')} |`);
}
await browser.close();

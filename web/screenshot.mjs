// Takes a screenshot of a view page in headless Chromium (Debian's chromium), as the README's:
//   node web/screenshot.mjs PAGE.html OUT.png [--width W] [--height H] [--layer K] [--cells]
// It waits until the page has drawn its first layer and its 3D view; --layer selects a layer
// first, --cells shows the sliced entity beside the model.
import path from 'node:path';
import { chromium } from 'playwright-core';

const args = process.argv.slice(2);
const positional = [];
const options = { width: 1400, height: 900, layer: null, cells: false };
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--width') options.width = Number(args[++i]);
  else if (args[i] === '--height') options.height = Number(args[++i]);
  else if (args[i] === '--layer') options.layer = Number(args[++i]);
  else if (args[i] === '--cells') options.cells = true;
  else positional.push(args[i]);
}
if (positional.length !== 2) {
  console.error('usage: node web/screenshot.mjs PAGE.html OUT.png [--width W] [--height H] [--layer K] [--cells]');
  process.exit(2);
}
const [input, output] = positional;
const browser = await chromium.launch({
  executablePath: process.env.STRATA_CHROMIUM ?? '/usr/bin/chromium',
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox',
    '--disable-background-networking', '--disable-component-update', '--no-first-run'],
});
try {
  const page = await browser.newPage({ viewport: { width: options.width, height: options.height } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(`file://${path.resolve(input)}`);
  const ready = await page.evaluate(() => window.strataView.ready);
  if (ready && ready.ok === false) throw new Error(`the page shows an error: ${ready.error ?? ''}`);
  if (options.layer !== null) {
    await page.locator('#layer-slider').focus();
    await page.keyboard.press('Home');
    for (let n = 0; n < 10_000 && (await page.evaluate(() => window.strataView.layer())) < options.layer; ++n) {
      await page.keyboard.press('ArrowRight');
    }
    await page.waitForFunction(() => window.strataView.drawnLayer() === window.strataView.layer());
  }
  if (options.cells) {
    await page.locator('#show-cells').check();
    await page.locator('#cells-beside').check();
    await page.waitForFunction(() => window.strataView.cellsShown());
  }
  await page.waitForTimeout(300);
  await page.screenshot({ path: output });
  if (errors.length) throw new Error(errors.join('; '));
  console.log(`wrote ${output}`);
} finally {
  await browser.close();
}

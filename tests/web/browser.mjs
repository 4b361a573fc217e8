// One headless Chromium for every browser suite of a node process: the suites acquire it in
// their before() and release it in their after(); the last release closes it. all.mjs imports
// every suite, so that CTest starts Chromium once.

import { chromium } from 'playwright-core';

export const chromiumPath = process.env.STRATA_CHROMIUM || '/usr/bin/chromium';

const ARGS = [
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];

/**
 * How long a page may take to show what a test waits for (a frame drawn, a job done). Under the
 * sanitizers, beside the other tests on two cores, Chromium's software WebGL and the strata
 * processes the pages start run several times slower than alone; Playwright's default of 30 s
 * was once too short there. A test that fails still fails, only later.
 */
export const PAGE_TIMEOUT_MS = 120_000;

/**
 * The pages' size in every suite: a common laptop screen. Chromium draws WebGL in software here
 * (SwiftShader, 4x multisampled), at a cost that goes with the pixels: at 1400 x 950 (view pages)
 * and 1500 x 950 (the app) the suites took a third more CPU time.
 */
export const VIEWPORT = { width: 1280, height: 800 };

/** A new browser context whose waits and actions allow PAGE_TIMEOUT_MS. */
export async function newContext(browser, options) {
  const context = await browser.newContext(options);
  context.setDefaultTimeout(PAGE_TIMEOUT_MS);
  return context;
}

let launched = null;
let users = 0;

/** The shared browser, launched on first use. */
export async function acquireBrowser() {
  users += 1;
  launched ??= chromium.launch({ executablePath: chromiumPath, args: ARGS });
  return launched;
}

/** Gives the browser back; the last user closes it. */
export async function releaseBrowser() {
  users = Math.max(0, users - 1);
  if (users > 0 || !launched) return;
  const browser = await launched;
  launched = null;
  await browser.close();
}

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

// Builds the page of strata view: bundles web/src (three.js, uPlot and their CSS included) and
// inlines JavaScript and CSS into one HTML file that holds the data marker exactly once; and the
// app page of strata serve (web/src/app/), which shows that page's views in frames.
//
//   node web/build.mjs OUT.html                  the template (the marker still in place)
//   node web/build.mjs OUT.html --data FILE.json a page with that data put in place of the marker
//   node web/build.mjs OUT.html --app            the app page of strata serve

import { mkdir, readFile, rename, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import * as esbuild from 'esbuild';

export const MARKER = '__STRATA_VIEW_DATA__';
const here = path.dirname(fileURLToPath(import.meta.url));
const source = path.join(here, 'src');

class BuildError extends Error {}

function occurrences(text, what) {
  let n = 0;
  for (let at = text.indexOf(what); at !== -1; at = text.indexOf(what, at + what.length)) ++n;
  return n;
}

/** The page template: one HTML string holding MARKER exactly once. */
export async function buildTemplate() {
  const html = await bundlePage(path.join(source, 'main.js'), path.join(source, 'index.html'));
  const n = occurrences(html, MARKER);
  if (n !== 1) throw new BuildError(`the page holds the marker ${MARKER} ${n} times, not once`);
  return html;
}

/** The app page of strata serve: web/src/app/ bundled into one HTML string. */
export async function buildAppPage() {
  const html = await bundlePage(path.join(source, 'app', 'main.js'), path.join(source, 'app', 'index.html'));
  if (html.includes(MARKER)) throw new BuildError(`the app page holds the data marker ${MARKER}`);
  return html;
}

/** Bundles an entry module and inlines it, with its CSS, into an HTML file's two slots. */
async function bundlePage(entry, htmlFile) {
  let result;
  try {
    result = await esbuild.build({
      entryPoints: [entry],
      bundle: true,
      format: 'iife',
      minify: true,
      target: ['chrome109', 'firefox115', 'safari16'],
      write: false,
      outdir: path.join(here, 'dist'),
      logLevel: 'silent',
      legalComments: 'eof',
      charset: 'utf8',
      loader: { '.css': 'css' },
    });
  } catch (e) {
    const messages = (e.errors ?? []).map((m) => `${m.location ? `${m.location.file}:${m.location.line}: ` : ''}${m.text}`);
    throw new BuildError(`bundling failed:\n  ${messages.join('\n  ') || e.message}`);
  }
  const js = result.outputFiles.find((f) => f.path.endsWith('.js'))?.text;
  const css = result.outputFiles.find((f) => f.path.endsWith('.css'))?.text ?? '';
  if (!js) throw new BuildError('bundling produced no JavaScript');
  if (/<\/script/i.test(js)) throw new BuildError('the bundled JavaScript contains "</script" and cannot be inlined');
  if (/<\/style/i.test(css)) throw new BuildError('the bundled CSS contains "</style" and cannot be inlined');
  if (js.includes(MARKER) || css.includes(MARKER)) throw new BuildError(`the bundle contains the data marker ${MARKER}`);

  const template = await readFile(htmlFile, 'utf8');
  for (const slot of ['<!--STRATA_STYLE-->', '<!--STRATA_SCRIPT-->']) {
    if (occurrences(template, slot) !== 1) throw new BuildError(`${path.relative(here, htmlFile)} must hold ${slot} exactly once`);
  }
  return template
    .replace('<!--STRATA_STYLE-->', () => `<style>\n${css}</style>`)
    .replace('<!--STRATA_SCRIPT-->', () => `<script>\n${js}</script>`);
}

/** Puts JSON text in place of the marker, as strata view does ("</" escaped). */
export function insertData(template, jsonText) {
  try {
    JSON.parse(jsonText);
  } catch (e) {
    throw new BuildError(`the data is not valid JSON: ${e.message}`);
  }
  const safe = jsonText.replace(/<\//g, '<\\/');
  return template.replace(MARKER, () => safe);
}

async function writeAtomically(file, text) {
  await mkdir(path.dirname(path.resolve(file)), { recursive: true });
  const temporary = `${file}.${process.pid}.tmp`;
  await writeFile(temporary, text);
  await rename(temporary, file);
}

/** Builds and writes OUT (with the data of dataFile when given; the app page when app). */
export async function buildPage(out, dataFile = null, app = false) {
  let html = app ? await buildAppPage() : await buildTemplate();
  if (dataFile) {
    let text;
    try {
      text = await readFile(dataFile, 'utf8');
    } catch (e) {
      throw new BuildError(`cannot read the data file ${dataFile}: ${e.message}`);
    }
    html = insertData(html, text);
  }
  await writeAtomically(out, html);
  return html.length;
}

async function main(argv) {
  const usage = 'usage: node web/build.mjs OUT.html [--data FILE.json | --app]';
  let out = null;
  let data = null;
  let app = false;
  for (let n = 0; n < argv.length; ++n) {
    const a = argv[n];
    if (a === '--data') {
      data = argv[++n];
      if (!data) throw new BuildError(`--data needs a file\n${usage}`);
    } else if (a === '--app') {
      app = true;
    } else if (a === '-h' || a === '--help') {
      console.log(usage);
      return;
    } else if (a.startsWith('-')) {
      throw new BuildError(`unknown option ${a}\n${usage}`);
    } else if (out) {
      throw new BuildError(`more than one output file\n${usage}`);
    } else {
      out = a;
    }
  }
  if (!out || (app && data)) throw new BuildError(usage);
  const started = performance.now();
  const bytes = await buildPage(out, data, app);
  console.log(`wrote ${out} (${(bytes / 1024).toFixed(0)} KiB) in ${((performance.now() - started) / 1000).toFixed(1)} s`);
}

if (process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href) {
  main(process.argv.slice(2)).catch((e) => {
    console.error(`web/build.mjs: error: ${e instanceof BuildError ? e.message : e.stack ?? e}`);
    process.exit(1);
  });
}

// A bounded load test of strata serve on 127.0.0.1: N concurrent clients send R requests in all,
// mixed uploads (each checked on the pool) and reads (job list and status, the app page, the
// viewer, the page data, downloads). It stops by itself and prints the figures; it fails when a
// request that should succeed did not, the server died, or its memory did not come back near
// its idle level.
//
//   node bench/serve_load.mjs [--clients 20] [--requests 200] [--cli build/release/src/strata]
//                             [--model data/ring.stl]

import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, a, n, all) => (a.startsWith('--') ? [...pairs, [a.slice(2), all[n + 1]]] : pairs), []),
);
const clients = Number(args.clients ?? 20);
const total = Number(args.requests ?? 200);
const cli = path.resolve(args.cli ?? process.env.STRATA_CLI ?? path.join(repo, 'build', 'release', 'src', 'strata'));
const modelPath = path.resolve(args.model ?? path.join(repo, 'data', 'ring.stl'));
const model = readFileSync(modelPath);

function rssKb(pid) {
  const status = readFileSync(`/proc/${pid}/status`, 'utf8');
  return Number(/VmRSS:\s+(\d+)/.exec(status)[1]);
}

function request(port, method, target, body = null) {
  return new Promise((resolve) => {
    const started = performance.now();
    const headers = body ? { 'Content-Length': body.length, 'Content-Type': 'application/octet-stream' } : {};
    const req = http.request({ host: '127.0.0.1', port, method, path: target, headers, agent: false }, (res) => {
      const chunks = [];
      res.on('data', (d) => chunks.push(d));
      res.on('end', () => resolve({ status: res.statusCode, body: Buffer.concat(chunks), ms: performance.now() - started }));
      res.on('error', (e) => resolve({ status: 0, error: e.message, ms: performance.now() - started }));
    });
    req.on('error', (e) => resolve({ status: 0, error: e.message, ms: performance.now() - started }));
    if (body) req.write(body);
    req.end();
  });
}

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

async function main() {
  const server = spawn(cli, ['serve', '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  const port = await new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (d) => {
      out += d;
      const m = /127\.0\.0\.1:(\d+)\//.exec(out);
      if (m) resolve(Number(m[1]));
    });
    server.on('exit', () => reject(new Error('strata serve exited')));
  });
  let stopping = false;
  let died = false;
  server.on('exit', () => (died = !stopping));

  // Warm up: one job, sliced, so that reads have files to fetch.
  const first = JSON.parse((await request(port, 'POST', `/api/jobs?name=${path.basename(modelPath)}`, model)).body).id;
  await request(port, 'POST', `/api/jobs/${first}/slice`, Buffer.from('{"cell":0.5,"layer":0.5}'));
  for (;;) {
    const s = JSON.parse((await request(port, 'GET', `/api/jobs/${first}`)).body);
    if (s.slice.state === 'done') break;
    if (s.slice.state === 'failed') throw new Error(s.slice.error);
    await sleep(100);
  }
  for (const target of ['/', `/viewer?job=${first}`, `/api/jobs/${first}/view.json`, `/api/jobs/${first}/files/png`]) {
    await request(port, 'GET', target);
  }
  await sleep(500);
  const idle = rssKb(server.pid);

  const kinds = [
    ['upload', 'POST', `/api/jobs?name=${path.basename(modelPath)}`, model, 201],
    ['list', 'GET', '/api/jobs', null, 200],
    ['status', 'GET', `/api/jobs/${first}`, null, 200],
    ['app page', 'GET', '/', null, 200],
    ['viewer', 'GET', `/viewer?job=${first}`, null, 200],
    ['page data', 'GET', `/api/jobs/${first}/view.json`, null, 200],
    ['cells', 'GET', `/api/jobs/${first}/files/cells`, null, 200],
    ['png zip', 'GET', `/api/jobs/${first}/files/png`, null, 200],
    ['refused', 'GET', '/api/jobs/../etc/passwd', null, 400],
    ['unknown', 'GET', '/nothing', null, 404],
  ];
  // Slices run on the pool meanwhile: the requests must not wait for them.
  const busy = [];
  for (let n = 0; n < 2; ++n) {
    const r = JSON.parse((await request(port, 'POST', `/api/jobs/${first}/slice`, Buffer.from('{"cell":0.04,"layer":0.04}'))).body);
    busy.push(r.id);
  }
  const results = [];
  let next = 0;
  let peak = idle;
  const sampler = setInterval(() => {
    try {
      peak = Math.max(peak, rssKb(server.pid));
    } catch {
      /* gone */
    }
  }, 20);
  const started = performance.now();
  await Promise.all(
    Array.from({ length: clients }, async () => {
      while (next < total) {
        const n = next++;
        const [name, method, target, body, expected] = kinds[n % kinds.length];
        const r = await request(port, method, target, body);
        results.push({ name, expected, ...r });
      }
    }),
  );
  const seconds = (performance.now() - started) / 1000;
  const slicing = [];
  for (const id of busy) {
    const s = JSON.parse((await request(port, 'GET', `/api/jobs/${id}`)).body).slice;
    slicing.push(`${s.state} at layer ${s.done} of ${s.total}`);
    await request(port, 'POST', `/api/jobs/${id}/cancel`, Buffer.from('{}'));
  }
  // Wait for the uploads' checks to finish, then for memory to settle.
  for (let n = 0; n < 300; ++n) {
    const jobs = JSON.parse((await request(port, 'GET', '/api/jobs')).body).jobs;
    const active = (t) => t.state === 'queued' || t.state === 'running';
    if (jobs.every((j) => !active(j.check) && !active(j.slice))) break;
    await sleep(100);
  }
  await sleep(1000);
  clearInterval(sampler);
  const after = rssKb(server.pid);
  const jobs = JSON.parse((await request(port, 'GET', '/api/jobs')).body).jobs.length;
  stopping = true;
  server.kill('SIGINT');
  const exit = await new Promise((resolve) => server.on('exit', (code, signal) => resolve({ code, signal })));

  const failed = results.filter((r) => r.status !== r.expected);
  const ms = results.map((r) => r.ms).sort((a, b) => a - b);
  const at = (q) => ms[Math.min(ms.length - 1, Math.floor(q * ms.length))].toFixed(1);
  console.log(`strata serve load test: ${clients} clients, ${results.length} requests in ${seconds.toFixed(2)} s (${(results.length / seconds).toFixed(0)} requests/s)`);
  for (const [name] of kinds) {
    const mine = results.filter((r) => r.name === name);
    const bad = mine.filter((r) => r.status !== r.expected).length;
    const t = mine.map((r) => r.ms).sort((a, b) => a - b);
    console.log(`  ${name.padEnd(10)} ${String(mine.length).padStart(4)} requests, ${bad} failed, median ${t[t.length >> 1].toFixed(1)} ms, max ${t.at(-1).toFixed(1)} ms`);
  }
  console.log(`  meanwhile two slices of 1000 x 1000 x 250 cells ran on the pool (${slicing.join(', ')}; cancelled after)`);
  console.log(`  latency   median ${at(0.5)} ms, 95th percentile ${at(0.95)} ms, max ${at(1)} ms`);
  console.log(`  memory    idle ${(idle / 1024).toFixed(1)} MB, peak ${(peak / 1024).toFixed(1)} MB, after ${(after / 1024).toFixed(1)} MB (${jobs} jobs held)`);
  console.log(`  exit      ${exit.signal ?? `code ${exit.code}`} after SIGINT`);
  const problems = [];
  if (failed.length) problems.push(`${failed.length} requests failed: ${failed.slice(0, 5).map((r) => `${r.name} ${r.status} ${r.error ?? ''}`).join('; ')}`);
  if (died || exit.code !== 0) problems.push('the server did not stop cleanly');
  if (after > idle * 1.5 + 20 * 1024) problems.push(`memory did not come back near idle (${idle} kB -> ${after} kB)`);
  if (problems.length) {
    console.error(`FAILED: ${problems.join('; ')}`);
    process.exit(1);
  }
  console.log('ok');
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});

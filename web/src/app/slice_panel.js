// The selected job's slice: progress, state, and its downloads.

import { count, escapeHtml, seconds } from '../format.js';
import { fileUrl } from './api.js';

const DOWNLOADS = [
  ['cells', 'cells file', '.cells'],
  ['png', 'PNG stack', '.zip'],
  ['svg', 'SVG layers', '.zip'],
  ['cli', 'CLI contours and hatches', '.cli'],
  ['json', 'report', '.json'],
  ['html', 'view page', '.html'],
  ['model', 'model', ''],
  ['check', 'check report', '.json'],
  ['validation', 'validation report', '.json'],
];

export const running = (task) => task?.state === 'queued' || task?.state === 'running';

export function showSlice({ progress, status, cancel }, job) {
  const s = job?.slice;
  cancel.disabled = !running(s);
  if (!s || s.state === 'none') {
    progress.value = 0;
    status.textContent = job ? 'not sliced yet' : '';
    return;
  }
  progress.max = Math.max(1, s.total);
  progress.value = s.state === 'done' ? progress.max : s.done;
  if (s.state === 'queued') status.textContent = 'queued…';
  else if (s.state === 'running') status.textContent = s.total ? `slicing: layer ${s.done} of ${s.total}` : 'reading and checking the model…';
  else if (s.state === 'cancelled') status.innerHTML = `<span class="error-text" data-testid="slice-cancelled">cancelled</span> · ${escapeHtml(s.error)}`;
  else if (s.state === 'failed') status.innerHTML = `<span class="error-text" data-testid="slice-error">${escapeHtml(s.error)}</span>`;
  else if (s.state === 'done') {
    const r = s.result ?? {};
    const g = r.grid ?? {};
    const c = r.cells ?? {};
    status.innerHTML =
      `<span data-testid="slice-done">done</span> in ${seconds(s.seconds)} · ${count(g.nx)} × ${count(g.ny)} × ${count(g.nz)} cells · ` +
      `${count(c.interior)} interior, ${count(c.boundary)} boundary`;
  }
}

export function showDownloads(element, job) {
  const files = new Set(job?.files ?? []);
  const links = DOWNLOADS.filter(([kind]) => files.has(kind)).map(
    ([kind, label, ext]) =>
      `<a class="download" href="${fileUrl(job.id, kind)}" download data-testid="download-${kind}" title="${escapeHtml(job.stem + ext)}">${escapeHtml(label)}</a>`,
  );
  element.innerHTML = links.length ? links.join('') : '<span class="muted small">Slice to get the outputs.</span>';
}

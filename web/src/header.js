// The page header: the model's title, the verdict of strata check and of the validation, and
// the notes the page must tell (a simplified mesh, a subsampled stack, missing parts).

import { count, escapeHtml } from './format.js';

const VERDICTS = {
  printable: ['good', 'printable'],
  'printable-under-rule': ['warn', 'printable under the fill rule'],
  'needs-repair': ['bad', 'needs repair'],
};

export function fillHeader({ title, meta, verdict, notes }, data) {
  document.title = `${data.title} – strata view`;
  title.textContent = data.title;
  const g = data.grid;
  const parts = data.layerCount === 0
    ? ['not sliced yet']
    : [`${g.nx} × ${g.ny} × ${g.nz} cells`, `${data.grid.dx} × ${data.grid.dy} × ${data.grid.dz} mm`];
  if (data.raw.generator) parts.push(data.raw.generator);
  meta.textContent = parts.join(' · ');

  const badges = [];
  if (data.check) {
    const [cls, word] = VERDICTS[data.check.verdict] ?? ['warn', data.check.verdict ?? 'unknown'];
    const reason = data.check.reason ? ` <span class="reason">${escapeHtml(data.check.reason)}</span>` : '';
    badges.push(`<span class="badge ${cls}">mesh: ${escapeHtml(word)}</span>${reason}`);
  }
  const v = data.validation;
  if (v) {
    badges.push(
      v.cells_differing > 0
        ? `<span class="badge bad">fast ≠ exact in ${count(v.cells_differing)} cells</span>`
        : `<span class="badge good">fast = exact on ${count(v.cells_compared)} cells</span>`,
    );
  }
  verdict.innerHTML = badges.join(' ');

  const list = data.notes.filter((n) => typeof n === 'string' && n.trim());
  notes.hidden = list.length === 0;
  notes.innerHTML = list.map((n) => `<li>${escapeHtml(n)}</li>`).join('');
}

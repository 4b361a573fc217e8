// The selected job's model: strata check's verdict and defects, or the reader's message; and
// the result of strata validate.

import { count, escapeHtml, num } from '../format.js';

const DEFECTS = [
  ['boundary_edges', 'open edges'],
  ['non_manifold_edges', 'non-manifold edges'],
  ['inconsistent_edges', 'edges of flipped neighbours'],
  ['degenerate_facets', 'degenerate facets'],
  ['duplicate_facets', 'duplicate facets'],
  ['non_manifold_vertices', 'non-manifold vertices'],
  ['self_intersections', 'self-intersections'],
];

const VERDICTS = {
  printable: 'printable',
  'printable-under-rule': 'printable under the fill rule',
  'needs-repair': 'needs repair',
};

export function showModel(element, job) {
  if (!job) {
    element.textContent = 'No model open.';
    return;
  }
  const check = job.check;
  const name = `<div class="model-name">${escapeHtml(job.name)}</div>`;
  if (check.state === 'queued' || check.state === 'running') {
    element.innerHTML = `${name}<div class="muted">checking the mesh…</div>`;
  } else if (check.state === 'failed') {
    element.innerHTML = `${name}<div class="error-text" data-testid="model-error"><b>This model cannot be read.</b> ${escapeHtml(check.error)}</div>`;
  } else if (check.state === 'done' && check.result) {
    const r = check.result;
    const m = r.model ?? {};
    const size = m.min_mm && m.max_mm ? m.max_mm.map((v, n) => num(v - m.min_mm[n])).join(' × ') : '–';
    const defects = DEFECTS.map(([key, label]) => [label, r[key]?.count ?? 0]).filter(([, n]) => n > 0);
    element.innerHTML =
      `${name}<div class="muted small">${escapeHtml(m.format ?? '')} · ${count(m.facets)} facets · ${size} mm</div>` +
      `<div class="verdict-line"><span class="verdict-chip ${escapeHtml(r.verdict)}" data-testid="verdict">${escapeHtml(VERDICTS[r.verdict] ?? r.verdict)}</span> ` +
      `<span class="small">${escapeHtml(r.reason ?? '')}</span></div>` +
      (defects.length
        ? `<ul class="defects">${defects.map(([label, n]) => `<li>${count(n)} ${escapeHtml(label)}</li>`).join('')}</ul><div class="muted small">Drawn in colour in the 3D view.</div>`
        : '<div class="muted small">no defects found</div>') +
      (m.warnings?.length ? `<ul class="warnings">${m.warnings.map((w) => `<li>${escapeHtml(w)}</li>`).join('')}</ul>` : '');
  } else {
    element.innerHTML = `${name}<div class="muted">${escapeHtml(check.state)}</div>`;
  }
}

export function showValidation(element, job) {
  const v = job?.validate;
  if (!v || v.state === 'none') {
    element.textContent = '';
  } else if (v.state === 'queued' || v.state === 'running') {
    element.textContent = v.total ? `validating… layer ${v.done} of ${v.total}` : 'validating…';
  } else if (v.state === 'failed') {
    element.innerHTML = `<span class="error-text">validation failed: ${escapeHtml(v.error)}</span>`;
  } else if (v.state === 'cancelled') {
    element.textContent = 'validation cancelled';
  } else if (v.result) {
    const c = v.result.cells ?? {};
    const agree = v.result.verdict === 'agree';
    element.innerHTML =
      `<span class="verdict-chip ${agree ? 'printable' : 'needs-repair'}" data-testid="validate-verdict">${agree ? 'fast = exact' : escapeHtml(v.result.verdict)}</span> ` +
      `${count(c.differing)} of ${count(c.compared)} cells differ · ` +
      `<a href="/api/jobs/${job.id}/files/validation" download>report</a>`;
  }
}

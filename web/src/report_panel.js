// The report panel: the slice parameters, the cell counts by class, the volumes and their
// relative errors, open chains, exact fallbacks, timings, and the fast-vs-exact validation.

import { count, escapeHtml, mm, num, percent, seconds } from './format.js';

function table(title, rows, note = '') {
  const body = rows
    .filter(Boolean)
    .map(([name, value, cls]) => `<tr class="${cls ?? ''}"><th>${escapeHtml(name)}</th><td>${value}</td></tr>`)
    .join('');
  return `<div class="card"><h3>${escapeHtml(title)}</h3><table>${body}</table>${note}</div>`;
}

const e = escapeHtml;

function relative(a, b) {
  return Number.isFinite(a) && Number.isFinite(b) && b !== 0 ? (a - b) / Math.abs(b) : null;
}

export function fillReport(container, data) {
  const r = data.report;
  const g = data.grid;
  const cards = [];
  const size = [g.nx * g.dx, g.ny * g.dy, g.nz * g.dz];
  const cellsTotal = g.nx * g.ny * g.nz;

  if (r?.parameters) {
    const p = r.parameters;
    cards.push(
      table('Parameters', [
        ['layer thickness', `${num(p.layer_mm)} mm`],
        ['cell', p.dx_mm === p.dy_mm ? `${num(p.dx_mm)} mm` : `${num(p.dx_mm)} × ${num(p.dy_mm)} mm`],
        ['shell', `${num(p.shell_mm ?? data.raw.shell_mm)} mm (${e(p.shell_mode ?? '–')})`],
        ['fill rule', e(p.fill_rule ?? '–')],
        ['scan offset', `${num(p.scan_offset_mm)} mm`],
        ['kernel', e(p.kernel ?? '–')],
        ['threads', count(p.threads)],
      ]),
    );
  } else if (data.raw.shell_mm != null) {
    cards.push(table('Parameters', [['shell', `${num(data.raw.shell_mm)} mm`]]));
  }

  cards.push(
    table('Grid', [
      ['cells', `${count(g.nx)} × ${count(g.ny)} × ${count(g.nz)} = ${count(cellsTotal)}`],
      ['origin', `${mm(g.x0)}, ${mm(g.y0)}, ${mm(g.z0)} mm`],
      ['spacing', `${num(g.dx)}, ${num(g.dy)}, ${num(g.dz)} mm`],
      ['size', `${num(size[0])} × ${num(size[1])} × ${num(size[2])} mm`],
      ['layers in this page', `${count(data.layerCount)}${data.stride > 1 ? ` (every ${data.stride})` : ''}`],
    ]),
  );

  if (r?.cells) {
    const c = r.cells;
    const total = (c.empty ?? 0) + (c.interior ?? 0) + (c.boundary ?? 0);
    const share = (n) => (total ? ` <span class="muted">${((100 * n) / total).toFixed(1)} %</span>` : '');
    cards.push(
      table('Cells by class', [
        [`empty (00)`, `<span class="chip empty"></span>${count(c.empty)}${share(c.empty)}`],
        [`interior (01)`, `<span class="chip interior"></span>${count(c.interior)}${share(c.interior)}`],
        [`boundary (11)`, `<span class="chip boundary"></span>${count(c.boundary)}${share(c.boundary)}`],
        r.empty_layers_inside_model ? ['empty layers inside', count(r.empty_layers_inside_model), 'warn'] : null,
      ]),
    );
  }

  if (r?.metrics) {
    const m = r.metrics;
    const cellError = m.cell_volume_relative_error ?? relative(m.cell_volume_mm3, m.mesh_volume_mm3);
    const contourError = relative(m.contour_volume_mm3, m.mesh_volume_mm3);
    cards.push(
      table('Volumes', [
        ['mesh', `${num(m.mesh_volume_mm3, 6)} mm³`],
        ['cells', `${num(m.cell_volume_mm3, 6)} mm³ <span class="muted">${percent(cellError)}</span>`],
        ['contours (Σ area · dz)', `${num(m.contour_volume_mm3, 6)} mm³ <span class="muted">${percent(contourError)}</span>`],
        ['surface area', `${num(m.surface_area_mm2, 6)} mm²`],
      ]),
    );
    const chains = r.open_chains ?? {};
    const firstChains = (chains.first ?? []).slice(0, 5);
    const chainNote = firstChains.length
      ? `<p class="muted small">first: ${firstChains.map((c) => `layer ${c.layer} (gap ${num(c.gap_mm, 3)} mm)`).join(', ')}</p>`
      : '';
    cards.push(
      table(
        'Slicing',
        [
          ['segments', count(m.segments)],
          ['open chains', count(chains.count ?? 0), chains.count > 0 ? 'warn' : ''],
          ['exact fallbacks', count(m.exact_fallbacks)],
          ['layers with crossing loops', count(m.crossing_loop_layers), m.crossing_loop_layers > 0 ? 'warn' : ''],
          ['layers with misnested loops', count(m.misnested_loop_layers), m.misnested_loop_layers > 0 ? 'warn' : ''],
          ['outlined layers', count(m.outline_layers), m.outline_layers > 0 ? 'warn' : ''],
        ],
        chainNote,
      ),
    );
  }

  if (r?.model) {
    const mo = r.model;
    cards.push(
      table('Model', [
        ['file', `<span class="path">${e(mo.path ?? data.raw.source?.path ?? '–')}</span>`],
        ['format', e(mo.format ?? '–')],
        ['facets', count(mo.facets)],
        ['vertices', count(mo.vertices)],
        mo.bbox_min_mm ? ['bounding box', `${mo.bbox_min_mm.map((v) => mm(v)).join(', ')} … ${mo.bbox_max_mm.map((v) => mm(v)).join(', ')} mm`] : null,
        mo.defects?.shells != null ? ['shells', count(mo.defects.shells)] : null,
      ]),
    );
  }

  if (r?.timings_s) {
    const t = r.timings_s;
    cards.push(table('Timings', Object.entries(t).map(([name, v]) => [name, seconds(v)])));
  }

  const v = data.validation;
  if (v) {
    const layers = v.layers_differing ?? [];
    const list = layers.length
      ? `<p class="small">differing layers: ${layers
          .slice(0, 40)
          .map((k) => `<button type="button" class="link" data-layer="${k}">${k}</button>`)
          .join(' ')}${layers.length > 40 ? ` … (${layers.length} in all)` : ''}</p>`
      : '';
    cards.push(
      table(
        'Fast vs exact',
        [
          ['cells compared', count(v.cells_compared)],
          ['cells differing', count(v.cells_differing), v.cells_differing > 0 ? 'bad' : 'good'],
          ['layers differing', count(layers.length), layers.length > 0 ? 'bad' : ''],
          v.cells && v.cells.length < v.cells_differing ? ['cells listed', count(v.cells.length)] : null,
        ],
        list,
      ),
    );
  }

  const diagnostics = r?.diagnostics ?? [];
  if (diagnostics.length) {
    const items = diagnostics
      .slice(0, 12)
      .map((d) => `<li class="${d.severity === 'warning' ? 'warn' : ''}"><b>${e(d.code)}</b> ${e(d.message)}</li>`)
      .join('');
    cards.push(`<div class="card wide"><h3>Diagnostics</h3><ul class="diagnostics">${items}</ul></div>`);
  }

  if (!r) cards.push('<div class="card"><h3>Report</h3><p class="muted">This page holds no slice report.</p></div>');
  container.innerHTML = cards.join('');
}

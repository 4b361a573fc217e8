// Number and text formatting for the page.

import { CLASS_WORDS } from './data.js';

const integer = new Intl.NumberFormat('en-US', { maximumFractionDigits: 0 });

export function count(n) {
  return n == null || Number.isNaN(n) ? '–' : integer.format(n);
}

export function mm(v, digits = 3) {
  return v == null || !Number.isFinite(v) ? '–' : v.toFixed(digits);
}

/** A number with a sensible number of significant digits. */
export function num(v, significant = 4) {
  if (v == null || !Number.isFinite(v)) return '–';
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e6 || a < 1e-4) return v.toExponential(significant - 1);
  const digits = Math.max(0, significant - 1 - Math.floor(Math.log10(a)));
  return v.toFixed(Math.min(digits, 6));
}

export function percent(v, digits = 2) {
  if (v == null || !Number.isFinite(v)) return '–';
  return `${v >= 0 ? '+' : ''}${(v * 100).toFixed(digits)} %`;
}

export function seconds(v) {
  if (v == null || !Number.isFinite(v)) return '–';
  return v < 1 ? `${(v * 1000).toFixed(0)} ms` : `${v.toFixed(2)} s`;
}

/** The text of #cell-info for cell (i, j, k) of class code. */
export function cellText(grid, i, j, k, code) {
  const x = grid.x0 + (i + 0.5) * grid.dx;
  const y = grid.y0 + (j + 0.5) * grid.dy;
  const z = grid.z0 + (k + 0.5) * grid.dz;
  return `i=${i} j=${j} k=${k} x=${mm(x)} y=${mm(y)} z=${mm(z)} mm  ${CLASS_WORDS[code]}`;
}

export function escapeHtml(text) {
  return String(text).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
}

// The layer slider, its label, the keyboard (Left/Right, PageUp/PageDown, Home/End), the marks
// of the layers on which the fast and exact paths differ, and the selected layer's counts.

import { count, escapeHtml, mm, num } from './format.js';

export class LayerControls {
  constructor({ slider, label, marks, stats, data, state }) {
    this.slider = slider;
    this.label = label;
    this.stats = stats;
    this.data = data;
    this.state = state;
    slider.min = '0';
    slider.max = String(data.layerCount - 1);
    slider.step = '1';
    slider.value = String(state.index);
    slider.disabled = data.layerCount < 2;
    slider.addEventListener('input', () => state.selectIndex(Number(slider.value)));
    document.addEventListener('keydown', (event) => this.#key(event));
    state.onLayer(() => this.update());
    this.#drawMarks(marks);
    this.update();
  }

  #key(event) {
    if (event.altKey || event.ctrlKey || event.metaKey) return;
    const t = event.target;
    const isSlider = t === this.slider;
    if (!isSlider && t instanceof HTMLElement && t.closest('input, select, textarea, [contenteditable="true"]')) {
      if (!(t instanceof HTMLInputElement && (t.type === 'checkbox' || t.type === 'button'))) return;
    }
    const page = Math.max(1, Math.round(this.data.layerCount / 10));
    const steps = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1, PageUp: page, PageDown: -page };
    let next;
    if (event.key in steps) {
      // Up and Down stay with the page's scrolling unless the slider has the focus.
      if (!isSlider && (event.key === 'ArrowUp' || event.key === 'ArrowDown')) return;
      next = this.state.index + steps[event.key];
    } else if (event.key === 'Home') next = 0;
    else if (event.key === 'End') next = this.data.layerCount - 1;
    else return;
    event.preventDefault();
    this.state.selectIndex(next);
  }

  update() {
    const { data, state } = this;
    const k = state.k;
    this.slider.value = String(state.index);
    const stride = data.stride > 1 ? ` (every ${data.stride}${ordinalSuffix(data.stride)} layer stored)` : '';
    this.label.textContent = `layer ${k} of ${data.grid.nz}, z = ${mm(data.layerZ(k))} mm${stride}`;
    this.label.classList.toggle('differs', data.differingLayers.has(k));
    this.#fillStats(k);
  }

  #fillStats(k) {
    const l = this.data.reportLayers.get(k);
    const rows = [];
    if (l) {
      rows.push(['interior cells', count(l.interior)], ['boundary cells', count(l.boundary)]);
      rows.push(['outer loops', count(l.outer_loops)], ['holes', count(l.holes)]);
      rows.push(['open chains', count(l.open_chains), l.open_chains > 0 ? 'warn' : '']);
      rows.push(['contour area', `${num(l.contour_area_mm2)} mm²`]);
      if (l.loops_cross) rows.push(['loops cross', 'yes', 'warn']);
      if (l.outline) rows.push(['outlined', 'yes', 'warn']);
    } else {
      rows.push(['counts', 'not in the report']);
    }
    const differing = this.data.differing.get(k);
    if (this.data.validation) {
      const n = differing?.length ?? 0;
      rows.push(['fast ≠ exact', count(n), n > 0 || this.data.differingLayers.has(k) ? 'bad' : '']);
    }
    this.stats.innerHTML = rows
      .map(([name, value, cls]) => `<tr class="${cls ?? ''}"><th>${escapeHtml(name)}</th><td>${escapeHtml(value)}</td></tr>`)
      .join('');
  }

  #drawMarks(marks) {
    marks.textContent = '';
    const { data } = this;
    if (!data.validation || data.layerCount < 2) return;
    for (const k of data.differingLayers) {
      const index = data.indexOfLayer(k);
      if (data.stored[index] !== k) continue;
      const tick = document.createElement('span');
      tick.className = 'tick';
      tick.style.left = `${(index / (data.layerCount - 1)) * 100}%`;
      tick.title = `layer ${k}: fast and exact cells differ`;
      marks.append(tick);
    }
  }
}

function ordinalSuffix(n) {
  const t = n % 100;
  if (t >= 11 && t <= 13) return 'th';
  return { 1: 'st', 2: 'nd', 3: 'rd' }[n % 10] ?? 'th';
}

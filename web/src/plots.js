// Per-layer plots of the report (uPlot): contour area by height, and interior and boundary
// cells by height. The selected layer is marked, layers where the fast and exact paths differ
// are marked red, and a click selects the layer under the pointer.

import uPlot from 'uplot';
import { DIFFERING, SELECTED_LAYER } from './palette.js';

export class LayerPlots {
  constructor({ container, data, state }) {
    this.data = data;
    this.state = state;
    this.plots = [];
    const layers = (data.report?.layers ?? []).filter((l) => Number.isFinite(l.z_mm));
    if (layers.length === 0) {
      container.innerHTML = '<p class="muted">The report holds no per-layer counts.</p>';
      return;
    }
    this.layers = layers;
    const z = layers.map((l) => l.z_mm);
    const specs = [
      {
        title: 'contour area by height',
        y: 'area (mm²)',
        series: [{ label: 'contour area (mm²)', stroke: '#1c7ed6', fill: 'rgba(28,126,214,0.08)', values: layers.map((l) => l.contour_area_mm2) }],
      },
      {
        title: 'cells by height',
        y: 'cells',
        series: [
          { label: 'interior', stroke: '#6c8fb8', values: layers.map((l) => l.interior) },
          { label: 'boundary', stroke: '#212529', values: layers.map((l) => l.boundary) },
        ],
      },
    ];
    for (const spec of specs) {
      const box = document.createElement('div');
      box.className = 'plot';
      box.innerHTML = `<h3>${spec.title}</h3>`;
      container.append(box);
      const plot = new uPlot(
        {
          width: Math.max(200, box.clientWidth || 400),
          height: 170,
          cursor: { drag: { x: false, y: false }, points: { size: 6 } },
          legend: { live: true },
          scales: { x: { time: false } },
          axes: [
            { label: 'z (mm)', labelSize: 18, size: 36, stroke: '#495057', grid: { stroke: '#e9ecef' } },
            { label: spec.y, labelSize: 20, size: 72, stroke: '#495057', grid: { stroke: '#e9ecef' } },
          ],
          series: [{ label: 'z (mm)', value: (u, v) => (v == null ? '–' : v.toFixed(3)) }, ...spec.series.map((s) => ({ label: s.label, stroke: s.stroke, fill: s.fill, width: 1.5, points: { show: false } }))],
          hooks: { draw: [(u) => this.#marks(u)] },
        },
        [z, ...spec.series.map((s) => s.values)],
        box,
      );
      plot.over.addEventListener('click', () => {
        const index = plot.cursor.idx;
        if (index != null && layers[index]) state.selectLayer(layers[index].k);
      });
      plot.over.title = 'click to select the layer';
      this.plots.push({ plot, box });
    }
    new ResizeObserver(() => {
      for (const { plot, box } of this.plots) {
        const width = Math.max(200, box.clientWidth);
        if (Math.abs(width - plot.width) > 1) plot.setSize({ width, height: 170 });
      }
    }).observe(container);
    state.onLayer(() => {
      for (const { plot } of this.plots) plot.redraw(false, false);
    });
  }

  #marks(u) {
    const ctx = u.ctx;
    const { top, height } = u.bbox;
    const line = (z, colour, width, dash) => {
      const x = Math.round(u.valToPos(z, 'x', true));
      ctx.save();
      ctx.strokeStyle = colour;
      ctx.lineWidth = width;
      ctx.setLineDash(dash);
      ctx.beginPath();
      ctx.moveTo(x, top);
      ctx.lineTo(x, top + height);
      ctx.stroke();
      ctx.restore();
    };
    const dpr = window.devicePixelRatio || 1;
    for (const k of this.data.differingLayers) line(this.data.layerZ(k), DIFFERING, 1.5 * dpr, []);
    line(this.data.layerZ(this.state.k), SELECTED_LAYER, 2 * dpr, [5 * dpr, 4 * dpr]);
  }
}

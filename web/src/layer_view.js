// The layer view: the selected layer's cells as an image (one pixel a cell, y up), its
// contours (outer loops, holes, open chains), optionally the scanline segments, the cells on
// which the fast and exact paths differ, and cell grid lines when zoomed in far enough.

import { Viewport2D } from './viewport2d.js';
import { layerCanvas } from './layer_image.js';
import { cellText } from './format.js';
import { CONTOUR, DIFFERING, HATCH } from './palette.js';
import { clearCanvas, drawCellImage, drawMessage, outlineCellRect, outlineCells } from './canvas_draw.js';

export class LayerView {
  constructor({ canvas, data, state, showHatches, fitButton, setCellInfo, onImage }) {
    this.onImage = onImage ?? (() => {});
    this.canvas = canvas;
    this.data = data;
    this.state = state;
    this.showHatches = showHatches;
    this.setCellInfo = setCellInfo;
    this.image = null; // {index, canvas, layer}
    this.pending = -1;
    this.hoverPoint = null;
    this.error = null;
    const g = data.grid;
    this.viewport = new Viewport2D(canvas, {
      draw: () => this.draw(),
      hover: (x, y) => this.hover(x, y),
      maxPxPerMm: () => 160 / Math.min(g.dx, g.dy),
    });
    this.viewport.setBounds(g.x0, g.y0, g.x0 + g.nx * g.dx, g.y0 + g.ny * g.dy);
    showHatches.addEventListener('change', () => this.viewport.requestDraw());
    fitButton.addEventListener('click', () => this.viewport.fit());
    this.firstDraw = new Promise((resolve) => (this.resolveFirstDraw = resolve));
    state.onLayer((index) => this.show(index));
    if (!data.hasHatches) {
      showHatches.disabled = true;
      showHatches.closest('label')?.setAttribute('title', 'this page holds no scanline segments');
    }
  }

  /** Decodes stored layer `index` (if needed) and draws it. */
  async show(index) {
    this.pending = index;
    let layer;
    try {
      layer = await this.data.layer(index);
    } catch (e) {
      this.error = e.message;
      this.viewport.requestDraw();
      return;
    }
    if (this.pending !== index) return; // a newer request won
    this.error = null;
    this.image = { index, layer, canvas: layerCanvas(layer) };
    this.viewport.requestDraw();
    this.onImage();
    if (this.hoverPoint) this.hover(...this.hoverPoint);
    this.#prefetch(index);
  }

  /** Decodes the neighbours of a shown layer ahead, so that stepping through layers waits less. */
  #prefetch(index) {
    const last = this.data.stored.length - 1;
    for (const n of [index + 1, index - 1, index + 2, index - 2]) {
      if (n < 0 || n > last || this.data.layerIfReady(n)) continue;
      this.data.layer(n).catch(() => {}); // an error shows when that layer is shown
    }
  }

  /** The image of the selected layer with empty cells transparent (for the 3D cutting plane). */
  transparentImage() {
    return this.image ? layerCanvas(this.image.layer, { transparentEmpty: true }) : null;
  }

  draw() {
    const ctx = this.canvas.getContext('2d');
    const vp = this.viewport;
    const g = this.data.grid;
    const dpr = vp.dpr;
    clearCanvas(ctx, this.canvas);
    if (this.error) {
      drawMessage(ctx, this.canvas, dpr, this.error);
      return;
    }
    if (!this.image) {
      drawMessage(ctx, this.canvas, dpr, 'decoding layer…');
      return;
    }
    this.cellRect = drawCellImage(ctx, vp, this.image.canvas, g.x0, g.y0, g.dx, g.dy, g.nx, g.ny);
    const n = this.image.index;
    if (this.showHatches.checked) this.#drawHatches(ctx, this.data.hatches(n));
    this.#drawContours(ctx, this.data.contours(n));
    this.#drawDiffering(ctx, this.image.layer.k);
    outlineCellRect(ctx, this.cellRect, dpr);
    this.drawnK = this.image.layer.k;
    if (!this.firstDrawn) {
      this.firstDrawn = true;
      this.resolveFirstDraw();
    }
  }

  #path(ctx, points, close) {
    const vp = this.viewport;
    const s = vp.scale;
    const ox = this.canvas.width / 2 - vp.cx * s;
    const oy = this.canvas.height / 2 + vp.cy * s;
    for (let n = 0; n + 1 < points.length; n += 2) {
      const x = ox + points[n] * s;
      const y = oy - points[n + 1] * s;
      if (n === 0) ctx.moveTo(x, y);
      else ctx.lineTo(x, y);
    }
    if (close) ctx.closePath();
  }

  #drawContours(ctx, loops) {
    const dpr = this.viewport.dpr;
    ctx.lineJoin = 'round';
    for (const kind of ['outer', 'hole', 'open']) {
      ctx.beginPath();
      for (const loop of loops) if (loop.kind === kind) this.#path(ctx, loop.points, kind !== 'open');
      ctx.strokeStyle = CONTOUR[kind];
      ctx.lineWidth = (kind === 'open' ? 2.5 : 1.75) * dpr;
      ctx.setLineDash(kind === 'open' ? [6 * dpr, 4 * dpr] : []);
      ctx.stroke();
    }
    ctx.setLineDash([]);
  }

  #drawHatches(ctx, segments) {
    const vp = this.viewport;
    const s = vp.scale;
    const ox = this.canvas.width / 2 - vp.cx * s;
    const oy = this.canvas.height / 2 + vp.cy * s;
    ctx.beginPath();
    for (let n = 0; n + 3 < segments.length; n += 4) {
      ctx.moveTo(ox + segments[n] * s, oy - segments[n + 1] * s);
      ctx.lineTo(ox + segments[n + 2] * s, oy - segments[n + 3] * s);
    }
    ctx.strokeStyle = HATCH;
    ctx.lineWidth = Math.max(1, 1.25 * vp.dpr);
    ctx.stroke();
  }

  #drawDiffering(ctx, k) {
    const cells = this.data.differing.get(k);
    const g = this.data.grid;
    if (cells) outlineCells(ctx, this.viewport, cells, g.x0, g.y0, g.dx, g.dy, DIFFERING);
  }

  /** Names the cell under world point (x, y), or clears the note when off the grid. */
  hover(x, y) {
    if (x == null) {
      this.hoverPoint = null;
      this.setCellInfo(null);
      return;
    }
    this.hoverPoint = [x, y];
    const g = this.data.grid;
    const i = Math.floor((x - g.x0) / g.dx);
    const j = Math.floor((y - g.y0) / g.dy);
    if (!this.image || i < 0 || j < 0 || i >= g.nx || j >= g.ny) {
      this.setCellInfo(null);
      return;
    }
    const layer = this.image.layer;
    let text = cellText(g, i, j, layer.k, layer.code(i, j));
    const differing = this.data.differing.get(layer.k)?.find((c) => c[0] === i && c[1] === j);
    if (differing) text += `  (fast ${code2(differing[2])}, exact ${code2(differing[3])})`;
    this.setCellInfo(text);
  }
}

function code2(code) {
  return ['00', '01', '10', '11'][code & 3];
}

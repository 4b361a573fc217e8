// The section view: a vertical section through the stack, XZ at row j or YZ at column i,
// assembled from the stored layers (decoded when the section is first shown), z up, cells at
// their true aspect, the selected layer marked by a line.

import { Viewport2D } from './viewport2d.js';
import { cellText, mm } from './format.js';
import { CELL_RGB, DIFFERING, SELECTED_LAYER } from './palette.js';
import { clearCanvas, drawCellImage, drawMessage, outlineCellRect, outlineCells } from './canvas_draw.js';

export class SectionView {
  constructor({ canvas, axisSelect, slider, sliderLabel, progress, fitButton, data, state, setCellInfo }) {
    this.canvas = canvas;
    this.axisSelect = axisSelect;
    this.slider = slider;
    this.sliderLabel = sliderLabel;
    this.progress = progress;
    this.data = data;
    this.state = state;
    this.setCellInfo = setCellInfo;
    this.axis = axisSelect.value === 'yz' ? 'yz' : 'xz';
    this.position = this.#middle();
    this.section = null; // {axis, position, across, codes, image, rep}
    this.generation = 0;
    this.started = false;
    this.complete = false;
    this.hoverPoint = null;
    this.viewport = new Viewport2D(canvas, {
      draw: () => this.draw(),
      hover: (x, y) => this.hover(x, y),
      maxPxPerMm: () => 160 / Math.min(data.grid.dx, data.grid.dy, data.grid.dz),
    });
    this.#setBounds();
    axisSelect.addEventListener('change', () => {
      this.axis = axisSelect.value === 'yz' ? 'yz' : 'xz';
      this.position = this.#middle();
      this.viewport.fitted = true;
      this.#setBounds();
      this.#syncSlider();
      this.assemble();
    });
    slider.addEventListener('input', () => {
      this.position = Number(slider.value);
      this.#syncSlider();
      this.assemble();
    });
    fitButton.addEventListener('click', () => this.viewport.fit());
    state.onLayer(() => this.viewport.requestDraw());
    this.#syncSlider();
    // Decode the stack only when the section comes into view.
    new IntersectionObserver((entries) => {
      if (entries.some((e) => e.isIntersecting) && !this.started) this.assemble();
    }).observe(canvas);
  }

  #middle() {
    const g = this.data.grid;
    return Math.floor((this.axis === 'xz' ? g.ny : g.nx) / 2);
  }

  #syncSlider() {
    const g = this.data.grid;
    const n = this.axis === 'xz' ? g.ny : g.nx;
    this.slider.max = String(n - 1);
    this.slider.value = String(this.position);
    const name = this.axis === 'xz' ? 'row j' : 'column i';
    const coordinate = this.axis === 'xz' ? `y = ${mm(g.y0 + (this.position + 0.5) * g.dy)}` : `x = ${mm(g.x0 + (this.position + 0.5) * g.dx)}`;
    this.sliderLabel.textContent = `${name} = ${this.position}, ${coordinate} mm`;
  }

  #setBounds() {
    const g = this.data.grid;
    const [a0, da, na] = this.axis === 'xz' ? [g.x0, g.dx, g.nx] : [g.y0, g.dy, g.ny];
    this.viewport.setBounds(a0, g.z0, a0 + na * da, g.z0 + g.nz * g.dz);
  }

  /** Builds the section from the stored layers; decodes those not yet decoded. */
  async assemble() {
    this.started = true;
    this.complete = false;
    const generation = ++this.generation;
    const { data } = this;
    const g = data.grid;
    const axis = this.axis;
    const position = this.position;
    const across = axis === 'xz' ? g.nx : g.ny;
    const codes = new Uint8Array(across * g.nz);
    const rep = new Int32Array(g.nz).fill(-1);
    const total = data.layerCount;
    let decoded = 0;
    const needDecoding = data.stored.some((_, n) => !data.layerIfReady(n));
    const showProgress = () => {
      if (needDecoding) this.progress.textContent = `decoding layers ${decoded} of ${total}…`;
    };
    this.progress.hidden = !needDecoding;
    showProgress();
    let failed = null;
    let next = 0;
    const worker = async () => {
      while (next < total && generation === this.generation) {
        const n = next++;
        let layer;
        try {
          layer = data.layerIfReady(n) ?? (await data.layer(n));
        } catch (e) {
          failed = e.message;
          return;
        }
        const k0 = data.stored[n];
        const k1 = n + 1 < total ? data.stored[n + 1] : Math.min(g.nz, k0 + data.stride);
        const row = new Uint8Array(across);
        for (let a = 0; a < across; ++a) row[a] = axis === 'xz' ? layer.code(a, position) : layer.code(position, a);
        for (let k = k0; k < k1; ++k) {
          codes.set(row, k * across);
          rep[k] = k0;
        }
        if (++decoded % 8 === 0) showProgress();
      }
    };
    await Promise.all(Array.from({ length: Math.min(4, total) }, worker));
    if (generation !== this.generation) return;
    this.progress.hidden = !failed;
    if (failed) this.progress.textContent = failed;
    this.section = { axis, position, across, codes, rep, image: this.#paint(codes, across, g.nz) };
    this.complete = !failed;
    this.viewport.requestDraw();
    if (this.hoverPoint) this.hover(...this.hoverPoint);
  }

  #paint(codes, across, nz) {
    const canvas = document.createElement('canvas');
    canvas.width = across;
    canvas.height = nz;
    const ctx = canvas.getContext('2d');
    const image = ctx.createImageData(across, nz);
    const pixels = new Uint32Array(image.data.buffer);
    const lut = [0, 1, 2, 3].map((c) => {
      const [r, gg, b] = CELL_RGB[c];
      return ((255 << 24) | (b << 16) | (gg << 8) | r) >>> 0;
    });
    for (let k = 0; k < nz; ++k) {
      const row = (nz - 1 - k) * across;
      for (let a = 0; a < across; ++a) pixels[row + a] = lut[codes[k * across + a]];
    }
    ctx.putImageData(image, 0, 0);
    return canvas;
  }

  #acrossGeometry() {
    const g = this.data.grid;
    return this.axis === 'xz' ? [g.x0, g.dx, g.nx] : [g.y0, g.dy, g.ny];
  }

  draw() {
    const ctx = this.canvas.getContext('2d');
    const vp = this.viewport;
    const g = this.data.grid;
    const dpr = vp.dpr;
    clearCanvas(ctx, this.canvas);
    const s = this.section;
    if (!s || s.axis !== this.axis) {
      drawMessage(ctx, this.canvas, dpr, this.started ? 'assembling the section…' : 'the section is built when shown');
      return;
    }
    const [a0, da, na] = this.#acrossGeometry();
    this.cellRect = drawCellImage(ctx, vp, s.image, a0, g.z0, da, g.dz, na, g.nz);
    const { left, right } = this.cellRect;

    // cells on which the fast and exact paths differ, in this section
    const differing = (this.data.validation?.cells ?? [])
      .filter((c) => (s.axis === 'xz' ? c[1] === s.position : c[0] === s.position))
      .map((c) => [s.axis === 'xz' ? c[0] : c[1], c[2]]);
    if (differing.length) outlineCells(ctx, vp, differing, a0, g.z0, da, g.dz, DIFFERING);

    outlineCellRect(ctx, this.cellRect, dpr);

    // the selected layer
    const k = this.state.k;
    const [, y] = vp.toScreen(0, this.data.layerZ(k));
    ctx.strokeStyle = SELECTED_LAYER;
    ctx.lineWidth = 2 * dpr;
    ctx.setLineDash([8 * dpr, 5 * dpr]);
    ctx.beginPath();
    ctx.moveTo(left - 12 * dpr, y);
    ctx.lineTo(right + 12 * dpr, y);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.font = `${12 * dpr}px system-ui, sans-serif`;
    const text = `layer ${k}`;
    const w = ctx.measureText(text).width + 8 * dpr;
    const h = 16 * dpr;
    const bx = Math.max(2 * dpr, left + 4 * dpr);
    const by = y - h - 3 * dpr;
    ctx.fillStyle = 'rgba(255, 255, 255, 0.9)';
    ctx.fillRect(bx, by, w, h);
    ctx.fillStyle = SELECTED_LAYER;
    ctx.textBaseline = 'middle';
    ctx.fillText(text, bx + 4 * dpr, by + h / 2);
    ctx.textBaseline = 'alphabetic';
  }

  hover(x, y) {
    if (x == null) {
      this.hoverPoint = null;
      this.setCellInfo(null);
      return;
    }
    this.hoverPoint = [x, y];
    const s = this.section;
    const g = this.data.grid;
    if (!s || s.axis !== this.axis) return;
    const [a0, da, na] = this.#acrossGeometry();
    const a = Math.floor((x - a0) / da);
    const kRow = Math.floor((y - g.z0) / g.dz);
    if (a < 0 || a >= na || kRow < 0 || kRow >= g.nz || s.rep[kRow] < 0) {
      this.setCellInfo(null);
      return;
    }
    const k = s.rep[kRow];
    const [i, j] = s.axis === 'xz' ? [a, s.position] : [s.position, a];
    let text = cellText(g, i, j, k, s.codes[kRow * s.across + a]);
    if (k !== kRow) text += `  (shown for layer ${kRow})`;
    this.setCellInfo(text);
  }
}

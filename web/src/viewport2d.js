// Pan and zoom for a 2D canvas showing a plane in millimetres, y (or z) up. Wheel zooms around
// the pointer, a drag pans, two fingers pinch; the canvas keeps its size in device pixels in
// step with its size on the page. Redraws are throttled to one an animation frame.

export class Viewport2D {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{draw: () => void, hover?: (x: number|null, y: number|null) => void,
   *          minCellPx?: () => number}} options
   */
  constructor(canvas, { draw, hover, maxPxPerMm }) {
    this.canvas = canvas;
    this.drawFn = draw;
    this.hoverFn = hover ?? (() => {});
    this.maxPxPerMm = maxPxPerMm ?? (() => 1e4);
    this.bounds = { x0: 0, y0: 0, x1: 1, y1: 1 };
    this.cx = 0.5;
    this.cy = 0.5;
    this.scale = 1; // device pixels per millimetre
    this.fitted = true;
    this.frame = 0;
    this.pointers = new Map();
    this.dragged = false;
    this.#listen();
    new ResizeObserver(() => this.#resize()).observe(canvas);
    this.#resize();
  }

  get dpr() {
    return window.devicePixelRatio || 1;
  }

  setBounds(x0, y0, x1, y1) {
    this.bounds = { x0, y0, x1, y1 };
    if (this.fitted) this.fit();
    else this.requestDraw();
  }

  /** Shows the whole bounds with a margin. */
  fit() {
    const { x0, y0, x1, y1 } = this.bounds;
    const w = this.canvas.width;
    const h = this.canvas.height;
    const margin = 16 * this.dpr;
    this.scale = Math.max(1e-6, Math.min((w - 2 * margin) / Math.max(x1 - x0, 1e-9), (h - 2 * margin) / Math.max(y1 - y0, 1e-9)));
    this.cx = (x0 + x1) / 2;
    this.cy = (y0 + y1) / 2;
    this.fitted = true;
    this.requestDraw();
  }

  fitScale() {
    const { x0, y0, x1, y1 } = this.bounds;
    const margin = 16 * this.dpr;
    return Math.min((this.canvas.width - 2 * margin) / Math.max(x1 - x0, 1e-9), (this.canvas.height - 2 * margin) / Math.max(y1 - y0, 1e-9));
  }

  /** World (mm) to canvas device pixels. */
  toScreen(x, y) {
    return [this.canvas.width / 2 + (x - this.cx) * this.scale, this.canvas.height / 2 - (y - this.cy) * this.scale];
  }

  /** Canvas device pixels to world (mm). */
  toWorld(px, py) {
    return [this.cx + (px - this.canvas.width / 2) / this.scale, this.cy - (py - this.canvas.height / 2) / this.scale];
  }

  /** Client (CSS) coordinates of an event to world. */
  eventToWorld(event) {
    const r = this.canvas.getBoundingClientRect();
    const px = ((event.clientX - r.left) / r.width) * this.canvas.width;
    const py = ((event.clientY - r.top) / r.height) * this.canvas.height;
    return this.toWorld(px, py);
  }

  zoomAt(px, py, factor) {
    const [wx, wy] = this.toWorld(px, py);
    const minScale = this.fitScale() / 4;
    const maxScale = Math.max(this.maxPxPerMm() * this.dpr, minScale);
    this.scale = Math.min(maxScale, Math.max(minScale, this.scale * factor));
    // keep (wx, wy) under the pointer
    this.cx = wx - (px - this.canvas.width / 2) / this.scale;
    this.cy = wy + (py - this.canvas.height / 2) / this.scale;
    this.fitted = false;
    this.requestDraw();
  }

  requestDraw() {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.drawFn();
    });
  }

  #resize() {
    const r = this.canvas.getBoundingClientRect();
    const w = Math.max(1, Math.round(r.width * this.dpr));
    const h = Math.max(1, Math.round(r.height * this.dpr));
    if (w === this.canvas.width && h === this.canvas.height) return;
    this.canvas.width = w;
    this.canvas.height = h;
    if (this.fitted) this.fit();
    else this.requestDraw();
  }

  #devicePoint(event) {
    const r = this.canvas.getBoundingClientRect();
    return [((event.clientX - r.left) / r.width) * this.canvas.width, ((event.clientY - r.top) / r.height) * this.canvas.height];
  }

  #listen() {
    const c = this.canvas;
    c.addEventListener(
      'wheel',
      (event) => {
        event.preventDefault();
        const [px, py] = this.#devicePoint(event);
        const unit = event.deltaMode === 1 ? 33 : event.deltaMode === 2 ? 400 : 1;
        this.zoomAt(px, py, Math.exp((-event.deltaY * unit) / 500));
      },
      { passive: false },
    );
    c.addEventListener('pointerdown', (event) => {
      if (event.pointerType === 'mouse' && event.button !== 0) return;
      c.setPointerCapture(event.pointerId);
      this.pointers.set(event.pointerId, this.#devicePoint(event));
      this.dragged = false;
    });
    c.addEventListener('pointermove', (event) => {
      const p = this.#devicePoint(event);
      const previous = this.pointers.get(event.pointerId);
      if (!previous) {
        const [x, y] = this.toWorld(p[0], p[1]);
        this.hoverFn(x, y);
        return;
      }
      if (this.pointers.size === 1) {
        const dx = p[0] - previous[0];
        const dy = p[1] - previous[1];
        if (dx !== 0 || dy !== 0) {
          this.cx -= dx / this.scale;
          this.cy += dy / this.scale;
          this.fitted = false;
          this.dragged = true;
          this.requestDraw();
        }
      } else if (this.pointers.size === 2) {
        const [a, b] = [...this.pointers.entries()];
        const other = a[0] === event.pointerId ? b[1] : a[1];
        const before = Math.hypot(previous[0] - other[0], previous[1] - other[1]);
        const after = Math.hypot(p[0] - other[0], p[1] - other[1]);
        if (before > 0) this.zoomAt((p[0] + other[0]) / 2, (p[1] + other[1]) / 2, after / before);
        this.dragged = true;
      }
      this.pointers.set(event.pointerId, p);
      const [x, y] = this.toWorld(p[0], p[1]);
      this.hoverFn(x, y);
    });
    const release = (event) => {
      this.pointers.delete(event.pointerId);
    };
    c.addEventListener('pointerup', release);
    c.addEventListener('pointercancel', release);
    c.addEventListener('pointerleave', () => {
      if (this.pointers.size === 0) this.hoverFn(null, null);
    });
    c.addEventListener('dblclick', () => this.fit());
  }
}

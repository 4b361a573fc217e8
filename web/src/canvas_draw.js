// Drawing helpers shared by the 2D views.

import { CANVAS_BACKGROUND, GRID_LINE } from './palette.js';

/** Fills the whole canvas with the 2D views' background, in device pixels. */
export function clearCanvas(ctx, canvas) {
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = CANVAS_BACKGROUND;
  ctx.fillRect(0, 0, canvas.width, canvas.height);
}

/** A centred note on a canvas (for "decoding…" and errors). */
export function drawMessage(ctx, canvas, dpr, text) {
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.fillStyle = '#495057';
  ctx.font = `${14 * dpr}px system-ui, sans-serif`;
  ctx.textAlign = 'center';
  ctx.fillText(text, canvas.width / 2, canvas.height / 2);
  ctx.textAlign = 'start';
}

/**
 * Lines between cells of a regular grid (origin (x0, y0), spacing (dx, dy), nx x ny cells),
 * drawn only when a cell is at least 10 CSS pixels wide and only where visible.
 */
export function drawCellGrid(ctx, vp, x0, y0, dx, dy, nx, ny) {
  if (vp.scale * Math.min(dx, dy) < 10 * vp.dpr) return;
  const [wx0, wy1] = vp.toWorld(0, 0);
  const [wx1, wy0] = vp.toWorld(vp.canvas.width, vp.canvas.height);
  const i0 = Math.max(0, Math.floor((wx0 - x0) / dx));
  const i1 = Math.min(nx, Math.ceil((wx1 - x0) / dx));
  const j0 = Math.max(0, Math.floor((wy0 - y0) / dy));
  const j1 = Math.min(ny, Math.ceil((wy1 - y0) / dy));
  if (i0 > i1 || j0 > j1) return;
  const [left, top] = vp.toScreen(x0 + i0 * dx, y0 + j1 * dy);
  const [right, bottom] = vp.toScreen(x0 + i1 * dx, y0 + j0 * dy);
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.beginPath();
  for (let i = i0; i <= i1; ++i) {
    const x = Math.round(vp.toScreen(x0 + i * dx, 0)[0]) + 0.5;
    ctx.moveTo(x, top);
    ctx.lineTo(x, bottom);
  }
  for (let j = j0; j <= j1; ++j) {
    const y = Math.round(vp.toScreen(0, y0 + j * dy)[1]) + 0.5;
    ctx.moveTo(left, y);
    ctx.lineTo(right, y);
  }
  ctx.strokeStyle = GRID_LINE;
  ctx.lineWidth = 1;
  ctx.stroke();
}

/**
 * A cell image (one pixel a cell, its first row the cells at b0 + nb * db) drawn pixel-sharp over
 * the na x nb cells from (a0, b0) of size da x db, with the lines between cells when zoomed in
 * far enough. Returns the cells' rectangle on the canvas, {left, top, right, bottom}.
 */
export function drawCellImage(ctx, vp, image, a0, b0, da, db, na, nb) {
  const [left, top] = vp.toScreen(a0, b0 + nb * db);
  const [right, bottom] = vp.toScreen(a0 + na * da, b0);
  ctx.imageSmoothingEnabled = false;
  ctx.setTransform(vp.scale * da, 0, 0, vp.scale * db, left, top);
  ctx.drawImage(image, 0, 0);
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  drawCellGrid(ctx, vp, a0, b0, da, db, na, nb);
  return { left, top, right, bottom };
}

/** The outline of the rectangle drawCellImage returned, on the pixel grid. */
export function outlineCellRect(ctx, rect, dpr) {
  const { left, top, right, bottom } = rect;
  ctx.strokeStyle = 'rgba(80, 90, 105, 0.7)';
  ctx.lineWidth = dpr;
  ctx.strokeRect(Math.round(left) - 0.5 * dpr, Math.round(top) - 0.5 * dpr, Math.round(right - left) + dpr, Math.round(bottom - top) + dpr);
}

/** Outlines cells (at least `minPx` device pixels wide so single cells stay visible). */
export function outlineCells(ctx, vp, cells, x0, y0, dx, dy, colour) {
  const minSize = 8 * vp.dpr;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.strokeStyle = colour;
  ctx.lineWidth = 2 * vp.dpr;
  for (const [a, b] of cells) {
    const [sx0, sy1] = vp.toScreen(x0 + a * dx, y0 + (b + 1) * dy);
    const [sx1, sy0] = vp.toScreen(x0 + (a + 1) * dx, y0 + b * dy);
    const w = Math.max(minSize, sx1 - sx0);
    const h = Math.max(minSize, sy0 - sy1);
    ctx.strokeRect((sx0 + sx1) / 2 - w / 2, (sy0 + sy1) / 2 - h / 2, w, h);
  }
}

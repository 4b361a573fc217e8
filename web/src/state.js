// The selection shared by the views: the current layer (an index into the stored layers).
// Views subscribe and are told when it changes.

export class ViewState {
  constructor(data) {
    this.data = data;
    this.index = Math.floor((data.layerCount - 1) / 2);
    this.listeners = new Set();
  }

  get k() {
    return this.data.stored[this.index];
  }

  onLayer(fn) {
    this.listeners.add(fn);
  }

  /** Selects stored layer index n (clamped). */
  selectIndex(n) {
    const next = Math.max(0, Math.min(this.data.layerCount - 1, Math.round(n)));
    if (next === this.index) return;
    this.index = next;
    for (const fn of this.listeners) fn(this.index, this.k);
  }

  /** Selects the stored layer nearest to grid layer k. */
  selectLayer(k) {
    const n = this.data.indexOfLayer(k);
    const s = this.data.stored;
    const best = n + 1 < s.length && Math.abs(s[n + 1] - k) < Math.abs(s[n] - k) ? n + 1 : n;
    this.selectIndex(best);
  }
}

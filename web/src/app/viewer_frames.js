// The viewer of strata view on one or two jobs, each in its own frame (/viewer?job=ID), so that
// two parameter sets can be compared side by side.

import { escapeHtml } from '../format.js';
import { optionsSummary } from './options_form.js';
import { viewerUrl } from './api.js';

export class ViewerFrames {
  constructor(container) {
    this.container = container;
    this.shown = [];
    this.emptyHtml = container.innerHTML;
  }

  /** jobs: up to two jobs ({id, name, options, slice}), sliced or only checked. */
  show(jobs) {
    // A job's frame is loaded again once it is sliced: its data then holds the layers.
    const ids = jobs.map((j) => `${j.id}:${j.slice?.state === 'done' ? 'sliced' : 'model'}`);
    if (ids.join() === this.shown.join()) return;
    this.shown = ids;
    if (!jobs.length) {
      this.container.innerHTML = this.emptyHtml;
      this.container.classList.remove('two');
      return;
    }
    this.container.classList.toggle('two', jobs.length === 2);
    this.container.innerHTML = jobs
      .map(
        (job) =>
          `<figure class="frame"><figcaption><b>${escapeHtml(job.name)}</b> <span class="mono">${job.id}</span>${job.options ? ` · ${escapeHtml(optionsSummary(job.options))}` : ''}</figcaption>` +
          `<iframe src="${viewerUrl(job.id)}" title="viewer of job ${job.id}" data-testid="viewer-${job.id}"` +
          ` data-sliced="${job.slice?.state === 'done'}"></iframe></figure>`,
      )
      .join('');
  }
}

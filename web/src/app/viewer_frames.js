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

  /** jobs: up to two sliced jobs ({id, name, options}). */
  show(jobs) {
    const ids = jobs.map((j) => j.id);
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
          `<figure class="frame"><figcaption><b>${escapeHtml(job.name)}</b> <span class="mono">${job.id}</span> · ${escapeHtml(optionsSummary(job.options))}</figcaption>` +
          `<iframe src="${viewerUrl(job.id)}" title="viewer of job ${job.id}" data-testid="viewer-${job.id}"></iframe></figure>`,
      )
      .join('');
  }
}

// The session's jobs: one row a job (model, parameters, state); a click shows it, the compare box
// puts it beside the shown one.

import { escapeHtml } from '../format.js';
import { optionsSummary } from './options_form.js';

function stateText(job) {
  if (job.check.state === 'failed') return 'unreadable';
  const s = job.slice;
  if (s.state === 'running') return s.total ? `${Math.floor((100 * s.done) / s.total)} %` : 'running';
  if (s.state === 'none') return job.check.state === 'done' ? 'checked' : job.check.state;
  return s.state;
}

export class JobList {
  constructor(table, { onSelect, onCompare }) {
    this.table = table;
    this.onSelect = onSelect;
    this.onCompare = onCompare;
    table.addEventListener('click', (event) => {
      const row = event.target.closest('tr[data-job]');
      if (!row) return;
      if (event.target.matches('input[type="checkbox"]')) {
        this.onCompare(row.dataset.job, event.target.checked);
      } else {
        this.onSelect(row.dataset.job);
      }
    });
    table.addEventListener('keydown', (event) => {
      const row = event.target.closest('tr[data-job]');
      if (row && (event.key === 'Enter' || event.key === ' ') && !event.target.matches('input')) {
        event.preventDefault();
        this.onSelect(row.dataset.job);
      }
    });
  }

  show(jobs, selected, compared) {
    if (!jobs.length) {
      this.table.innerHTML = '<tr><td class="muted small">No jobs yet.</td></tr>';
      return;
    }
    this.table.innerHTML =
      '<tr><th>job</th><th>model · parameters</th><th>state</th><th title="show beside the selected job">compare</th></tr>' +
      jobs
        .slice()
        .reverse()
        .map((job) => {
          const sliced = job.slice.state === 'done';
          return (
            `<tr data-job="${job.id}" tabindex="0" data-testid="job-${job.id}" class="${job.id === selected ? 'selected' : ''}">` +
            `<td class="mono">${job.id}</td>` +
            `<td><div>${escapeHtml(job.name)}</div><div class="muted small">${escapeHtml(optionsSummary(job.options))}</div></td>` +
            `<td class="state ${escapeHtml(job.slice.state)}">${escapeHtml(stateText(job))}</td>` +
            `<td><input type="checkbox" aria-label="compare job ${job.id}" ${compared === job.id ? 'checked' : ''} ${sliced && job.id !== selected ? '' : 'disabled'}></td>` +
            '</tr>'
          );
        })
        .join('');
  }
}

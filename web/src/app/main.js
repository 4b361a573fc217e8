// The app page of strata serve: open a model, see its check, set the parameters, slice, look at
// the result in the viewer of strata view, download the outputs, validate; the session's jobs.
// The selected job is kept in the address (#job=ID), so a reload comes back to it.

import './app.css';
import * as api from './api.js';
import { JobList } from './job_list.js';
import { showModel, showValidation } from './model_panel.js';
import { OptionsForm } from './options_form.js';
import { running, showDownloads, showSlice } from './slice_panel.js';
import { ViewerFrames } from './viewer_frames.js';

const $ = (id) => document.getElementById(id);

const form = new OptionsForm($('options'));
const frames = new ViewerFrames($('viewer'));
let maxUpload = Infinity;
let jobs = [];
let selected = null; // the job shown
let selectedJob = null; // its full status
let compared = null; // the job beside it
let pollTimer = null;

function message(text, kind = 'error') {
  const box = $('message');
  box.hidden = !text;
  box.className = `message ${kind}`;
  box.textContent = text ?? '';
}

function megabytes(bytes) {
  return bytes >= 1e9 ? `${(bytes / 1e9).toPrecision(3)} GB` : `${(bytes / 1e6).toPrecision(3)} MB`;
}

const jobList = new JobList($('jobs'), {
  onSelect: (id) => select(id, true),
  onCompare: (id, on) => {
    compared = on ? id : null;
    render();
  },
});

function render() {
  const job = selectedJob;
  $('model-job').textContent = job ? `job ${job.id}` : '';
  showModel($('model-info'), job);
  showValidation($('validate-status'), job);
  showSlice({ progress: $('progress'), status: $('slice-status'), cancel: $('cancel') }, job);
  showDownloads($('downloads'), job);
  const readable = job && job.check.state !== 'failed';
  $('slice').disabled = !readable;
  $('validate').disabled = !readable || running(job?.validate);
  jobList.show(jobs, selected, compared);
  const shown = [];
  // Once checked, the model and its defects in 3D; once sliced, the whole viewer.
  if (job?.slice.state === 'done' || job?.check.state === 'done') shown.push(job);
  const other = jobs.find((j) => j.id === compared && j.slice.state === 'done' && j.id !== selected);
  if (other && shown.length) shown.push(other);
  frames.show(shown);
}

async function refresh() {
  try {
    jobs = (await api.listJobs()).jobs;
    if (selected) selectedJob = await api.job(selected);
  } catch (e) {
    if (selected && /no such job/.test(e.message)) {
      selected = null;
      selectedJob = null;
    } else {
      message(e.message);
    }
  }
  render();
  const busy = jobs.some((j) => running(j.check) || running(j.slice) || running(j.validate));
  clearTimeout(pollTimer);
  pollTimer = setTimeout(refresh, busy ? 300 : 3000);
}

async function select(id, fromUser = false) {
  selected = id;
  if (compared === id) compared = null;
  history.replaceState(null, '', id ? `#job=${id}` : '#');
  try {
    selectedJob = id ? await api.job(id) : null;
  } catch (e) {
    message(e.message);
    selectedJob = null;
  }
  if (fromUser && selectedJob?.options) form.set(selectedJob.options);
  await refresh();
}

async function openFile(file) {
  if (!file) return;
  message(null);
  if (file.size > maxUpload) {
    message(`${file.name} is ${megabytes(file.size)}: larger than the upload limit of ${megabytes(maxUpload)} (strata serve --max-upload).`);
    return;
  }
  const status = $('upload-status');
  status.textContent = `uploading ${file.name}…`;
  try {
    const { id } = await api.upload(file, (f) => {
      status.textContent = `uploading ${file.name}: ${Math.round(f * 100)} %`;
    });
    status.textContent = `${file.name} uploaded`;
    compared = null;
    await select(id);
  } catch (e) {
    status.textContent = '';
    message(`${file.name}: ${e.message}`);
  }
}

$('model-file').addEventListener('change', (event) => {
  openFile(event.target.files[0]);
  event.target.value = '';
});
$('open-model').addEventListener('keydown', (event) => {
  if (event.key === 'Enter' || event.key === ' ') {
    event.preventDefault();
    $('model-file').click();
  }
});

// Drag and drop anywhere on the page.
let dragDepth = 0;
window.addEventListener('dragenter', (event) => {
  if (![...(event.dataTransfer?.types ?? [])].includes('Files')) return;
  dragDepth += 1;
  $('drop-overlay').hidden = false;
});
window.addEventListener('dragleave', () => {
  dragDepth = Math.max(0, dragDepth - 1);
  if (dragDepth === 0) $('drop-overlay').hidden = true;
});
window.addEventListener('dragover', (event) => event.preventDefault());
window.addEventListener('drop', (event) => {
  event.preventDefault();
  dragDepth = 0;
  $('drop-overlay').hidden = true;
  openFile(event.dataTransfer?.files?.[0]);
});

/** The form's options; null after showing why they cannot be read. */
function formOptions() {
  message(null);
  try {
    return form.values();
  } catch (e) {
    message(e.message);
    return null;
  }
}

$('slice').addEventListener('click', async () => {
  const options = formOptions();
  if (!options) return;
  try {
    const { id } = await api.slice(selected, options);
    await select(id);
  } catch (e) {
    message(e.message);
  }
});

$('cancel').addEventListener('click', async () => {
  try {
    await api.cancel(selected);
  } catch (e) {
    message(e.message);
  }
  await refresh();
});

$('validate').addEventListener('click', async () => {
  const options = formOptions();
  if (!options) return;
  try {
    await api.validate(selected, options);
  } catch (e) {
    message(e.message);
  }
  await refresh();
});

async function start() {
  try {
    maxUpload = (await api.info()).max_upload_bytes;
    $('upload-limit').textContent = megabytes(maxUpload);
  } catch (e) {
    message(e.message);
  }
  const fromHash = /^#job=([0-9a-f]{1,16})$/.exec(location.hash)?.[1];
  jobs = (await api.listJobs().catch(() => ({ jobs: [] }))).jobs;
  const initial = fromHash && jobs.some((j) => j.id === fromHash) ? fromHash : jobs.at(-1)?.id ?? null;
  await select(initial, true);
}

window.strataServe = Object.freeze({
  ready: start(),
  selected: () => selected,
  job: () => selectedJob,
});

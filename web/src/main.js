// The page's entry point: reads the embedded data, builds the views, wires them to the shared
// layer selection, and exposes read-only helpers as window.strataView. Any failure is shown in
// the page, never a blank page.

import 'uplot/dist/uPlot.min.css';
import './style.css';
import { DataError, loadPageData, StrataData } from './data.js';
import { fillHeader } from './header.js';
import { LayerControls } from './layer_controls.js';
import { LayerView } from './layer_view.js';
import { ModelView } from './model_view.js';
import { LayerPlots } from './plots.js';
import { fillReport } from './report_panel.js';
import { SectionView } from './section_view.js';
import { ViewState } from './state.js';

const $ = (id) => document.getElementById(id);

function showError(message) {
  const box = $('error');
  box.innerHTML = '';
  const title = document.createElement('h2');
  title.textContent = 'This page cannot show the model';
  const text = document.createElement('p');
  text.textContent = message;
  box.append(title, text);
  box.hidden = false;
}

function webglAvailable() {
  try {
    const canvas = document.createElement('canvas');
    return !!(canvas.getContext('webgl2') || canvas.getContext('webgl'));
  } catch {
    return false;
  }
}

/** A model checked but not sliced yet: the 3D view with its defects, nothing else. */
function startModelOnly(data, state) {
  $('app').classList.add('model-only');
  let modelView = null;
  let modelReady = Promise.resolve();
  if (webglAvailable()) {
    modelView = new ModelView({ container: $('view3d'), legend: $('legend-3d'), toolbar: $('toolbar-3d'), data, state, layerImage: () => null });
    modelReady = modelView.firstRender;
  } else {
    $('view3d').innerHTML = '<p class="error-inline">This browser offers no WebGL: the 3D view is not available.</p>';
  }
  return { ready: modelReady.then(() => ({ ok: true, error: null })), data, state, controls: null, layerView: null, modelView, section: null };
}

function start(raw) {
  const data = new StrataData(raw);
  const state = new ViewState(data);
  fillHeader({ title: $('model-title'), meta: $('model-meta'), verdict: $('verdict'), notes: $('notes') }, data);
  $('app').hidden = false;
  if (data.layerCount === 0) return startModelOnly(data, state);

  const cellInfo = $('cell-info');
  const idleText = cellInfo.textContent;
  const setCellInfo = (text) => {
    cellInfo.textContent = text ?? idleText;
    cellInfo.classList.toggle('idle', text == null);
  };
  setCellInfo(null);

  const controls = new LayerControls({ slider: $('layer-slider'), label: $('layer-label'), marks: $('layer-marks'), stats: $('layer-stats'), data, state });
  let modelView = null;
  const layerView = new LayerView({
    canvas: $('layer-canvas'),
    data,
    state,
    showHatches: $('show-hatches'),
    fitButton: $('layer-fit'),
    setCellInfo,
    onImage: () => modelView?.layerImageChanged(),
  });
  document.querySelector('.validation-key').hidden = !data.validation;

  let modelReady = Promise.resolve();
  if (webglAvailable()) {
    modelView = new ModelView({
      container: $('view3d'),
      legend: $('legend-3d'),
      toolbar: $('toolbar-3d'),
      data,
      state,
      layerImage: () => layerView.transparentImage(),
    });
    modelReady = modelView.firstRender;
  } else {
    $('view3d').innerHTML = '<p class="error-inline">This browser offers no WebGL: the 3D view is not available.</p>';
  }
  layerView.show(state.index);

  const section = new SectionView({
    canvas: $('section-canvas'),
    axisSelect: $('section-axis'),
    slider: $('section-slider'),
    sliderLabel: $('section-label'),
    progress: $('section-progress'),
    fitButton: $('section-fit'),
    data,
    state,
    setCellInfo,
  });
  new LayerPlots({ container: $('plots'), data, state });
  const report = $('report');
  fillReport(report, data);
  report.addEventListener('click', (event) => {
    const k = event.target.closest?.('[data-layer]')?.dataset.layer;
    if (k != null) state.selectLayer(Number(k));
  });

  return {
    ready: Promise.all([layerView.firstDraw, modelReady]).then(() => ({ ok: true, error: null })),
    data,
    state,
    controls,
    layerView,
    modelView,
    section,
  };
}

let app = null;
let failure = null;

function fail(e) {
  failure = e instanceof DataError ? e.message : `An unexpected error stopped the page: ${e?.message ?? e}`;
  if (!(e instanceof DataError)) console.error(e);
  showError(failure);
  return { ok: false, error: failure };
}

const ready = loadPageData().then(
  (raw) => {
    try {
      app = start(raw);
    } catch (e) {
      return fail(e);
    }
    return app.ready.catch((e) => {
      failure = e?.message ?? String(e);
      showError(failure);
      return { ok: false, error: failure };
    });
  },
  (e) => fail(e),
);

window.strataView = Object.freeze({
  ready,
  error: () => failure,
  camera: () => app?.modelView?.cameraPosition() ?? null,
  layer: () => (app?.data.layerCount ? app.state.k : null),
  layerIndex: () => app?.state.index ?? null,
  drawnLayer: () => app?.layerView?.drawnK ?? null,
  layers: () => (app ? [...app.data.stored] : []),
  grid: () => (app ? { ...app.data.grid } : null),
  section: () => (app?.section ? { axis: app.section.axis, position: app.section.position, complete: app.section.complete } : null),
  cellsShown: () => !!app?.modelView?.cells?.visible,
  // Where the cells of the layer or section view were last drawn, in client pixels.
  gridRect: (which) => {
    const view = which === 'section' ? app?.section : app?.layerView;
    if (!view?.cellRect) return null;
    const c = view.canvas.getBoundingClientRect();
    const sx = c.width / view.canvas.width;
    const sy = c.height / view.canvas.height;
    const r = view.cellRect;
    return { left: c.left + r.left * sx, top: c.top + r.top * sy, width: (r.right - r.left) * sx, height: (r.bottom - r.top) * sy };
  },
});

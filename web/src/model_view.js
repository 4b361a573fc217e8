// The 3D view: the display mesh (front faces sand, back faces orange so inside-out parts show),
// the defects found by strata check, the grid's bounding box with its dimensions, the axes, the
// cutting plane at the selected layer, clipping above it with the layer's cells on the cut, and
// the sliced entity (the cells' exposed faces) over or beside the mesh. z is up.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { CSS2DObject, CSS2DRenderer } from 'three/addons/renderers/CSS2DRenderer.js';
import { buildCellSurface } from './cell_surface.js';
import { buildDefects } from './defects.js';
import { count, escapeHtml, mm } from './format.js';
import { hex, MESH_BACK, MESH_FRONT, SELECTED_LAYER } from './palette.js';

const VIEW_DIRECTIONS = {
  top: [0, -1e-4, 1],
  bottom: [0, 1e-4, -1],
  front: [0, -1, 0],
  back: [0, 1, 0],
  left: [-1, 0, 0],
  right: [1, 0, 0],
  iso: [1, -1.2, 0.9],
};

export class ModelView {
  constructor({ container, legend, toolbar, data, state, layerImage }) {
    this.container = container;
    this.data = data;
    this.state = state;
    this.layerImage = layerImage; // () => canvas of the selected layer, empty cells transparent
    this.frame = 0;
    this.cells = null;
    this.cellsBuilding = null;

    const g = data.grid;
    this.gridBox = new THREE.Box3(
      new THREE.Vector3(g.x0, g.y0, g.z0),
      new THREE.Vector3(g.x0 + g.nx * g.dx, g.y0 + g.ny * g.dy, g.z0 + g.nz * g.dz),
    );
    this.size = this.gridBox.getSize(new THREE.Vector3());
    this.extent = Math.max(this.size.x, this.size.y, this.size.z, 1e-6);

    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.localClippingEnabled = true;
    this.renderer.setClearColor(0xf1f3f5);
    this.canvas = this.renderer.domElement;
    this.canvas.className = 'view3d-canvas';
    container.prepend(this.canvas);
    this.labels = new CSS2DRenderer();
    this.labels.domElement.className = 'view3d-labels';
    container.append(this.labels.domElement);

    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(35, 1, this.extent / 1000, this.extent * 100);
    this.camera.up.set(0, 0, 1);
    this.scene.add(this.camera);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8d7f6a, 1.6));
    const key = new THREE.DirectionalLight(0xffffff, 1.8);
    key.position.set(0.4, 0.6, 1);
    this.camera.add(key);
    this.scene.add(new THREE.AmbientLight(0xffffff, 0.25));

    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.enableDamping = false;
    this.controls.screenSpacePanning = true;
    this.controls.addEventListener('change', () => this.requestRender());

    this.clipPlane = new THREE.Plane(new THREE.Vector3(0, 0, -1), 0);
    this.clipPlanes = [];

    this.#addMesh();
    this.#addDefects();
    this.#addFrame();
    this.#addCuttingPlane();
    this.#fillLegend(legend);
    this.#wireToolbar(toolbar);

    state.onLayer(() => this.#placeCut());
    this.#placeCut();
    new ResizeObserver(() => this.#resize()).observe(container);
    this.#resize();
    this.setView('iso');
    this.firstRender = new Promise((resolve) => (this.resolveFirstRender = resolve));
  }

  // -------------------------------------------------------------------------------------------
  // Scene content.

  #addMesh() {
    this.meshGroup = new THREE.Group();
    this.scene.add(this.meshGroup);
    const mesh = this.data.mesh();
    this.meshInfo = mesh;
    if (!mesh || mesh.indices.length < 3) return;
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(mesh.positions, 3));
    geometry.setIndex(new THREE.BufferAttribute(mesh.indices, 1));
    geometry.computeBoundingBox();
    geometry.computeBoundingSphere();
    this.meshBox = geometry.boundingBox.clone();
    this.frontMaterial = new THREE.MeshStandardMaterial({
      color: MESH_FRONT,
      roughness: 0.85,
      metalness: 0,
      flatShading: true,
      side: THREE.FrontSide,
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    this.backMaterial = new THREE.MeshStandardMaterial({
      color: MESH_BACK,
      roughness: 0.9,
      metalness: 0,
      flatShading: true,
      side: THREE.BackSide,
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    this.meshGroup.add(new THREE.Mesh(geometry, this.frontMaterial), new THREE.Mesh(geometry, this.backMaterial));
  }

  #addDefects() {
    this.defectGroup = new THREE.Group();
    this.scene.add(this.defectGroup);
    this.defects = buildDefects(this.data.defects(), this.clipPlanes);
    for (const d of this.defects) if (d.object) this.defectGroup.add(d.object);
  }

  #addFrame() {
    const { gridBox: box, size } = this;
    this.frame3d = new THREE.Group();
    this.scene.add(this.frame3d);
    const edges = new THREE.LineSegments(
      new THREE.EdgesGeometry(new THREE.BoxGeometry(size.x, size.y, size.z)),
      new THREE.LineBasicMaterial({ color: 0x5c6773, transparent: true, opacity: 0.75 }),
    );
    box.getCenter(edges.position);
    this.frame3d.add(edges);

    // build plate grid at the bottom of the grid box
    const step = niceStep(this.extent / 8);
    const half = Math.ceil((Math.max(size.x, size.y) * 0.75) / step) * step;
    const plate = new THREE.GridHelper(2 * half, Math.round((2 * half) / step), 0xb8bec6, 0xd5d9de);
    plate.rotation.x = Math.PI / 2;
    const c = box.getCenter(new THREE.Vector3());
    plate.position.set(snap(c.x, step), snap(c.y, step), box.min.z);
    plate.material.transparent = true;
    plate.material.opacity = 0.7;
    plate.material.depthWrite = false;
    this.frame3d.add(plate);

    // axes at the grid origin
    const length = this.extent * 0.22;
    const axes = new THREE.AxesHelper(length);
    axes.position.copy(box.min);
    axes.material.depthTest = false;
    axes.renderOrder = 3;
    this.frame3d.add(axes);
    for (const [name, v] of [['X', [1, 0, 0]], ['Y', [0, 1, 0]], ['Z', [0, 0, 1]]]) {
      const label = this.#label(name, `axis-label axis-${name.toLowerCase()}`);
      label.position.set(box.min.x + v[0] * length * 1.12, box.min.y + v[1] * length * 1.12, box.min.z + v[2] * length * 1.12);
      this.frame3d.add(label);
    }

    // dimensions on three edges seen from the front-right
    const dims = [
      [`${mm(size.x, 2)} mm`, [c.x, box.min.y, box.min.z]],
      [`${mm(size.y, 2)} mm`, [box.max.x, c.y, box.min.z]],
      [`${mm(size.z, 2)} mm`, [box.min.x, box.min.y, c.z]],
    ];
    for (const [text, p] of dims) {
      const label = this.#label(text, 'dimension-label');
      label.position.set(...p);
      this.frame3d.add(label);
    }
  }

  #label(text, className) {
    const div = document.createElement('div');
    div.className = className;
    div.textContent = text;
    return new CSS2DObject(div);
  }

  #addCuttingPlane() {
    const { size, gridBox: box } = this;
    const margin = this.extent * 0.06;
    const w = size.x + 2 * margin;
    const h = size.y + 2 * margin;
    this.cut = new THREE.Group();
    const plane = new THREE.Mesh(
      new THREE.PlaneGeometry(w, h),
      new THREE.MeshBasicMaterial({ color: SELECTED_LAYER, transparent: true, opacity: 0.16, side: THREE.DoubleSide, depthWrite: false }),
    );
    plane.renderOrder = 4;
    const outline = new THREE.LineLoop(
      new THREE.BufferGeometry().setFromPoints([
        new THREE.Vector3(-w / 2, -h / 2, 0),
        new THREE.Vector3(w / 2, -h / 2, 0),
        new THREE.Vector3(w / 2, h / 2, 0),
        new THREE.Vector3(-w / 2, h / 2, 0),
      ]),
      new THREE.LineBasicMaterial({ color: SELECTED_LAYER }),
    );
    this.cutPlane = plane;
    this.cut.add(plane, outline);
    const c = box.getCenter(new THREE.Vector3());
    this.cut.position.set(c.x, c.y, 0);
    this.scene.add(this.cut);

    // the layer's cells, on the cut when clipping
    this.layerTexture = null;
    this.layerQuad = new THREE.Mesh(
      new THREE.PlaneGeometry(size.x, size.y),
      new THREE.MeshBasicMaterial({ transparent: true, alphaTest: 0.5, side: THREE.DoubleSide }),
    );
    this.layerQuad.position.set(c.x, c.y, 0);
    this.layerQuad.visible = false;
    this.scene.add(this.layerQuad);
    // the same cells on the cut of the sliced entity (which moves with it when beside the mesh)
    this.cellsCap = new THREE.Mesh(this.layerQuad.geometry, this.layerQuad.material);
    this.cellsCap.position.set(c.x, c.y, 0);
    this.cellsCap.visible = false;
  }

  #placeCut() {
    if (this.data.layerCount === 0) {
      this.cut.visible = false;
      return;
    }
    const z = this.data.layerZ(this.state.k);
    this.cut.position.z = z;
    this.clipPlane.constant = z;
    this.layerQuad.position.z = z + this.data.grid.dz * 0.02;
    this.cellsCap.position.z = this.layerQuad.position.z;
    this.requestRender();
  }

  /** Called when the layer view has decoded the selected layer's image. */
  layerImageChanged() {
    if (!this.clipping) return;
    const image = this.layerImage();
    if (!image) return;
    this.layerTexture?.dispose();
    this.layerTexture = new THREE.CanvasTexture(image);
    this.layerTexture.magFilter = THREE.NearestFilter;
    this.layerTexture.minFilter = THREE.LinearFilter;
    this.layerTexture.generateMipmaps = false;
    this.layerTexture.colorSpace = THREE.SRGBColorSpace;
    this.layerQuad.material.map = this.layerTexture;
    this.layerQuad.material.needsUpdate = true;
    this.layerQuad.visible = true;
    this.cellsCap.visible = true;
    this.requestRender();
  }

  // -------------------------------------------------------------------------------------------
  // Toolbar.

  #wireToolbar(toolbar) {
    for (const button of toolbar.querySelectorAll('[data-view]')) {
      button.addEventListener('click', () => this.setView(button.dataset.view));
    }
    const meshBox = toolbar.querySelector('#show-mesh');
    const cellsBox = toolbar.querySelector('#show-cells');
    const besideBox = toolbar.querySelector('#cells-beside');
    const planeBox = toolbar.querySelector('#show-plane');
    const clipBox = toolbar.querySelector('#clip');
    const defectsBox = toolbar.querySelector('#show-defects');
    if (!this.meshInfo) {
      meshBox.checked = false;
      meshBox.disabled = true;
    }
    if (!this.data.raw.volume) {
      cellsBox.disabled = true;
      besideBox.disabled = true;
    }
    defectsBox.disabled = !this.defects.some((d) => d.object);
    if (this.data.layerCount === 0) {
      // Nothing sliced yet: no cutting plane, no clipped view.
      planeBox.checked = false;
      planeBox.disabled = true;
      clipBox.disabled = true;
    }
    meshBox.addEventListener('change', () => {
      this.meshGroup.visible = meshBox.checked;
      this.requestRender();
    });
    defectsBox.addEventListener('change', () => {
      this.defectGroup.visible = defectsBox.checked;
      this.requestRender();
    });
    planeBox.addEventListener('change', () => {
      this.cutPlane.visible = planeBox.checked;
      this.requestRender();
    });
    clipBox.addEventListener('change', () => this.setClipping(clipBox.checked));
    const cellsChanged = async () => {
      besideBox.disabled = !cellsBox.checked || !this.data.raw.volume;
      await this.setCells(cellsBox.checked, besideBox.checked);
    };
    cellsBox.addEventListener('change', cellsChanged);
    besideBox.addEventListener('change', cellsChanged);
    besideBox.disabled = true;
    this.cellsNote = this.container.querySelector('.view3d-note');
  }

  setClipping(on) {
    this.clipping = on;
    this.clipPlanes.length = 0;
    if (on) this.clipPlanes.push(this.clipPlane);
    for (const m of this.#clippedMaterials()) {
      m.clippingPlanes = on ? [this.clipPlane] : null;
      m.needsUpdate = true;
    }
    if (on) this.layerImageChanged();
    else this.layerQuad.visible = this.cellsCap.visible = false;
    this.requestRender();
  }

  #clippedMaterials() {
    const out = [this.frontMaterial, this.backMaterial, this.cells?.material];
    for (const d of this.defects) if (d.object) out.push(d.object.material);
    return out.filter(Boolean);
  }

  /** Shows or hides the sliced entity; builds its surface the first time. */
  async setCells(on, beside) {
    if (on && !this.cells) {
      if (!this.cellsBuilding) {
        this.#note('building the cell surface…');
        this.cellsBuilding = (async () => {
          await new Promise((r) => setTimeout(r, 20)); // let the note show
          const volume = await this.data.volume();
          const { geometry, quads } = buildCellSurface(volume, this.data.grid);
          // both sides: the cracks where merged faces meet show the far side, not the background
          const material = new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.9, metalness: 0, side: THREE.DoubleSide });
          if (this.clipping) material.clippingPlanes = [this.clipPlane];
          this.cells = new THREE.Mesh(geometry, material);
          this.cells.userData.quads = quads;
          this.cells.add(this.cellsCap);
          this.scene.add(this.cells);
          const v = this.data.raw.volume;
          const reduced = v.bx > 1 || v.by > 1 || v.bz > 1 ? `, blocks of ${v.bx}×${v.by}×${v.bz} cells` : '';
          this.cellsText = `${count(quads)} faces${reduced}`;
        })();
      }
      try {
        await this.cellsBuilding;
      } catch (e) {
        this.#note(`the cell surface could not be built: ${e.message}`);
        return;
      }
    }
    if (this.cells) {
      this.cells.visible = on;
      this.cells.position.x = beside ? this.size.x + this.extent * 0.15 : 0;
    }
    this.#note(on && this.cellsText ? `sliced entity: ${this.cellsText}` : '');
    this.fit();
  }

  #note(text) {
    if (!this.cellsNote) return;
    this.cellsNote.textContent = text;
    this.cellsNote.hidden = !text;
  }

  // -------------------------------------------------------------------------------------------
  // Camera.

  #visibleBox() {
    const box = this.gridBox.clone();
    if (this.meshBox && this.meshGroup.visible) box.union(this.meshBox);
    if (this.cells?.visible && this.cells.position.x !== 0) {
      box.union(this.gridBox.clone().translate(this.cells.position));
    }
    return box;
  }

  /** Looks at the model from a named direction (top, bottom, front, back, left, right, iso) or fits. */
  setView(name) {
    if (name === 'fit') {
      this.fit();
      return;
    }
    const d = VIEW_DIRECTIONS[name];
    if (!d) return;
    this.#place(new THREE.Vector3(...d).normalize());
  }

  /** Keeps the viewing direction and shows everything visible. */
  fit() {
    const direction = this.camera.position.clone().sub(this.controls.target);
    if (direction.lengthSq() === 0) direction.set(...VIEW_DIRECTIONS.iso);
    this.#place(direction.normalize());
  }

  #place(direction) {
    const box = this.#visibleBox();
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const vFov = THREE.MathUtils.degToRad(this.camera.fov);
    const hFov = 2 * Math.atan(Math.tan(vFov / 2) * this.camera.aspect);
    const distance = (sphere.radius * 1.08) / Math.sin(Math.min(vFov, hFov) / 2);
    this.controls.target.copy(sphere.center);
    this.camera.position.copy(sphere.center).addScaledVector(direction, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 20;
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.requestRender();
  }

  cameraPosition() {
    const p = this.camera.position;
    return { x: p.x, y: p.y, z: p.z };
  }

  // -------------------------------------------------------------------------------------------
  // Rendering.

  #resize() {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    // Layout changes elsewhere reach here too; reallocating the drawing buffer is costly.
    if (w === this.width && h === this.height) return;
    this.width = w;
    this.height = h;
    this.renderer.setSize(w, h, false);
    this.canvas.style.width = '100%';
    this.canvas.style.height = '100%';
    this.labels.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    const resolution = new THREE.Vector2(w, h);
    for (const d of this.defects) if (d.lineMaterial) d.lineMaterial.resolution.copy(resolution);
    this.requestRender();
  }

  requestRender() {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.render();
    });
  }

  render() {
    this.renderer.render(this.scene, this.camera);
    this.labels.render(this.scene, this.camera);
    if (!this.rendered) {
      this.rendered = true;
      this.resolveFirstRender();
    }
  }

  // -------------------------------------------------------------------------------------------
  // Legend.

  #fillLegend(legend) {
    const rows = [];
    if (this.meshInfo) {
      const m = this.meshInfo;
      const facets = m.simplified ? `${count(m.facetsShown)} of ${count(m.facetsInModel)} facets` : `${count(m.facetsShown ?? m.indices.length / 3)} facets`;
      rows.push(`<li><span class="swatch" style="background:${hex(MESH_FRONT)}"></span>mesh, ${facets}</li>`);
      rows.push(`<li><span class="swatch" style="background:${hex(MESH_BACK)}"></span>back faces (inside out)</li>`);
    } else {
      rows.push('<li class="muted">no mesh in this page</li>');
    }
    for (const [index, d] of this.defects.entries()) {
      const shown = d.shown < d.count ? ` <span class="muted">(${count(d.shown)} shown)</span>` : '';
      const shape = d.shape === 'points' ? 'dot' : d.shape === 'segments' ? 'line' : 'swatch';
      rows.push(
        `<li><label><input type="checkbox" data-defect="${index}" ${d.object ? 'checked' : 'disabled'}>` +
          `<span class="${shape}" style="background:${hex(d.colour)}"></span>${escapeHtml(d.label)}: <b>${count(d.count)}</b>${shown}</label></li>`,
      );
    }
    if (this.data.check && this.defects.length === 0) rows.push('<li class="muted">no defects found</li>');
    legend.innerHTML = `<ul>${rows.join('')}</ul>`;
    legend.addEventListener('change', (event) => {
      const index = event.target.dataset?.defect;
      if (index == null) return;
      const d = this.defects[Number(index)];
      if (d?.object) d.object.visible = event.target.checked;
      this.requestRender();
    });
  }
}

function niceStep(target) {
  const p = 10 ** Math.floor(Math.log10(target));
  for (const m of [1, 2, 5, 10]) if (m * p >= target) return m * p;
  return 10 * p;
}

function snap(v, step) {
  return Math.round(v / step) * step;
}

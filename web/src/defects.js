// The defects found by strata check, as 3D objects: segments as wide lines, triangles as
// coloured triangles, points as dots; one object a defect kind, with its legend entry.

import * as THREE from 'three';
import { LineSegments2 } from 'three/addons/lines/LineSegments2.js';
import { LineSegmentsGeometry } from 'three/addons/lines/LineSegmentsGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { DEFECT_COLOURS, DEFECT_FALLBACK } from './palette.js';

/**
 * @returns {{object: THREE.Object3D, colour: number, label: string, count: number, shown: number,
 *            lineMaterial?: LineMaterial}[]}
 */
export function buildDefects(defects, clippingPlanes) {
  const out = [];
  for (const d of defects) {
    const colour = DEFECT_COLOURS[d.kind] ?? DEFECT_FALLBACK;
    const v = d.values;
    let object = null;
    let lineMaterial = null;
    if (d.shape === 'segments' && v.length >= 6) {
      const geometry = new LineSegmentsGeometry();
      geometry.setPositions(v.subarray(0, v.length - (v.length % 6)));
      lineMaterial = new LineMaterial({ color: colour, linewidth: 3, clippingPlanes });
      object = new LineSegments2(geometry, lineMaterial);
    } else if (d.shape === 'triangles' && v.length >= 9) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(v.slice(0, v.length - (v.length % 9)), 3));
      const material = new THREE.MeshBasicMaterial({
        color: colour,
        side: THREE.DoubleSide,
        polygonOffset: true,
        polygonOffsetFactor: -2,
        polygonOffsetUnits: -2,
        clippingPlanes,
      });
      object = new THREE.Mesh(geometry, material);
    } else if (d.shape === 'points' && v.length >= 3) {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(v.slice(0, v.length - (v.length % 3)), 3));
      const material = new THREE.PointsMaterial({ color: colour, size: 8, sizeAttenuation: false, clippingPlanes });
      object = new THREE.Points(geometry, material);
    }
    if (object) {
      object.renderOrder = 2;
      object.name = d.kind;
    }
    out.push({
      object,
      colour,
      kind: d.kind,
      label: d.label || d.kind.replace(/_/g, ' '),
      count: d.count ?? d.shown ?? 0,
      shown: d.shown ?? 0,
      shape: d.shape,
      lineMaterial,
    });
  }
  return out;
}

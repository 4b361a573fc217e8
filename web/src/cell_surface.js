// The sliced entity as a surface: the exposed faces of the solid blocks of the reduced volume
// (DATA.md "volume"), merged into rectangles where neighbouring faces share a plane and a
// class (greedy meshing), as one indexed BufferGeometry with a colour a vertex.

import * as THREE from 'three';
import { CELLS_BOUNDARY, CELLS_INTERIOR } from './palette.js';

/**
 * @param {{nx, ny, nz, bx, by, bz, blocks: Uint8Array}} volume
 * @param {{x0, y0, z0, dx, dy, dz, nx, ny, nz}} grid
 */
export function buildCellSurface(volume, grid) {
  const dims = [volume.nx, volume.ny, volume.nz];
  const blocks = volume.blocks;
  const size = [volume.bx * grid.dx, volume.by * grid.dy, volume.bz * grid.dz];
  const origin = [grid.x0, grid.y0, grid.z0];
  const limit = [grid.x0 + grid.nx * grid.dx, grid.y0 + grid.ny * grid.dy, grid.z0 + grid.nz * grid.dz];
  const stride = [1, dims[0], dims[0] * dims[1]];
  const colours = {
    1: new THREE.Color(CELLS_INTERIOR),
    3: new THREE.Color(CELLS_BOUNDARY),
  };

  let positions = new Float32Array(4096);
  let normals = new Float32Array(4096);
  let vertexColours = new Float32Array(4096);
  let indices = new Uint32Array(3072);
  let vertexCount = 0;
  let indexCount = 0;
  const grow = () => {
    const more = (a) => {
      const b = new a.constructor(a.length * 2);
      b.set(a);
      return b;
    };
    positions = more(positions);
    normals = more(normals);
    vertexColours = more(vertexColours);
  };

  const coordinate = (axis, blockIndex) => Math.min(limit[axis], origin[axis] + blockIndex * size[axis]);

  for (let d = 0; d < 3; ++d) {
    const u = (d + 1) % 3;
    const v = (d + 2) % 3;
    const nu = dims[u];
    const nv = dims[v];
    const mask = new Int8Array(nu * nv);
    const x = [0, 0, 0];
    for (x[d] = 0; x[d] <= dims[d]; ++x[d]) {
      // faces between block x[d]-1 and block x[d]
      let any = false;
      let n = 0;
      const hasBelow = x[d] > 0;
      const hasAbove = x[d] < dims[d];
      for (let jv = 0; jv < nv; ++jv) {
        let index = x[d] * stride[d] + jv * stride[v];
        for (let iu = 0; iu < nu; ++iu, ++n, index += stride[u]) {
          const a = hasBelow ? blocks[index - stride[d]] : 0;
          const b = hasAbove ? blocks[index] : 0;
          let m = 0;
          if (a && !b) m = classOf(a); // facing +d
          else if (!a && b) m = -classOf(b); // facing -d
          mask[n] = m;
          if (m) any = true;
        }
      }
      if (!any) continue;
      // merge into rectangles
      n = 0;
      for (let j = 0; j < nv; ++j) {
        for (let i = 0; i < nu; ) {
          const m = mask[n];
          if (!m) {
            ++i;
            ++n;
            continue;
          }
          let w = 1;
          while (i + w < nu && mask[n + w] === m) ++w;
          let h = 1;
          grow_h: for (; j + h < nv; ++h) {
            for (let k = 0; k < w; ++k) if (mask[n + k + h * nu] !== m) break grow_h;
          }
          // emit the quad
          if ((vertexCount + 4) * 3 > positions.length) grow();
          if (indexCount + 6 > indices.length) {
            const b = new Uint32Array(indices.length * 2);
            b.set(indices);
            indices = b;
          }
          const p = [0, 0, 0];
          p[d] = coordinate(d, x[d]);
          const u0 = coordinate(u, i);
          const u1 = coordinate(u, i + w);
          const v0 = coordinate(v, j);
          const v1 = coordinate(v, j + h);
          const corners = [
            [u0, v0],
            [u1, v0],
            [u1, v1],
            [u0, v1],
          ];
          const colour = colours[Math.abs(m)] ?? colours[3];
          const base = vertexCount;
          for (const [cu, cv] of corners) {
            p[u] = cu;
            p[v] = cv;
            const o = vertexCount * 3;
            positions[o] = p[0];
            positions[o + 1] = p[1];
            positions[o + 2] = p[2];
            normals[o] = normals[o + 1] = normals[o + 2] = 0;
            normals[o + d] = m > 0 ? 1 : -1;
            vertexColours[o] = colour.r;
            vertexColours[o + 1] = colour.g;
            vertexColours[o + 2] = colour.b;
            ++vertexCount;
          }
          // counter-clockwise seen from the side the normal points to
          const order = m > 0 ? [0, 1, 2, 0, 2, 3] : [0, 2, 1, 0, 3, 2];
          for (const o of order) indices[indexCount++] = base + o;
          // clear the merged faces
          for (let hh = 0; hh < h; ++hh) for (let k = 0; k < w; ++k) mask[n + k + hh * nu] = 0;
          i += w;
          n += w;
        }
      }
    }
  }

  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions.slice(0, vertexCount * 3), 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normals.slice(0, vertexCount * 3), 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(vertexColours.slice(0, vertexCount * 3), 3));
  geometry.setIndex(new THREE.BufferAttribute(indices.slice(0, indexCount), 1));
  geometry.computeBoundingBox();
  geometry.computeBoundingSphere();
  return { geometry, quads: indexCount / 6 };
}

function classOf(code) {
  return code === 3 || code === 2 ? 3 : 1;
}

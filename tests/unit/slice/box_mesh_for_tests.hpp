#pragma once

#include "strata/mesh/indexed_mesh.hpp"

namespace strata::testing {

/// An outward-oriented closed box as an indexed mesh (8 vertices, 12 triangles).
inline IndexedMesh indexed_box(Vec3 lo, Vec3 hi) {
  IndexedMesh m;
  for (int c = 0; c < 8; ++c) {
    m.vertices.push_back({(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z});
  }
  // Faces as quads (counter-clockwise seen from outside), split into two triangles each.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({VertexIndex(q[0]), VertexIndex(q[1]), VertexIndex(q[2])});
    m.triangles.push_back({VertexIndex(q[0]), VertexIndex(q[2]), VertexIndex(q[3])});
  }
  return m;
}

/// Appends another mesh's vertices and triangles (no welding).
inline void append_mesh(IndexedMesh& to, const IndexedMesh& from) {
  const auto base = static_cast<VertexIndex>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  for (auto t : from.triangles) to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

}  // namespace strata::testing

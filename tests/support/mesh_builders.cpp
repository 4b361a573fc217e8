#include "support/mesh_builders.hpp"

#include <numeric>
#include <utility>

#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"

namespace strata::test {

IndexedMesh indexed_box_lo_hi_diagonals(Vec3 lo, Vec3 hi) {
  IndexedMesh m;
  for (int c = 0; c < 8; ++c) {
    m.vertices.push_back({(c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z});
  }
  // Faces as quads (counter-clockwise seen from outside) starting at the corner nearest lo; the
  // split (q0, q1, q2), (q0, q2, q3) takes the diagonal q0-q2 to the corner nearest hi.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({VertexIndex(q[0]), VertexIndex(q[1]), VertexIndex(q[2])});
    m.triangles.push_back({VertexIndex(q[0]), VertexIndex(q[2]), VertexIndex(q[3])});
  }
  return m;
}

std::vector<Facet> box_facets_lo_hi_diagonals(Vec3 lo, Vec3 hi) {
  const IndexedMesh m = indexed_box_lo_hi_diagonals(lo, hi);
  std::vector<Facet> out;
  for (const auto& t : m.triangles)
    out.push_back({m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]});
  return out;
}

IndexedMesh welded_box(const Vec3& min, const Vec3& max) {
  return weld_vertices(mesh::make_box(min, max));
}

void append_mesh(IndexedMesh& to, const IndexedMesh& from) {
  const auto base = static_cast<VertexIndex>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  for (auto t : from.triangles) to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

std::vector<FacetIndex> all_facets(const IndexedMesh& mesh) {
  std::vector<FacetIndex> facets(mesh.triangles.size());
  std::iota(facets.begin(), facets.end(), FacetIndex{0});
  return facets;
}

Facet reversed(const Facet& facet) { return {facet[0], facet[2], facet[1]}; }

std::vector<Facet> reversed(std::vector<Facet> facets) {
  for (Facet& f : facets) f = reversed(f);
  return facets;
}

std::vector<Facet> joined(std::vector<Facet> a, const std::vector<Facet>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace strata::test

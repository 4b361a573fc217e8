#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/vec3.hpp"

/// Meshes built by hand for the tests: boxes with a stated split of their faces, and the small
/// operations the tests combine them with. Coordinates are used as given (no float32 rounding,
/// unlike strata::mesh::make_box), and nothing is welded unless the name says so.
namespace strata::test {

/// One facet of a triangle soup: three corners, counter-clockwise seen from outside.
using Facet = std::array<Vec3, 3>;

/// The box [lo, hi] as 8 vertices and 12 outward-oriented triangles. Vertex c has hi.x when bit 0
/// of c is set, hi.y for bit 1, hi.z for bit 2 (else lo). Faces in the order -z, +z, -y, +y, -x,
/// +x, each split into two triangles along the diagonal from its corner nearest lo to its corner
/// nearest hi, so two boxes that share a face also share that face's diagonal.
IndexedMesh indexed_box_lo_hi_diagonals(Vec3 lo, Vec3 hi);

/// The 12 facets of indexed_box_lo_hi_diagonals(lo, hi), in the same order, as corner triples.
std::vector<Facet> box_facets_lo_hi_diagonals(Vec3 lo, Vec3 hi);

/// strata::mesh::make_box(min, max) welded: float32 corners, 8 shared vertices.
IndexedMesh welded_box(const Vec3& min, const Vec3& max);

/// Appends another mesh's vertices and triangles (no welding: equal positions stay separate
/// vertices).
void append_mesh(IndexedMesh& to, const IndexedMesh& from);

/// The indices of every facet of `mesh`, in order: what a stage that takes candidate facets is
/// given when every facet is a candidate.
std::vector<FacetIndex> all_facets(const IndexedMesh& mesh);

/// The facet with its orientation reversed (corners 1 and 2 swapped).
Facet reversed(const Facet& facet);

/// Every facet reversed, in the same order.
std::vector<Facet> reversed(std::vector<Facet> facets);

/// The facets of `a` followed by those of `b`.
std::vector<Facet> joined(std::vector<Facet> a, const std::vector<Facet>& b);

}  // namespace strata::test

#pragma once

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata {

/// Builds an indexed mesh by merging corners whose coordinates are exactly equal (+0 and -0 are
/// equal). Near-coincident but unequal corners stay distinct (SPEC §2b).
/// Every input triangle is kept, in order, degenerate ones included. Vertices are numbered in order
/// of first appearance. A large soup is welded a block of facets a thread, with the same result
/// whatever the number of threads. Complexity: expected O(n).
IndexedMesh weld_vertices(const TriangleSoup& soup);

}  // namespace strata

#pragma once

#include <cstddef>

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/mesh/triangle_soup.hpp"

namespace strata::detail {

/// weld_vertices with the facets welded in `blocks` consecutive blocks side by side (at least 1,
/// at most one a facet): the same mesh, vertex for vertex, whatever the number of blocks.
IndexedMesh weld_vertices_in_blocks(const TriangleSoup& soup, std::size_t blocks);

}  // namespace strata::detail

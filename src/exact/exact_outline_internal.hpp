#pragma once

// The outline of a layer from the exact path, behind an interface without CGAL or GMP types, so
// that the fast path can call it for the layers whose chained loops are not simple (issue 3).

#include <cstdint>
#include <span>

#include "strata/contour/contour.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata::exact::detail {

/// Cuts layer k exactly (cut_layer) and returns the outline of the region the fill rule fills,
/// from the exact arrangement of its segments (arrangement_contours with left_of = grid.x0),
/// rounded once (finish_contours). `open_chains` is the arrangement's count of chain starts.
/// @param candidates facets that may cross the layer, in increasing order
/// @pre rule is NonZero or EvenOdd. Throws what CGAL throws.
LayerContours outline_contours(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                               const GridSpec& grid, std::uint32_t k, FillRule rule);

}  // namespace strata::exact::detail

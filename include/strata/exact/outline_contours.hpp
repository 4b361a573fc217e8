#pragma once

/// @file
/// The outline of a layer from the exact path, behind an interface without CGAL or GMP types, so
/// that the fast path can take it for the layers whose chained loops are not simple (issue 3).

#include <cstdint>
#include <optional>
#include <span>

#include "strata/contour/contour.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata::exact {

/// Cuts layer k exactly and returns the outline of the region the fill rule fills, from the
/// exact arrangement of its segments (left_of = grid.x0), each point an exact value rounded once
/// to double. `open_chains` is the arrangement's count of chain starts; `outline` is set.
/// @param mesh       the welded mesh
/// @param candidates facets that may cross the layer, in increasing order
/// @param grid       the grid; layer k's plane is grid.zk(k)
/// @param k          the layer
/// @param rule       the fill rule deciding the region
/// @pre rule is NonZero or EvenOdd. Throws what CGAL throws (std::exception).
/// Thread safety: layers may be outlined concurrently; the mesh must not change meanwhile.
LayerContours outline_contours(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                               const GridSpec& grid, std::uint32_t k, FillRule rule);

/// outline_contours, or nothing when CGAL fails (a std::exception other than std::bad_alloc,
/// which propagates).
std::optional<LayerContours> try_outline_contours(const IndexedMesh& mesh,
                                                  std::span<const FacetIndex> candidates,
                                                  const GridSpec& grid, std::uint32_t k,
                                                  FillRule rule);

}  // namespace strata::exact

#pragma once

#include "exact/exact_numbers_internal.hpp"
#include "strata/fill/scanline_fill.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata::exact::detail {

/// The inside rule of SPEC §2 on exact values: row j's scanline y = yc(j) + scan_offset (a
/// double, computed as written) crosses a segment when exactly one end point has y below it; the
/// crossing's exact x counts for cell i when it is greater than xc(i), adding the sign of the
/// facet normal's x (nonzero: solid when the sum is not 0; evenodd: when the count is odd).
/// Hatches are the inside intervals of each scanline between crossings rounded once to double.
/// `exact_fallbacks` counts the comparisons that the nearest doubles left tied.
/// @pre rule is NonZero or EvenOdd.
/// The crossings are computed from the plane of each segment's facet in `mesh` (the mesh the
/// layer was cut from). Without `want_hatches`, LayerFill::hatches stays empty and a crossing is
/// rounded only where a double interval cannot place it between two cell centres.
LayerFill fill_layer(const IndexedMesh& mesh, const ExactLayer& layer, const GridSpec& grid,
                     FillRule rule, double scan_offset_mm, bool want_hatches = true);

}  // namespace strata::exact::detail

#include "exact/exact_arrangement_internal.hpp"
#include "exact/exact_cut_internal.hpp"
#include "exact/exact_loops_internal.hpp"
#include "exact/exact_outline_internal.hpp"

namespace strata::exact::detail {

LayerContours outline_contours(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                               const GridSpec& grid, std::uint32_t k, FillRule rule) {
  const double z = grid.zk(k);
  // The arrangement needs no normal signs: an empty span leaves them 0.
  const ExactLayer layer = cut_layer(mesh, candidates, {}, k, z);
  ArrangementContours a = arrangement_contours(layer, rule, grid.x0);
  LayerContours out = finish_contours(k, z, std::move(a.loops), a.open_chains);
  out.outline = true;
  return out;
}

}  // namespace strata::exact::detail

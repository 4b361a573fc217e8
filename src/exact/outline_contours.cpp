#include "strata/exact/outline_contours.hpp"

#include <exception>
#include <new>

#include "exact/exact_arrangement_internal.hpp"
#include "exact/exact_cut_internal.hpp"
#include "exact/exact_loops_internal.hpp"

namespace strata::exact {

LayerContours outline_contours(const IndexedMesh& mesh, std::span<const FacetIndex> candidates,
                               const GridSpec& grid, std::uint32_t k, FillRule rule) {
  const double z = grid.zk(k);
  // The arrangement needs no normal signs: an empty span leaves them 0.
  const detail::ExactLayer layer = detail::cut_layer(mesh, candidates, {}, k, z);
  detail::ArrangementContours a = detail::arrangement_contours(layer, rule, grid.x0);
  LayerContours out = detail::finish_contours(k, z, std::move(a.loops), a.open_chains);
  out.outline = true;
  return out;
}

std::optional<LayerContours> try_outline_contours(const IndexedMesh& mesh,
                                                  std::span<const FacetIndex> candidates,
                                                  const GridSpec& grid, std::uint32_t k,
                                                  FillRule rule) {
  try {
    return outline_contours(mesh, candidates, grid, k, rule);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace strata::exact

#include <algorithm>
#include <optional>

#include "slicer/fast_kernel_internal.hpp"
#include "strata/contour/assemble_contours.hpp"
#include "strata/exact/outline_contours.hpp"
#include "strata/fill/scanline_fill.hpp"

namespace strata::detail {

FastKernel::FastKernel(const IndexedMesh& mesh, const GridSpec& grid, const SliceOptions& options)
    : mesh_(mesh), grid_(grid), options_(options) {}

void FastKernel::prepare_batch(std::uint32_t k0, std::uint32_t k1) {
  if (!sweep_.grouped()) {
    // On the first batch, not in the constructor: the run builds the shell's marker beside the
    // first batch, and this grouping, on one thread, then overlaps the marker's set-up.
    sweep_.group(mesh_, grid_);
  }
  sweep_.advance(k0, k1);
}

LayerGeometry FastKernel::compute_layer(std::uint32_t k) const {
  const std::vector<FacetIndex> candidates = sweep_.candidates(k);
  const LayerSegments segments = slice_layer(mesh_, candidates, grid_, k);
  LayerGeometry geometry;
  geometry.segments = static_cast<std::uint32_t>(segments.segments.size());
  geometry.fill = scanline_fill(mesh_, segments, grid_, options_.fill_rule, options_.scan_offset_mm,
                                {.cells = cells_wanted_, .hatches = hatches_wanted_});
  geometry.contours = assemble_contours(mesh_, segments);
  if (!geometry.contours.loops_are_simple()) {
    geometry.contours = outline_layer(std::move(geometry.contours), candidates, k);
  }
  return geometry;
}

LayerContours FastKernel::outline_layer(LayerContours chained,
                                        std::span<const FacetIndex> candidates,
                                        std::uint32_t k) const {
  // Issue 3: loops that cross, touch, stay open or nest without alternating are not boundaries
  // of the filled region; the exact path's outline of that region replaces them, so both paths
  // give the same contours. The fill rule is nonzero or evenodd (see the class), the two that
  // have an arrangement outline. Should CGAL fail, the chained loops stay; their flags still say
  // why they are not simple.
  std::optional<LayerContours> outline =
      exact::try_outline_contours(mesh_, candidates, grid_, k, options_.fill_rule);
  if (!outline) return chained;
  LayerContours out = std::move(*outline);
  // Open chains stay reported as chained, with their end points (issue 4: never hidden).
  for (Contour& c : chained.loops) {
    if (c.kind == LoopKind::Open) out.loops.push_back(std::move(c));
  }
  out.open_chains = chained.open_chains;
  out.loops_cross = chained.loops_cross;
  out.misnested = chained.misnested;
  return out;
}

}  // namespace strata::detail

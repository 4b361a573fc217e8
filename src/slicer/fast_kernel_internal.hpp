#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "strata/pipeline/layer_kernel.hpp"
#include "strata/slice/slice_float.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata::detail {

/// The fast path: double crossing points for output, exact filtered predicates for every
/// decision, facets swept through the layers by their first layer (O(n + k + m)).
/// @pre options.fill_rule is NonZero or EvenOdd: slice_model gives Winding to WindingKernel.
class FastKernel final : public LayerKernel {
 public:
  FastKernel(const IndexedMesh& mesh, const GridSpec& grid, const SliceOptions& options);

  void prepare_batch(std::uint32_t k0, std::uint32_t k1) override;
  LayerGeometry compute_layer(std::uint32_t k) const override;
  void want_cells(bool wanted) override { cells_wanted_ = wanted; }
  void want_hatches(bool wanted) override { hatches_wanted_ = wanted; }
  std::string_view name() const override { return "fast path"; }

 private:
  /// The layer's contours when its chained loops are not simple: the exact outline of the
  /// filled region, plus the chained open chains; `chained` unchanged if no outline can be made.
  LayerContours outline_layer(LayerContours chained, std::span<const FacetIndex> candidates,
                              std::uint32_t k) const;

  const IndexedMesh& mesh_;
  GridSpec grid_;
  SliceOptions options_;
  FacetSweep sweep_;  ///< grouped by the first prepare_batch
  bool cells_wanted_ = true;
  bool hatches_wanted_ = true;
};

}  // namespace strata::detail

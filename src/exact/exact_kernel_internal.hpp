#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "strata/core/result.hpp"
#include "strata/exact/slice_exact.hpp"
#include "strata/mesh/indexed_mesh.hpp"
#include "strata/pipeline/layer_kernel.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_float.hpp"
#include "strata/slice/slice_options.hpp"

namespace strata::exact::detail {

class SoupMesh;

/// Where the exact kernel takes a layer's contours from.
enum class ContourMethod {
  Automatic,    ///< the halfedge structure when it chains the layer, else the arrangement
  Arrangement,  ///< always the exact 2D arrangement (for tests and comparisons)
};

/// Checks what CGAL would only assert: vertex indices in range, finite coordinates.
/// @return Error{BadInput} naming the first offending facet or vertex.
Result<void> check_mesh_for_exact(const IndexedMesh& mesh);

/// The exact path (SPEC §1) as a LayerKernel for run_slice: facets grouped by the layers they
/// cross (found once from their z ranges), each layer cut on exact rationals, cells by the exact
/// inside rule, contours through the repaired soup's halfedge structure or the arrangement.
/// The mesh must outlive the kernel. compute_layer is safe to call from several threads.
class ExactKernel final : public LayerKernel {
 public:
  /// Builds the soup (may throw what CGAL throws). @pre check_mesh_for_exact(mesh) succeeded;
  /// options.fill_rule is NonZero or EvenOdd.
  ExactKernel(const IndexedMesh& mesh, const GridSpec& grid, const SliceOptions& options,
              ContourMethod method = ContourMethod::Automatic);
  ~ExactKernel() override;

  void prepare_batch(std::uint32_t k0, std::uint32_t k1) override;
  LayerGeometry compute_layer(std::uint32_t k) const override;
  void want_hatches(bool wanted) override { hatches_wanted_ = wanted; }
  std::string_view name() const override { return "exact path"; }

  /// The soup repair figures and the layers counted so far by contour method.
  ExactSliceReport report() const;

 private:
  const IndexedMesh& mesh_;
  GridSpec grid_;
  SliceOptions options_;
  ContourMethod method_;
  std::unique_ptr<SoupMesh> soup_;
  std::vector<std::int8_t> normal_x_signs_;
  FacetSweep sweep_;
  bool hatches_wanted_ = true;
  mutable std::atomic<std::uint32_t> halfedge_layers_{0};
  mutable std::atomic<std::uint32_t> arrangement_layers_{0};
  mutable std::atomic<std::uint32_t> empty_layers_{0};
};

}  // namespace strata::exact::detail

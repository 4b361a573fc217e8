#pragma once

#include <cstdint>
#include <string_view>

#include "strata/contour/contour.hpp"
#include "strata/fill/scanline_fill.hpp"

namespace strata {

/// What a slicing kernel computes for one layer, before the shell step.
struct LayerGeometry {
  LayerFill fill;  ///< solid cells and hatches
  LayerContours contours;
  std::uint32_t segments = 0;
};

/// A slicing kernel: the fast (double + exact fallback) or the exact (CGAL) path. The pipeline
/// calls prepare_batch(k0, k1) from one thread, then compute_layer(k) for every k in [k0, k1),
/// possibly concurrently; batches come in increasing order and do not overlap, and may skip layers
/// (a layer range starts past layer 0): a batch's facets include those that began below it. Either
/// may throw: run_slice then aborts the sinks and returns Error{Internal}.
class LayerKernel {
 public:
  virtual ~LayerKernel() = default;
  /// Prepares the layers [k0, k1) (e.g. groups the facets that cross them); one thread.
  virtual void prepare_batch(std::uint32_t k0, std::uint32_t k1) = 0;
  /// Contours, segments and the solid cells of layer k of the prepared batch; thread-safe.
  virtual LayerGeometry compute_layer(std::uint32_t k) const = 0;
  /// Says, before the first batch of a run, whether its cells are wanted: when not (the outputs
  /// hold contours and hatches only) a kernel may leave LayerGeometry::fill.solid without rows
  /// and skip deciding cells.
  virtual void want_cells(bool /*wanted*/) {}
  /// Says, before the first batch of a run, whether its hatches are wanted: when not (no output
  /// holds them) a kernel may leave LayerGeometry::fill.hatches empty and skip what only they
  /// need.
  virtual void want_hatches(bool /*wanted*/) {}
  /// How failure messages name the kernel: "fast path", "exact path".
  virtual std::string_view name() const { return "layer kernel"; }
};

}  // namespace strata

#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "strata/mesh/indexed_mesh.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/pipeline/run_slice.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"
#include "strata/validate/validate_options.hpp"
#include "strata/validate/validation_report.hpp"

namespace strata::validate {

/// Compares two slices of one mesh on one grid, layer by layer as they stream, and measures the
/// model (the engine of validate_model, usable on hand-made layers).
///
/// Feed it, in increasing k: first (optionally) the scan-offset layers, then the layer pairs.
/// Only the layers needed for the shell measurement (three of the fast path) and the differing
/// cells it lists are kept.
///
/// The mesh, grid and options must outlive the comparison. Not thread-safe.
class SliceComparison {
 public:
  /// @pre options.fill_rule is NonZero or EvenOdd; the grid is the one both slices used.
  SliceComparison(const IndexedMesh& mesh, const GridSpec& grid, const SliceOptions& options,
                  const ValidateOptions& validate_options = {});
  ~SliceComparison();
  SliceComparison(const SliceComparison&) = delete;
  SliceComparison& operator=(const SliceComparison&) = delete;

  /// Layer k of the fast path with options.scan_offset_mm (`with_offset`) and with offset 0
  /// (`without_offset`), nx * ny classes each: the cells that differ are the cells the offset
  /// changes. Must come before add_layers for the same k.
  void add_scan_offset_layer(std::uint32_t k, std::span<const CellClass> with_offset,
                             std::span<const CellClass> without_offset);

  /// Layer k of both paths (same k): compares classes and contours, explains every differing
  /// cell, and measures the fast path's layer.
  void add_layers(const LayerResult& fast, const LayerResult& exact);

  /// Layer k of the fast path alone (the exact path did not deliver it): measured, not compared.
  void add_fast_layer(const LayerResult& fast);

  /// Ends the comparison: measures the model (mesh volume and area, surface-to-shell Hausdorff
  /// distance, shell thickness) and returns the report. The PathFigures are left for the caller
  /// to fill from the two runs' summaries, except solid_bounds, filled here from the layers.
  ValidationReport finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace strata::validate

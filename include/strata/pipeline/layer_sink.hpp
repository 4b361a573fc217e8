#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "strata/contour/contour.hpp"
#include "strata/core/result.hpp"
#include "strata/fill/scanline_fill.hpp"
#include "strata/slice/grid_spec.hpp"
#include "strata/slice/slice_options.hpp"
#include "strata/voxel/cell_class.hpp"

namespace strata {

/// What every sink is told before the first layer.
struct SliceRunInfo {
  GridSpec grid;
  SliceOptions options;
  std::string model_name;  ///< the model's file stem, used to name outputs
  /// The layers the run sends (SPEC §3.1b), in indices of `grid`; nullopt: all of them.
  std::optional<LayerSpan> layers;

  /// The layers the sink receives: `layers`, or every layer of the grid.
  LayerSpan span() const { return layers.value_or(LayerSpan{0, grid.nz}); }
};

/// One finished layer, handed to the sinks in increasing k (indices of the whole grid). The
/// references live until add_layer returns.
struct LayerResult {
  std::uint32_t layer = 0;  ///< k
  double z_mm = 0.0;        ///< the cutting plane, GridSpec::zk(k)
  /// nx * ny, row-major (j * nx + i); empty when no sink needs cells (LayerSink::needs_cells).
  std::span<const CellClass> cells;
  const LayerContours& contours;
  const std::vector<HatchSegment>& hatches;
};

/// What a sink makes of one layer ahead of add_prepared_layer (LayerSink::prepare_layer): its
/// encoded bytes, say. Each sink defines its own.
class PreparedLayer {
 public:
  virtual ~PreparedLayer() = default;
};

/// A consumer of finished layers: a file writer, a statistics collector. Layers stream through,
/// so a sink must not keep references past add_layer. If any step fails, abort() is called on
/// every sink and must leave no partial file behind.
class LayerSink {
 public:
  virtual ~LayerSink() = default;
  /// Called once before the first layer: open the output (under a temporary name) for `run`.
  virtual Result<void> begin(const SliceRunInfo& run) = 0;
  /// Called for every layer, k = 0 .. nz-1 in order; an error stops the run.
  virtual Result<void> add_layer(const LayerResult& layer) = 0;
  /// The part of add_layer's work that needs only the layer and what begin() set up (encoding,
  /// compression), so that the engine can do it on its worker threads while the layers before
  /// are written. Called after begin(), on any thread, in any order, at most once a layer; it
  /// must not change the sink. The default prepares nothing.
  virtual std::unique_ptr<PreparedLayer> prepare_layer(const LayerResult& /*layer*/) const {
    return nullptr;
  }
  /// add_layer for a layer prepare_layer was called on, with what it returned; same order and
  /// errors as add_layer. The default ignores `prepared`.
  virtual Result<void> add_prepared_layer(const LayerResult& layer,
                                          std::unique_ptr<PreparedLayer> /*prepared*/) {
    return add_layer(layer);
  }
  /// Called once after the last layer: complete the output (rename it into place).
  virtual Result<void> finish() = 0;
  /// Called instead of finish() when the run fails anywhere: remove what was written.
  virtual void abort() noexcept = 0;
  /// Whether add_layer reads LayerResult::cells. When no sink does and the options allow it
  /// (SliceOptions::always_classify false), the engine skips the shell and the classification
  /// and hands every sink an empty `cells`.
  virtual bool needs_cells() const { return true; }
  /// Whether add_layer reads LayerResult::hatches. When no sink does, the engine may hand every
  /// sink an empty `hatches`.
  virtual bool needs_hatches() const { return true; }
};

/// Aborts every sink (each abort() is idempotent and does not throw).
inline void abort_all(std::span<LayerSink* const> sinks) noexcept {
  for (LayerSink* sink : sinks) sink->abort();
}

}  // namespace strata

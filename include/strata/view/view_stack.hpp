#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "strata/contour/contour.hpp"
#include "strata/pipeline/layer_sink.hpp"
#include "strata/slice/grid_spec.hpp"

namespace strata::view {

/// One loop of a layer as the page draws it.
struct ViewLoop {
  LoopKind kind = LoopKind::Open;
  std::vector<float> xy;  ///< x0, y0, x1, y1, ... in millimetres
};

/// The stack reduced to blocks for the 3D view: a block holds the highest class of its cells.
struct ViewVolume {
  std::uint32_t nx = 0, ny = 0, nz = 0;  ///< size in blocks
  std::uint32_t bx = 1, by = 1, bz = 1;  ///< grid cells a block along each axis
  std::vector<std::uint8_t> blocks;      ///< (k * ny + j) * nx + i; codes 0, 1, 3
};

/// The layers as the view page holds them.
struct ViewStack {
  GridSpec grid;
  double shell_mm = 0.0;
  std::vector<std::uint32_t> stored;  ///< the grid layers kept, increasing
  std::uint32_t stride = 1;           ///< > 1 when the stack was subsampled to fit the budget
  /// Per stored layer: its cells packed as in the .cells file (2 bits a cell, first cell in the
  /// most significant bits, padded to a byte), zlib-compressed.
  std::vector<std::string> cells_zlib;
  std::vector<std::vector<ViewLoop>> contours;  ///< per stored layer
  bool has_hatches = false;
  std::vector<std::vector<float>> hatches;  ///< per stored layer: x1, y1, x2, y2, ...
  ViewVolume volume;
  std::vector<std::string> notes;  ///< what was left out to fit, in words
};

/// The page's default budget for its layers, in bytes of page text.
inline constexpr std::uint64_t kDefaultViewBudgetBytes = std::uint64_t{200} << 20;

/// What ViewStackCollector keeps of each layer.
struct ViewStackOptions {
  bool hatches = true;             ///< keep the scanline segments
  bool contours = true;            ///< keep the contours (a cells file alone has none)
  std::uint32_t max_blocks = 200;  ///< the 3D volume's largest size in blocks along an axis
};

/// A sink that keeps every layer compactly for the view page; take() gives the stack once the
/// run has finished.
class ViewStackCollector final : public LayerSink {
 public:
  /// Keeps what `options` asks for.
  explicit ViewStackCollector(ViewStackOptions options = {});

  Result<void> begin(const SliceRunInfo& run) override;
  Result<void> add_layer(const LayerResult& layer) override;
  /// Packs, compresses and reduces the layer; add_prepared_layer only appends it.
  std::unique_ptr<PreparedLayer> prepare_layer(const LayerResult& layer) const override;
  Result<void> add_prepared_layer(const LayerResult& layer,
                                  std::unique_ptr<PreparedLayer> prepared) override;
  Result<void> finish() override;
  void abort() noexcept override;
  bool needs_hatches() const override { return options_.hatches; }

  /// The collected stack. @pre finish() returned success.
  ViewStack take();

 private:
  ViewStackOptions options_;
  ViewStack stack_;
};

/// Fits a stack to about `budget_bytes` of page text: when its layers take more, the scanline
/// segments are left out first, then only every n-th layer (k % n == 0) is kept; `notes` says
/// what was left out.
void fit_to_budget(ViewStack& stack, std::uint64_t budget_bytes);

}  // namespace strata::view

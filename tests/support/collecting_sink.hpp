#pragma once

#include <vector>

#include "strata/pipeline/layer_sink.hpp"

namespace strata::testing {

/// Keeps every layer's classes in memory, for tests on small grids.
class CollectingSink final : public LayerSink {
 public:
  Result<void> begin(const SliceRunInfo& run) override {
    grid = run.grid;
    return {};
  }
  Result<void> add_layer(const LayerResult& layer) override {
    layers.emplace_back(layer.cells.begin(), layer.cells.end());
    loops.push_back(layer.contours.loops);
    order.push_back(layer.layer);
    hatches += layer.hatches.size();
    return {};
  }
  Result<void> finish() override {
    finished = true;
    return {};
  }
  void abort() noexcept override { aborted = true; }
  bool needs_hatches() const override { return reads_hatches; }

  CellClass at(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    return layers[k][std::size_t{j} * grid.nx + i];
  }
  std::size_t count(CellClass c) const {
    std::size_t n = 0;
    for (const auto& layer : layers) {
      for (const CellClass x : layer) n += x == c ? 1 : 0;
    }
    return n;
  }

  GridSpec grid;
  std::vector<std::vector<CellClass>> layers;
  std::vector<std::vector<Contour>> loops;
  std::vector<std::uint32_t> order;
  std::size_t hatches = 0;    ///< hatch segments handed out, over all layers
  bool reads_hatches = true;  ///< what needs_hatches() says
  bool finished = false;
  bool aborted = false;
};

}  // namespace strata::testing

#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "strata/exact/slice_exact.hpp"
#include "strata/mesh/triangle_soup.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slicer/slice_model.hpp"

namespace strata::testing {

/// A slice kept in memory: the classes of every layer, for small grids.
struct SlicedCells {
  GridSpec grid;
  std::vector<std::vector<CellClass>> layers;
  SliceSummary summary;

  CellClass at(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    return layers[k][std::size_t{j} * grid.nx + i];
  }
  std::uint64_t solid() const { return summary.class_counts[1] + summary.class_counts[2]; }
};

/// The ways strata computes the cells of a slice, as the property tests run them.
enum class Kernel {
  Fast,     ///< slice_model with the options' fill rule
  Exact,    ///< slice_model_exact, the oracle: the same cells bit for bit (SPEC §2)
  Winding,  ///< slice_model under FillRule::Winding in place of nonzero: on a closed, outward
            ///< mesh exactly the nonzero cells (no caps, an integer winding number)
};

inline std::string kernel_name(Kernel kernel) {
  switch (kernel) {
    case Kernel::Fast:
      return "Fast";
    case Kernel::Exact:
      return "Exact";
    case Kernel::Winding:
      return "Winding";
  }
  return "Unknown";
}

/// Lets GoogleTest print a Kernel parameter by its name.
inline void PrintTo(Kernel kernel, std::ostream* os) { *os << kernel_name(kernel); }

/// GoogleTest parameter names "Fast", "Exact", "Winding".
struct KernelTestName {
  template <class ParamInfo>
  std::string operator()(const ParamInfo& info) const {
    return kernel_name(info.param);
  }
};

/// Slices `soup` on the grid its bounds and `options` give, with `kernel`, keeping every layer.
/// Kernel::Winding replaces FillRule::NonZero by FillRule::Winding (other rules are kept).
inline SlicedCells slice_in_memory(const TriangleSoup& soup, const SliceOptions& options,
                                   Kernel kernel = Kernel::Fast) {
  class Sink final : public LayerSink {
   public:
    explicit Sink(SlicedCells& out) : out_(out) {}
    Result<void> begin(const SliceRunInfo& run) override {
      out_.grid = run.grid;
      return {};
    }
    Result<void> add_layer(const LayerResult& layer) override {
      out_.layers.emplace_back(layer.cells.begin(), layer.cells.end());
      return {};
    }
    Result<void> finish() override { return {}; }
    void abort() noexcept override {}

   private:
    SlicedCells& out_;
  };
  SlicedCells out;
  const IndexedMesh mesh = weld_vertices(soup);
  auto grid = make_grid(mesh.bounds(), options.grid);
  EXPECT_TRUE(grid.has_value());
  if (!grid) return out;
  Sink sink(out);
  LayerSink* sinks[] = {&sink};
  Result<SliceSummary> summary = Error{};
  if (kernel == Kernel::Exact) {
    summary = slice_model_exact(mesh, *grid, options, sinks);
  } else {
    SliceOptions o = options;
    if (kernel == Kernel::Winding && o.fill_rule == FillRule::NonZero) {
      o.fill_rule = FillRule::Winding;
    }
    summary = slice_model(mesh, *grid, o, sinks);
  }
  EXPECT_TRUE(summary.has_value()) << (summary ? "" : summary.error().to_string());
  if (summary) out.summary = *summary;
  return out;
}

inline SliceOptions cells_of(double d, ShellMode mode = ShellMode::Distance, double shell = 0.5) {
  SliceOptions o;
  o.grid.dx_mm = o.grid.dy_mm = o.grid.dz_mm = d;
  o.shell_mode = mode;
  o.shell_mm = shell;
  return o;
}

}  // namespace strata::testing

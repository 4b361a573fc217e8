// A layer range (SPEC §3.1b) decides the cells and contours of a whole run in its layers, sends
// only those, and computes no layer beyond the shell's reach.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "strata/exact/slice_exact.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/pipeline/run_slice.hpp"
#include "strata/slicer/slice_model.hpp"
#include "support/collecting_sink.hpp"
#include "support/mesh_builders.hpp"

namespace strata {
namespace {

struct Model {
  std::string name;
  IndexedMesh mesh;
};

std::vector<Model> models() {
  std::vector<Model> out;
  out.push_back({"sphere", weld_vertices(mesh::make_sphere(6.0, 2))});
  out.push_back({"ring", weld_vertices(mesh::make_ring(7.0, 3.0, 9.0, 24))});
  // Two overlapping boxes: nonzero fills the union, evenodd leaves the overlap empty.
  IndexedMesh boxes = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {8, 6, 5});
  test::append_mesh(boxes, test::indexed_box_lo_hi_diagonals({3, 2, 2}, {11, 9, 9.5}));
  out.push_back({"overlapping_boxes", std::move(boxes)});
  return out;
}

SliceOptions coarse(FillRule rule, ShellMode mode) {
  SliceOptions o;
  o.grid.dx_mm = o.grid.dy_mm = 0.7;
  o.grid.dz_mm = 0.5;
  o.shell_mm = 1.2;  // layers mode: int(1.2 / 0.5) = 2 rings, reaching two layers
  o.shell_mode = mode;
  o.fill_rule = rule;
  o.batch_layers = 3;  // several batches in a range, to cross the window's edges
  return o;
}

TEST(RunSliceRange, RangesEqualTheSameLayersOfAWholeRun) {
  for (const Model& model : models()) {
    for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd, FillRule::Winding}) {
      for (const ShellMode mode : {ShellMode::Distance, ShellMode::Layers}) {
        SCOPED_TRACE(model.name + " " + to_string(rule) + " " + to_string(mode));
        const SliceOptions options = coarse(rule, mode);
        const GridSpec grid = make_grid(model.mesh.bounds(), options.grid).value();
        testing::CollectingSink whole;
        LayerSink* whole_sinks[] = {&whole};
        ASSERT_TRUE(slice_model(model.mesh, grid, options, whole_sinks));
        ASSERT_GE(grid.nz, 8u);
        const std::uint32_t nz = grid.nz;
        const std::vector<LayerRange> ranges = {{0, 1},           {1, 2},
                                                {2, 5},           {nz / 2, nz / 2 + 1},
                                                {3, nz - 2},      {nz - 1, std::nullopt},
                                                {0, std::nullopt}};
        for (const LayerRange& range : ranges) {
          const std::uint32_t end = range.end.value_or(nz);
          SCOPED_TRACE("layers " + std::to_string(range.first) + ":" + std::to_string(end));
          SliceOptions ranged = options;
          ranged.layers = range;
          testing::CollectingSink part;
          LayerSink* sinks[] = {&part};
          auto summary = slice_model(model.mesh, grid, ranged, sinks);
          ASSERT_TRUE(summary) << summary.error().message;
          EXPECT_EQ(summary->range, (LayerSpan{range.first, end}));
          ASSERT_EQ(part.layers.size(), end - range.first);
          ASSERT_EQ(summary->layers.size(), end - range.first);
          std::uint64_t solid = 0;
          for (std::uint32_t k = range.first; k < end; ++k) {
            EXPECT_EQ(part.order[k - range.first], k);
            EXPECT_EQ(part.layers[k - range.first], whole.layers[k]) << "layer " << k;
            EXPECT_EQ(part.loops[k - range.first].size(), whole.loops[k].size()) << "layer " << k;
            EXPECT_EQ(summary->layers[k - range.first].layer, k);
            for (const CellClass c : whole.layers[k]) solid += c != CellClass::Empty ? 1 : 0;
          }
          EXPECT_EQ(summary->class_counts[1] + summary->class_counts[2], solid);
          EXPECT_EQ(summary->class_counts[0] + solid, grid.cells_per_layer() * (end - range.first));
        }
      }
    }
  }
}

TEST(RunSliceRange, ExactPathRangeEqualsItsWholeRun) {
  const IndexedMesh mesh = weld_vertices(mesh::make_sphere(5.0, 1));
  const SliceOptions options = coarse(FillRule::NonZero, ShellMode::Distance);
  const GridSpec grid = make_grid(mesh.bounds(), options.grid).value();
  testing::CollectingSink whole;
  LayerSink* whole_sinks[] = {&whole};
  ASSERT_TRUE(slice_model_exact(mesh, grid, options, whole_sinks));
  SliceOptions ranged = options;
  ranged.layers = {4, 9};
  testing::CollectingSink part;
  LayerSink* sinks[] = {&part};
  ASSERT_TRUE(slice_model_exact(mesh, grid, ranged, sinks));
  ASSERT_EQ(part.layers.size(), 5u);
  for (std::uint32_t k = 4; k < 9; ++k) EXPECT_EQ(part.layers[k - 4], whole.layers[k]);
}

/// Solid everywhere; records which layers it computed.
class RecordingKernel final : public LayerKernel {
 public:
  explicit RecordingKernel(const GridSpec& grid) : grid_(grid), computed(grid.nz) {}
  void prepare_batch(std::uint32_t, std::uint32_t) override {}
  LayerGeometry compute_layer(std::uint32_t k) const override {
    ++computed[k];
    LayerGeometry g;
    g.fill.layer = k;
    g.fill.solid = SolidRows(grid_.nx, grid_.ny);
    for (std::uint32_t j = 0; j < grid_.ny; ++j) g.fill.solid.add(j, 0, grid_.nx);
    return g;
  }

  GridSpec grid_;
  mutable std::vector<std::atomic<int>> computed;
};

TEST(RunSliceRange, ComputesTheRangeAndTheShellsReachAlone) {
  GridSpec grid;
  grid.nx = grid.ny = 10;
  grid.nz = 40;
  const IndexedMesh mesh = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {10, 10, 40});
  for (const ShellMode mode : {ShellMode::Distance, ShellMode::Layers}) {
    SliceOptions options;
    options.shell_mode = mode;
    options.shell_mm = 3.0;  // layers mode: 3 rings reach 3 layers; distance mode reads 1
    options.batch_layers = 4;
    options.layers = {20, 25};
    RecordingKernel kernel(grid);
    testing::CollectingSink sink;
    LayerSink* sinks[] = {&sink};
    ASSERT_TRUE(run_slice(mesh, grid, options, kernel, sinks));
    const std::uint32_t reach = mode == ShellMode::Layers ? 3 : 1;
    for (std::uint32_t k = 0; k < grid.nz; ++k) {
      const bool needed = k + reach >= 20 && k < 25 + reach;
      EXPECT_EQ(kernel.computed[k].load(), needed ? 1 : 0) << to_string(mode) << " layer " << k;
    }
    EXPECT_EQ(sink.order, (std::vector<std::uint32_t>{20, 21, 22, 23, 24}));
    // Cells at the range's ends are interior: the layers beyond it are solid, not outside.
    EXPECT_EQ(sink.at(5, 5, 0), CellClass::Interior) << to_string(mode);
    EXPECT_EQ(sink.at(5, 5, 4), CellClass::Interior) << to_string(mode);
  }
}

TEST(RunSliceRange, RefusesARangeOutsideTheGridBeforeAnySinkBegins) {
  const IndexedMesh mesh = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
  SliceOptions options;
  options.grid.dx_mm = options.grid.dy_mm = options.grid.dz_mm = 0.5;
  const GridSpec grid = make_grid(mesh.bounds(), options.grid).value();
  for (const LayerRange range : {LayerRange{4, std::nullopt}, LayerRange{2, 5}}) {
    options.layers = range;
    testing::CollectingSink sink;
    LayerSink* sinks[] = {&sink};
    auto summary = slice_model(mesh, grid, options, sinks);
    ASSERT_FALSE(summary);
    EXPECT_EQ(summary.error().code, ErrorCode::Usage);
    EXPECT_NE(summary.error().message.find("4 layers"), std::string::npos)
        << summary.error().message;
    EXPECT_TRUE(sink.layers.empty());
  }
}

}  // namespace
}  // namespace strata

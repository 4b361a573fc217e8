// Contour outputs alone (CLI, SVG) need no cell: the engine then skips the shell and the
// classification, and everything it still hands out is what a full run hands out. Likewise
// outputs without hatches (cells, PNG) get none, and the same cells.
#include <gtest/gtest.h>

#include <vector>

#include "strata/exact/slice_exact.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/pipeline/cancel_sink.hpp"
#include "strata/slicer/slice_model.hpp"
#include "support/collecting_sink.hpp"

namespace strata {
namespace {

/// Records what a contour writer reads: the contours, the hatches and how many cells came.
class ContourSink final : public LayerSink {
 public:
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult& layer) override {
    cells_seen += layer.cells.size();
    loops.push_back(layer.contours.loops);
    hatches.push_back(layer.hatches);
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override {}
  bool needs_cells() const override { return false; }

  std::size_t cells_seen = 0;
  std::vector<std::vector<Contour>> loops;
  std::vector<std::vector<HatchSegment>> hatches;
};

bool same_loops(const std::vector<std::vector<Contour>>& a,
                const std::vector<std::vector<Contour>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].size() != b[k].size()) return false;
    for (std::size_t l = 0; l < a[k].size(); ++l) {
      if (a[k][l].kind != b[k][l].kind || a[k][l].points.size() != b[k][l].points.size()) {
        return false;
      }
      for (std::size_t p = 0; p < a[k][l].points.size(); ++p) {
        if (a[k][l].points[p].x != b[k][l].points[p].x ||
            a[k][l].points[p].y != b[k][l].points[p].y) {
          return false;
        }
      }
    }
  }
  return true;
}

bool same_hatches(const std::vector<std::vector<HatchSegment>>& a,
                  const std::vector<std::vector<HatchSegment>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].size() != b[k].size()) return false;
    for (std::size_t h = 0; h < a[k].size(); ++h) {
      if (a[k][h].row != b[k][h].row || a[k][h].x_start != b[k][h].x_start ||
          a[k][h].x_end != b[k][h].x_end) {
        return false;
      }
    }
  }
  return true;
}

enum class Kernel { Fast, Exact };

struct SphereRun {
  IndexedMesh mesh = weld_vertices(mesh::make_sphere(5.0, 2));
  SliceOptions options = [] {
    SliceOptions o;
    o.grid = GridOptions{0.5, 0.5, 0.5, std::nullopt};
    o.shell_mm = 1.0;
    o.batch_layers = 3;  // several batches, so the skipped shell window is crossed
    return o;
  }();
  GridSpec grid = make_grid(mesh.bounds(), options.grid).value();

  Result<SliceSummary> run(Kernel kernel, const SliceOptions& o,
                           std::span<LayerSink* const> sinks) const {
    return kernel == Kernel::Fast ? slice_model(mesh, grid, o, sinks)
                                  : slice_model_exact(mesh, grid, o, sinks);
  }
};

class ContourOnly : public ::testing::TestWithParam<Kernel> {};

TEST_P(ContourOnly, SkipsTheCellsAndHandsOutTheSameContoursAndHatches) {
  const SphereRun s;
  ContourSink full_contours;
  testing::CollectingSink full_cells;
  LayerSink* full_sinks[] = {&full_contours, &full_cells};
  const auto full = s.run(GetParam(), s.options, full_sinks);
  ASSERT_TRUE(full) << full.error().message;
  ASSERT_GT(full->class_counts[1], 0u);
  ASSERT_GT(full->class_counts[2], 0u);

  SliceOptions lean = s.options;
  lean.always_classify = false;
  ContourSink contours;
  LayerSink* sinks[] = {&contours};
  const auto only = s.run(GetParam(), lean, sinks);
  ASSERT_TRUE(only) << only.error().message;

  EXPECT_FALSE(only->cells_classified);
  EXPECT_EQ(contours.cells_seen, 0u);
  EXPECT_EQ(only->class_counts[0] + only->class_counts[1] + only->class_counts[2], 0u);
  EXPECT_EQ(only->solid_volume_mm3, 0.0);
  EXPECT_EQ(contours.loops.size(), s.grid.nz);
  EXPECT_TRUE(same_loops(contours.loops, full_contours.loops));
  EXPECT_TRUE(same_hatches(contours.hatches, full_contours.hatches));
  EXPECT_EQ(only->segments, full->segments);
  EXPECT_EQ(only->contour_volume_mm3, full->contour_volume_mm3);
  EXPECT_EQ(only->open_chains, full->open_chains);
  ASSERT_EQ(only->layers.size(), full->layers.size());
  for (std::size_t k = 0; k < only->layers.size(); ++k) {
    EXPECT_EQ(only->layers[k].outer_loops, full->layers[k].outer_loops) << "layer " << k;
    EXPECT_EQ(only->layers[k].holes, full->layers[k].holes) << "layer " << k;
    EXPECT_EQ(only->layers[k].interior + only->layers[k].boundary, 0u) << "layer " << k;
  }
}

TEST_P(ContourOnly, ASinkThatReadsCellsGetsThemClassifiedAsInAFullRun) {
  const SphereRun s;
  testing::CollectingSink reference;
  LayerSink* reference_sinks[] = {&reference};
  ASSERT_TRUE(s.run(GetParam(), s.options, reference_sinks));

  SliceOptions lean = s.options;
  lean.always_classify = false;
  ContourSink contours;
  testing::CollectingSink cells;
  LayerSink* sinks[] = {&contours, &cells};
  const auto r = s.run(GetParam(), lean, sinks);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_TRUE(r->cells_classified);
  EXPECT_EQ(cells.layers, reference.layers);
  EXPECT_EQ(r->class_counts[1], reference.count(CellClass::Interior));
  EXPECT_EQ(r->class_counts[2], reference.count(CellClass::Boundary));
}

TEST_P(ContourOnly, TheDefaultOptionsClassifyForTheSummaryEvenWithoutACellSink) {
  const SphereRun s;
  testing::CollectingSink reference;
  LayerSink* reference_sinks[] = {&reference};
  ASSERT_TRUE(s.run(GetParam(), s.options, reference_sinks));

  std::atomic<bool> never{false};
  CancelSink cancel(never);  // reads no cell either
  ContourSink contours;
  LayerSink* sinks[] = {&cancel, &contours};
  const auto r = s.run(GetParam(), s.options, sinks);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_TRUE(r->cells_classified);
  EXPECT_EQ(r->class_counts[1], reference.count(CellClass::Interior));
  EXPECT_EQ(r->class_counts[2], reference.count(CellClass::Boundary));
  EXPECT_EQ(r->class_counts[0] + r->class_counts[1] + r->class_counts[2], s.grid.cell_count());
}

TEST_P(ContourOnly, WithoutAHatchSinkTheCellsAndTheSummaryAreThoseOfAFullRun) {
  const SphereRun s;
  testing::CollectingSink reference;
  LayerSink* reference_sinks[] = {&reference};
  const auto full = s.run(GetParam(), s.options, reference_sinks);
  ASSERT_TRUE(full) << full.error().message;
  ASSERT_GT(reference.hatches, 0u);

  testing::CollectingSink cells;
  cells.reads_hatches = false;
  LayerSink* sinks[] = {&cells};
  const auto r = s.run(GetParam(), s.options, sinks);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(cells.hatches, 0u);
  EXPECT_EQ(cells.layers, reference.layers);
  EXPECT_TRUE(same_loops(cells.loops, reference.loops));
  EXPECT_EQ(r->exact_fallbacks, full->exact_fallbacks);
  EXPECT_EQ(r->contour_volume_mm3, full->contour_volume_mm3);

  // One sink that reads them is enough for every sink to get them.
  testing::CollectingSink without;
  without.reads_hatches = false;
  testing::CollectingSink with;
  LayerSink* both[] = {&without, &with};
  ASSERT_TRUE(s.run(GetParam(), s.options, both));
  EXPECT_EQ(with.hatches, reference.hatches);
  EXPECT_EQ(without.hatches, reference.hatches);
}

INSTANTIATE_TEST_SUITE_P(Kernels, ContourOnly, ::testing::Values(Kernel::Fast, Kernel::Exact),
                         [](const auto& info) {
                           return info.param == Kernel::Fast ? "Fast" : "Exact";
                         });

}  // namespace
}  // namespace strata

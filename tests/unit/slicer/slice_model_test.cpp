#include "strata/slicer/slice_model.hpp"

#include <gtest/gtest.h>

#include "strata/pipeline/cancel_sink.hpp"
#include "support/collecting_sink.hpp"
#include "support/mesh_builders.hpp"

namespace strata {
namespace {

struct Sliced {
  testing::CollectingSink sink;
  SliceSummary summary;
};

Sliced slice_with(const IndexedMesh& mesh, SliceOptions options) {
  Sliced out;
  auto grid = make_grid(mesh.bounds(), options.grid);
  EXPECT_TRUE(grid.has_value());
  LayerSink* sinks[] = {&out.sink};
  auto summary = slice_model(mesh, *grid, options, sinks);
  EXPECT_TRUE(summary.has_value()) << (summary ? "" : summary.error().to_string());
  if (summary) out.summary = *summary;
  return out;
}

SliceOptions unit_cells(ShellMode mode, double shell_mm) {
  SliceOptions o;
  o.grid = GridOptions{1.0, 1.0, 1.0, std::nullopt};
  o.shell_mode = mode;
  o.shell_mm = shell_mm;
  o.batch_layers = 2;  // several batches, so the shell window is exercised
  return o;
}

TEST(SliceModel, AlignedBoxLayersModeOneRing) {
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {6, 5, 7});
  const Sliced r = slice_with(box, unit_cells(ShellMode::Layers, 1.0));
  EXPECT_EQ(r.sink.count(CellClass::Empty), 0u);
  EXPECT_EQ(r.sink.count(CellClass::Interior), 4u * 3 * 5);
  EXPECT_EQ(r.sink.count(CellClass::Boundary), 210u - 60);
  EXPECT_EQ(r.summary.class_counts[1], 60u);
  EXPECT_TRUE(r.sink.finished);
}

TEST(SliceModel, AlignedBoxLayersModeTwoRings) {
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {6, 5, 7});
  const Sliced r = slice_with(box, unit_cells(ShellMode::Layers, 2.0));
  EXPECT_EQ(r.sink.count(CellClass::Interior), 2u * 1 * 3);
  EXPECT_EQ(r.sink.count(CellClass::Boundary), 210u - 6);
}

TEST(SliceModel, DistanceModeExcludesCentresExactlyAtThickness) {
  // Second-ring centres lie exactly 1.5 from the nearest face: "closer than t" is strict.
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {6, 5, 7});
  const Sliced r = slice_with(box, unit_cells(ShellMode::Distance, 1.5));
  EXPECT_EQ(r.sink.count(CellClass::Interior), 60u);
  const Sliced thicker = slice_with(box, unit_cells(ShellMode::Distance, 1.6));
  EXPECT_EQ(thicker.sink.count(CellClass::Interior), 6u);
}

TEST(SliceModel, LayersArriveInOrderAndCoverTheGrid) {
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {3, 3, 9});
  const Sliced r = slice_with(box, unit_cells(ShellMode::Layers, 3.0));
  ASSERT_EQ(r.sink.order.size(), 9u);
  for (std::uint32_t k = 0; k < 9; ++k) EXPECT_EQ(r.sink.order[k], k);
}

TEST(SliceModel, BoxContoursAreOneCounterClockwiseLoopPerLayer) {
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 2});
  const Sliced r = slice_with(box, unit_cells(ShellMode::Distance, 0.5));
  ASSERT_EQ(r.sink.loops.size(), 2u);
  for (const auto& loops : r.sink.loops) {
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_TRUE(loops[0].is_closed);
    EXPECT_EQ(loops[0].kind, LoopKind::Outer);
    EXPECT_DOUBLE_EQ(loops[0].signed_area_mm2, 12.0);
  }
  EXPECT_DOUBLE_EQ(r.summary.contour_volume_mm3, 24.0);
  EXPECT_DOUBLE_EQ(r.summary.solid_volume_mm3, 24.0);
}

TEST(SliceModel, BoxWithHoleGivesOuterAndHoleLoops) {
  // A frame: outer box minus an inner box (inner box with flipped orientation).
  IndexedMesh frame = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {6, 6, 1});
  IndexedMesh inner = test::indexed_box_lo_hi_diagonals({2, 2, 0}, {4, 4, 1});
  for (auto& t : inner.triangles) std::swap(t[1], t[2]);
  test::append_mesh(frame, inner);
  const Sliced r = slice_with(frame, unit_cells(ShellMode::Layers, 1.0));
  EXPECT_EQ(r.summary.class_counts[1] + r.summary.class_counts[2], 36u - 4u);
  ASSERT_FALSE(r.sink.loops.empty());
  int outer = 0, holes = 0;
  for (const auto& loop : r.sink.loops[0]) {
    outer += loop.kind == LoopKind::Outer;
    holes += loop.kind == LoopKind::Hole;
    if (loop.kind == LoopKind::Hole) {
      EXPECT_EQ(loop.depth, 1);
    }
  }
  EXPECT_EQ(outer, 1);
  EXPECT_EQ(holes, 1);
}

TEST(SliceModel, OpenMeshReportsOpenChains) {
  IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 4, 4});
  box.triangles.erase(box.triangles.begin() + 4, box.triangles.begin() + 6);  // drop one side
  const Sliced r = slice_with(box, unit_cells(ShellMode::Distance, 0.5));
  EXPECT_EQ(r.summary.open_chains, 4u);
  ASSERT_EQ(r.summary.open_chain_reports.size(), 4u);
  EXPECT_EQ(r.summary.open_chain_reports[0].layer, 0u);
}

TEST(SliceModel, WindingRuleFillsABoxWithAMissingSideAsTheClosedBox) {
  const IndexedMesh closed = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 4, 4});
  IndexedMesh open = closed;
  open.triangles.erase(open.triangles.begin() + 10, open.triangles.begin() + 12);  // the x = 4 side
  SliceOptions nonzero = unit_cells(ShellMode::Distance, 0.5);
  SliceOptions winding = nonzero;
  winding.fill_rule = FillRule::Winding;
  const Sliced expected = slice_with(closed, nonzero);
  const Sliced got = slice_with(open, winding);
  EXPECT_EQ(got.sink.layers, expected.sink.layers);
  EXPECT_EQ(got.summary.open_chains, 4u);  // still reported: the caps only decide the cells
  // Under nonzero the open box loses the rows the missing side should have closed.
  const Sliced wrong = slice_with(open, nonzero);
  EXPECT_NE(wrong.sink.layers, expected.sink.layers);
}

TEST(SliceModel, ACancelledWindingRunReturnsTheCancelAndNoDiagnostics) {
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 4, 4});
  SliceOptions winding = unit_cells(ShellMode::Distance, 0.5);
  winding.fill_rule = FillRule::Winding;
  const GridSpec grid = make_grid(box.bounds(), winding.grid).value();
  const std::atomic<bool> cancelled{true};
  CancelSink stop(cancelled);
  testing::CollectingSink sink;
  LayerSink* sinks[] = {&sink, &stop};
  const auto r = slice_model(box, grid, winding, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_TRUE(is_cancelled(r.error()));
  EXPECT_TRUE(sink.aborted);
  EXPECT_TRUE(sink.layers.empty());
}

}  // namespace
}  // namespace strata

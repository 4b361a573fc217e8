#include "strata/validate/slice_comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "strata/slicer/slice_model.hpp"
#include "support/mesh_builders.hpp"

namespace strata::validate {
namespace {

using test::welded_box;

/// Every layer of a fast-path slice, kept for hand-made comparisons.
struct SlicedLayers final : LayerSink {
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult& layer) override {
    cells.emplace_back(layer.cells.begin(), layer.cells.end());
    contours.push_back(layer.contours);
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override {}

  LayerResult layer(std::uint32_t k) const {
    return LayerResult{k, contours[k].z_mm, cells[k], contours[k], hatches};
  }

  std::vector<std::vector<CellClass>> cells;
  std::vector<LayerContours> contours;
  std::vector<HatchSegment> hatches;
};

IndexedMesh join(IndexedMesh a, const IndexedMesh& b) {
  test::append_mesh(a, b);
  return a;
}

/// A mesh sliced on the 1 mm grid from the origin, with the fast path.
struct Fixture {
  Fixture(IndexedMesh m, FillRule rule, double shell_mm = 0.5) : mesh(std::move(m)) {
    options.grid.dx_mm = options.grid.dy_mm = options.grid.dz_mm = 1.0;
    options.grid.origin = Vec3{0, 0, 0};
    options.fill_rule = rule;
    options.shell_mm = shell_mm;
    grid = make_grid(mesh.bounds(), options.grid).value();
    LayerSink* sinks[] = {&fast};
    EXPECT_TRUE(slice_model(mesh, grid, options, sinks).has_value());
  }

  std::size_t at(std::uint32_t i, std::uint32_t j) const { return std::size_t{j} * grid.nx + i; }

  /// Compares the fast layers with themselves, except layer k, which is `exact_k`.
  ValidationReport compare_with(std::uint32_t k, const SlicedLayers& exact) const {
    SliceComparison comparison(mesh, grid, options, validate_options);
    for (std::uint32_t q = 0; q < grid.nz; ++q) {
      comparison.add_layers(fast.layer(q), q == k ? exact.layer(q) : fast.layer(q));
    }
    return comparison.finish();
  }

  IndexedMesh mesh;
  SliceOptions options;
  ValidateOptions validate_options;
  GridSpec grid;
  SlicedLayers fast;
};

TEST(SliceComparison, FindsNothingBetweenEqualLayers) {
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  const ValidationReport r = f.compare_with(0, f.fast);
  EXPECT_EQ(r.cells_differing, 0u);
  EXPECT_EQ(r.cells_compared, f.grid.cell_count());
  ASSERT_EQ(r.layers.size(), f.grid.nz);
  for (const LayerComparison& l : r.layers) {
    EXPECT_EQ(l.area_method, AreaMethod::Identical);
    EXPECT_EQ(l.hausdorff_mm, 0.0);
  }
}

TEST(SliceComparison, CallsAFlippedCellFarFromAnyTieUnexplained) {
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  SlicedLayers exact = f.fast;
  ASSERT_EQ(exact.cells[1][f.at(3, 2)], CellClass::Interior);
  exact.cells[1][f.at(3, 2)] = CellClass::Empty;
  const ValidationReport r = f.compare_with(1, exact);
  EXPECT_EQ(r.cells_differing, 1u);
  ASSERT_EQ(r.differences.size(), 1u);
  const CellDifference& d = r.differences[0];
  EXPECT_EQ(d.i, 3u);
  EXPECT_EQ(d.j, 2u);
  EXPECT_EQ(d.k, 1u);
  EXPECT_EQ(d.fast, CellClass::Interior);
  EXPECT_EQ(d.exact, CellClass::Empty);
  EXPECT_EQ(d.reason, DifferenceReason::Unexplained);
  EXPECT_EQ(r.differing_by_reason[static_cast<std::size_t>(DifferenceReason::Unexplained)], 1u);
}

TEST(SliceComparison, CallsACellWhoseCentreIsOnTheSurfaceNearDegenerate) {
  // The face x = 6.5 passes through the centres of column i = 6: the crossing ties the centre.
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  SlicedLayers exact = f.fast;
  ASSERT_EQ(exact.cells[1][f.at(6, 2)], CellClass::Empty);
  exact.cells[1][f.at(6, 2)] = CellClass::Boundary;
  const ValidationReport r = f.compare_with(1, exact);
  ASSERT_EQ(r.differences.size(), 1u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::NearDegenerate);
}

TEST(SliceComparison, CallsAShellMarkNextToASolidityDifferenceShell) {
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero, 0.4);
  SlicedLayers exact = f.fast;
  ASSERT_EQ(exact.cells[1][f.at(3, 2)], CellClass::Interior);
  exact.cells[1][f.at(3, 2)] = CellClass::Empty;     // solidity differs
  exact.cells[1][f.at(2, 2)] = CellClass::Boundary;  // so its neighbour would touch the outside
  const ValidationReport r = f.compare_with(1, exact);
  ASSERT_EQ(r.differences.size(), 2u);
  EXPECT_EQ(r.differences[0].i, 2u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::Shell);
  EXPECT_EQ(r.differing_by_reason[static_cast<std::size_t>(DifferenceReason::Shell)], 1u);
}

TEST(SliceComparison, CallsAShellMarkWithoutSolidityDifferenceUnexplained) {
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero, 0.4);
  SlicedLayers exact = f.fast;
  exact.cells[1][f.at(2, 2)] = CellClass::Boundary;
  const ValidationReport r = f.compare_with(1, exact);
  ASSERT_EQ(r.differences.size(), 1u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::Unexplained);
}

TEST(SliceComparison, CallsACellTheScanOffsetChangesScanOffset) {
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  f.options.scan_offset_mm = 0.0001;
  SliceComparison comparison(f.mesh, f.grid, f.options);
  std::vector<CellClass> without = f.fast.cells[1];
  without[f.at(3, 2)] = CellClass::Empty;
  for (std::uint32_t k = 0; k < f.grid.nz; ++k) {
    comparison.add_scan_offset_layer(k, f.fast.cells[k], k == 1 ? without : f.fast.cells[k]);
  }
  SlicedLayers exact = f.fast;
  exact.cells[1][f.at(3, 2)] = CellClass::Empty;
  for (std::uint32_t k = 0; k < f.grid.nz; ++k) {
    comparison.add_layers(f.fast.layer(k), exact.layer(k));
  }
  const ValidationReport r = comparison.finish();
  EXPECT_EQ(r.scan_offset.cells_changed, 1u);
  ASSERT_EQ(r.scan_offset.cells.size(), 1u);
  EXPECT_EQ(r.scan_offset.cells[0].i, 3u);
  ASSERT_EQ(r.differences.size(), 1u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::ScanOffset);
}

TEST(SliceComparison, CallsACellInAnOverlapFillRule) {
  // Under evenodd the overlap [2, 4] x [0, 4] x [0, 4] is empty; nonzero would fill it.
  Fixture f(join(welded_box({0, 0, 0}, {4, 4, 4}), welded_box({2, 0, 0}, {6, 4, 4})),
            FillRule::EvenOdd);
  SlicedLayers exact = f.fast;
  ASSERT_EQ(exact.cells[1][f.at(3, 2)], CellClass::Empty);
  exact.cells[1][f.at(3, 2)] = CellClass::Interior;
  const ValidationReport r = f.compare_with(1, exact);
  ASSERT_EQ(r.differences.size(), 1u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::FillRule);
}

TEST(SliceComparison, MeasuresAMissingLoopAsContourDifference) {
  Fixture f(join(welded_box({0, 0, 0}, {2, 2, 3}), welded_box({4, 0, 0}, {6, 2, 3})),
            FillRule::NonZero);
  SlicedLayers exact = f.fast;
  ASSERT_EQ(exact.contours[1].loops.size(), 2u);
  exact.contours[1].loops.pop_back();
  const ValidationReport r = f.compare_with(1, exact);
  EXPECT_EQ(r.layers_with_different_counts, 1u);
  EXPECT_EQ(r.layers[1].area_method, AreaMethod::Arrangement);
  EXPECT_DOUBLE_EQ(r.layers[1].symmetric_difference_mm2, 4.0);
  EXPECT_DOUBLE_EQ(r.max_symmetric_difference_mm2, 4.0);
  EXPECT_GT(r.layers[1].hausdorff_mm, 2.0);
}

TEST(SliceComparison, MeasuresTheModel) {
  Fixture f(welded_box({0, 0, 0}, {6, 4, 3}), FillRule::NonZero, 1.0);
  const ValidationReport r = f.compare_with(0, f.fast);
  EXPECT_DOUBLE_EQ(r.model.mesh_volume_mm3, 72.0);
  EXPECT_DOUBLE_EQ(r.model.surface_area_mm2, 2 * (24.0 + 18.0 + 12.0));
  EXPECT_EQ(r.fast.solid_bounds.min, (Vec3{0, 0, 0}));
  EXPECT_EQ(r.fast.solid_bounds.max, (Vec3{6, 4, 3}));
  // Every surface point is within half a cell diagonal of a boundary cell centre.
  ASSERT_TRUE(r.model.surface_to_boundary_mm.has_value());
  EXPECT_LE(*r.model.surface_to_boundary_mm, 0.5 * std::sqrt(3.0) + 1e-12);
  // The interior of a 6 x 4 x 3 box with a 1 mm shell: 4 x 2 x 1 cells, all next to the shell,
  // all 1.5 mm from the nearest face.
  EXPECT_EQ(r.model.shell.cells, 8u);
  EXPECT_DOUBLE_EQ(r.model.shell.min_mm, 1.5);
  EXPECT_DOUBLE_EQ(r.model.shell.max_mm, 1.5);
}

TEST(SliceComparison, MeasuresFastLayersTheExactPathDidNotDeliverWithoutComparingThem) {
  Fixture f(welded_box({0, 0, 0}, {6, 4, 3}), FillRule::NonZero, 1.0);
  std::vector<std::uint32_t> told;
  f.validate_options.progress = [&](std::uint32_t done, std::uint32_t total) {
    EXPECT_EQ(total, 3u);
    told.push_back(done);
  };
  SliceComparison comparison(f.mesh, f.grid, f.options, f.validate_options);
  comparison.add_layers(f.fast.layer(0), f.fast.layer(0));
  comparison.add_fast_layer(f.fast.layer(1));
  comparison.add_fast_layer(f.fast.layer(2));
  const ValidationReport r = comparison.finish();
  EXPECT_EQ(told, (std::vector<std::uint32_t>{1, 2, 3}));
  EXPECT_EQ(r.layers_compared, 1u);
  EXPECT_EQ(r.cells_compared, f.grid.cells_per_layer());
  ASSERT_EQ(r.layers.size(), 1u);
  // The fast layers are measured all the same: its solid cells reach the top, its shell is whole.
  EXPECT_EQ(r.fast.solid_bounds.max, (Vec3{6, 4, 3}));
  EXPECT_EQ(r.exact.solid_bounds.max, (Vec3{6, 4, 1}));
  EXPECT_EQ(r.model.shell.cells, 8u);
}

TEST(SliceComparison, RefusesLayersOutsideTheGridOrOfTheWrongSize) {
  Fixture f(welded_box({0, 0, 0}, {6, 4, 3}), FillRule::NonZero);
  SliceComparison comparison(f.mesh, f.grid, f.options);
  LayerResult beyond = f.fast.layer(2);
  beyond.layer = 3;
  EXPECT_THROW(comparison.add_fast_layer(beyond), InternalError);
  EXPECT_THROW(comparison.add_layers(beyond, beyond), InternalError);
  EXPECT_THROW(comparison.add_layers(f.fast.layer(1), f.fast.layer(2)), InternalError);
  const std::vector<CellClass> short_layer(5, CellClass::Empty);
  const LayerResult short_fast{1, f.fast.contours[1].z_mm, short_layer, f.fast.contours[1],
                               f.fast.hatches};
  EXPECT_THROW(comparison.add_fast_layer(short_fast), InternalError);
  EXPECT_THROW(comparison.add_layers(short_fast, f.fast.layer(1)), InternalError);
  EXPECT_THROW(comparison.add_layers(f.fast.layer(1), short_fast), InternalError);
  EXPECT_THROW(comparison.add_scan_offset_layer(3, f.fast.cells[0], f.fast.cells[0]),
               InternalError);
  EXPECT_THROW(comparison.add_scan_offset_layer(0, short_layer, f.fast.cells[0]), InternalError);
  EXPECT_THROW(comparison.add_scan_offset_layer(0, f.fast.cells[0], short_layer), InternalError);
}

TEST(SliceComparison, CountsLoopsButLeavesContoursUncomparedWhenAskedTo) {
  Fixture f(join(welded_box({0, 0, 0}, {2, 2, 3}), welded_box({4, 0, 0}, {6, 2, 3})),
            FillRule::NonZero);
  f.validate_options.compare_contours = false;
  SlicedLayers exact = f.fast;
  exact.contours[1].loops.pop_back();
  const ValidationReport r = f.compare_with(1, exact);
  EXPECT_EQ(r.layers_with_different_counts, 1u);
  EXPECT_EQ(r.layers[1].fast.outer_loops, 2u);
  EXPECT_EQ(r.layers[1].exact.outer_loops, 1u);
  for (const LayerComparison& l : r.layers) {
    EXPECT_EQ(l.area_method, AreaMethod::NotCompared);
    EXPECT_EQ(l.hausdorff_mm, 0.0);
    EXPECT_EQ(l.symmetric_difference_mm2, 0.0);
  }
  EXPECT_EQ(r.layers_overlay_skipped, 0u) << "not skipped for rounding: not compared at all";
}

TEST(SliceComparison, OverlaysOnlyEveryNthLayerThatDiffersAtRoundingLevel) {
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  f.validate_options.max_overlay_layers = 2;  // 4 layers: every 2nd is overlaid
  SlicedLayers exact = f.fast;
  for (LayerContours& layer : exact.contours) {
    ASSERT_EQ(layer.loops.size(), 1u);
    layer.loops[0].points[0].x += 1e-12;  // far below the tolerance, 1e-9 of the model's scale
  }
  SliceComparison comparison(f.mesh, f.grid, f.options, f.validate_options);
  for (std::uint32_t k = 0; k < f.grid.nz; ++k)
    comparison.add_layers(f.fast.layer(k), exact.layer(k));
  const ValidationReport r = comparison.finish();
  ASSERT_EQ(r.layers.size(), 4u);
  EXPECT_EQ(r.layers[0].area_method, AreaMethod::Arrangement);
  EXPECT_EQ(r.layers[1].area_method, AreaMethod::NotCompared);
  EXPECT_EQ(r.layers[2].area_method, AreaMethod::Arrangement);
  EXPECT_EQ(r.layers[3].area_method, AreaMethod::NotCompared);
  EXPECT_EQ(r.layers_arrangement, 2u);
  EXPECT_EQ(r.layers_overlay_skipped, 2u);
  EXPECT_GT(r.max_hausdorff_mm, 0.0);
  EXPECT_LT(r.max_hausdorff_mm, 1e-11);
}

TEST(SliceComparison, AlwaysOverlaysALayerWhoseLoopCountsDiffer) {
  Fixture f(join(welded_box({0, 0, 0}, {2, 2, 3}), welded_box({4, 0, 0}, {6, 2, 3})),
            FillRule::NonZero);
  f.validate_options.max_overlay_layers = 1;  // every 3rd layer only, unless it differs
  SlicedLayers exact = f.fast;
  exact.contours[1].loops.pop_back();
  const ValidationReport r = f.compare_with(1, exact);
  EXPECT_EQ(r.layers[1].area_method, AreaMethod::Arrangement);
  EXPECT_DOUBLE_EQ(r.layers[1].symmetric_difference_mm2, 4.0);
}

TEST(SliceComparison, ListsAtMostTheLimitOfDifferingCellsAndCountsThemAll) {
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  f.validate_options.max_listed_cells = 2;
  SlicedLayers exact = f.fast;
  for (std::uint32_t i = 2; i <= 4; ++i) exact.cells[1][f.at(i, 2)] = CellClass::Empty;
  const ValidationReport r = f.compare_with(1, exact);
  EXPECT_EQ(r.cells_differing, 3u);
  EXPECT_EQ(r.differing_by_reason[static_cast<std::size_t>(DifferenceReason::Unexplained)], 3u);
  ASSERT_EQ(r.differences.size(), 2u);
  EXPECT_EQ(r.differences[0].i, 2u);
  EXPECT_EQ(r.differences[1].i, 3u);
}

TEST(SliceComparison, CallsACellInTheRowOfAnEdgeEndNearDegenerate) {
  // The face y = 4.5 holds the centres of row j = 4: the section's corners lie on its scanline.
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  SlicedLayers exact = f.fast;
  exact.cells[1][f.at(3, 4)] = CellClass::Empty;
  exact.cells[1][f.at(4, 4)] = CellClass::Empty;
  const ValidationReport r = f.compare_with(1, exact);
  ASSERT_EQ(r.differences.size(), 2u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::NearDegenerate);
  EXPECT_EQ(r.differences[1].reason, DifferenceReason::NearDegenerate);
}

TEST(SliceComparison, CallsACellInALayerWhosePlaneHoldsAVertexNearDegenerate) {
  // The top z = 2.5 is the plane of layer 2: the top facets' vertices lie in it.
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 2.5}), FillRule::NonZero);
  ASSERT_EQ(f.grid.nz, 3u);
  SlicedLayers exact = f.fast;
  // A vertex on the plane counts as above it: the sides cross the plane, the layer is solid.
  ASSERT_EQ(exact.cells[2][f.at(3, 2)], CellClass::Boundary);
  exact.cells[2][f.at(3, 2)] = CellClass::Empty;
  const ValidationReport r = f.compare_with(2, exact);
  ASSERT_EQ(r.differences.size(), 1u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::NearDegenerate);
}

TEST(SliceComparison, ExplainsAShellMarkByASolidityDifferenceWithinTheRingsOfLayersMode) {
  // In layers mode a change of solidity moves the shell mark by up to t / d layers (here 2).
  for (const ShellMode mode : {ShellMode::Layers, ShellMode::Distance}) {
    Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero, 2.0);
    f.options.shell_mode = mode;
    SlicedLayers exact = f.fast;
    ASSERT_NE(exact.cells[0][f.at(3, 2)], CellClass::Empty);
    exact.cells[0][f.at(3, 2)] = CellClass::Empty;
    CellClass& mark = exact.cells[2][f.at(3, 2)];
    mark = mark == CellClass::Boundary ? CellClass::Interior : CellClass::Boundary;
    SliceComparison comparison(f.mesh, f.grid, f.options);
    for (std::uint32_t k = 0; k < f.grid.nz; ++k) {
      comparison.add_layers(f.fast.layer(k), exact.layer(k));
    }
    const ValidationReport r = comparison.finish();
    ASSERT_EQ(r.differences.size(), 2u);
    EXPECT_EQ(r.differences[1].k, 2u);
    EXPECT_EQ(r.differences[1].reason,
              mode == ShellMode::Layers ? DifferenceReason::Shell : DifferenceReason::Unexplained)
        << to_string(mode);
  }
}

TEST(SliceComparison, CountsEveryCellTheOffsetChangesAndRemembersOnlyTheLimit) {
  Fixture f(welded_box({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  f.options.scan_offset_mm = 0.0001;
  f.validate_options.max_listed_cells = 1;
  f.validate_options.max_remembered_offset_cells = 1;
  SliceComparison comparison(f.mesh, f.grid, f.options, f.validate_options);
  std::vector<CellClass> without = f.fast.cells[1];
  without[f.at(3, 2)] = CellClass::Empty;
  without[f.at(4, 2)] = CellClass::Empty;
  for (std::uint32_t k = 0; k < f.grid.nz; ++k) {
    comparison.add_scan_offset_layer(k, f.fast.cells[k], k == 1 ? without : f.fast.cells[k]);
  }
  SlicedLayers exact = f.fast;
  exact.cells[1] = without;
  for (std::uint32_t k = 0; k < f.grid.nz; ++k) {
    comparison.add_layers(f.fast.layer(k), exact.layer(k));
  }
  const ValidationReport r = comparison.finish();
  EXPECT_EQ(r.scan_offset.cells_changed, 2u);
  ASSERT_EQ(r.scan_offset.cells.size(), 1u);
  EXPECT_EQ(r.scan_offset.cells[0].i, 3u);
  // The first change is remembered and explains its cell; the second is not checked.
  EXPECT_EQ(r.differing_by_reason[static_cast<std::size_t>(DifferenceReason::ScanOffset)], 1u);
  EXPECT_EQ(r.differing_by_reason[static_cast<std::size_t>(DifferenceReason::Unexplained)], 1u);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "validate.offset_cells");
  EXPECT_EQ(r.diagnostics[0].message,
            "more than 1 cells change with the scan offset; differences beyond them were not "
            "checked against the offset");
}

TEST(SliceComparison, LeavesTheSurfaceToShellDistanceUnmeasuredBeyondTheBoundaryCellLimit) {
  Fixture f(welded_box({0, 0, 0}, {6, 4, 3}), FillRule::NonZero, 1.0);
  f.validate_options.max_boundary_cells = 10;
  const ValidationReport r = f.compare_with(0, f.fast);
  EXPECT_FALSE(r.model.surface_to_boundary_mm.has_value());
  EXPECT_EQ(r.model.surface_samples, 0u);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "validate.boundary_cells");
  EXPECT_EQ(r.diagnostics[0].message,
            "the surface-to-shell distance was not measured: more than 10 boundary cells");
  EXPECT_EQ(r.model.shell.cells, 8u) << "the shell is measured all the same";
}

TEST(SliceComparison, SamplesTheSurfaceWithinItsBudget) {
  Fixture f(welded_box({0, 0, 0}, {6, 4, 3}), FillRule::NonZero, 1.0);
  f.validate_options.max_surface_samples = 6;
  const ValidationReport r = f.compare_with(0, f.fast);
  ASSERT_TRUE(r.model.surface_to_boundary_mm.has_value());
  // 8 corners, every 2nd: 4 samples; the 2 left of the budget allow every 24th facet (4 * 12
  // samples over 2): facet 0 alone, 4 samples more.
  EXPECT_EQ(r.model.surface_samples, 8u);
  EXPECT_LE(*r.model.surface_to_boundary_mm, 0.5 * std::sqrt(3.0) + 1e-12);
}

TEST(SliceComparison, SamplesTheShellUniformlyWithinItsBudget) {
  Fixture f(welded_box({0, 0, 0}, {6, 4, 3}), FillRule::NonZero, 1.0);
  f.validate_options.max_shell_samples = 3;
  const ValidationReport r = f.compare_with(0, f.fast);
  EXPECT_EQ(r.model.shell.cells, 8u);
  EXPECT_EQ(r.model.shell.measured, 3u);
  EXPECT_DOUBLE_EQ(r.model.shell.min_mm, 1.5);
  EXPECT_DOUBLE_EQ(r.model.shell.max_mm, 1.5);
}

TEST(SliceComparison, MeasuresTheShellOfALayerWithoutItsNeighboursInItsOwnPlane) {
  // An 8 x 8 x 5 box with a 1 mm shell: layers 1 to 3 hold 6 x 6 interior cells, all of layers
  // 1 and 3 next to the shell below or above them, the ring of 20 in layer 2. Without layer 2,
  // layer 1 has no neighbour above and its cells are only checked in their plane (the ring).
  Fixture f(welded_box({0, 0, 0}, {8, 8, 5}), FillRule::NonZero, 1.0);
  const ValidationReport all = f.compare_with(0, f.fast);
  EXPECT_EQ(all.model.shell.cells, 36u + 20u + 36u);
  SliceComparison comparison(f.mesh, f.grid, f.options);
  for (const std::uint32_t k : {0u, 1u, 3u, 4u}) comparison.add_fast_layer(f.fast.layer(k));
  const ValidationReport gap = comparison.finish();
  EXPECT_EQ(gap.model.shell.cells, 20u + 36u);
}

TEST(SliceComparison, MeasuresNothingAgainstAMeshWithoutFacets) {
  const IndexedMesh empty;
  const GridSpec grid{0, 0, 0, 1, 1, 1, 3, 3, 3};
  SliceOptions options;
  SliceComparison comparison(empty, grid, options);
  std::vector<CellClass> cells(9, CellClass::Boundary);
  cells[4] = CellClass::Interior;
  const LayerContours no_contours;
  for (std::uint32_t k = 0; k < 3; ++k) {
    const LayerResult layer{k, grid.zk(k), cells, no_contours, {}};
    comparison.add_layers(layer, layer);
  }
  const ValidationReport r = comparison.finish();
  EXPECT_EQ(r.model.mesh_volume_mm3, 0.0);
  EXPECT_TRUE(r.model.mesh_bounds.empty());
  EXPECT_FALSE(r.model.surface_to_boundary_mm.has_value());
  EXPECT_EQ(r.model.shell.cells, 3u);
  EXPECT_EQ(r.model.shell.measured, 0u);
  EXPECT_EQ(r.fast.solid_bounds.max, (Vec3{3, 3, 3}));
}

}  // namespace
}  // namespace strata::validate

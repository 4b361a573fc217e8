#include "strata/validate/slice_comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slicer/slice_model.hpp"

namespace strata::validate {
namespace {

/// Every layer of a fast-path slice, kept for hand-made comparisons.
struct SlicedLayers final : LayerSink {
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult& layer) override {
    cells.push_back(layer.cells);
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

IndexedMesh box_mesh(const Vec3& min, const Vec3& max) {
  return weld_vertices(mesh::make_box(min, max));
}

IndexedMesh join(const IndexedMesh& a, const IndexedMesh& b) {
  IndexedMesh m = a;
  const auto offset = static_cast<VertexIndex>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return m;
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
    SliceComparison comparison(mesh, grid, options);
    for (std::uint32_t q = 0; q < grid.nz; ++q) {
      comparison.add_layers(fast.layer(q), q == k ? exact.layer(q) : fast.layer(q));
    }
    return comparison.finish();
  }

  IndexedMesh mesh;
  SliceOptions options;
  GridSpec grid;
  SlicedLayers fast;
};

TEST(SliceComparison, FindsNothingBetweenEqualLayers) {
  Fixture f(box_mesh({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
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
  Fixture f(box_mesh({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
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
  Fixture f(box_mesh({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
  SlicedLayers exact = f.fast;
  ASSERT_EQ(exact.cells[1][f.at(6, 2)], CellClass::Empty);
  exact.cells[1][f.at(6, 2)] = CellClass::Boundary;
  const ValidationReport r = f.compare_with(1, exact);
  ASSERT_EQ(r.differences.size(), 1u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::NearDegenerate);
}

TEST(SliceComparison, CallsAShellMarkNextToASolidityDifferenceShell) {
  Fixture f(box_mesh({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero, 0.4);
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
  Fixture f(box_mesh({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero, 0.4);
  SlicedLayers exact = f.fast;
  exact.cells[1][f.at(2, 2)] = CellClass::Boundary;
  const ValidationReport r = f.compare_with(1, exact);
  ASSERT_EQ(r.differences.size(), 1u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::Unexplained);
}

TEST(SliceComparison, CallsACellTheScanOffsetChangesScanOffset) {
  Fixture f(box_mesh({0, 0, 0}, {6.5, 4.5, 3.5}), FillRule::NonZero);
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
  Fixture f(join(box_mesh({0, 0, 0}, {4, 4, 4}), box_mesh({2, 0, 0}, {6, 4, 4})),
            FillRule::EvenOdd);
  SlicedLayers exact = f.fast;
  ASSERT_EQ(exact.cells[1][f.at(3, 2)], CellClass::Empty);
  exact.cells[1][f.at(3, 2)] = CellClass::Interior;
  const ValidationReport r = f.compare_with(1, exact);
  ASSERT_EQ(r.differences.size(), 1u);
  EXPECT_EQ(r.differences[0].reason, DifferenceReason::FillRule);
}

TEST(SliceComparison, MeasuresAMissingLoopAsContourDifference) {
  Fixture f(join(box_mesh({0, 0, 0}, {2, 2, 3}), box_mesh({4, 0, 0}, {6, 2, 3})),
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
  Fixture f(box_mesh({0, 0, 0}, {6, 4, 3}), FillRule::NonZero, 1.0);
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

}  // namespace
}  // namespace strata::validate

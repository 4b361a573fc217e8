// The exact fill's crossings: each one the double nearest the exact crossing, down to the
// subnormal doubles, where the rounding takes the rational's own path; without hatches, the same
// cells and the same exact decisions from double intervals.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "exact/exact_cut_internal.hpp"
#include "exact/exact_fill_internal.hpp"
#include "exact_test_support.hpp"
#include "support/mesh_builders.hpp"

namespace strata::exact_test {
namespace {

TEST(ExactFill, ACrossingAmongTheSubnormalDoublesIsThatDoubleExactly) {
  const double tiny = 3e-310;  // subnormal
  ASSERT_LT(tiny, std::numeric_limits<double>::min());
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({tiny, 0.0, 0.0}, {1.0, 1.0, 1.0});
  GridSpec grid;
  grid.x0 = -0.5;
  grid.y0 = 0.0;
  grid.z0 = 0.0;
  grid.dx = grid.dy = grid.dz = 0.25;
  grid.nx = 8;
  grid.ny = 4;
  grid.nz = 4;
  SliceOptions options;
  const exact_test::Run run = run_exact(box, grid, options);
  ASSERT_TRUE(run.ok);
  for (std::uint32_t k = 0; k < grid.nz; ++k) {
    ASSERT_EQ(run.sink.hatches[k].size(), grid.ny) << "layer " << k;
    for (const HatchSegment& h : run.sink.hatches[k]) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(h.x_start), std::bit_cast<std::uint64_t>(tiny))
          << "layer " << k << " row " << h.row;
      EXPECT_EQ(h.x_end, 1.0);
    }
    for (std::uint32_t i = 0; i < grid.nx; ++i) {
      const double xc = grid.xc(i);
      EXPECT_EQ(run.sink.solid(i, 0, k), xc > tiny && xc < 1.0) << "cell " << i;
    }
  }
}

/// Every layer of `mesh` filled by the exact path with and without hatches: the cells, the number
/// of crossings and of exact decisions must agree, and no hatch be made without them; the model
/// must cross some row. Returns the exact decisions of the whole model.
std::uint64_t expect_fill_without_hatches_agrees(const IndexedMesh& mesh, const GridSpec& grid,
                                                 FillRule rule, double scan_offset = 0.0) {
  using namespace exact::detail;
  const std::vector<FacetIndex> facets = test::all_facets(mesh);
  const std::vector<std::int8_t> signs = facet_normal_x_signs(mesh);
  std::uint64_t fallbacks = 0;
  std::uint64_t crossings = 0;
  for (std::uint32_t k = 0; k < grid.nz; ++k) {
    const ExactLayer layer = cut_layer(mesh, facets, signs, k, grid.zk(k));
    const LayerFill full = fill_layer(mesh, layer, grid, rule, scan_offset, true);
    const LayerFill cells_only = fill_layer(mesh, layer, grid, rule, scan_offset, false);
    EXPECT_EQ(cells_only.solid, full.solid) << "layer " << k;
    EXPECT_EQ(cells_only.crossings, full.crossings) << "layer " << k;
    EXPECT_EQ(cells_only.exact_fallbacks, full.exact_fallbacks) << "layer " << k;
    EXPECT_TRUE(cells_only.hatches.empty()) << "layer " << k;
    fallbacks += full.exact_fallbacks;
    crossings += full.crossings;
  }
  EXPECT_GT(crossings, 0u) << "the model must cross the grid's rows";
  return fallbacks;
}

GridSpec centred_grid(double lo, double d, std::uint32_t n, std::uint32_t nz) {
  GridSpec grid;
  grid.x0 = grid.y0 = grid.z0 = lo;
  grid.dx = grid.dy = grid.dz = d;
  grid.nx = grid.ny = n;
  grid.nz = nz;
  return grid;
}

TEST(ExactFill, WithoutHatchesCrossingsOnCellCentresGoTheExactWay) {
  // A double pyramid whose sections are squares turned 45 degrees, with corners on cell
  // centres: rows through centres cross its sides exactly on centres (ties the exact way must
  // decide); rows offset by half a cell cross them half way between centres.
  const IndexedMesh pyramid = octahedron(0.0, 0.0, 1.0, -1.0, 0.0, 1.0);
  const GridSpec grid = centred_grid(-1.125, 0.25, 9, 9);
  for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    EXPECT_GT(expect_fill_without_hatches_agrees(pyramid, grid, rule), 0u);
    expect_fill_without_hatches_agrees(pyramid, grid, rule, 0.125);
  }
}

TEST(ExactFill, WithoutHatchesFacetsInGeneralPositionGiveTheSameCells) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const IndexedMesh sphere = perturbed_sphere(1.0, 3, 0.01, seed, {0.0, 0.0, 0.0});
    expect_fill_without_hatches_agrees(sphere, centred_grid(-1.2, 0.05, 48, 48), FillRule::NonZero);
  }
}

TEST(ExactFill, WithoutHatchesFarAndTinyModelsGiveTheSameCells) {
  // Far from the origin the interval is wide against a cell; at 1e-300 its absolute slack and
  // the subnormal doubles come into play.
  for (const double scale : {1e-300, 1e-3, 1e12}) {
    IndexedMesh sphere = perturbed_sphere(1.0, 2, 0.01, 7, {0.0, 0.0, 0.0});
    for (Vec3& v : sphere.vertices) v = {v.x * scale + 3.0 * scale, v.y * scale, v.z * scale};
    GridSpec grid = centred_grid(-1.2 * scale, 0.1 * scale, 24, 24);
    grid.x0 += 3.0 * scale;
    expect_fill_without_hatches_agrees(sphere, grid, FillRule::NonZero);
  }
  IndexedMesh far = perturbed_sphere(1.0, 2, 0.01, 8, {0.0, 0.0, 0.0});
  for (Vec3& v : far.vertices) v.x += 1e9;
  GridSpec grid = centred_grid(-1.2, 0.1, 24, 24);
  grid.x0 += 1e9;
  expect_fill_without_hatches_agrees(far, grid, FillRule::NonZero);
}

}  // namespace
}  // namespace strata::exact_test

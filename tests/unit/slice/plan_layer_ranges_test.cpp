#include "strata/slice/plan_layer_ranges.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slice/slice_float.hpp"
#include "support/mesh_builders.hpp"

namespace strata {
namespace {

GridSpec grid_for(const IndexedMesh& mesh, double cell_mm, double layer_mm) {
  return make_grid(mesh.bounds(), GridOptions{cell_mm, cell_mm, layer_mm, std::nullopt}).value();
}

void expect_tiles(const LayerPlan& plan, std::uint32_t nz, std::size_t parts) {
  ASSERT_EQ(plan.parts.size(), parts);
  EXPECT_EQ(plan.nz_total, nz);
  std::uint32_t next = 0;
  for (const PlannedPart& p : plan.parts) {
    EXPECT_EQ(p.layers.first, next);
    EXPECT_LT(p.layers.first, p.layers.end);
    next = p.layers.end;
  }
  EXPECT_EQ(next, nz);
}

TEST(PlanLayerRanges, PartsTileTheLayers) {
  const IndexedMesh mesh = weld_vertices(mesh::make_sphere(10.0, 3));
  const GridSpec grid = grid_for(mesh, 1.0, 0.5);
  for (const std::uint32_t parts : {1u, 2u, 3u, 7u, grid.nz}) {
    SCOPED_TRACE(parts);
    const auto plan = plan_layer_ranges(mesh, grid, parts);
    ASSERT_TRUE(plan);
    expect_tiles(*plan, grid.nz, parts);
  }
}

TEST(PlanLayerRanges, CrossingsAddUpToTheFacetsLayerRanges) {
  const IndexedMesh mesh = weld_vertices(mesh::make_ring(8.0, 3.0, 6.0, 40));
  const GridSpec grid = grid_for(mesh, 0.5, 0.25);
  const FacetLayerRanges ranges = facet_layer_ranges(mesh, grid);
  std::uint64_t expected = 0;
  for (std::size_t f = 0; f < ranges.first.size(); ++f) {
    if (ranges.first[f] <= ranges.last[f]) expected += ranges.last[f] - ranges.first[f] + 1;
  }
  const auto plan = plan_layer_ranges(mesh, grid, 3);
  ASSERT_TRUE(plan);
  std::uint64_t crossings = 0;
  for (const PlannedPart& p : plan->parts) crossings += p.crossings;
  EXPECT_EQ(crossings, expected);
}

TEST(PlanLayerRanges, BalancesCrossingsNotLayerCounts) {
  // A block carrying a cylinder of 2000 wall segments: 100 layers of 8 crossings, then 16 of
  // 4000, nearly all the work.
  IndexedMesh mesh = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {20, 20, 50});
  const IndexedMesh dense =
      weld_vertices(mesh::translate_soup(mesh::make_cylinder(4.0, 8.0, 2000), {10, 10, 50}));
  test::append_mesh(mesh, dense);
  const GridSpec grid = grid_for(mesh, 2.0, 0.5);
  ASSERT_EQ(grid.nz, 116u);
  const auto plan = plan_layer_ranges(mesh, grid, 4);
  ASSERT_TRUE(plan);
  expect_tiles(*plan, grid.nz, 4);
  // Equal layer counts would give 29 layers a part; the first part takes the whole block and
  // a few cylinder layers, the other three share the cylinder's.
  EXPECT_GT(plan->parts[0].layers.count(), 100u);
  for (std::size_t p = 1; p < 4; ++p) EXPECT_LE(plan->parts[p].layers.count(), 5u);
  std::uint64_t most = 0, least = UINT64_MAX;
  for (const PlannedPart& p : plan->parts) {
    most = std::max(most, p.work);
    least = std::min(least, p.work);
  }
  EXPECT_LT(static_cast<double>(most), 1.3 * static_cast<double>(least));
}

TEST(PlanLayerRanges, RefusesMorePartsThanLayersOrNone) {
  const IndexedMesh mesh = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {1, 1, 2});
  const GridSpec grid = grid_for(mesh, 0.5, 0.5);
  ASSERT_EQ(grid.nz, 4u);
  EXPECT_TRUE(plan_layer_ranges(mesh, grid, 4));
  for (const std::uint32_t parts : {0u, 5u}) {
    const auto plan = plan_layer_ranges(mesh, grid, parts);
    ASSERT_FALSE(plan);
    EXPECT_EQ(plan.error().code, ErrorCode::Usage);
  }
}

}  // namespace
}  // namespace strata

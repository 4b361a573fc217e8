#include "strata/fill/scanline_fill.hpp"

#include <gtest/gtest.h>

#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/slice/slice_float.hpp"
#include "support/mesh_builders.hpp"

namespace strata {
namespace {

LayerFill fill_layer(const IndexedMesh& mesh, const GridSpec& grid, std::uint32_t k,
                     FillRule rule = FillRule::NonZero, double offset = 0.0,
                     FillWanted wanted = {}) {
  const LayerSegments segments = slice_layer(mesh, test::all_facets(mesh), grid, k);
  return scanline_fill(mesh, segments, grid, rule, offset, wanted);
}

GridSpec unit_grid(std::uint32_t n) {
  GridSpec g;
  g.nx = g.ny = g.nz = n;
  return g;
}

int count_solid(const LayerFill& fill) { return static_cast<int>(fill.solid.count()); }

TEST(ScanlineFill, BoxAlignedWithGridFillsItsCells) {
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({1, 1, 1}, {4, 3, 5});
  const GridSpec grid = unit_grid(6);
  for (std::uint32_t k = 0; k < 6; ++k) {
    const LayerFill fill = fill_layer(box, grid, k);
    const bool layer_inside = k >= 1 && k < 5;
    EXPECT_EQ(count_solid(fill), layer_inside ? 3 * 2 : 0) << "layer " << k;
    if (layer_inside) {
      for (std::uint32_t j = 0; j < 6; ++j) {
        for (std::uint32_t i = 0; i < 6; ++i) {
          const bool expected = i >= 1 && i < 4 && j >= 1 && j < 3;
          EXPECT_EQ(fill.solid.cells()[j * 6 + i], expected ? 1 : 0) << i << "," << j;
        }
      }
    }
  }
}

TEST(ScanlineFill, WallThroughCellCentreTakesMaterialOnPlusXSide) {
  // Walls at x = 1.5 and x = 3.5 pass exactly through cell centres of columns 1 and 3.
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({1.5, 0, 0}, {3.5, 1, 1});
  const LayerFill fill = fill_layer(box, unit_grid(5), 0);
  // Column 1's centre lies on the left wall: material is on its +x side, so it is solid; column
  // 3's centre lies on the right wall with empty space on +x, so it is empty.
  EXPECT_EQ(fill.solid.cells()[1], 1);
  EXPECT_EQ(fill.solid.cells()[2], 1);
  EXPECT_EQ(fill.solid.cells()[3], 0);
}

TEST(ScanlineFill, FaceOnScanlineTakesMaterialBelowInY) {
  // The box's faces y = 0.5 and y = 2.5 lie exactly on the scanlines of rows 0 and 2.
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0.5, 0}, {1, 2.5, 1});
  const LayerFill fill = fill_layer(box, unit_grid(4), 0);
  // A point on the line counts as above: row 0 (on the lower face) is empty, row 2 (on the
  // upper face) takes the material below it.
  EXPECT_EQ(fill.solid.cells()[0 * 4 + 0], 0);
  EXPECT_EQ(fill.solid.cells()[1 * 4 + 0], 1);
  EXPECT_EQ(fill.solid.cells()[2 * 4 + 0], 1);
  EXPECT_EQ(fill.solid.cells()[3 * 4 + 0], 0);
}

TEST(ScanlineFill, OverlappingBoxesDifferBetweenNonZeroAndEvenOdd) {
  IndexedMesh two = test::indexed_box_lo_hi_diagonals({0, 0, 0}, {3, 1, 1});
  test::append_mesh(two, test::indexed_box_lo_hi_diagonals({1, 0, 0}, {4, 1, 1}));
  const GridSpec grid = unit_grid(4);
  const LayerFill nonzero = fill_layer(two, grid, 0, FillRule::NonZero);
  const LayerFill evenodd = fill_layer(two, grid, 0, FillRule::EvenOdd);
  const auto first_row = [](const LayerFill& fill) {
    const std::vector<std::uint8_t> cells = fill.solid.cells();
    return std::vector<int>(cells.begin(), cells.begin() + 4);
  };
  EXPECT_EQ(first_row(nonzero), (std::vector<int>{1, 1, 1, 1}));
  EXPECT_EQ(first_row(evenodd), (std::vector<int>{1, 0, 0, 1}));
}

TEST(ScanlineFill, HatchesCoverTheSolidSpanOfEachRow) {
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0.25, 0, 0}, {2.75, 2, 1});
  const LayerFill fill = fill_layer(box, unit_grid(3), 0);
  ASSERT_EQ(fill.hatches.size(), 2u);
  EXPECT_EQ(fill.hatches[0].row, 0u);
  EXPECT_DOUBLE_EQ(fill.hatches[0].x_start, 0.25);
  EXPECT_DOUBLE_EQ(fill.hatches[0].x_end, 2.75);
}

TEST(ScanlineFill, ScanOffsetMovesTheRowOffAFace) {
  const IndexedMesh box = test::indexed_box_lo_hi_diagonals({0, 0.5, 0}, {1, 2.5, 1});
  const LayerFill fill = fill_layer(box, unit_grid(4), 0, FillRule::NonZero, 0.0001);
  // Shifted up by 0.1 um, row 0's scanline is inside the box and row 2's is above it.
  EXPECT_EQ(fill.solid.cells()[0 * 4 + 0], 1);
  EXPECT_EQ(fill.solid.cells()[2 * 4 + 0], 0);
}

TEST(ScanlineFill, HatchesAloneAreTheHatchesOfAFullFillAndDecideNoCell) {
  // Two overlapping boxes (where the rules differ) and a sphere, whose rows cross many facets at
  // every slope; each layer filled whole, for its hatches alone and for its cells alone.
  IndexedMesh two = test::indexed_box_lo_hi_diagonals({0.25, 0.5, 0}, {3, 2.5, 2});
  test::append_mesh(two, test::indexed_box_lo_hi_diagonals({1.5, 0.25, 0.5}, {4.75, 1.5, 3}));
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(2.6, 3));
  GridSpec centred = unit_grid(6);
  centred.x0 = centred.y0 = centred.z0 = -3.0;
  centred.dx = centred.dy = centred.dz = 1.0;
  struct Case {
    const IndexedMesh* mesh;
    GridSpec grid;
  };
  for (const Case& c : {Case{&two, unit_grid(5)}, Case{&sphere, centred}}) {
    for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
      for (const double offset : {0.0, 0.25}) {
        for (std::uint32_t k = 0; k < c.grid.nz; ++k) {
          const LayerFill full = fill_layer(*c.mesh, c.grid, k, rule, offset);
          const LayerFill hatches =
              fill_layer(*c.mesh, c.grid, k, rule, offset, {.cells = false, .hatches = true});
          const LayerFill cells =
              fill_layer(*c.mesh, c.grid, k, rule, offset, {.cells = true, .hatches = false});
          EXPECT_FALSE(hatches.solid.has_rows());
          EXPECT_TRUE(cells.hatches.empty());
          EXPECT_EQ(cells.solid, full.solid) << "layer " << k;
          EXPECT_EQ(hatches.crossings, full.crossings) << "layer " << k;
          ASSERT_EQ(hatches.hatches.size(), full.hatches.size()) << "layer " << k;
          for (std::size_t h = 0; h < full.hatches.size(); ++h) {
            EXPECT_EQ(hatches.hatches[h].row, full.hatches[h].row);
            EXPECT_EQ(hatches.hatches[h].x_start, full.hatches[h].x_start);
            EXPECT_EQ(hatches.hatches[h].x_end, full.hatches[h].x_end);
          }
        }
      }
    }
  }
  // The layers above are not all empty: the comparison has hatches and cells to compare.
  EXPECT_GT(fill_layer(sphere, centred, 3).hatches.size(), 2u);
  EXPECT_GT(count_solid(fill_layer(two, unit_grid(5), 1, FillRule::EvenOdd)), 4);
}

}  // namespace
}  // namespace strata

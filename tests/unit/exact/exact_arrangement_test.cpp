// The exact arrangement path (exact_arrangement.cpp), driven through the exact kernel.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "exact_test_support.hpp"

namespace strata {
namespace {

using exact::detail::ContourMethod;
using exact_test::run_exact_with;
using test::append_mesh;
using test::indexed_box_lo_hi_diagonals;

exact_test::Run slice_on_arrangement(const IndexedMesh& mesh, FillRule rule) {
  SliceOptions o;
  o.grid = GridOptions{1.0, 1.0, 1.0, std::nullopt};
  o.fill_rule = rule;
  const auto grid = make_grid(mesh.bounds(), o.grid);
  EXPECT_TRUE(grid.has_value());
  return run_exact_with(mesh, *grid, o, ContourMethod::Arrangement);
}

IndexedMesh overlapping_squares() {
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 4, 2});
  append_mesh(m, indexed_box_lo_hi_diagonals({2, 2, 0}, {6, 6, 2}));
  return m;
}

TEST(ExactArrangement, OverlappingBoxesUnderNonzeroGiveTheirUnion) {
  const auto r = slice_on_arrangement(overlapping_squares(), FillRule::NonZero);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.arrangement_layers, 2u);
  for (const LayerContours& c : r.sink.contours) {
    ASSERT_EQ(c.loops.size(), 1u);
    EXPECT_EQ(c.loops[0].kind, LoopKind::Outer);
    EXPECT_EQ(c.loops[0].points.size(), 8u);
    EXPECT_EQ(c.loops[0].signed_area_mm2, 28.0);
    EXPECT_EQ(c.loops[0].depth, 0);
    EXPECT_EQ(c.open_chains, 0u);
  }
}

TEST(ExactArrangement, OverlappingBoxesUnderEvenOddLeaveTheOverlapOut) {
  // The two L-shaped differences touch at (2, 4) and (4, 2): two loops, one at each side.
  const auto r = slice_on_arrangement(overlapping_squares(), FillRule::EvenOdd);
  ASSERT_TRUE(r.ok);
  for (const LayerContours& c : r.sink.contours) {
    ASSERT_EQ(c.loops.size(), 2u);
    for (const Contour& loop : c.loops) {
      EXPECT_EQ(loop.kind, LoopKind::Outer);
      EXPECT_EQ(loop.points.size(), 6u);
      EXPECT_EQ(loop.signed_area_mm2, 12.0);
    }
    EXPECT_EQ(c.area_mm2, 24.0);
  }
}

TEST(ExactArrangement, FrameGivesAnOuterLoopAndAClockwiseHole) {
  const auto r = slice_on_arrangement(exact_test::frame({0, 0}, {10, 8}, {3, 2}, {7, 5}, 0, 3),
                                      FillRule::NonZero);
  ASSERT_TRUE(r.ok);
  for (const LayerContours& c : r.sink.contours) {
    ASSERT_EQ(c.loops.size(), 2u);
    const auto outer = std::find_if(c.loops.begin(), c.loops.end(),
                                    [](const Contour& l) { return l.kind == LoopKind::Outer; });
    const auto hole = std::find_if(c.loops.begin(), c.loops.end(),
                                   [](const Contour& l) { return l.kind == LoopKind::Hole; });
    ASSERT_NE(outer, c.loops.end());
    ASSERT_NE(hole, c.loops.end());
    EXPECT_EQ(outer->signed_area_mm2, 80.0);
    EXPECT_EQ(outer->depth, 0);
    EXPECT_EQ(hole->signed_area_mm2, -12.0);
    EXPECT_EQ(hole->depth, 1);
  }
}

TEST(ExactArrangement, NestedFrameInsideAFrameUnderEvenOddStaysSeparate) {
  IndexedMesh m = exact_test::frame({0, 0}, {12, 12}, {2, 2}, {10, 10}, 0, 2);
  append_mesh(m, indexed_box_lo_hi_diagonals({4, 4, 0}, {8, 8, 2}));  // an island in the hole
  const auto r = slice_on_arrangement(m, FillRule::EvenOdd);
  ASSERT_TRUE(r.ok);
  for (const LayerContours& c : r.sink.contours) {
    ASSERT_EQ(c.loops.size(), 3u);
    std::vector<int> depths;
    for (const Contour& l : c.loops) depths.push_back(l.depth);
    std::sort(depths.begin(), depths.end());
    EXPECT_EQ(depths, (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(c.area_mm2, 144.0 - 64.0 + 16.0);
  }
}

TEST(ExactArrangement, BoxesMeetingAlongPartOfAWallMergeAcrossTheTJunction) {
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {2, 2, 1});
  append_mesh(m, indexed_box_lo_hi_diagonals({2, 0, 0}, {4, 1, 1}));
  const auto r = slice_on_arrangement(m, FillRule::NonZero);
  ASSERT_TRUE(r.ok);
  const LayerContours& c = r.sink.contours[0];
  ASSERT_EQ(c.loops.size(), 1u);
  EXPECT_EQ(c.loops[0].points.size(), 6u);  // collinear vertices dropped
  EXPECT_EQ(c.loops[0].signed_area_mm2, 6.0);
}

TEST(ExactArrangement, DuplicateOppositeFacetsCancel) {
  // A second copy of the whole box, turned inside out: every wall is walked both ways, so the
  // winding is 0 everywhere and there is no contour (and no solid cell).
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {3, 3, 1});
  IndexedMesh flipped = indexed_box_lo_hi_diagonals({0, 0, 0}, {3, 3, 1});
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  append_mesh(m, flipped);
  const auto r = slice_on_arrangement(m, FillRule::NonZero);
  ASSERT_TRUE(r.ok);
  EXPECT_TRUE(r.sink.contours[0].loops.empty());
  for (const CellClass cell : r.sink.cells[0]) EXPECT_EQ(cell, CellClass::Empty);
}

TEST(ExactArrangement, OpenChainsAreCountedAndTheRegionExtendsToTheGridEdge) {
  // Without one triangle of its +x wall, a row through the gap has only the -x wall to cross:
  // centres left of the box wind -1 (solid), centres inside wind 0 (empty).
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 3});
  m.triangles.erase(m.triangles.begin() + 10);
  SliceOptions o;
  o.grid = GridOptions{1.0, 1.0, 1.0, Vec3{-2, 0, 0}};
  const auto grid = make_grid(m.bounds(), o.grid);
  ASSERT_TRUE(grid.has_value());
  const auto r = run_exact_with(m, *grid, o, ContourMethod::Automatic);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.arrangement_layers, 3u);
  for (std::uint32_t k = 0; k < 3; ++k) {
    const LayerContours& c = r.sink.contours[k];
    EXPECT_EQ(c.open_chains, 1u);
    double x_min = 0.0;
    for (const Contour& l : c.loops) {
      for (const Point2& p : l.points) x_min = std::min(x_min, p.x);
    }
    EXPECT_EQ(x_min, grid->x0);  // the band left of the box, cut at the grid edge
  }
  EXPECT_TRUE(r.sink.solid(0, 2, 0));   // left of the box, in the gap's row
  EXPECT_FALSE(r.sink.solid(3, 2, 0));  // inside the box, same row
}

}  // namespace
}  // namespace strata

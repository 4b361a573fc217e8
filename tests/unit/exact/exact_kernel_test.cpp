// Issue 3: a layer whose chained loops are not simple (they cross or touch, stay open, or nest
// without alternating in orientation) gets the outline of the region the fill rule fills, from
// the exact arrangement, in both kernels; simple layers keep their chained loops.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "exact_test_support.hpp"
#include "strata/io/read_mesh.hpp"

namespace strata::exact_test {
namespace {

using test::append_mesh;
using test::indexed_box_lo_hi_diagonals;

SliceOptions options_with(FillRule rule) {
  SliceOptions o;
  o.grid = GridOptions{1.0, 1.0, 1.0, std::nullopt};
  o.shell_mm = 1.0;
  o.fill_rule = rule;
  return o;
}

struct BothKernels {
  Run fast;
  Run exact;
};

BothKernels run_both(const IndexedMesh& mesh, FillRule rule) {
  const SliceOptions o = options_with(rule);
  const auto grid = make_grid(mesh.bounds(), o.grid);
  EXPECT_TRUE(grid.has_value());
  return {run_fast(mesh, *grid, o), run_exact(mesh, *grid, o)};
}

bool has_diagnostic(const SliceSummary& s, const std::string& code) {
  for (const Diagnostic& d : s.diagnostics) {
    if (d.code == code) return true;
  }
  return false;
}

/// The closed loops of both kernels are the same points (both come from one exact outline).
void expect_same_closed_loops(const LayerContours& a, const LayerContours& b) {
  ASSERT_EQ(a.loops.size(), b.loops.size());
  for (std::size_t l = 0; l < a.loops.size(); ++l) {
    EXPECT_EQ(a.loops[l].points, b.loops[l].points) << "loop " << l;
    EXPECT_EQ(a.loops[l].kind, b.loops[l].kind) << "loop " << l;
    EXPECT_EQ(a.loops[l].depth, b.loops[l].depth) << "loop " << l;
  }
}

IndexedMesh overlapping_boxes() {
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {10, 10, 4});
  append_mesh(m, indexed_box_lo_hi_diagonals({5, 5, 0}, {15, 15, 4}));
  return m;
}

TEST(ExactKernelOutline, OverlappingBoxesGiveTheUnionOutlineInBothKernels) {
  const BothKernels r = run_both(overlapping_boxes(), FillRule::NonZero);
  ASSERT_TRUE(r.fast.ok && r.exact.ok);
  ASSERT_EQ(r.fast.sink.contours.size(), 4u);
  for (std::uint32_t k = 0; k < 4; ++k) {
    const LayerContours& c = r.fast.sink.contours[k];
    ASSERT_EQ(c.loops.size(), 1u) << "layer " << k;
    EXPECT_EQ(c.loops[0].kind, LoopKind::Outer);
    EXPECT_EQ(c.loops[0].points.size(), 8u);  // the union: an L-shaped octagon
    EXPECT_EQ(c.area_mm2, 175.0);
    EXPECT_TRUE(c.loops_cross);
    EXPECT_TRUE(c.outline);
    expect_same_closed_loops(c, r.exact.sink.contours[k]);
  }
  EXPECT_EQ(r.fast.summary.crossing_loop_layers, 4u);
  EXPECT_EQ(r.exact.summary.crossing_loop_layers, 4u);
  EXPECT_EQ(r.fast.summary.outline_layers, 4u);
  EXPECT_TRUE(r.fast.summary.layers[2].loops_cross);
  EXPECT_TRUE(has_diagnostic(r.fast.summary, "contours.loops_cross"));
  EXPECT_TRUE(has_diagnostic(r.exact.summary, "contours.loops_cross"));
  // Two manifold shells chain through the halfedge structure, but their loops cross.
  EXPECT_EQ(r.exact.report.halfedge_layers, 0u);
  EXPECT_EQ(r.exact.report.arrangement_layers, 4u);
}

TEST(ExactKernelOutline, OverlappingBoxesUnderEvenOddLeaveTheOverlapOut) {
  const BothKernels r = run_both(overlapping_boxes(), FillRule::EvenOdd);
  ASSERT_TRUE(r.fast.ok && r.exact.ok);
  for (std::uint32_t k = 0; k < 4; ++k) {
    EXPECT_EQ(r.fast.sink.contours[k].area_mm2, 150.0);
    expect_same_closed_loops(r.fast.sink.contours[k], r.exact.sink.contours[k]);
  }
}

TEST(ExactKernelOutline, CrossingDiagnosticNamesTheFirstLayers) {
  const BothKernels r = run_both(overlapping_boxes(), FillRule::NonZero);
  ASSERT_TRUE(r.fast.ok);
  std::string message;
  for (const Diagnostic& d : r.fast.summary.diagnostics) {
    if (d.code == "contours.loops_cross") message = d.message;
  }
  EXPECT_EQ(message,
            "loops cross or touch each other in 4 layers (first: 0, 1, 2, 3): contours are the "
            "outline of the filled region");
}

TEST(ExactKernelOutline, BoxesSharingAnEdgeTouchAndGiveTheirOutline) {
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
  append_mesh(m, indexed_box_lo_hi_diagonals({2, 2, 0}, {4, 4, 2}));
  for (const IndexedMesh& mesh : {m, welded(m)}) {
    const BothKernels r = run_both(mesh, FillRule::NonZero);
    ASSERT_TRUE(r.fast.ok && r.exact.ok);
    for (std::uint32_t k = 0; k < 2; ++k) {
      const LayerContours& c = r.fast.sink.contours[k];
      EXPECT_TRUE(c.loops_cross);
      EXPECT_TRUE(c.outline);
      EXPECT_EQ(c.area_mm2, 8.0);
      expect_same_closed_loops(c, r.exact.sink.contours[k]);
    }
  }
}

TEST(ExactKernelOutline, BoxesSharingAFaceGiveOneRectangle) {
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {2, 3, 2});
  append_mesh(m, indexed_box_lo_hi_diagonals({2, 0, 0}, {5, 3, 2}));
  const BothKernels r = run_both(m, FillRule::NonZero);
  ASSERT_TRUE(r.fast.ok && r.exact.ok);
  for (std::uint32_t k = 0; k < 2; ++k) {
    const LayerContours& c = r.fast.sink.contours[k];
    ASSERT_EQ(c.loops.size(), 1u);
    EXPECT_EQ(c.loops[0].points.size(), 4u);  // collinear corners dropped
    EXPECT_EQ(c.area_mm2, 15.0);
    expect_same_closed_loops(c, r.exact.sink.contours[k]);
  }
}

IndexedMesh nested_boxes() {
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {10, 10, 3});
  append_mesh(
      m, indexed_box_lo_hi_diagonals({3, 3, 0}, {5, 5, 3}));  // inside, facing out too: winding 2
  return m;
}

TEST(ExactKernelOutline, NestedBoxesOfOneOrientationUnderNonZeroGiveTheBigBox) {
  const BothKernels r = run_both(nested_boxes(), FillRule::NonZero);
  ASSERT_TRUE(r.fast.ok && r.exact.ok);
  for (std::uint32_t k = 0; k < 3; ++k) {
    const LayerContours& c = r.fast.sink.contours[k];
    EXPECT_FALSE(c.loops_cross);
    EXPECT_TRUE(c.misnested);
    ASSERT_EQ(c.loops.size(), 1u);
    EXPECT_EQ(c.area_mm2, 100.0);
    expect_same_closed_loops(c, r.exact.sink.contours[k]);
  }
  EXPECT_EQ(r.fast.summary.crossing_loop_layers, 0u);
  EXPECT_EQ(r.fast.summary.misnested_layers, 3u);
  EXPECT_TRUE(has_diagnostic(r.fast.summary, "contours.loops_misnested"));
}

TEST(ExactKernelOutline, NestedBoxesOfOneOrientationUnderEvenOddGiveAHole) {
  const BothKernels r = run_both(nested_boxes(), FillRule::EvenOdd);
  ASSERT_TRUE(r.fast.ok && r.exact.ok);
  for (std::uint32_t k = 0; k < 3; ++k) {
    const LayerContours& c = r.fast.sink.contours[k];
    ASSERT_EQ(c.loops.size(), 2u);
    const Contour& hole = c.loops[0].kind == LoopKind::Hole ? c.loops[0] : c.loops[1];
    EXPECT_EQ(hole.kind, LoopKind::Hole);
    EXPECT_EQ(hole.depth, 1);
    EXPECT_EQ(hole.signed_area_mm2, -4.0);
    EXPECT_EQ(c.area_mm2, 96.0);
    expect_same_closed_loops(c, r.exact.sink.contours[k]);
  }
}

TEST(ExactKernelOutline, RingLayersStaySimpleAndChained) {
  auto soup = io::read_mesh(STRATA_DATA_DIR "/ring.stl");
  ASSERT_TRUE(soup.has_value());
  const IndexedMesh mesh = weld_vertices(*soup);
  const BothKernels r = run_both(mesh, FillRule::NonZero);
  ASSERT_TRUE(r.fast.ok && r.exact.ok);
  EXPECT_EQ(r.fast.summary.crossing_loop_layers, 0u);
  EXPECT_EQ(r.fast.summary.misnested_layers, 0u);
  EXPECT_EQ(r.fast.summary.outline_layers, 0u);
  EXPECT_EQ(r.exact.summary.crossing_loop_layers, 0u);
  EXPECT_EQ(r.exact.report.arrangement_layers, 0u);
  EXPECT_FALSE(has_diagnostic(r.fast.summary, "contours.loops_cross"));
  for (const LayerContours& c : r.fast.sink.contours) {
    if (c.loops.empty()) continue;
    ASSERT_EQ(c.loops.size(), 2u);
    EXPECT_FALSE(c.outline);
    EXPECT_EQ(c.loops[0].depth + c.loops[1].depth, 1);
    EXPECT_NE(c.loops[0].kind, c.loops[1].kind);
  }
}

TEST(ExactKernelOutline, OpenChainsAreStillReportedOnOutlineLayers) {
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 3});
  m.triangles.erase(m.triangles.begin() + 10, m.triangles.end());  // the +x face removed
  const BothKernels r = run_both(m, FillRule::NonZero);
  ASSERT_TRUE(r.fast.ok && r.exact.ok);
  EXPECT_EQ(r.fast.summary.open_chains, 3u);
  EXPECT_EQ(r.fast.summary.open_chain_reports.size(), 3u);
  for (const LayerContours& c : r.fast.sink.contours) {
    EXPECT_EQ(c.open_chains, 1u);
    EXPECT_TRUE(c.outline);
    std::size_t open = 0;
    for (const Contour& loop : c.loops) open += loop.kind == LoopKind::Open ? 1 : 0;
    EXPECT_EQ(open, 1u);
  }
}

}  // namespace
}  // namespace strata::exact_test

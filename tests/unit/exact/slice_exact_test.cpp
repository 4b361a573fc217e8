#include "strata/exact/slice_exact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <new>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "exact_test_support.hpp"

namespace strata {
namespace {

using exact_test::frame;
using exact_test::octahedron;
using exact_test::perturbed_sphere;
using exact_test::run_exact;
using exact_test::run_exact_with;
using exact_test::run_fast;
using exact_test::welded;
using test::append_mesh;
using test::indexed_box_lo_hi_diagonals;

/// A convex prism: the counter-clockwise polygon `base` extruded from z0 to z1, closed, outward.
IndexedMesh prism(const std::vector<std::array<double, 2>>& base, double z0, double z1) {
  IndexedMesh m;
  const auto n = static_cast<VertexIndex>(base.size());
  for (const auto& p : base) m.vertices.push_back({p[0], p[1], z0});
  for (const auto& p : base) m.vertices.push_back({p[0], p[1], z1});
  for (VertexIndex k = 0; k < n; ++k) {
    const VertexIndex next = (k + 1) % n;
    exact_test::add_quad(m, k, next, n + next, n + k);
  }
  for (VertexIndex k = 1; k + 1 < n; ++k) {
    m.triangles.push_back({0, k + 1, k});
    m.triangles.push_back({n, n + k, n + k + 1});
  }
  return m;
}

struct Model {
  Model(std::string n, std::function<IndexedMesh()> b, double c = 1.0, std::optional<Vec3> o = {},
        bool comparable = true)
      : name(std::move(n)),
        build(std::move(b)),
        cell(c),
        origin(o),
        contours_comparable(comparable) {}

  std::string name;
  std::function<IndexedMesh()> build;
  double cell = 1.0;                ///< cell and layer size of the aligned grid
  std::optional<Vec3> origin;       ///< of the aligned grid (default: the bounding box corner)
  bool contours_comparable = true;  ///< the fast path closes every loop, so areas agree
};

void PrintTo(const Model& model, std::ostream* os) { *os << model.name; }

std::vector<Model> models() {
  std::vector<Model> out;
  out.push_back({"box", [] { return indexed_box_lo_hi_diagonals({0, 0, 0}, {6, 5, 7}); }});
  out.push_back({"tetrahedron", [] { return weld_vertices(mesh::make_tetrahedron()); }});
  out.push_back({"overlapping_boxes", [] {
                   IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 4, 3});
                   append_mesh(m, indexed_box_lo_hi_diagonals({2, 2, 1}, {6, 6, 4}));
                   return m;
                 }});
  out.push_back({"frame", [] { return frame({0, 0}, {10, 8}, {3, 2}, {7, 5}, 0, 3); }});
  out.push_back({"vertex_on_plane", [] { return octahedron(2, 2, 2, 0, 1.5, 3); }});
  out.push_back({"vertex_on_cell_centre", [] { return octahedron(2.5, 2.5, 2, 0.5, 1.5, 2.5); },
                 1.0, Vec3{0, 0, 0}});
  out.push_back({"walls_through_centres",
                 [] {
                   return indexed_box_lo_hi_diagonals({0.5, 0.5, 0.5}, {3.5, 2.5, 2.5});
                 },
                 1.0, Vec3{0, 0, 0}});
  out.push_back({"faces_on_scanlines",
                 [] {
                   return prism({{0, 0}, {4, 0}, {0, 4}}, 0, 2);
                 },
                 1.0, Vec3{0, 0, 0}});
  out.push_back({"slanted_on_scanlines",
                 [] {
                   return prism({{0.5, 0.5}, {4.5, 1.5}, {2.5, 3.5}}, 0.5, 2.5);
                 },
                 1.0, Vec3{0, 0, 0}});
  out.push_back({"open_box_top", [] {
                   IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 3});
                   m.triangles.erase(m.triangles.begin() + 2, m.triangles.begin() + 4);
                   return m;
                 }});
  out.push_back({"open_box_side",
                 [] {
                   IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 3});
                   m.triangles.erase(m.triangles.begin() + 10);
                   return m;
                 },
                 1.0, std::nullopt, false});
  out.push_back({"shared_edge", [] {
                   IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
                   append_mesh(m, indexed_box_lo_hi_diagonals({2, 2, 0}, {4, 4, 2}));
                   return welded(m);
                 }});
  out.push_back({"duplicate_facets",
                 [] {
                   IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 3});
                   m.triangles.push_back(m.triangles[10]);
                   const auto t = m.triangles[4];
                   m.triangles.push_back({t[0], t[2], t[1]});
                   return m;
                 },
                 1.0, std::nullopt, false});
  out.push_back({"zero_area_facets", [] {
                   IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 3});
                   m.triangles.push_back({0, 0, 4});  // a repeated corner on a box edge
                   const auto v = static_cast<VertexIndex>(m.vertices.size());
                   m.vertices.push_back({1, 1, 0.2});  // three points on a vertical line
                   m.vertices.push_back({1, 1, 1.7});
                   m.vertices.push_back({1, 1, 2.9});
                   m.vertices.push_back({1.5, 1, 0.5});  // three points on a slanted line
                   m.vertices.push_back({2, 1.5, 1.5});
                   m.vertices.push_back({2.5, 2, 2.5});
                   m.triangles.push_back({v, v + 1, v + 2});
                   m.triangles.push_back({v + 3, v + 4, v + 5});
                   return m;
                 }});
  out.push_back({"perturbed_sphere",
                 [] {
                   return perturbed_sphere(5, 3, 0.05, 20240611, {5.3, 5.1, 5.2});
                 },
                 0.5});
  out.push_back({"cylinder", [] { return weld_vertices(mesh::make_cylinder(4, 6, 24)); }, 0.5});
  return out;
}

GridSpec aligned_grid(const Model& model, const IndexedMesh& mesh) {
  GridOptions g{model.cell, model.cell, model.cell, model.origin};
  auto grid = make_grid(mesh.bounds(), g);
  EXPECT_TRUE(grid.has_value());
  return *grid;
}

GridSpec skew_grid(const IndexedMesh& mesh) {
  const Bbox3 b = mesh.bounds();
  GridOptions g{0.37, 0.41, 0.29, Vec3{b.min.x - 0.123, b.min.y - 0.271, b.min.z - 0.0917}};
  auto grid = make_grid(b, g);
  EXPECT_TRUE(grid.has_value());
  return *grid;
}

SliceOptions options_with(FillRule rule, double offset) {
  SliceOptions o;
  o.fill_rule = rule;
  o.scan_offset_mm = offset;
  o.shell_mm = 0.6;
  o.batch_layers = 3;  // several batches: the kernels' facet sweeps are exercised
  return o;
}

std::string describe(FillRule rule, double offset, bool aligned) {
  return std::string(to_string(rule)) + ", offset " + std::to_string(offset) +
         (aligned ? ", aligned grid" : ", skew grid");
}

class ExactAgreesWithFast : public ::testing::TestWithParam<Model> {};

TEST_P(ExactAgreesWithFast, CellsAreIdentical) {
  const Model& model = GetParam();
  const IndexedMesh mesh = model.build();
  for (const bool aligned : {true, false}) {
    const GridSpec grid = aligned ? aligned_grid(model, mesh) : skew_grid(mesh);
    for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
      for (const double offset : {0.0, 0.0001}) {
        const SliceOptions options = options_with(rule, offset);
        const auto fast = run_fast(mesh, grid, options);
        const auto exact = run_exact(mesh, grid, options);
        ASSERT_TRUE(fast.ok && exact.ok);
        ASSERT_EQ(fast.sink.cells.size(), exact.sink.cells.size());
        std::size_t differ = 0;
        std::string first;
        std::uint64_t solid = 0;
        for (std::uint32_t k = 0; k < grid.nz; ++k) {
          for (std::size_t c = 0; c < grid.cells_per_layer(); ++c) {
            solid += exact.sink.cells[k][c] != CellClass::Empty ? 1 : 0;
            if (fast.sink.cells[k][c] == exact.sink.cells[k][c]) continue;
            if (differ++ == 0) {
              first = "cell (" + std::to_string(c % grid.nx) + ", " + std::to_string(c / grid.nx) +
                      ", " + std::to_string(k) + ")";
            }
          }
        }
        EXPECT_EQ(differ, 0u) << describe(rule, offset, aligned) << ": first at " << first;
        EXPECT_GT(solid, 0u) << describe(rule, offset, aligned);
      }
    }
  }
}

TEST_P(ExactAgreesWithFast, ContourAreasAgree) {
  const Model& model = GetParam();
  if (!model.contours_comparable) GTEST_SKIP() << "the fast path leaves open chains here";
  const IndexedMesh mesh = model.build();
  for (const bool aligned : {true, false}) {
    const GridSpec grid = aligned ? aligned_grid(model, mesh) : skew_grid(mesh);
    const SliceOptions options = options_with(FillRule::NonZero, 0.0);
    const auto fast = run_fast(mesh, grid, options);
    const auto exact = run_exact(mesh, grid, options);
    ASSERT_TRUE(fast.ok && exact.ok);
    for (std::uint32_t k = 0; k < grid.nz; ++k) {
      const double a = fast.sink.contours[k].area_mm2;
      const double b = exact.sink.contours[k].area_mm2;
      EXPECT_LE(std::fabs(a - b), 1e-9 * std::max({std::fabs(a), std::fabs(b), 1e-3}))
          << "layer " << k << (aligned ? " (aligned grid)" : " (skew grid)") << ": fast " << a
          << ", exact " << b;
    }
  }
}

TEST_P(ExactAgreesWithFast, ArrangementContoursBoundTheSolidCells) {
  // Forced onto the arrangement, a layer's loops bound exactly the region the cell rule makes
  // solid: every cell centre (off the loops, on a skew grid) is inside them iff it is solid.
  const Model& model = GetParam();
  const IndexedMesh mesh = model.build();
  const GridSpec grid = skew_grid(mesh);
  for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
    const SliceOptions options = options_with(rule, 0.0);
    const auto r = run_exact_with(mesh, grid, options, exact::detail::ContourMethod::Arrangement);
    ASSERT_TRUE(r.ok);
    std::size_t differ = 0;
    for (std::uint32_t k = 0; k < grid.nz; ++k) {
      for (const Contour& c : r.sink.contours[k].loops) {
        EXPECT_TRUE(c.is_closed);
        EXPECT_EQ(c.kind, c.signed_area_mm2 > 0 ? LoopKind::Outer : LoopKind::Hole);
      }
      for (std::uint32_t j = 0; j < grid.ny; ++j) {
        for (std::uint32_t i = 0; i < grid.nx; ++i) {
          const bool inside =
              exact_test::winding_of_loops(r.sink.contours[k], grid.xc(i), grid.yc(j)) != 0;
          if (inside != r.sink.solid(i, j, k)) ++differ;
        }
      }
    }
    EXPECT_EQ(differ, 0u) << to_string(rule);
    EXPECT_EQ(r.report.halfedge_layers, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Exact, ExactAgreesWithFast, ::testing::ValuesIn(models()),
                         [](const ::testing::TestParamInfo<Model>& info) {
                           return info.param.name;
                         });

// --- the report ---------------------------------------------------------------------------------

SliceOptions unit_options() {
  SliceOptions o;
  o.grid = GridOptions{1.0, 1.0, 1.0, std::nullopt};
  return o;
}

Result<GridSpec> unit_grid(const IndexedMesh& mesh) {
  return make_grid(mesh.bounds(), unit_options().grid);
}

TEST(ExactSliceReport, ClosedBoxIsChainedThroughTheHalfedgeStructure) {
  const IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 5});
  const auto r = run_exact(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(r.ok);
  EXPECT_TRUE(r.report.polygon_mesh);
  EXPECT_EQ(r.report.input_polygons, 12u);
  EXPECT_EQ(r.report.polygons_removed, 0u);
  EXPECT_EQ(r.report.points_duplicated, 0u);
  EXPECT_EQ(r.report.halfedge_layers, 5u);
  EXPECT_EQ(r.report.arrangement_layers, 0u);
  for (const LayerContours& c : r.sink.contours) {
    ASSERT_EQ(c.loops.size(), 1u);
    EXPECT_EQ(c.loops[0].kind, LoopKind::Outer);
    EXPECT_EQ(c.loops[0].signed_area_mm2, 12.0);
  }
}

TEST(ExactSliceReport, SharedEdgeIsSplitByOrientation) {
  IndexedMesh m = indexed_box_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
  append_mesh(m, indexed_box_lo_hi_diagonals({2, 2, 0}, {4, 4, 2}));
  const IndexedMesh mesh = welded(m);
  const auto r = run_exact(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.non_manifold_edges, 1u);
  EXPECT_GT(r.report.points_duplicated, 0u);
  EXPECT_TRUE(r.report.polygon_mesh);
  // The two squares touch at a corner in every layer: not simple, so outlined.
  EXPECT_EQ(r.report.arrangement_layers, 2u);
  EXPECT_DOUBLE_EQ(r.sink.contours[0].area_mm2, 8.0);
}

TEST(ExactSliceReport, OverlappingShellsAreOutlinedWhereTheirLoopsCross) {
  IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 4, 3});
  append_mesh(mesh, indexed_box_lo_hi_diagonals({2, 2, 1}, {6, 6, 4}));
  const auto r = run_exact(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.halfedge_layers, 2u);  // layers 0 and 3 hold one box each
  EXPECT_EQ(r.report.arrangement_layers, 2u);
  ASSERT_EQ(r.sink.contours[1].loops.size(), 1u);
  EXPECT_EQ(r.sink.contours[1].area_mm2, 28.0);  // the union: 16 + 16 - 4
}

TEST(ExactSliceReport, DuplicateFacetsAreRemovedAndTheirLayersUseTheArrangement) {
  IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 3});
  mesh.triangles.push_back(mesh.triangles[10]);
  const auto r = run_exact(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.polygons_removed, 1u);
  EXPECT_EQ(r.report.arrangement_layers + r.report.halfedge_layers + r.report.empty_layers, 3u);
  EXPECT_GT(r.report.arrangement_layers, 0u);
  bool reported = false;
  for (const Diagnostic& d : r.summary.diagnostics) reported |= d.code == "exact.polygons_removed";
  EXPECT_TRUE(reported);
}

TEST(ExactSliceReport, RepeatedCornerFacetIsRemovedWithoutLeavingTheHalfedgePath) {
  IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 3});
  mesh.triangles.push_back({0, 0, 4});
  const auto r = run_exact(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.polygons_removed, 1u);
  EXPECT_EQ(r.report.halfedge_layers, 3u);
}

TEST(ExactSliceReport, ASoupOfNeedlesLeavesNoPolygonMeshAndSaysSo) {
  IndexedMesh mesh;
  mesh.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 3, 3}};
  mesh.triangles = {{0, 0, 1}, {2, 2, 1}};
  const auto r = run_exact(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.polygons_removed, 2u);
  EXPECT_FALSE(r.report.polygon_mesh);
  std::vector<std::string> codes;
  for (const Diagnostic& d : r.summary.diagnostics) codes.push_back(d.code);
  EXPECT_NE(std::find(codes.begin(), codes.end(), "exact.not_a_polygon_mesh"), codes.end());
  for (const std::vector<CellClass>& layer : r.sink.cells) {
    EXPECT_EQ(std::count(layer.begin(), layer.end(), CellClass::Empty),
              static_cast<std::ptrdiff_t>(layer.size()));
  }
}

TEST(ExactSliceReport, UnweldedCopiesAreMerged) {
  IndexedMesh mesh;
  const IndexedMesh b = indexed_box_lo_hi_diagonals({0, 0, 0}, {2, 2, 2});
  for (const auto& t : b.triangles) {  // every facet with its own three vertices
    const auto v = static_cast<VertexIndex>(mesh.vertices.size());
    for (const VertexIndex c : t) mesh.vertices.push_back(b.vertices[c]);
    mesh.triangles.push_back({v, v + 1, v + 2});
  }
  const auto r = run_exact(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.points_merged, 36u - 8u);
  EXPECT_TRUE(r.report.polygon_mesh);
  // The input's own edges do not chain (every facet has its own corners), so the layers are
  // outlined on the arrangement: the same square.
  EXPECT_EQ(r.report.arrangement_layers, 2u);
  EXPECT_EQ(r.sink.contours[0].area_mm2, 4.0);
}

// --- orientation and hatches ---------------------------------------------------------------------

TEST(ExactSliceContours, InsideOutBoxIsOutlinedAsTheRegionNonzeroFillsLikeTheFastPath) {
  IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 2});
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  const auto exact = run_exact(mesh, *unit_grid(mesh), unit_options());
  const auto fast = run_fast(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(exact.ok && fast.ok);
  for (std::uint32_t k = 0; k < 2; ++k) {
    // A lone clockwise loop does not alternate with depth: winding -1 is filled under nonzero,
    // and both paths give the outline of that region, counter-clockwise.
    ASSERT_EQ(exact.sink.contours[k].loops.size(), 1u);
    EXPECT_EQ(exact.sink.contours[k].loops[0].kind, LoopKind::Outer);
    EXPECT_EQ(exact.sink.contours[k].area_mm2, 12.0);
    EXPECT_EQ(fast.sink.contours[k].area_mm2, 12.0);
  }
}

TEST(ExactSliceContours, FrameHasAnOuterLoopAndANestedHole) {
  const IndexedMesh mesh = frame({0, 0}, {10, 8}, {3, 2}, {7, 5}, 0, 3);
  const auto r = run_exact(mesh, *unit_grid(mesh), unit_options());
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.report.halfedge_layers, 3u);
  for (const LayerContours& c : r.sink.contours) {
    ASSERT_EQ(c.loops.size(), 2u);
    const Contour& outer = c.loops[0].kind == LoopKind::Outer ? c.loops[0] : c.loops[1];
    const Contour& hole = c.loops[0].kind == LoopKind::Outer ? c.loops[1] : c.loops[0];
    EXPECT_EQ(outer.signed_area_mm2, 80.0);
    EXPECT_EQ(outer.depth, 0);
    EXPECT_EQ(hole.kind, LoopKind::Hole);
    EXPECT_EQ(hole.signed_area_mm2, -12.0);
    EXPECT_EQ(hole.depth, 1);
    EXPECT_EQ(c.area_mm2, 68.0);
  }
}

TEST(ExactSliceFill, HatchesRunBetweenTheWalls) {
  const IndexedMesh mesh = indexed_box_lo_hi_diagonals({0.25, 0.5, 0}, {5.75, 2.5, 1});
  SliceOptions o = unit_options();
  o.grid.origin = Vec3{0, 0, 0};
  const auto r = run_exact(mesh, *make_grid(mesh.bounds(), o.grid), o);
  ASSERT_TRUE(r.ok);
  // Scanlines y = 0.5 and 2.5 lie on the faces y = 0.5 and y = 2.5: each takes the material just
  // below it, so rows 1 and 2 are hatched and row 0 is not.
  ASSERT_EQ(r.sink.hatches[0].size(), 2u);
  for (const HatchSegment& h : r.sink.hatches[0]) {
    EXPECT_EQ(h.x_start, 0.25);
    EXPECT_EQ(h.x_end, 5.75);
  }
  EXPECT_EQ(r.sink.hatches[0][0].row, 1u);
  EXPECT_EQ(r.sink.hatches[0][1].row, 2u);
}

TEST(ExactSliceFill, CrossingsAreRoundedOnceToTheNearestDouble) {
  // A wedge under the slanted face x + z = 1: at the plane z = zk(0) (about 1/3) its wall stands
  // at x = 1 - z exactly, which needs one bit more than a double has near 2/3; the hatch ends at
  // the nearest double, which is what IEEE subtraction gives for 1 - z.
  IndexedMesh wedge;
  wedge.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 4, 0}, {1, 4, 0}, {0, 4, 1}};
  wedge.triangles = {{0, 1, 2}, {3, 5, 4},   // y = 0 and y = 4
                     {0, 3, 4}, {0, 4, 1},   // bottom
                     {1, 4, 5}, {1, 5, 2},   // the slanted face
                     {0, 2, 5}, {0, 5, 3}};  // x = 0
  SliceOptions o;
  o.grid = GridOptions{0.25, 1.0, 2.0 / 3.0, Vec3{0, 0, 0}};
  const auto grid = make_grid(wedge.bounds(), o.grid);
  ASSERT_TRUE(grid.has_value());
  const auto r = run_exact(wedge, *grid, o);
  ASSERT_TRUE(r.ok);
  ASSERT_EQ(r.sink.hatches[0].size(), 4u);
  const double z = grid->zk(0);
  ASSERT_NE(1.0 - (1.0 - z), z) << "the test needs a crossing that is not a double";
  for (const HatchSegment& h : r.sink.hatches[0]) {
    EXPECT_EQ(h.x_start, 0.0);
    EXPECT_EQ(h.x_end, 1.0 - z);
  }
}

// --- errors
// ---------------------------------------------------------------------------------------

TEST(ExactSliceErrors, WindingRuleIsAUsageError) {
  const IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  SliceOptions o = unit_options();
  o.fill_rule = FillRule::Winding;
  exact_test::LayerCollector sink;
  LayerSink* sinks[] = {&sink};
  auto r = slice_model_exact(mesh, *unit_grid(mesh), o, sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::Usage);
}

TEST(ExactSliceErrors, NonFiniteCoordinateIsBadInput) {
  IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  const GridSpec grid = *unit_grid(mesh);
  mesh.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
  exact_test::LayerCollector sink;
  LayerSink* sinks[] = {&sink};
  auto r = slice_model_exact(mesh, grid, unit_options(), sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::BadInput);
  EXPECT_NE(r.error().message.find("vertex 3"), std::string::npos);
  EXPECT_TRUE(sink.cells.empty());
}

TEST(ExactSliceErrors, VertexIndexOutOfRangeIsBadInput) {
  IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
  const GridSpec grid = *unit_grid(mesh);
  mesh.triangles[5][1] = 99;
  exact_test::LayerCollector sink;
  LayerSink* sinks[] = {&sink};
  auto r = slice_model_exact(mesh, grid, unit_options(), sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::BadInput);
  EXPECT_NE(r.error().message.find("facet 5"), std::string::npos);
}

TEST(ExactSliceErrors, NonFiniteCoordinateOnAnyAxisIsBadInput) {
  for (int axis = 0; axis < 3; ++axis) {
    IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {1, 1, 1});
    const GridSpec grid = *unit_grid(mesh);
    Vec3& v = mesh.vertices[0];
    v = {0, 0, 0};
    (axis == 0 ? v.x : axis == 1 ? v.y : v.z) = std::numeric_limits<double>::infinity();
    exact_test::LayerCollector sink;
    LayerSink* sinks[] = {&sink};
    auto r = slice_model_exact(mesh, grid, unit_options(), sinks);
    ASSERT_FALSE(r.has_value()) << axis;
    EXPECT_EQ(r.error().code, ErrorCode::BadInput);
    const char* expected[] = {"vertex 0 has a non-finite coordinate (inf, 0, 0)",
                              "vertex 0 has a non-finite coordinate (0, inf, 0)",
                              "vertex 0 has a non-finite coordinate (0, 0, inf)"};
    EXPECT_EQ(r.error().message, expected[axis]);
  }
}

/// A sink that fails on its second layer by throwing, and remembers being aborted.
class ThrowingSink final : public LayerSink {
 public:
  explicit ThrowingSink(std::function<void()> fail) : fail_(std::move(fail)) {}
  Result<void> begin(const SliceRunInfo&) override { return {}; }
  Result<void> add_layer(const LayerResult&) override {
    if (++layers_ == 2) fail_();
    return {};
  }
  Result<void> finish() override { return {}; }
  void abort() noexcept override { aborted = true; }
  bool aborted = false;

 private:
  std::function<void()> fail_;
  int layers_ = 0;
};

TEST(ExactSliceErrors, AFailureInASinkIsAnInternalErrorOfTheExactPath) {
  const IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 5});
  ThrowingSink failing([] { throw std::runtime_error("disk full"); });
  exact_test::LayerCollector other;
  LayerSink* sinks[] = {&failing, &other};
  auto r = slice_model_exact(mesh, *unit_grid(mesh), unit_options(), sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::Internal);
  EXPECT_EQ(r.error().message, "exact path failed: disk full");
  EXPECT_TRUE(failing.aborted);
  EXPECT_TRUE(other.aborted);
  EXPECT_FALSE(other.finished);
}

TEST(ExactSliceErrors, RunningOutOfMemoryIsAnInternalErrorOfTheExactPath) {
  const IndexedMesh mesh = indexed_box_lo_hi_diagonals({0, 0, 0}, {4, 3, 5});
  ThrowingSink failing([] { throw std::bad_alloc(); });
  LayerSink* sinks[] = {&failing};
  auto r = slice_model_exact(mesh, *unit_grid(mesh), unit_options(), sinks);
  ASSERT_FALSE(r.has_value());
  EXPECT_EQ(r.error().code, ErrorCode::Internal);
  EXPECT_EQ(r.error().message, "exact path: out of memory");
  EXPECT_TRUE(failing.aborted);
}

}  // namespace
}  // namespace strata

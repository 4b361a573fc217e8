// The reference slicer (CGAL Polygon_mesh_slicer with the exact kernel) inside validate_model,
// and its section of one plane (src/validate/reference_slicer.cpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <vector>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/validate/validate_model.hpp"
#include "strata/validate/validation_json.hpp"
#include "strata/validate/validation_text.hpp"
#include "support/mesh_builders.hpp"
#include "support/validated_model.hpp"
#include "validate/reference_slicer_internal.hpp"

namespace strata::validate {
namespace {

using test::validated_model;
using test::welded_box;

SliceOptions cells_of(double d, std::optional<Vec3> origin = Vec3{0, 0, 0}) {
  SliceOptions options;
  options.grid.dx_mm = options.grid.dy_mm = options.grid.dz_mm = d;
  options.grid.origin = origin;
  options.fill_rule = FillRule::NonZero;
  options.shell_mm = d;
  options.threads = 1;
  return options;
}

double diagonal(const IndexedMesh& mesh) {
  const Bbox3 b = mesh.bounds();
  return std::hypot(b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z);
}

TEST(ReferenceSlicer, AgreesWithBothPathsOnAnIcosphere) {
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(10.0, 3));
  const ValidationReport r = validated_model(sphere, cells_of(0.7, std::nullopt));
  const ReferenceSlicerFigures& f = r.reference;
  ASSERT_TRUE(f.ran) << f.reason;
  EXPECT_EQ(f.skipped, ReferenceSkip::None);
  EXPECT_EQ(f.layers_compared, r.grid.nz);
  EXPECT_EQ(f.layers_vertex_on_plane, 0u);
  const double size = diagonal(sphere);
  EXPECT_LT(f.max_hausdorff_exact_mm, 1e-9 * size);
  EXPECT_LT(f.max_hausdorff_fast_mm, 1e-9 * size);
  EXPECT_LT(f.max_symmetric_difference_exact_mm2, 1e-9 * size * size);
  EXPECT_LT(f.max_symmetric_difference_fast_mm2, 1e-9 * size * size);
  EXPECT_EQ(f.layers_differing_exact, 0u);
  EXPECT_EQ(f.layers_differing_fast, 0u);
  EXPECT_EQ(f.open_polylines, 0u);
}

TEST(ReferenceSlicer, AgreesWithBothPathsOnTheRing) {
  const auto soup = io::read_mesh(std::string(STRATA_DATA_DIR) + "/ring.stl");
  ASSERT_TRUE(soup.has_value()) << soup.error().to_string();
  const IndexedMesh ring = weld_vertices(*soup);
  const ValidationReport r = validated_model(ring, cells_of(0.5, std::nullopt));
  const ReferenceSlicerFigures& f = r.reference;
  ASSERT_TRUE(f.ran) << f.reason;
  EXPECT_EQ(f.layers_compared, 20u);
  const double size = diagonal(ring);
  EXPECT_LT(f.max_hausdorff_exact_mm, 1e-9 * size);
  EXPECT_LT(f.max_hausdorff_fast_mm, 1e-9 * size);
  EXPECT_LT(f.max_symmetric_difference_exact_mm2, 1e-9 * size * size);
  EXPECT_EQ(f.layers_differing_exact, 0u);
  // Each layer: the outer wall and the hole.
  for (const ReferenceLayerComparison& l : f.layers) {
    EXPECT_EQ(l.closed_polylines, 2u) << "layer " << l.layer;
  }
}

TEST(ReferenceSlicer, GivesTheExactPathsPointsOnAGenericPlane) {
  // Exact intersection points rounded once to the nearest double, like the exact path: the two
  // sets of loops have the same edges.
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(10.0, 2));
  const ValidationReport r = validated_model(sphere, cells_of(0.9, std::nullopt));
  ASSERT_TRUE(r.reference.ran) << r.reference.reason;
  for (const ReferenceLayerComparison& l : r.reference.layers) {
    EXPECT_EQ(l.area_method_exact, AreaMethod::Identical) << "layer " << l.layer;
    EXPECT_EQ(l.hausdorff_exact_mm, 0.0) << "layer " << l.layer;
  }
}

TEST(ReferenceSlicer, SkipsANonManifoldModelAndSaysWhy) {
  // Two boxes sharing one edge: four facets around it.
  const IndexedMesh m = welded_box({0, 0, 0}, {2, 2, 2});
  const IndexedMesh b = welded_box({2, 2, 0}, {4, 4, 2});
  TriangleSoup soup;
  for (const IndexedMesh* part : {&m, &b}) {
    for (FacetIndex f = 0; f < part->triangles.size(); ++f) {
      soup.triangles.push_back({part->corner(f, 0), part->corner(f, 1), part->corner(f, 2)});
    }
  }
  const ValidationReport r = validated_model(weld_vertices(soup), cells_of(1.0));
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::NonManifold);
  EXPECT_NE(r.reference.reason.find("non-manifold"), std::string::npos) << r.reference.reason;
  EXPECT_EQ(r.reference.layers_compared, 0u);
  EXPECT_NE(validation_text(r).find("not run: not a 2-manifold"), std::string::npos)
      << validation_text(r);
}

TEST(ReferenceSlicer, SkipsAnOpenModel) {
  IndexedMesh m = welded_box({0, 0, 0}, {2, 2, 2});
  m.triangles.pop_back();
  const ValidationReport r = validated_model(m, cells_of(1.0));
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::NotClosed);
  EXPECT_NE(r.reference.reason.find("border edges"), std::string::npos) << r.reference.reason;
}

TEST(ReferenceSlicer, SkipsAnInconsistentlyOrientedModel) {
  IndexedMesh m = welded_box({0, 0, 0}, {2, 2, 2});
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  const ValidationReport r = validated_model(m, cells_of(1.0));
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::Inconsistent) << r.reference.reason;
}

TEST(ReferenceSlicer, SkipsAModelOverTheFacetCap) {
  ValidateOptions vopts;
  vopts.reference_max_facets = 11;
  const ValidationReport r =
      validated_model(welded_box({0, 0, 0}, {2, 2, 2}), cells_of(1.0), vopts);
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::TooManyFacets);
  EXPECT_EQ(r.reference.max_facets, 11u);
  EXPECT_NE(r.reference.reason.find("12 facets"), std::string::npos) << r.reference.reason;
}

TEST(ReferenceSlicer, IsOffWhenAskedTo) {
  ValidateOptions vopts;
  vopts.reference_slicer = false;
  const ValidationReport r =
      validated_model(welded_box({0, 0, 0}, {2, 2, 2}), cells_of(1.0), vopts);
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::Off);
}

TEST(ReferenceSlicer, CountsALayerWhosePlaneHoldsAVertex) {
  // The apex (0, 0, 2.5) lies on the plane of layer 2; no other vertex is on a plane.
  const IndexedMesh tetra =
      weld_vertices(mesh::make_tetrahedron({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 2.5}));
  const ValidationReport r = validated_model(tetra, cells_of(1.0));
  const ReferenceSlicerFigures& f = r.reference;
  ASSERT_TRUE(f.ran) << f.reason;
  ASSERT_EQ(f.layers.size(), 3u);
  EXPECT_EQ(f.layers_vertex_on_plane, 1u);
  EXPECT_EQ(f.layers_facet_on_plane, 0u);
  EXPECT_EQ(f.layers[2].vertices_on_plane, 1u);
  EXPECT_EQ(f.layers[2].isolated_points, 1u);  // CGAL keeps the apex as a point
  EXPECT_FALSE(f.layers[0].vertex_on_plane());
  EXPECT_EQ(f.layers_differing_exact, 0u);
  EXPECT_EQ(f.max_hausdorff_exact_mm, 0.0);
}

TEST(ReferenceSlicer, CountsTheBottomFacetOnAPlaneAsALegitimateDifference) {
  // The bottom face z = 0.5 lies on the plane of layer 0: CGAL returns its outline, strata counts
  // its vertices above the plane and sees nothing there.
  const ValidationReport r = validated_model(welded_box({0, 0, 0.5}, {3, 2, 3}), cells_of(1.0));
  const ReferenceSlicerFigures& f = r.reference;
  ASSERT_TRUE(f.ran) << f.reason;
  ASSERT_EQ(f.layers.size(), 3u);
  EXPECT_TRUE(f.layers[0].facet_on_plane);
  EXPECT_EQ(f.layers[0].closed_polylines, 1u);
  EXPECT_TRUE(f.layers[0].differs_from_exact);
  EXPECT_EQ(f.layers_vertex_on_plane, 1u);
  EXPECT_EQ(f.layers_facet_on_plane, 1u);
  EXPECT_EQ(f.layers_differing_exact_at_vertex, 1u);
  EXPECT_EQ(f.layers_differing_exact, 0u);
  EXPECT_EQ(f.max_symmetric_difference_exact_mm2, 0.0);
  EXPECT_DOUBLE_EQ(f.max_symmetric_difference_exact_all_mm2, 6.0);
}

TEST(ReferenceSlicer, AgreesWhereTheTopFacetLiesOnAPlane) {
  // The top face z = 2.5 lies on the plane of layer 2: CGAL orients its outline by the side
  // faces below it, strata sees the section just below the plane: the same rectangle.
  const ValidationReport r = validated_model(welded_box({0, 0, 0}, {3, 2, 2.5}), cells_of(1.0));
  const ReferenceSlicerFigures& f = r.reference;
  ASSERT_TRUE(f.ran) << f.reason;
  ASSERT_EQ(f.layers.size(), 3u);
  EXPECT_TRUE(f.layers[2].facet_on_plane);
  EXPECT_FALSE(f.layers[2].differs_from_exact);
  EXPECT_FALSE(f.layers[2].differs_from_fast);
  EXPECT_EQ(f.max_symmetric_difference_exact_all_mm2, 0.0);
}

TEST(ReferenceSlicer, GivesACounterClockwiseLoopAroundTheMaterial) {
  const IndexedMesh m = welded_box({0, 0, 0}, {2, 3, 2});
  detail::ReferenceSlicer slicer(m, 1000);
  ASSERT_TRUE(slicer.ready()) << slicer.figures().reason;
  const detail::ReferenceSection s = slicer.slice(1.25);
  ASSERT_EQ(s.contours.size(), 1u);
  EXPECT_TRUE(s.contours[0].is_closed);
  EXPECT_EQ(s.contours[0].kind, LoopKind::Outer);
  EXPECT_DOUBLE_EQ(s.contours[0].signed_area_mm2, 6.0);
  EXPECT_EQ(s.closed_polylines, 1u);
  EXPECT_EQ(s.open_polylines, 0u);
  EXPECT_EQ(slicer.vertices_on_plane(1.25), 0u);
  EXPECT_EQ(slicer.vertices_on_plane(2.0), 4u);
  EXPECT_TRUE(slicer.facet_on_plane(2.0));
}

TEST(ReferenceSlicer, WritesItsSectionInTheJsonReport) {
  const ValidationReport r = validated_model(welded_box({0, 0, 0}, {3, 2, 2}), cells_of(1.0));
  const nlohmann::json j = nlohmann::json::parse(validation_json(r));
  const nlohmann::json& ref = j.at("reference_slicer");
  EXPECT_TRUE(ref.at("ran").get<bool>());
  EXPECT_EQ(ref.at("skipped"), "none");
  EXPECT_EQ(ref.at("layers_compared"), r.grid.nz);
  EXPECT_EQ(ref.at("layers").size(), r.grid.nz);
  EXPECT_NE(validation_text(r).find("reference slicer (CGAL Polygon_mesh_slicer"),
            std::string::npos);
}

TEST(ReferenceSlicer, RefusesAModelWhoseFacetsAllRepeatACorner) {
  IndexedMesh needles;
  needles.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 1}};
  needles.triangles = {{0, 1, 1}, {2, 2, 0}};
  const detail::ReferenceSlicer slicer(needles, 100);
  EXPECT_FALSE(slicer.ready());
  EXPECT_EQ(slicer.figures().skipped, ReferenceSkip::Empty);
  EXPECT_EQ(slicer.figures().reason, "no facet with three distinct corners");
  EXPECT_EQ(slicer.figures().degenerate_facets_dropped, 2u);
  EXPECT_EQ(slicer.figures().facets, 2u);
}

TEST(ReferenceSlicer, LeavesOutAFacetWithARepeatedCornerAndSlicesTheRest) {
  IndexedMesh m = welded_box({0, 0, 0}, {2, 2, 2});
  m.triangles.push_back({0, 1, 1});
  const ValidationReport r = validated_model(m, cells_of(1.0));
  ASSERT_TRUE(r.reference.ran) << r.reference.reason;
  EXPECT_EQ(r.reference.degenerate_facets_dropped, 1u);
  EXPECT_EQ(r.reference.facets, 13u);
  EXPECT_EQ(r.reference.layers_differing_exact, 0u);
  EXPECT_NE(validation_text(r).find("; 1 facets with a repeated corner left out"),
            std::string::npos)
      << validation_text(r);
}

TEST(ReferenceSlicer, OverlaysOnlyEveryNthLayerThatDiffersAtRoundingLevel) {
  // The fast path's points differ from the exact ones by rounding: with a budget of one overlay
  // only layer 0 is overlaid among the layers that differ that little.
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(10.0, 3));
  ValidateOptions vopts;
  vopts.max_overlay_layers = 1;
  const ValidationReport r = validated_model(sphere, cells_of(0.7, std::nullopt), vopts);
  const ReferenceSlicerFigures& f = r.reference;
  ASSERT_TRUE(f.ran) << f.reason;
  EXPECT_GT(f.layers_overlay_skipped, 0u);
  std::uint32_t skipped = 0;
  for (const ReferenceLayerComparison& l : f.layers) {
    if (l.area_method_fast != AreaMethod::NotCompared) continue;
    ++skipped;
    EXPECT_NE(l.layer, 0u);
    EXPECT_LE(l.hausdorff_fast_mm, 1e-9 * diagonal(sphere));
    EXPECT_FALSE(l.differs_from_fast);
  }
  for (const ReferenceLayerComparison& l : f.layers) {
    if (l.area_method_exact == AreaMethod::NotCompared) ++skipped;
  }
  EXPECT_EQ(skipped, f.layers_overlay_skipped);
  EXPECT_EQ(f.layers_differing_fast, 0u);
}

/// A roof over the square [-1, 1]^2 (base z = 0) whose top is a cross of four ridges at z = 1,
/// from the centre (0, 0) to the middle of each side: a closed 2-manifold of 14 facets.
IndexedMesh cross_roof() {
  IndexedMesh m;
  m.vertices = {{0, 0, 1}, {1, 0, 1},  {0, 1, 1},   {-1, 0, 1}, {0, -1, 1},
                {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}};
  m.triangles = {{0, 1, 5}, {0, 5, 2}, {0, 2, 6}, {0, 6, 3}, {0, 3, 7}, {0, 7, 4}, {0, 4, 8},
                 {0, 8, 1}, {8, 5, 1}, {5, 6, 2}, {6, 7, 3}, {7, 8, 4}, {5, 7, 6}, {5, 8, 7}};
  return m;
}

TEST(ReferenceSlicer, KeepsTheRidgesInTheTopPlaneAsOpenChains) {
  // CGAL gives the four ridges, cut at the centre where they meet, each towards the centre: no
  // chain starts where another ends, so all four stay open.
  const detail::ReferenceSlicer slicer(cross_roof(), 100);
  ASSERT_TRUE(slicer.ready()) << slicer.figures().reason;
  const detail::ReferenceSection top = slicer.slice(1.0);
  EXPECT_EQ(top.open_polylines, 4u);
  EXPECT_EQ(top.closed_polylines, 0u);
  EXPECT_EQ(top.open_after_joining, 4u);
  std::vector<std::vector<Point2>> chains;
  for (const Contour& c : top.contours) {
    EXPECT_EQ(c.kind, LoopKind::Open);
    chains.push_back(c.points);
  }
  std::sort(chains.begin(), chains.end(), [](const auto& a, const auto& b) {
    return std::tie(a[0].x, a[0].y) < std::tie(b[0].x, b[0].y);
  });
  EXPECT_EQ(chains, (std::vector<std::vector<Point2>>{
                        {{-1, 0}, {0, 0}}, {{0, -1}, {0, 0}}, {{0, 1}, {0, 0}}, {{1, 0}, {0, 0}}}));
  EXPECT_EQ(slicer.vertices_on_plane(1.0), 5u);
  EXPECT_FALSE(slicer.facet_on_plane(1.0));
  const detail::ReferenceSection middle = slicer.slice(0.5);
  EXPECT_EQ(middle.closed_polylines, 1u);
  ASSERT_EQ(middle.contours.size(), 1u);
  EXPECT_EQ(middle.contours[0].points.size(), 12u);
  EXPECT_EQ(middle.contours[0].kind, LoopKind::Outer);
  EXPECT_DOUBLE_EQ(middle.contours[0].signed_area_mm2, 3.0);
}

TEST(JoinChains, ClosesChainsThatFollowEachOther) {
  detail::ReferenceSection out;
  detail::join_chains({{{0, 1}, {0, 0}}, {{0, 0}, {1, 0}}, {{1, 0}, {1, 1}, {0, 1}}}, out);
  ASSERT_EQ(out.contours.size(), 1u);
  const Contour& c = out.contours[0];
  EXPECT_TRUE(c.is_closed);
  EXPECT_EQ(c.points, (std::vector<Point2>{{0, 1}, {0, 0}, {1, 0}, {1, 1}}));
  EXPECT_EQ(c.kind, LoopKind::Outer);
  EXPECT_DOUBLE_EQ(c.signed_area_mm2, 1.0);
  EXPECT_EQ(out.open_after_joining, 0u);
}

TEST(JoinChains, GivesAClockwiseLoopAsAHole) {
  detail::ReferenceSection out;
  detail::join_chains({{{0, 0}, {0, 2}, {2, 2}}, {{2, 2}, {2, 0}, {0, 0}}}, out);
  ASSERT_EQ(out.contours.size(), 1u);
  EXPECT_EQ(out.contours[0].kind, LoopKind::Hole);
  EXPECT_DOUBLE_EQ(out.contours[0].signed_area_mm2, -4.0);
}

TEST(JoinChains, JoinsToTheFirstChainStartingThereAndLeavesTheRestOpen) {
  detail::ReferenceSection out;
  detail::join_chains({{{0, 0}, {1, 0}},
                       {{1, 0}, {1, 1}, {0, 0}},
                       {{1, 0}, {2, 0}},
                       {{5, 5}, {6, 6}},
                       {{6, 6}, {7, 7}}},
                      out);
  ASSERT_EQ(out.contours.size(), 3u);
  EXPECT_TRUE(out.contours[0].is_closed);
  EXPECT_EQ(out.contours[0].points, (std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}}));
  EXPECT_FALSE(out.contours[1].is_closed);
  EXPECT_EQ(out.contours[1].kind, LoopKind::Open);
  EXPECT_EQ(out.contours[1].points, (std::vector<Point2>{{1, 0}, {2, 0}}));
  EXPECT_EQ(out.contours[2].points, (std::vector<Point2>{{5, 5}, {6, 6}, {7, 7}}));
  EXPECT_EQ(out.open_after_joining, 2u);
}

}  // namespace
}  // namespace strata::validate

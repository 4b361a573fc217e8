// The reference slicer (CGAL Polygon_mesh_slicer with the exact kernel) inside validate_model,
// and its section of one plane (src/validate/reference_slicer.cpp).

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "strata/io/read_mesh.hpp"
#include "strata/mesh/primitive_models.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/validate/validate_model.hpp"
#include "strata/validate/validation_json.hpp"
#include "strata/validate/validation_text.hpp"
#include "validate/reference_slicer_internal.hpp"

namespace strata::validate {
namespace {

IndexedMesh box_mesh(const Vec3& min, const Vec3& max) {
  return weld_vertices(mesh::make_box(min, max));
}

SliceOptions cells_of(double d, std::optional<Vec3> origin = Vec3{0, 0, 0}) {
  SliceOptions options;
  options.grid.dx_mm = options.grid.dy_mm = options.grid.dz_mm = d;
  options.grid.origin = origin;
  options.fill_rule = FillRule::NonZero;
  options.shell_mm = d;
  options.threads = 1;
  return options;
}

ValidationReport validate(const IndexedMesh& mesh, const SliceOptions& options,
                          const ValidateOptions& vopts = {}) {
  const GridSpec grid = make_grid(mesh.bounds(), options.grid).value();
  auto report = validate_model(mesh, grid, options, vopts);
  EXPECT_TRUE(report.has_value()) << (report ? "" : report.error().to_string());
  return report ? std::move(report).value() : ValidationReport{};
}

double diagonal(const IndexedMesh& mesh) {
  const Bbox3 b = mesh.bounds();
  return std::hypot(b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z);
}

TEST(ReferenceSlicer, AgreesWithBothPathsOnAnIcosphere) {
  const IndexedMesh sphere = weld_vertices(mesh::make_sphere(10.0, 3));
  const ValidationReport r = validate(sphere, cells_of(0.7, std::nullopt));
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
  const ValidationReport r = validate(ring, cells_of(0.5, std::nullopt));
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
  const ValidationReport r = validate(sphere, cells_of(0.9, std::nullopt));
  ASSERT_TRUE(r.reference.ran) << r.reference.reason;
  for (const ReferenceLayerComparison& l : r.reference.layers) {
    EXPECT_EQ(l.area_method_exact, AreaMethod::Identical) << "layer " << l.layer;
    EXPECT_EQ(l.hausdorff_exact_mm, 0.0) << "layer " << l.layer;
  }
}

TEST(ReferenceSlicer, SkipsANonManifoldModelAndSaysWhy) {
  // Two boxes sharing one edge: four facets around it.
  const IndexedMesh m = box_mesh({0, 0, 0}, {2, 2, 2});
  const IndexedMesh b = box_mesh({2, 2, 0}, {4, 4, 2});
  TriangleSoup soup;
  for (const IndexedMesh* part : {&m, &b}) {
    for (FacetIndex f = 0; f < part->triangles.size(); ++f) {
      soup.triangles.push_back({part->corner(f, 0), part->corner(f, 1), part->corner(f, 2)});
    }
  }
  const ValidationReport r = validate(weld_vertices(soup), cells_of(1.0));
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::NonManifold);
  EXPECT_NE(r.reference.reason.find("non-manifold"), std::string::npos) << r.reference.reason;
  EXPECT_EQ(r.reference.layers_compared, 0u);
  EXPECT_NE(validation_text(r).find("not run: not a 2-manifold"), std::string::npos)
      << validation_text(r);
}

TEST(ReferenceSlicer, SkipsAnOpenModel) {
  IndexedMesh m = box_mesh({0, 0, 0}, {2, 2, 2});
  m.triangles.pop_back();
  const ValidationReport r = validate(m, cells_of(1.0));
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::NotClosed);
  EXPECT_NE(r.reference.reason.find("border edges"), std::string::npos) << r.reference.reason;
}

TEST(ReferenceSlicer, SkipsAnInconsistentlyOrientedModel) {
  IndexedMesh m = box_mesh({0, 0, 0}, {2, 2, 2});
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  const ValidationReport r = validate(m, cells_of(1.0));
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::Inconsistent) << r.reference.reason;
}

TEST(ReferenceSlicer, SkipsAModelOverTheFacetCap) {
  ValidateOptions vopts;
  vopts.reference_max_facets = 11;
  const ValidationReport r = validate(box_mesh({0, 0, 0}, {2, 2, 2}), cells_of(1.0), vopts);
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::TooManyFacets);
  EXPECT_EQ(r.reference.max_facets, 11u);
  EXPECT_NE(r.reference.reason.find("12 facets"), std::string::npos) << r.reference.reason;
}

TEST(ReferenceSlicer, IsOffWhenAskedTo) {
  ValidateOptions vopts;
  vopts.reference_slicer = false;
  const ValidationReport r = validate(box_mesh({0, 0, 0}, {2, 2, 2}), cells_of(1.0), vopts);
  EXPECT_FALSE(r.reference.ran);
  EXPECT_EQ(r.reference.skipped, ReferenceSkip::Off);
}

TEST(ReferenceSlicer, CountsALayerWhosePlaneHoldsAVertex) {
  // The apex (0, 0, 2.5) lies on the plane of layer 2; no other vertex is on a plane.
  const IndexedMesh tetra =
      weld_vertices(mesh::make_tetrahedron({0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 2.5}));
  const ValidationReport r = validate(tetra, cells_of(1.0));
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
  const ValidationReport r = validate(box_mesh({0, 0, 0.5}, {3, 2, 3}), cells_of(1.0));
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
  const ValidationReport r = validate(box_mesh({0, 0, 0}, {3, 2, 2.5}), cells_of(1.0));
  const ReferenceSlicerFigures& f = r.reference;
  ASSERT_TRUE(f.ran) << f.reason;
  ASSERT_EQ(f.layers.size(), 3u);
  EXPECT_TRUE(f.layers[2].facet_on_plane);
  EXPECT_FALSE(f.layers[2].differs_from_exact);
  EXPECT_FALSE(f.layers[2].differs_from_fast);
  EXPECT_EQ(f.max_symmetric_difference_exact_all_mm2, 0.0);
}

TEST(ReferenceSlicer, GivesACounterClockwiseLoopAroundTheMaterial) {
  const IndexedMesh m = box_mesh({0, 0, 0}, {2, 3, 2});
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
  const ValidationReport r = validate(box_mesh({0, 0, 0}, {3, 2, 2}), cells_of(1.0));
  const nlohmann::json j = nlohmann::json::parse(validation_json(r));
  const nlohmann::json& ref = j.at("reference_slicer");
  EXPECT_TRUE(ref.at("ran").get<bool>());
  EXPECT_EQ(ref.at("skipped"), "none");
  EXPECT_EQ(ref.at("layers_compared"), r.grid.nz);
  EXPECT_EQ(ref.at("layers").size(), r.grid.nz);
  EXPECT_NE(validation_text(r).find("reference slicer (CGAL Polygon_mesh_slicer"),
            std::string::npos);
}

}  // namespace
}  // namespace strata::validate

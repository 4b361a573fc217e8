#include "strata/diagnose/mesh_report_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace strata::diagnose {
namespace {

MeshReport open_edges_report() {
  MeshReport r;
  r.num_input_facets = 11;
  r.num_facets = 11;
  r.boundary_edges.count = 3;
  r.boundary_edges.locations = {{{0, 0, 0}, {1, 0, 0}}};
  r.num_boundary_loops = 1;
  r.verdict = Verdict::NeedsRepair;
  r.verdict_reason = "3 open edges in 1 loop";
  return r;
}

TEST(MeshReportText, EndsWithVerdictAndReason) {
  const std::string text = mesh_report_text(open_edges_report());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const std::string last = text.substr(text.rfind('\n', text.size() - 2) + 1);
  EXPECT_EQ(last, "verdict: needs-repair - 3 open edges in 1 loop\n");
}

TEST(MeshReportText, ShowsCountAndFirstLocation) {
  const std::string text = mesh_report_text(open_edges_report());
  EXPECT_NE(text.find("boundary edges"), std::string::npos);
  EXPECT_NE(text.find("3 in 1 loop"), std::string::npos) << text;
  EXPECT_NE(text.find("(0, 0, 0)-(1, 0, 0)"), std::string::npos) << text;
}

TEST(MeshReportText, SaysWhenSelfIntersectionsWereNotChecked) {
  const std::string text = mesh_report_text(open_edges_report());
  EXPECT_NE(text.find("not checked"), std::string::npos) << text;
}

/// A report in which every defect was found `count` times, with the first `located` locations
/// kept, and both optional checks run.
MeshReport report_with_every_defect(std::size_t count, std::size_t located) {
  MeshReport r;
  r.num_input_facets = 12;
  r.num_facets = 12;
  r.num_vertices = 8;
  r.normals_checked = true;
  r.self_intersections_checked = true;
  r.near_vertex_tolerance_mm = 1e-6;
  r.num_boundary_loops = 1;
  const auto fill = [&](auto& occurrences, auto make) {
    occurrences.count = count;
    for (std::size_t n = 0; n < located; ++n) occurrences.locations.push_back(make(n));
  };
  const auto point = [](std::size_t n) { return Vec3{static_cast<double>(n), 0.5, 0}; };
  const auto edge = [&](std::size_t n) { return EdgeLocation{point(n), point(n + 1)}; };
  fill(r.boundary_edges, edge);
  fill(r.non_manifold_edges, edge);
  fill(r.inconsistent_edges, edge);
  fill(r.unbalanced_edges, edge);
  fill(r.non_manifold_vertices, point);
  fill(r.near_vertices, [&](std::size_t n) { return PointPair{point(n), point(n)}; });
  const auto facet = [](std::size_t n) { return static_cast<FacetIndex>(10 + n); };
  fill(r.degenerate_facets, facet);
  fill(r.duplicate_facets, facet);
  fill(r.inverted_shells, [](std::size_t n) { return n; });
  fill(r.flipped_normals, facet);
  fill(r.zero_normals, facet);
  fill(r.non_finite_normals, facet);
  fill(r.self_intersections, [&](std::size_t n) {
    return FacetPair{facet(n), static_cast<FacetIndex>(2 * n)};
  });
  return r;
}

/// The line of `label` (padded to its column as the report does).
std::string line_of(const std::string& text, const std::string& label) {
  const std::string start = "  " + label + std::string(28 - label.size(), ' ') + " ";
  const std::size_t at = text.find(start);
  if (at == std::string::npos) return "(no line " + label + ")";
  return text.substr(at + start.size(), text.find('\n', at) - at - start.size());
}

TEST(MeshReportText, ShowsThreeLocationsOfEveryDefectAndSaysThereAreMore) {
  const std::string text = mesh_report_text(report_with_every_defect(5, 4));
  const std::string edges =
      "5  e.g. (0, 0.5, 0)-(1, 0.5, 0), (1, 0.5, 0)-(2, 0.5, 0), "
      "(2, 0.5, 0)-(3, 0.5, 0), ...";
  EXPECT_EQ(line_of(text, "boundary edges"),
            "5 in 1 loop  e.g. (0, 0.5, 0)-(1, 0.5, 0), (1, 0.5, 0)-(2, 0.5, 0), "
            "(2, 0.5, 0)-(3, 0.5, 0), ...");
  EXPECT_EQ(line_of(text, "non-manifold edges"), edges);
  EXPECT_EQ(line_of(text, "inconsistent edges"), edges);
  EXPECT_EQ(line_of(text, "unbalanced edges"), edges);
  EXPECT_EQ(line_of(text, "non-manifold vertices"),
            "5  e.g. (0, 0.5, 0), (1, 0.5, 0), (2, 0.5, 0), ...");
  EXPECT_EQ(line_of(text, "near-coincident vertices"),
            "5 (closer than 1e-06 mm)  e.g. (0, 0.5, 0) ~ (0, 0.5, 0), (1, 0.5, 0) ~ (1, 0.5, 0), "
            "(2, 0.5, 0) ~ (2, 0.5, 0), ...");
  const std::string facets = "5  e.g. facet 10, facet 11, facet 12, ...";
  EXPECT_EQ(line_of(text, "degenerate facets"), facets);
  EXPECT_EQ(line_of(text, "duplicate facets"), facets);
  EXPECT_EQ(line_of(text, "inverted shells"), "5  e.g. shell 0, shell 1, shell 2, ...");
  EXPECT_EQ(line_of(text, "stored normals flipped"), facets);
  EXPECT_EQ(line_of(text, "stored normals zero"), facets);
  EXPECT_EQ(line_of(text, "stored normals not finite"), facets);
  EXPECT_EQ(line_of(text, "self-intersecting pairs"),
            "5  e.g. facets 10 & 0, facets 11 & 2, facets 12 & 4, ...");
}

TEST(MeshReportText, ShowsEveryLocationWhenThereAreFew) {
  const std::string text = mesh_report_text(report_with_every_defect(2, 2));
  EXPECT_EQ(line_of(text, "non-manifold edges"),
            "2  e.g. (0, 0.5, 0)-(1, 0.5, 0), (1, 0.5, 0)-(2, 0.5, 0)");
  EXPECT_EQ(line_of(text, "non-manifold vertices"), "2  e.g. (0, 0.5, 0), (1, 0.5, 0)");
  EXPECT_EQ(line_of(text, "near-coincident vertices"),
            "2 (closer than 1e-06 mm)  e.g. (0, 0.5, 0) ~ (0, 0.5, 0), (1, 0.5, 0) ~ (1, 0.5, 0)");
  EXPECT_EQ(line_of(text, "degenerate facets"), "2  e.g. facet 10, facet 11");
  EXPECT_EQ(line_of(text, "inverted shells"), "2  e.g. shell 0, shell 1");
  EXPECT_EQ(line_of(text, "self-intersecting pairs"), "2  e.g. facets 10 & 0, facets 11 & 2");
}

TEST(MeshReportText, ShowsOnlyTheCountOfDefectsFoundWithoutLocations) {
  const std::string text = mesh_report_text(report_with_every_defect(7, 0));
  EXPECT_EQ(line_of(text, "boundary edges"), "7 in 1 loop");
  EXPECT_EQ(line_of(text, "non-manifold vertices"), "7");
  EXPECT_EQ(line_of(text, "near-coincident vertices"), "7 (closer than 1e-06 mm)");
  EXPECT_EQ(line_of(text, "degenerate facets"), "7");
  EXPECT_EQ(line_of(text, "inverted shells"), "7");
  EXPECT_EQ(line_of(text, "self-intersecting pairs"), "7");
}

TEST(MeshReportText, SaysWhenASearchWasCutShort) {
  MeshReport r = report_with_every_defect(1, 1);
  r.near_vertices_truncated = true;
  r.self_intersections_truncated = true;
  r.num_boundary_loops = 2;
  const std::string text = mesh_report_text(r);
  EXPECT_EQ(line_of(text, "near-coincident vertices"),
            "1 (closer than 1e-06 mm, search cut short)  e.g. (0, 0.5, 0) ~ (0, 0.5, 0)");
  EXPECT_EQ(line_of(text, "self-intersecting pairs"),
            "1 (search cut short: at least)  e.g. facets 10 & 0");
  EXPECT_EQ(line_of(text, "boundary edges"), "1 in 2 loops  e.g. (0, 0.5, 0)-(1, 0.5, 0)");
}

TEST(MeshReportText, GivesTheSizeOfTheMesh) {
  MeshReport r = open_edges_report();
  r.num_vertices = 8;
  r.bounds.add({-1, 0, 2});
  r.bounds.add({1, 0.5, 5});
  r.volume_mm3 = 3;
  r.surface_area_mm2 = 12.5;
  r.shells.resize(2);
  r.num_closed_shells = 1;
  r.inverted_shells.count = 1;
  const std::string text = mesh_report_text(r);
  EXPECT_EQ(line_of(text, "facets"), "11 (11 read)");
  EXPECT_EQ(line_of(text, "vertices (exact weld)"), "8");
  EXPECT_EQ(line_of(text, "bounding box"), "2 x 0.5 x 3 mm at (-1, 0, 2)");
  EXPECT_EQ(line_of(text, "volume (exact)"), "3 mm3");
  EXPECT_EQ(line_of(text, "surface area"), "12.5 mm2");
  EXPECT_EQ(line_of(text, "shells"), "2 (1 closed, 1 inverted)");
  EXPECT_EQ(line_of(text, "bounding box"), "2 x 0.5 x 3 mm at (-1, 0, 2)");
  EXPECT_EQ(line_of(mesh_report_text(MeshReport{}), "bounding box"), "empty");
  EXPECT_EQ(text.find("stored normals"), std::string::npos) << "not checked: no line";
}

}  // namespace
}  // namespace strata::diagnose

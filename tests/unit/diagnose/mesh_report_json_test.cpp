#include "strata/diagnose/mesh_report_json.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

namespace strata::diagnose {
namespace {

MeshReport report_with_every_section() {
  MeshReport r;
  r.num_input_facets = 11;
  r.num_facets = 11;
  r.num_vertices = 8;
  r.bounds.add({0, 0, 0});
  r.bounds.add({1, 2, 3});
  r.boundary_edges.count = 3;
  r.boundary_edges.locations = {{{0, 0, 0}, {1, 0, 0}}};
  r.num_boundary_loops = 1;
  r.self_intersections_checked = true;
  r.self_intersections.count = 2;
  r.self_intersections.locations = {{1, 4}, {2, 9}};
  r.shells.push_back(ShellReport{.num_facets = 11, .signed_volume_mm3 = 0.5});
  r.verdict = Verdict::NeedsRepair;
  r.verdict_reason = "3 open edges in 1 loop";
  return r;
}

TEST(MeshReportJson, CarriesCountsLocationsAndVerdict) {
  const auto j = nlohmann::json::parse(mesh_report_json(report_with_every_section()));
  EXPECT_EQ(j["facets"], 11);
  EXPECT_EQ(j["vertices"], 8);
  EXPECT_EQ(j["boundary_edges"]["count"], 3);
  EXPECT_EQ(j["boundary_edges"]["loops"], 1);
  EXPECT_EQ(j["boundary_edges"]["first"][0][1], nlohmann::json::parse("[1.0, 0.0, 0.0]"));
  EXPECT_EQ(j["self_intersections"]["first"][1], nlohmann::json::parse("[2, 9]"));
  EXPECT_EQ(j["bounds_mm"]["size"], nlohmann::json::parse("[1.0, 2.0, 3.0]"));
  EXPECT_EQ(j["shells"]["count"], 1);
  EXPECT_EQ(j["shells"]["first"][0]["signed_volume_mm3"], 0.5);
  EXPECT_EQ(j["verdict"], "needs-repair");
  EXPECT_EQ(j["reason"], "3 open edges in 1 loop");
}

TEST(MeshReportJson, UncheckedPartsAreNull) {
  MeshReport r = report_with_every_section();
  r.self_intersections_checked = false;
  const auto j = nlohmann::json::parse(mesh_report_json(r));
  EXPECT_TRUE(j["self_intersections"].is_null());
  EXPECT_TRUE(j["stored_normals"].is_null());
}

TEST(MeshReportJson, NonFiniteNumbersBecomeNull) {
  MeshReport r = report_with_every_section();
  r.volume_mm3 = std::numeric_limits<double>::infinity();
  const auto j = nlohmann::json::parse(mesh_report_json(r));
  EXPECT_TRUE(j["volume_mm3"].is_null());
}

TEST(MeshReportJson, EmptyBoundsAreNull) {
  const auto j = nlohmann::json::parse(mesh_report_json(MeshReport{}));
  EXPECT_TRUE(j["bounds_mm"].is_null());
  EXPECT_EQ(j["verdict"], "printable");
}

TEST(MeshReportJson, CarriesTheLocationsOfEveryKindOfDefect) {
  MeshReport r;
  r.normals_checked = true;
  r.near_vertices = {1, {{{0, 0, 0}, {0, 0, 1e-9}}}};
  r.non_manifold_vertices = {2, {{1, 2, 3}}};
  r.degenerate_facets = {1, {4}};
  r.duplicate_facets = {1, {5}};
  r.unbalanced_edges = {1, {{{0, 0, 0}, {0, 1, 0}}}};
  r.inverted_shells = {1, {0}};
  r.flipped_normals = {1, {6}};
  r.zero_normals = {1, {7}};
  r.non_finite_normals = {1, {8}};
  const auto j = nlohmann::json::parse(mesh_report_json(r));
  EXPECT_EQ(j.at("near_vertices").at("first"),
            nlohmann::json::parse("[[[0, 0, 0], [0, 0, 1e-9]]]"));
  EXPECT_EQ(j.at("non_manifold_vertices"),
            nlohmann::json::parse(R"({"count": 2, "first": [[1, 2, 3]]})"));
  EXPECT_EQ(j.at("degenerate_facets").at("first"), nlohmann::json::parse("[4]"));
  EXPECT_EQ(j.at("duplicate_facets").at("first"), nlohmann::json::parse("[5]"));
  EXPECT_EQ(j.at("unbalanced_edges").at("first"),
            nlohmann::json::parse("[[[0, 0, 0], [0, 1, 0]]]"));
  EXPECT_EQ(j.at("shells").at("inverted"), nlohmann::json::parse(R"({"count": 1, "first": [0]})"));
  EXPECT_EQ(j.at("stored_normals"), nlohmann::json::parse(R"({
      "flipped": {"count": 1, "first": [6]}, "zero": {"count": 1, "first": [7]},
      "non_finite": {"count": 1, "first": [8]}})"));
}

TEST(MeshReportJson, ListsTheFirstTwentyShells) {
  MeshReport r;
  for (FacetIndex s = 0; s < 25; ++s) r.shells.push_back(ShellReport{.first_facet = 4 * s});
  const auto j = nlohmann::json::parse(mesh_report_json(r));
  EXPECT_EQ(j.at("shells").at("count"), 25);
  const auto& first = j.at("shells").at("first");
  ASSERT_EQ(first.size(), kMaxLocations);
  EXPECT_EQ(first.back().at("first_facet"), 76);
}

}  // namespace
}  // namespace strata::diagnose

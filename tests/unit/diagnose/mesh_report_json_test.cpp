#include "strata/diagnose/mesh_report_json.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

namespace strata::diagnose {
namespace {

MeshReport open_report() {
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
  const auto j = nlohmann::json::parse(mesh_report_json(open_report()));
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
  MeshReport r = open_report();
  r.self_intersections_checked = false;
  const auto j = nlohmann::json::parse(mesh_report_json(r));
  EXPECT_TRUE(j["self_intersections"].is_null());
  EXPECT_TRUE(j["stored_normals"].is_null());
}

TEST(MeshReportJson, NonFiniteNumbersBecomeNull) {
  MeshReport r = open_report();
  r.volume_mm3 = std::numeric_limits<double>::infinity();
  const auto j = nlohmann::json::parse(mesh_report_json(r));
  EXPECT_TRUE(j["volume_mm3"].is_null());
}

TEST(MeshReportJson, EmptyBoundsAreNull) {
  const auto j = nlohmann::json::parse(mesh_report_json(MeshReport{}));
  EXPECT_TRUE(j["bounds_mm"].is_null());
  EXPECT_EQ(j["verdict"], "printable");
}

}  // namespace
}  // namespace strata::diagnose

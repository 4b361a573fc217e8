#include "strata/diagnose/mesh_report_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace strata::diagnose {
namespace {

MeshReport open_report() {
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
  const std::string text = mesh_report_text(open_report());
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const std::string last = text.substr(text.rfind('\n', text.size() - 2) + 1);
  EXPECT_EQ(last, "verdict: needs-repair - 3 open edges in 1 loop\n");
}

TEST(MeshReportText, ShowsCountAndFirstLocation) {
  const std::string text = mesh_report_text(open_report());
  EXPECT_NE(text.find("boundary edges"), std::string::npos);
  EXPECT_NE(text.find("3 in 1 loop"), std::string::npos) << text;
  EXPECT_NE(text.find("(0, 0, 0)-(1, 0, 0)"), std::string::npos) << text;
}

TEST(MeshReportText, SaysWhenSelfIntersectionsWereNotChecked) {
  const std::string text = mesh_report_text(open_report());
  EXPECT_NE(text.find("not checked"), std::string::npos) << text;
}

}  // namespace
}  // namespace strata::diagnose

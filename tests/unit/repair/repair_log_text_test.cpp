#include "strata/repair/repair_log_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace strata::repair {
namespace {

TEST(RepairLogText, HasALineForEveryStepEvenWhenNothingWasDone) {
  RepairLog log;
  log.polygon_mesh = true;
  const std::string text = repair_log_text(log);
  for (const char* label :
       {"degenerate facets removed", "duplicate facets removed", "T-junction cracks closed",
        "non-manifold vertices split", "facets flipped (consistency)", "borders stitched", "holes",
        "shells reoriented (volume)", "output"}) {
    EXPECT_NE(text.find(label), std::string::npos) << label << "\n" << text;
  }
  EXPECT_EQ(text.rfind("repair\n", 0), 0u) << text;
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find("changed input facets"), std::string::npos) << text;
}

TEST(RepairLogText, SaysWhenHolesWereNotFilled) {
  RepairLog log;
  log.polygon_mesh = true;
  log.holes_found = 3;
  EXPECT_NE(repair_log_text(log).find("3 found, not filled (filling not requested)"),
            std::string::npos);
  EXPECT_NE(repair_log_text(log, "--fill-holes not given")
                .find("3 found, not filled (--fill-holes not given)"),
            std::string::npos);
  log.fill_holes_requested = true;
  log.holes_filled = 2;
  log.hole_facets_added = 5;
  log.holes_not_filled = 1;
  EXPECT_NE(repair_log_text(log).find("3 found, 2 filled (5 facets added), 1 left open"),
            std::string::npos)
      << repair_log_text(log);
}

TEST(RepairLogText, ListsTheFirstChangedFacets) {
  RepairLog log;
  log.changes = {{4, FacetChangeKind::RemovedDuplicate}, {9, FacetChangeKind::Flipped}};
  EXPECT_NE(repair_log_text(log).find("2  e.g. facet 4 removed-duplicate, facet 9 flipped"),
            std::string::npos)
      << repair_log_text(log);
}

TEST(RepairLogSummary, NamesWhatChangedOnOneLine) {
  RepairLog log;
  log.input_facets = 11;
  log.output_facets = 12;
  log.fill_holes_requested = true;
  log.holes_found = 1;
  log.holes_filled = 1;
  log.facets_flipped = 2;
  EXPECT_EQ(repair_log_summary(log),
            "repair: 11 facets in, 12 out; 2 facets flipped, 1 hole filled");
}

TEST(RepairLogSummary, SaysWhenThereWasNothingToChange) {
  RepairLog log;
  log.input_facets = 12;
  log.output_facets = 12;
  EXPECT_EQ(repair_log_summary(log), "repair: 12 facets in, 12 out; nothing to change");
}

/// The value of the line `label` (padded to its column as the text does).
std::string value_of(const std::string& text, const std::string& label) {
  const std::string start = "  " + label + std::string(28 - label.size(), ' ') + " ";
  const std::size_t at = text.find(start);
  if (at == std::string::npos) return "(no line " + label + ")";
  return text.substr(at + start.size(), text.find('\n', at) - at - start.size());
}

TEST(RepairLogText, GivesTheFiguresOfEveryStep) {
  RepairLog log;
  log.input_facets = 1;
  log.input_vertices = 1;
  log.points_merged = 2;
  log.degenerate_facets_removed = 3;
  log.duplicate_facets_removed = 4;
  log.cancelling_duplicates_removed = 1;
  log.t_junctions_closed = 2;
  log.t_junction_facets_added = 1;
  log.non_manifold_vertices_split = 1;
  log.vertex_copies_added = 1;
  log.non_manifold_edges = 5;
  log.facets_flipped_for_consistency = 6;
  log.polygon_mesh = true;
  log.borders_stitched = 1;
  log.holes_found = 2;
  log.seams_at_shared_edges = 1;
  const std::string text = repair_log_text(log, "not asked");
  EXPECT_EQ(value_of(text, "input"), "1 facet, 1 vertex");
  EXPECT_EQ(value_of(text, "corners merged (exact weld)"), "2");
  EXPECT_EQ(value_of(text, "degenerate facets removed"), "3");
  EXPECT_EQ(value_of(text, "duplicate facets removed"),
            "4, and the last copy of 1 set whose orientations cancel");
  EXPECT_EQ(value_of(text, "T-junction cracks closed"), "2 (1 facet added)");
  EXPECT_EQ(value_of(text, "non-manifold vertices split"),
            "1 (1 copy added; 5 non-manifold edges)");
  EXPECT_EQ(value_of(text, "facets flipped (consistency)"), "6");
  EXPECT_EQ(value_of(text, "borders stitched"), "1 edge pair");
  EXPECT_EQ(value_of(text, "holes"),
            "2 found, not filled (not asked); 1 border along non-manifold edges left as they are");
  EXPECT_EQ(value_of(text, "shells reoriented (volume)"), "not run");
  log.cancelling_duplicates_removed = 2;
  log.t_junction_facets_added = 3;
  log.vertex_copies_added = 2;
  log.borders_stitched = 2;
  log.seams_at_shared_edges = 2;
  const std::string plural = repair_log_text(log, "not asked");
  EXPECT_EQ(value_of(plural, "duplicate facets removed"),
            "4, and the last copy of 2 sets whose orientations cancel");
  EXPECT_EQ(value_of(plural, "T-junction cracks closed"), "2 (3 facets added)");
  EXPECT_EQ(value_of(plural, "non-manifold vertices split"),
            "1 (2 copies added; 5 non-manifold edges)");
  EXPECT_EQ(value_of(plural, "borders stitched"), "2 edge pairs");
  EXPECT_EQ(value_of(plural, "holes"),
            "2 found, not filled (not asked); 2 borders along non-manifold edges left as they are");
}

TEST(RepairLogText, SkipsStitchingAndHolesWhenTheFacetsAreNoPolygonMesh) {
  RepairLog log;
  const std::string text = repair_log_text(log);
  EXPECT_EQ(value_of(text, "stitching, holes"), "skipped: the facets do not form a polygon mesh");
  EXPECT_EQ(text.find("borders stitched"), std::string::npos) << text;
}

TEST(RepairLogText, GivesTheVolumeOrientationAndItsNote) {
  RepairLog log;
  log.volume_orientation_done = true;
  log.shells_reoriented = 1;
  log.closed_shells = 2;
  log.facets_flipped_with_shells = 12;
  EXPECT_EQ(value_of(repair_log_text(log), "shells reoriented (volume)"),
            "1 of 2 closed (12 facets flipped)");
  log.volume_orientation_note = "1 open shell left as it is";
  EXPECT_EQ(value_of(repair_log_text(log), "shells reoriented (volume)"),
            "1 of 2 closed (12 facets flipped); 1 open shell left as it is");
  log.volume_orientation_done = false;
  log.volume_orientation_note = "skipped: the closed shells do not form a polygon mesh";
  EXPECT_EQ(value_of(repair_log_text(log), "shells reoriented (volume)"),
            "skipped: the closed shells do not form a polygon mesh");
}

TEST(RepairLogText, ListsFiveChangedFacetsAndSaysThereAreMore) {
  RepairLog log;
  log.changes = {{0, FacetChangeKind::RemovedDegenerate},
                 {1, FacetChangeKind::RemovedDuplicate},
                 {2, FacetChangeKind::RemovedCancellingDuplicate},
                 {3, FacetChangeKind::SplitAtTJunction},
                 {4, FacetChangeKind::Flipped},
                 {5, FacetChangeKind::Flipped}};
  EXPECT_EQ(value_of(repair_log_text(log), "changed input facets"),
            "6  e.g. facet 0 removed-degenerate, facet 1 removed-duplicate, facet 2 "
            "removed-cancelling-duplicate, facet 3 split-at-t-junction, facet 4 flipped, ...");
}

TEST(RepairLogSummary, NamesEveryKindOfChange) {
  RepairLog log;
  log.input_facets = 1;
  log.output_facets = 1;
  log.degenerate_facets_removed = 1;
  log.duplicate_facets_removed = 1;
  log.cancelling_duplicates_removed = 1;
  log.t_junctions_closed = 1;
  log.facets_flipped = 1;
  log.shells_reoriented = 2;
  log.holes_found = 3;
  log.holes_not_filled = 1;
  EXPECT_EQ(repair_log_summary(log),
            "repair: 1 facet in, 1 out; 1 degenerate facet removed, 2 duplicate facets removed, 1 "
            "T-junction crack closed, 1 facet flipped, 2 shells reoriented, 1 hole left open, 3 "
            "holes found (not filled)");
}

}  // namespace
}  // namespace strata::repair

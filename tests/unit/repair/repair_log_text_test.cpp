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

}  // namespace
}  // namespace strata::repair

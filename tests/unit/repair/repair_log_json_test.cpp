#include "strata/repair/repair_log_json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace strata::repair {
namespace {

RepairLog sample_log() {
  RepairLog log;
  log.input_facets = 14;
  log.input_vertices = 9;
  log.degenerate_facets_removed = 1;
  log.duplicate_facets_removed = 1;
  log.fill_holes_requested = true;
  log.holes_found = 2;
  log.holes_filled = 1;
  log.hole_facets_added = 3;
  log.holes_not_filled = 1;
  log.volume_orientation_note = "1 open shell left as oriented";
  log.output_facets = 15;
  log.kept_input_facets = 12;
  for (FacetIndex f = 0; f < 30; ++f) log.changes.push_back({f, FacetChangeKind::Flipped});
  log.changes[0].kind = FacetChangeKind::RemovedDegenerate;
  return log;
}

TEST(RepairLogJson, GroupsTheCountsByStep) {
  const auto json = nlohmann::json::parse(repair_log_json(sample_log()));
  EXPECT_EQ(json["changed"], true);
  EXPECT_EQ(json["input"]["facets"], 14);
  EXPECT_EQ(json["degenerate"]["facets_removed"], 1);
  EXPECT_EQ(json["duplicates"]["facets_removed"], 1);
  EXPECT_EQ(json["holes"]["found"], 2);
  EXPECT_EQ(json["holes"]["filled"], 1);
  EXPECT_EQ(json["holes"]["facets_added"], 3);
  EXPECT_EQ(json["holes"]["not_filled"], 1);
  EXPECT_EQ(json["volume_orientation"]["note"], "1 open shell left as oriented");
  EXPECT_EQ(json["output"]["facets"], 15);
}

TEST(RepairLogJson, ListsTheFirstChangesAndCountsAll) {
  const auto json = nlohmann::json::parse(repair_log_json(sample_log()));
  EXPECT_EQ(json["changes"]["count"], 30);
  ASSERT_EQ(json["changes"]["first"].size(), kMaxChangesListed);
  EXPECT_EQ(json["changes"]["first"][0]["facet"], 0);
  EXPECT_EQ(json["changes"]["first"][0]["change"], "removed-degenerate");
  EXPECT_EQ(json["changes"]["first"][1]["change"], "flipped");
}

TEST(RepairLogJson, AnUntouchedMeshSaysNothingChanged) {
  const auto json = nlohmann::json::parse(repair_log_json(RepairLog{}));
  EXPECT_EQ(json["changed"], false);
  EXPECT_EQ(json["changes"]["count"], 0);
  EXPECT_TRUE(json["changes"]["first"].empty());
}

}  // namespace
}  // namespace strata::repair

// repair_mesh() over the defective STL files of the shared corpus: with and without hole filling it
// must succeed, must open no edge and make no edge non-manifold, and must leave no zero-area and
// no duplicate facet; a second repair must change nothing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <vector>

#include "strata/diagnose/diagnose_mesh.hpp"
#include "strata/io/read_mesh.hpp"
#include "strata/mesh/weld_vertices.hpp"
#include "strata/repair/repair_log_text.hpp"
#include "strata/repair/repair_mesh.hpp"
#include "support/corpus.hpp"

namespace strata::repair {
namespace {

using test::CorpusEntry;

constexpr std::uint64_t kMaxBytes = 2'000'000;

/// Files whose manifest defects include something repair is for.
bool needs_repair(const CorpusEntry& e) {
  for (std::string item : e.defects) {
    std::transform(item.begin(), item.end(), item.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* word : {"hole", "open", "duplicate", "flipped", "inconsistent"}) {
      if (item.find(word) != std::string::npos) return true;
    }
  }
  return false;
}

std::vector<CorpusEntry> defective_stl_files() {
  std::vector<CorpusEntry> out;
  for (CorpusEntry& e : test::load_corpus_manifest()) {
    if (e.is_stl() && e.bytes < kMaxBytes && needs_repair(e)) out.push_back(std::move(e));
  }
  return out;
}

diagnose::MeshReport counts_of(const TriangleSoup& soup) {
  diagnose::DiagnoseOptions options;
  options.check_self_intersections = false;
  options.near_vertex_mm = 0.0;
  return diagnose::diagnose_mesh(weld_vertices(soup), soup, options);
}

class RepairCorpus : public testing::TestWithParam<CorpusEntry> {};

TEST_P(RepairCorpus, OpensNoEdgeAndLeavesNoDegenerateOrDuplicateFacet) {
  const auto soup = io::read_mesh(GetParam().full_path());
  if (!soup) GTEST_SKIP() << "not readable: " << soup.error().to_string();
  const diagnose::MeshReport before = counts_of(*soup);
  std::size_t open_without_filling = 0;
  for (const bool fill : {false, true}) {
    SCOPED_TRACE(fill ? "with --fill-holes" : "without --fill-holes");
    const auto repaired = repair_mesh(*soup, RepairOptions{.fill_holes = fill});
    ASSERT_TRUE(repaired.has_value()) << repaired.error().to_string();
    const RepairLog& log = repaired->log;
    const diagnose::MeshReport after = counts_of(repaired->soup);
    EXPECT_LE(after.boundary_edges.count, before.boundary_edges.count);
    EXPECT_LE(after.non_manifold_edges.count, before.non_manifold_edges.count);
    EXPECT_EQ(after.degenerate_facets.count, 0u);
    EXPECT_EQ(after.duplicate_facets.count, 0u);
    EXPECT_EQ(log.output_facets, repaired->soup.triangles.size());
    EXPECT_EQ(log.input_facets, log.kept_input_facets + log.degenerate_facets_removed +
                                    log.duplicate_facets_removed +
                                    log.cancelling_duplicates_removed);
    if (fill) {
      EXPECT_LE(after.boundary_edges.count, open_without_filling);
      EXPECT_EQ(log.holes_filled + log.holes_not_filled, log.holes_found);
    } else {
      open_without_filling = after.boundary_edges.count;
    }

    const auto again = repair_mesh(repaired->soup, RepairOptions{.fill_holes = fill});
    ASSERT_TRUE(again.has_value()) << again.error().to_string();
    EXPECT_FALSE(again->log.changed_anything()) << repair_log_summary(again->log);
    EXPECT_TRUE(again->soup.triangles == repaired->soup.triangles)
        << "a second repair changed the facets";
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, RepairCorpus, testing::ValuesIn(defective_stl_files()),
                         test::CorpusTestName{});

TEST(RepairCorpusSelection, FindsDefectiveFiles) { EXPECT_GE(defective_stl_files().size(), 20u); }

}  // namespace
}  // namespace strata::repair
